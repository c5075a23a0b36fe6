#!/usr/bin/env python3
"""Serial tracer benchmark: the complex scene for the paper's test cases A-D (Table III), on
one thread and on all threads. Reports the median time, rays traced and rays per second over
several runs.

Usage: bench/serial.py [--prt build/prt] [--runs 3] [--cases A,B,C,D] [--width W --height H]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

SUMMARY = re.compile(r"([\d.]+) s, (\d+) rays, ([\d.]+) Mrays/s")


def render(prt, scene, case, threads, out, size):
    cmd = [prt, "render", scene, "--case", case, "--threads", str(threads), "-o", out] + size
    text = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    m = SUMMARY.search(text)
    return float(m.group(1)), int(m.group(2))


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--prt", default=os.path.join(root, "build", "prt"))
    ap.add_argument("--scene", default=os.path.join(root, "scenes", "complex.scene"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--cases", default="A,B,C,D")
    ap.add_argument("--width", type=int)
    ap.add_argument("--height", type=int)
    args = ap.parse_args()
    size = []
    if args.width:
        size += ["--width", str(args.width)]
    if args.height:
        size += ["--height", str(args.height)]
    out = os.path.join(tempfile.mkdtemp(prefix="prt-bench-"), "img.pfm")
    threads_all = os.cpu_count() or 1
    # Which build of the trace kernels ran (baseline or an x86-64 level): figures depend on it.
    version = subprocess.run([args.prt, "--version"], capture_output=True, text=True).stdout
    print(version.strip())
    print(f"{'case':<5} {'threads':>7} {'median_s':>9} {'rays':>12} {'Mrays/s':>8}")
    for case in args.cases.split(","):
        for threads in (1, threads_all):
            times, rays = [], 0
            for _ in range(args.runs):
                t, rays = render(args.prt, args.scene, case, threads, out, size)
                times.append(t)
            t = statistics.median(times)
            print(f"{case:<5} {threads:>7} {t:9.3f} {rays:12d} {rays / t / 1e6:8.2f}")


if __name__ == "__main__":
    sys.exit(main())
