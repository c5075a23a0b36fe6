#!/usr/bin/env python3
"""One scene of bench/cycles/ rendered by PRT's path tracer against Cycles' committed reference:

    path_vs_cycles.py --prt PRT --root REPO --scene NAME --width W --height H --spp N
                      --min-psnr DB --luminance LO,HI --out DIR

Renders `prt render MODEL --integrator path --spp N --width W --height H --threads 2` (W x H
a whole fraction of the reference's size: the reference is box-averaged to it), then fails
unless PSNR >= DB, LO <= mean luminance PRT / Cycles <= HI and no sample is NaN or infinite.
Exits 77 (CTest's SKIP_RETURN_CODE) when `prt render --help` lists no --integrator: a prt
without the path tracer renders the Whitted/Hall model, which these bars are not for.
"""
import argparse
import os
import subprocess
import sys


def main():
    p = argparse.ArgumentParser()
    for name in ("prt", "root", "scene", "out"):
        p.add_argument("--" + name, required=True)
    for name in ("width", "height", "spp"):
        p.add_argument("--" + name, type=int, required=True)
    p.add_argument("--min-psnr", type=float, required=True)
    p.add_argument("--luminance", required=True, help="LO,HI")
    a = p.parse_args()
    sys.path.insert(0, os.path.join(a.root, "bench", "cycles"))
    import compare
    import run

    help_text = subprocess.run([a.prt, "render", "--help"], capture_output=True, text=True).stdout
    if "--integrator" not in help_text:
        print("SKIP: prt render has no --integrator option: this build has no path tracer to "
              "check against Cycles")
        return 77
    scenes = {s[0]: s for s in run.SCENES}
    name, model, _, _, _ = scenes[a.scene]
    os.makedirs(a.out, exist_ok=True)
    image = os.path.join(a.out, name + ".pfm")
    if os.path.exists(image):
        os.unlink(image)
    cmd = [a.prt, "render", os.path.join(a.root, model), "--integrator", "path", "--spp",
           str(a.spp), "--width", str(a.width), "--height", str(a.height), "--threads", "2",
           "-q", "-o", image]
    print(" ".join(cmd), flush=True)
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        print("FAIL: prt exited with code %d: %s" % (done.returncode, done.stderr.strip()))
        return 1
    reference = os.path.join(run.REFERENCES, name + ".pfm")
    png = os.path.join(a.out, name + ".png")
    result = compare.compare(reference, image, png)
    print(compare.json_line(result))
    print(compare.human_line(result))
    lo, hi = (float(v) for v in a.luminance.split(","))
    failures = []
    if not result["psnr_db"] >= a.min_psnr:
        failures.append("PSNR %.2f dB < %.2f dB" % (result["psnr_db"], a.min_psnr))
    if not lo <= result["luminance_ratio"] <= hi:
        failures.append("luminance ratio %.4f outside [%g, %g]" % (result["luminance_ratio"], lo, hi))
    if result["non_finite_samples"]:
        failures.append("%d NaN or infinite samples in the image" % result["non_finite_samples"])
    if failures:
        print("FAIL: %s (reference | PRT | difference x4: %s)" % ("; ".join(failures), png))
        return 1
    print("pass: PSNR >= %g dB, luminance ratio in [%g, %g]" % (a.min_psnr, lo, hi))
    return 0


if __name__ == "__main__":
    sys.exit(main())
