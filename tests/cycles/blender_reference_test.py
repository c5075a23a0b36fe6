#!/usr/bin/env python3
"""A committed Cycles reference stays reproducible: renders one scene again with Blender
(bench/cycles/render_cycles.py, small and at fewer samples) and checks it against the
committed reference, box-averaged to its size, to within noise:

    blender_reference_test.py --root REPO --scene NAME --width W --height H --spp N
                              --min-psnr DB --luminance LO,HI --out DIR [--blender blender]

Exits 77 (CTest's SKIP_RETURN_CODE), saying why, when Blender or its Python's NumPy is
missing: Blender is a tool for these checks, never a dependency of prt.
"""
import argparse
import os
import sys


def main():
    p = argparse.ArgumentParser()
    for name in ("root", "scene", "out"):
        p.add_argument("--" + name, required=True)
    for name in ("width", "height", "spp"):
        p.add_argument("--" + name, type=int, required=True)
    p.add_argument("--min-psnr", type=float, required=True)
    p.add_argument("--luminance", required=True, help="LO,HI")
    p.add_argument("--blender", default="blender")
    a = p.parse_args()
    sys.path.insert(0, os.path.join(a.root, "bench", "cycles"))
    import compare
    import run

    scenes = {s[0]: s for s in run.SCENES}
    name, model, _, _, _ = scenes[a.scene]
    os.makedirs(a.out, exist_ok=True)
    image = os.path.join(a.out, name + "-cycles.pfm")
    try:
        record = run.render_cycles(a.blender, os.path.join(a.root, model), image, a.width,
                                   a.height, a.spp, 2)
    except run.BlenderError as e:
        message = str(e)
        if "not installed" in message or "no NumPy" in message:
            print("SKIP: " + message)
            return 77
        print("FAIL: " + message)
        return 1
    print("Blender %s rendered %s in %.2f s" % (record["blender"], model, record["render_seconds"]))
    result = compare.compare(os.path.join(run.REFERENCES, name + ".pfm"), image,
                             os.path.join(a.out, name + ".png"))
    print(compare.json_line(result))
    print(compare.human_line(result))
    lo, hi = (float(v) for v in a.luminance.split(","))
    if not (result["psnr_db"] >= a.min_psnr and lo <= result["luminance_ratio"] <= hi):
        print("FAIL: the committed reference bench/cycles/references/%s.pfm is not what this "
              "Blender renders (PSNR >= %g dB and luminance ratio in [%g, %g] expected); "
              "render it again with bench/cycles/run.py --render-references" % (name, a.min_psnr, lo, hi))
        return 1
    print("pass: PSNR >= %g dB, luminance ratio in [%g, %g]" % (a.min_psnr, lo, hi))
    return 0


if __name__ == "__main__":
    sys.exit(main())
