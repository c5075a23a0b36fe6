#!/usr/bin/env python3
"""The default strategy against the ideal and against the emulation's own ceiling, and under a
speed that changes mid-render, on 4 local emulated workers (--slowdown 2,2,4,4: 1.5 cores'
worth, the ideal speed-up 1.5).

Part 1, for each case (A-D): the serial render on one thread, the ceiling -- a static split by
the true speeds (scatter-weighted with --speed-index slowdown: each worker reports its own
factor, nothing is measured) -- and the default strategy, round-robin, --runs times. It
reports the medians and, per round, the default's elapsed time over the ceiling's (a ratio
within one round, so a busy spell on the machine hits both alike).

Part 2 (--change-case, default A): worker 0 runs 2x slower, then 8x slower from a third of the
run on. The oracle knows the schedule: worker 0's mean factor over the run is then 4 (a third
at 1/2, two thirds at 1/8), so it splits statically by 4,2,4,4 (--slowdown 4,2,4,4 with the
true schedule 0:0:2,0:T:8 and --speed-index slowdown). T is a third of the oracle's expected
time, 1.2 x the ceiling's median elapsed time from part 1 (the oracle's total rate is 1.25
against the ceiling's 1.5). Every strategy in --strategies runs the same schedule.

Timing on a shared machine is noisy: run it when the machine is quiet, and quote ratios.

Usage: bench/adaptive.py [--prt build/prt] [--cases A,B,C,D] [--runs 3] [--change-case A]
                         [--strategies adaptive,reservoir-scatter,...] [--json out.json]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

CHANGE_STRATEGIES = ["adaptive", "awf-b", "awf-c", "af", "stealing", "reservoir-scatter",
                     "reservoir", "hybrid", "hybrid-weighted", "scatter", "scatter-weighted"]


def render(prt, scene, case, out, extra):
    t0 = time.perf_counter()
    subprocess.run([prt, "render", scene, "--case", case, "-o", out, "--quiet"] + extra,
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - t0


def parallel(prt, scene, case, tmp, strategy, slowdown, extra, serial_s):
    report = os.path.join(tmp, "report.json")
    render(prt, scene, case, os.path.join(tmp, "img.pfm"),
           ["--workers", "4", "--strategy", strategy, "--slowdown", slowdown,
            "--serial-seconds", f"{serial_s:.6f}", "--report", report] + extra)
    with open(report) as f:
        return json.load(f)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--prt", default=os.path.join(root, "build", "prt"))
    ap.add_argument("--scene", default=os.path.join(root, "scenes", "complex.scene"))
    ap.add_argument("--cases", default="A,B,C,D")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--default", default="adaptive", help="the strategy measured as the default")
    ap.add_argument("--change-case", default="A", help="case of part 2; empty: skip it")
    ap.add_argument("--strategies", default=",".join(CHANGE_STRATEGIES))
    ap.add_argument("--json", help="also write the raw results here")
    args = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="prt-adaptive-")
    out = os.path.join(tmp, "img.pfm")
    results = {"cases": {}, "change": {}}
    slow = "2,2,4,4"

    print(f"uptime: {os.getloadavg()[0]:.1f} load (1 min) on {os.cpu_count()} cores")
    for case in args.cases.split(","):
        rows = {"serial": [], "ceiling": [], "default": [], "ratio": []}
        for _ in range(args.runs):
            serial = render(args.prt, args.scene, case, out, ["--threads", "1"])
            ceiling = parallel(args.prt, args.scene, case, tmp, "scatter-weighted", slow,
                               ["--speed-index", "slowdown"], serial)
            default = parallel(args.prt, args.scene, case, tmp, args.default, slow, [], serial)
            rows["serial"].append(serial)
            rows["ceiling"].append(ceiling["elapsed_s"])
            rows["default"].append(default["elapsed_s"])
            rows["ratio"].append(ceiling["elapsed_s"] / default["elapsed_s"])
        med = {k: statistics.median(v) for k, v in rows.items()}
        results["cases"][case] = {"runs": rows, "median": med}
        speedup = med["serial"] / med["default"]
        print(f"case {case}: serial {med['serial']:.3f} s, ceiling {med['ceiling']:.3f} s "
              f"(speed-up {med['serial'] / med['ceiling']:.2f}), {args.default} "
              f"{med['default']:.3f} s (speed-up {speedup:.2f} = {speedup / 1.5:.2f} of the "
              f"ideal 1.5; {med['ratio']:.3f} of the ceiling, median of per-round ratios "
              f"{', '.join(f'{r:.3f}' for r in rows['ratio'])})")

    if args.change_case:
        case = args.change_case
        base = results["cases"].get(case, {}).get("median", {}).get("ceiling")
        serial = results["cases"].get(case, {}).get("median", {}).get("serial")
        if base is None:
            serial = render(args.prt, args.scene, case, out, ["--threads", "1"])
            base = parallel(args.prt, args.scene, case, tmp, "scatter-weighted", slow,
                            ["--speed-index", "slowdown"], serial)["elapsed_s"]
        at = 0.4 * base  # a third of the oracle's 1.2 x base
        schedule = f"0:{at:.3f}:8"
        print(f"\ncase {case}, worker 0 from 2x to 8x slower at {at:.3f} s "
              f"(--slowdown-at {schedule}), median of {args.runs} rounds")
        strategies = args.strategies.split(",")
        times = {s: [] for s in ["oracle"] + strategies}
        for _ in range(args.runs):
            oracle = parallel(args.prt, args.scene, case, tmp, "scatter-weighted", "4,2,4,4",
                              ["--speed-index", "slowdown", "--slowdown-at", f"0:0:2,{schedule}"],
                              serial)
            times["oracle"].append(oracle["elapsed_s"])
            for s in strategies:
                r = parallel(args.prt, args.scene, case, tmp, s, slow,
                             ["--slowdown-at", schedule], serial)
                times[s].append(r["elapsed_s"])
        oracle_med = statistics.median(times["oracle"])
        for s, v in times.items():
            m = statistics.median(v)
            print(f"  {s:<18} {m:7.3f} s  {m / oracle_med:5.2f}x the oracle's time")
        results["change"] = {"case": case, "at_s": at, "times": times}

    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=2)


if __name__ == "__main__":
    sys.exit(main())
