#!/usr/bin/env python3
"""PRT against Blender's Cycles on the model files of bench/cycles/references/: one command
that renders each scene with PRT, compares it with Cycles' committed reference and prints a
table (docs/benchmarks.md, "PRT against Cycles").

    bench/cycles/run.py [--integrator path|hall] [--spp N] [--threads 2] [--scale 1]
                        [--scenes a,b,...] [--prt build/prt] [--prt-args "..."]
                        [--cycles-time] [--cycles-noise]
                        [--render-references [--cycles-spp N] [--references-only]]
                        [--out build/cycles] [--markdown FILE]

For each scene: `prt render MODEL --spp N --width W --height H --threads T -q -o OUT.pfm`
(plus `--integrator NAME` when this prt has the flag: a prt without it renders the paper's
Whitted/Hall model, and asking it for `path` is an error), then bench/cycles/compare.py
against the reference (PSNR in 8-bit sRGB, mean linear luminance, a side-by-side PNG in
--out). W x H is the reference's size times --scale (1/2 averages the reference over 2 x 2
blocks, exact for a box filter).

Times: "PRT s" is prt's whole process (start-up, reading, building, rendering, writing).
"Cycles s" is bpy.ops.render.render alone: by default the reference's own render (at its
sample count, size and threads, from references.json), compared per sample and pixel; with
--cycles-time Cycles renders each scene again at PRT's sample count, size and threads (needs
Blender) and the ratio is the two times themselves. --render-references renders the
references again (Blender, 2 threads) and rewrites references.json. --cycles-noise judges
Cycles itself (seed 1) in PRT's place: the figures a renderer of Cycles' model reaches at that
sample count and size, from which the tests' bars come.
"""
import argparse
import json
import math
import os
import shlex
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import compare  # noqa: E402

REFERENCES = os.path.join(HERE, "references")
RENDER_SCRIPT = os.path.join(HERE, "render_cycles.py")

# name, model file (from the repository's root), reference size, Cycles' samples per pixel
SCENES = [
    ("cornell-box", "scenes/models/cornell-box.glb", 128, 128, 2048),
    ("cornell-box-point", "scenes/models/cornell-box-point.glb", 128, 128, 2048),
    ("crate", "scenes/models/crate.glb", 160, 120, 512),
    ("pawns", "scenes/models/pawns.gltf", 160, 120, 512),
    ("blender-cube", "tests/models/blender-cube.glb", 160, 120, 512),
    ("blender-lights", "tests/models/blender-lights.glb", 160, 120, 512),
    ("street", "scenes/models/street.glb", 160, 120, 512),
    ("maps", "scenes/models/maps.glb", 160, 120, 512),
    ("volume", "scenes/models/volume.glb", 160, 120, 512),
    ("specular", "scenes/models/specular.glb", 160, 120, 512),
    ("clearcoat", "scenes/models/clearcoat.glb", 160, 120, 512),
]


def prt_integrators(prt):
    """True when `prt render --help` lists --integrator."""
    try:
        out = subprocess.run([prt, "render", "--help"], capture_output=True, text=True,
                             timeout=60).stdout
    except (OSError, subprocess.TimeoutExpired) as e:
        raise SystemExit("run.py: cannot run %s: %s" % (prt, e))
    return "--integrator" in out


def render_prt(prt, model, out, width, height, spp, threads, integrator, has_flag, extra):
    cmd = [prt, "render", model, "--spp", str(spp), "--width", str(width), "--height",
           str(height), "--threads", str(threads), "-q", "-o", out]
    if has_flag:
        cmd += ["--integrator", integrator]
    cmd += extra
    start = time.perf_counter()
    done = subprocess.run(cmd, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit("run.py: %s failed (%d): %s" % (" ".join(cmd), done.returncode,
                                                          done.stderr.strip()))
    return seconds, cmd


class BlenderError(Exception):
    pass


def blender_path(blender):
    found = shutil.which(blender)
    if found is None:
        raise BlenderError("Blender is not installed (%s not found; Debian: apt-get install "
                           "blender python3-numpy)" % blender)
    return os.path.abspath(found)


def render_cycles(blender, model, out, width, height, spp, threads, seed=0):
    """Runs render_cycles.py in Blender; returns its CYCLES_RESULT record."""
    blender = blender_path(blender)
    # Blender's embedded Python finds its standard library from the first python3 on PATH:
    # the one beside Blender (Debian's /usr/bin), not a virtual environment's that runs this.
    env = dict(os.environ, PATH=os.path.dirname(blender) + os.pathsep + os.environ.get("PATH", ""))
    cmd = ["nice", "-n", "10", blender, "-b", "--factory-startup", "--python-exit-code", "3",
           "--python", RENDER_SCRIPT, "--", model, "-o", out, "--width", str(width), "--height",
           str(height), "--samples", str(spp), "--threads", str(threads), "--seed", str(seed)]
    done = subprocess.run(cmd, capture_output=True, text=True, env=env)
    lines = [l for l in done.stdout.splitlines() if l.startswith("CYCLES_RESULT ")]
    if done.returncode != 0 or not lines:
        text = (done.stdout + done.stderr)
        if "No module named 'numpy'" in text:
            raise BlenderError("Blender's Python has no NumPy, which its glTF importer needs "
                               "(Debian: apt-get install python3-numpy)")
        tail = [l for l in text.splitlines() if not l.startswith("Fra:")][-20:]
        raise BlenderError("%s failed (exit code %d):\n%s" % (" ".join(cmd), done.returncode,
                                                              "\n".join(tail)))
    return json.loads(lines[-1].split(" ", 1)[1])


def load_manifest():
    path = os.path.join(REFERENCES, "references.json")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        return json.load(f)


def save_manifest(manifest):
    path = os.path.join(REFERENCES, "references.json")
    compare.atomic_write(path, (json.dumps(manifest, indent=1, sort_keys=True) + "\n").encode())


def fmt(v, spec):
    if v is None:
        return "-"
    if isinstance(v, float) and math.isinf(v):
        return "inf"
    return format(v, spec)


def main(argv=None):
    p = argparse.ArgumentParser(description="PRT against Cycles' references")
    p.add_argument("--integrator", choices=("path", "hall"), default="path")
    p.add_argument("--spp", type=int, help="PRT's samples per pixel (default: path 256, hall 16)")
    p.add_argument("--threads", type=int, default=2, help="PRT's (and --cycles-time's) threads")
    p.add_argument("--scale", type=float, default=1.0,
                   help="render PRT at this fraction of the reference's size (1, 1/2, 1/4...)")
    p.add_argument("--scenes", help="comma-separated names (default: all)")
    p.add_argument("--prt", default=os.path.join(ROOT, "build", "prt"))
    p.add_argument("--prt-args", default="", help="more arguments for prt render")
    p.add_argument("--blender", default="blender")
    p.add_argument("--cycles-time", action="store_true",
                   help="render Cycles again at PRT's samples, size and threads, for the times")
    p.add_argument("--render-references", action="store_true",
                   help="render the references again with Cycles (2 threads) first")
    p.add_argument("--cycles-spp", type=int, help="with --render-references: samples per pixel")
    p.add_argument("--references-only", action="store_true",
                   help="with --render-references: stop once they are rendered (no prt needed)")
    p.add_argument("--cycles-noise", action="store_true",
                   help="judge Cycles itself instead of PRT (seed 1, --spp, --scale, --threads): "
                        "the figures a renderer of the same model reaches at that sample count")
    p.add_argument("--out", default=os.path.join(ROOT, "build", "cycles"))
    p.add_argument("--markdown", help="write the table here (default OUT/table-INTEGRATOR.md)")
    a = p.parse_args(argv)

    names = [s[0] for s in SCENES]
    wanted = a.scenes.split(",") if a.scenes else names
    unknown = [w for w in wanted if w not in names]
    if unknown:
        p.error("unknown scene(s) %s; known: %s" % (", ".join(unknown), ", ".join(names)))
    scenes = [s for s in SCENES if s[0] in wanted]
    spp = a.spp or (256 if a.integrator == "path" else 16)
    if a.references_only and not a.render_references:
        p.error("--references-only goes with --render-references")
    os.makedirs(a.out, exist_ok=True)
    prt = os.path.abspath(a.prt)
    has_flag = a.cycles_noise or a.references_only or prt_integrators(prt)
    if a.integrator == "path" and not has_flag:
        raise SystemExit("run.py: %s has no --integrator: it renders the Whitted/Hall model only "
                         "(use --integrator hall)" % prt)

    manifest = load_manifest()
    if a.render_references:
        for name, model, w, h, ref_spp in scenes:
            ref_spp = a.cycles_spp or ref_spp
            print("rendering the reference of %s with Cycles (%dx%d, %d spp)..." % (name, w, h, ref_spp),
                  flush=True)
            r = render_cycles(a.blender, os.path.join(ROOT, model),
                              os.path.join(REFERENCES, name + ".pfm"), w, h, ref_spp, 2)
            r["model"], r["output"] = model, "%s.pfm" % name
            manifest[name] = r
            save_manifest(manifest)
        if a.references_only:
            return 0

    rows, results = [], []
    for name, model, w, h, ref_spp in scenes:
        reference = os.path.join(REFERENCES, name + ".pfm")
        if not os.path.exists(reference):
            raise SystemExit("run.py: no reference %s (render it with --render-references)" % reference)
        k = round(1 / a.scale)
        if not (k >= 1 and abs(1 / k - a.scale) < 1e-9 and w % k == 0 and h % k == 0):
            raise SystemExit("run.py: --scale must be 1/k dividing %dx%d" % (w, h))
        width, height = w // k, h // k
        label = "cycles" if a.cycles_noise else a.integrator
        image = os.path.join(a.out, "%s-%s.pfm" % (name, label))
        if a.cycles_noise:
            record = render_cycles(a.blender, os.path.join(ROOT, model), image, width, height,
                                   spp, a.threads, seed=1)
            prt_seconds, cmd = record["render_seconds"], ["render_cycles.py", "--seed", "1"]
        else:
            prt_seconds, cmd = render_prt(prt, os.path.join(ROOT, model), image, width, height,
                                          spp, a.threads, a.integrator, has_flag,
                                          shlex.split(a.prt_args))
        result = compare.compare(reference, image, os.path.join(a.out, "%s-%s.png" % (name, label)))
        entry = manifest.get(name, {})
        if a.cycles_time:
            live = render_cycles(a.blender, os.path.join(ROOT, model),
                                 os.path.join(a.out, "%s-cycles.pfm" % name), width, height, spp,
                                 a.threads)
            cycles_seconds, cycles_spp, cycles_pixels = live["render_seconds"], spp, width * height
            ratio = cycles_seconds / prt_seconds
        else:
            cycles_seconds = entry.get("render_seconds")
            cycles_spp = entry.get("samples", ref_spp)
            cycles_pixels = entry.get("width", w) * entry.get("height", h)
            ratio = None
            if cycles_seconds:  # per sample and pixel, PRT's whole process against the render
                ratio = (cycles_seconds / (cycles_spp * cycles_pixels)) / (
                    prt_seconds / (spp * width * height))
        result.update({"scene": name, "model": model, "integrator": a.integrator, "spp": spp,
                       "threads": a.threads, "prt_seconds": round(prt_seconds, 3),
                       "prt_command": " ".join(cmd), "cycles_seconds": cycles_seconds,
                       "cycles_spp": cycles_spp, "cycles_threads": entry.get("threads")
                       if not a.cycles_time else a.threads, "time_ratio": ratio})
        results.append(result)
        rows.append("| %s | %dx%d | %d | %s | %s | %s (%d spp) | %s | %s |" % (
            name, width, height, spp, fmt(result["psnr_db"], ".1f"),
            fmt(result["luminance_ratio"], ".3f"), fmt(cycles_seconds, ".1f"), cycles_spp,
            fmt(prt_seconds, ".2f"), fmt(ratio, ".2f")))
        print(compare.json_line(result), flush=True)
        print(compare.human_line(result), flush=True)

    how = ("the Cycles render at PRT's samples, size and threads" if a.cycles_time else
           "the reference's render; ratio per sample and pixel")
    if a.cycles_noise:
        how += "; 'PRT s' is the seed-1 render's time"
    table = ["| scene | size | PRT spp | PSNR (dB) | luminance PRT / Cycles | Cycles s | PRT s | "
             "Cycles / PRT time |", "|---|---|---|---|---|---|---|---|"] + rows
    judged = ("Cycles (seed 1" if a.cycles_noise else "PRT (`--integrator %s`" % a.integrator)
    text = ("%s, %d spp, %d threads) against Cycles' references (%s).\n\n"
            % (judged, spp, a.threads, how) + "\n".join(table) + "\n")
    print()
    print(text, end="")
    label = "cycles-noise" if a.cycles_noise else a.integrator
    markdown = a.markdown or os.path.join(a.out, "table-%s.md" % label)
    compare.atomic_write(markdown, text.encode())
    compare.atomic_write(os.path.join(a.out, "results-%s.json" % label),
                         (json.dumps([json.loads(compare.json_line(r)) for r in results],
                                     indent=1) + "\n").encode())
    print("written: %s, side-by-side PNGs in %s" % (markdown, a.out))
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (BlenderError, compare.ImageError) as e:
        print("run.py: %s" % e, file=sys.stderr)
        sys.exit(2)
