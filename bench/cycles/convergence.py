#!/usr/bin/env python3
"""Error against time: PRT's path tracer and Cycles, one thread each, on one scene.

    bench/cycles/convergence.py [--scene cornell-box] [--spp 4,8,16,32,64,128,256] [--prt PRT]
                                [--out build/cycles/convergence]

For each sample count, runs `run.py --threads 1` (PRT's whole process, timed) and
`run.py --cycles-noise --threads 1` (Cycles' render alone, `bpy.ops.render.render`, seed 1),
both at the reference's size, and records each image's PSNR against the committed reference
(Cycles at 2048 samples for the Cornell box). Writes OUT/convergence.csv (the source of truth)
and OUT/convergence.svg (gnuplot, when installed): PSNR against seconds, log scale in time.
Blender is needed for the Cycles half (its rows are skipped without it).
"""
import argparse
import csv
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def results(args):
    done = subprocess.run([sys.executable, os.path.join(HERE, "run.py")] + args,
                          capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit("run.py %s failed:\n%s%s" % (" ".join(args), done.stdout, done.stderr))
    return [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--scene", default="cornell-box")
    p.add_argument("--spp", default="4,8,16,32,64,128,256")
    p.add_argument("--prt", default=os.path.join(ROOT, "build", "prt"))
    p.add_argument("--out", default=os.path.join(ROOT, "build", "cycles", "convergence"))
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for spp in [int(s) for s in a.spp.split(",")]:
        common = ["--scenes", a.scene, "--spp", str(spp), "--threads", "1", "--out",
                  os.path.join(a.out, "spp%d" % spp)]
        for who, extra in (("prt", ["--prt", a.prt]), ("cycles", ["--cycles-noise"])):
            if who == "cycles" and shutil.which("blender") is None:
                continue
            for r in results(common + extra):
                rows.append({"renderer": who, "scene": a.scene, "spp": spp,
                             "seconds": r["prt_seconds"], "psnr_db": r["psnr_db"],
                             "luminance_ratio": r["luminance_ratio"]})
                print("%-6s %4d spp  %7.2f s  %6.2f dB  luminance %.4f" % (
                    who, spp, r["prt_seconds"], r["psnr_db"], r["luminance_ratio"]), flush=True)
    table = os.path.join(a.out, "convergence.csv")
    with open(table, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("written:", table)
    if shutil.which("gnuplot") and {r["renderer"] for r in rows} == {"prt", "cycles"}:
        data = {}
        for who in ("prt", "cycles"):
            path = os.path.join(a.out, who + ".dat")
            with open(path, "w") as f:
                for r in rows:
                    if r["renderer"] == who:
                        f.write("%g %g %d\n" % (r["seconds"], r["psnr_db"], r["spp"]))
            data[who] = path
        svg = os.path.join(a.out, "convergence.svg")
        script = """set terminal svg size 640,400 dynamic font 'sans,12'
set output '%s'
set title 'Error against time, one thread: %s (reference: Cycles, 2048 samples)'
set xlabel 'seconds (PRT: the whole process; Cycles: its render)'
set ylabel 'PSNR against the reference (dB)'
set logscale x 2
set grid
set key bottom right
plot '%s' using 1:2 with linespoints title 'PRT path tracer', \\
     '%s' using 1:2:3 with labels offset 0,1 notitle, \\
     '%s' using 1:2 with linespoints title 'Cycles 3.4'
""" % (svg, a.scene, data["prt"], data["prt"], data["cycles"])
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
        print("written:", svg)


if __name__ == "__main__":
    main()
