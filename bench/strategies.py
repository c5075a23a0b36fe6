#!/usr/bin/env python3
"""Load-balancing benchmark: the complex scene rendered by the local driver with every
strategy on emulated heterogeneous workers, each configuration run several times.

Reports the median elapsed time, efficiency, speed-up, MASU, ASU and messages, plus the ratios
the project tracks (reservoir vs scatter and vs hybrid). The serial time is measured in the
same run (median of the serial renders on one thread), so ratios are not skewed by a noisy
machine between runs.

Faithfulness: `--slowdown 2,2,4,4` asks 1/2+1/2+1/4+1/4 = 1.5 cores of a 2-core machine; the
emulation only holds while that fits the free cores, so run it on an otherwise idle machine.

Usage: bench/strategies.py [--prt build/prt] [--case A] [--runs 3] [--slowdown 2,2,4,4]
                          [--width W --height H]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

STRATEGIES = ["scatter", "scatter-weighted", "hybrid", "hybrid-weighted", "reservoir",
              "reservoir-scatter", "adaptive", "blocks", "self", "guided", "factoring", "awf-b",
              "awf-c", "af", "stealing"]


def run(cmd):
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--prt", default=os.path.join(root, "build", "prt"))
    ap.add_argument("--scene", default=os.path.join(root, "scenes", "complex.scene"))
    ap.add_argument("--case", default="A")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--slowdown", default="2,2,4,4")
    ap.add_argument("--strategies", default=",".join(STRATEGIES))
    ap.add_argument("--width", type=int, help="image width (default: the scene's)")
    ap.add_argument("--height", type=int, help="image height (default: the scene's)")
    ap.add_argument("--json", help="also write the raw results here")
    args = ap.parse_args()
    workers = len(args.slowdown.split(","))
    tmp = tempfile.mkdtemp(prefix="prt-bench-")
    out = os.path.join(tmp, "img.pfm")
    size = []
    if args.width:
        size += ["--width", str(args.width)]
    if args.height:
        size += ["--height", str(args.height)]

    serial = []
    for _ in range(args.runs):
        t0 = time.perf_counter()
        run([args.prt, "render", args.scene, "--case", args.case, "--threads", "1", "-o", out, "--quiet"] + size)
        serial.append(time.perf_counter() - t0)
    serial_s = statistics.median(serial)
    print(f"serial (1 thread, case {args.case}): median {serial_s:.3f} s of {args.runs} runs")

    # Round-robin over the strategies, so that a noisy spell on the machine hits them alike.
    strategies = args.strategies.split(",")
    all_reports = {s: [] for s in strategies}
    for _ in range(args.runs):
        for strategy in strategies:
            report = os.path.join(tmp, "report.json")
            run([args.prt, "render", args.scene, "--case", args.case, "--workers", str(workers),
                 "--strategy", strategy, "--slowdown", args.slowdown,
                 "--serial-seconds", f"{serial_s:.6f}", "--report", report, "-o", out, "--quiet"] + size)
            with open(report) as f:
                all_reports[strategy].append(json.load(f))
    results = {}
    for strategy, reports in all_reports.items():
        med = lambda key: statistics.median(r[key] for r in reports)
        results[strategy] = {k: med(k) for k in ("elapsed_s", "speedup", "efficiency", "masu", "asu", "messages", "bytes")}

    where = f", {args.width}x{args.height}" if args.width and args.height else ""
    print(f"\n{workers} local workers, --slowdown {args.slowdown}, case {args.case}{where}, median of {args.runs} runs")
    print(f"{'strategy':<18} {'elapsed_s':>9} {'speedup':>8} {'effic.':>7} {'MASU':>6} {'ASU':>6} {'messages':>9} {'bytes':>10}")
    for s, r in results.items():
        print(f"{s:<18} {r['elapsed_s']:9.3f} {r['speedup']:8.2f} {100*r['efficiency']:6.1f}% "
              f"{r['masu']:6.2f} {100*r['asu']:5.1f}% {r['messages']:9.0f} {r['bytes']:10.0f}")
    for mine in ("reservoir", "reservoir-scatter", "adaptive"):
        if mine not in results:
            continue
        res = results[mine]["elapsed_s"]
        for other in ("scatter", "hybrid"):
            if other in results:
                print(f"{mine} is {results[other]['elapsed_s'] / res:.2f}x as fast as {other}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"serial_s": serial_s, "results": results}, f, indent=2)


if __name__ == "__main__":
    sys.exit(main())
