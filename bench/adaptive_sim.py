#!/usr/bin/env python3
"""Every strategy in the simulator at scale: 1,024 workers of which half are 4x slower, a
3840x2160 image, an hour of serial work (the synthetic complex-scene cost map), deterministic.

Two cases:
  stable    the speeds never change;
  changing  every eighth worker (0, 8, 16, ...) drops to speed 0.125 two seconds in
            (--speed-at W:2:0.125), a machine that gets busy with other work.
For each it prints the elapsed virtual time, speed-up, ASU (and what the MASU is computed
from: the speed index, or the measured throughput where none was run), and messages per
worker; for the changing case also the oracle's time, a split that knows the schedule: the
time T at which the workers' summed speed over [0, T] covers the serial work, plus the
start-up the simulated network takes (the first pixel starts when the scene has reached
everyone, taken from the default strategy's run).

Usage: bench/adaptive_sim.py [--prt build/prt] [--strategies a,b,...] [--json out.json]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

COMMON = ["--workers", "1024", "--width", "3840", "--height", "2160", "--serial-seconds", "3600",
          "--slow-share", "0.5"]
CHANGED = range(0, 1024, 8)
CHANGE = ",".join(f"{w}:2:0.125" for w in CHANGED)


def simulate(prt, strategy, extra, tmp):
    report = os.path.join(tmp, "report.json")
    trace = os.path.join(tmp, "trace.json")
    subprocess.run([prt, "simulate", "--strategy", strategy, "--report", report, "--trace", trace,
                    "-q"] + COMMON + extra, check=True)
    with open(report) as f:
        r = json.load(f)
    with open(trace) as f:
        events = json.load(f)
    events = events["traceEvents"] if isinstance(events, dict) else events
    starts = [e["ts"] / 1e6 for e in events if e.get("name") == "rendering"]
    r["first_pixel_s"] = min(starts) if starts else 0
    return r


def oracle(speeds, serial, startup):
    def work(t):
        return sum(s * 2 + 0.125 * (t - 2) if i in CHANGED and t > 2 else s * t
                   for i, s in enumerate(speeds))
    lo, hi = 0.0, 1e6
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if work(mid) < serial else (lo, mid)
    return lo + startup


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--prt", default=os.path.join(os.path.dirname(here), "build", "prt"))
    ap.add_argument("--strategies", help="default: every strategy prt knows")
    ap.add_argument("--json")
    args = ap.parse_args()
    if args.strategies:
        strategies = args.strategies.split(",")
    else:
        help_text = subprocess.run([args.prt, "simulate", "--help"], check=True,
                                   capture_output=True, text=True).stdout
        strategies = [line.split()[0] for line in help_text.splitlines()
                      if "(static)" in line or "(dynamic)" in line or "(adaptive)" in line]
    tmp = tempfile.mkdtemp(prefix="prt-adaptive-sim-")
    results = {}
    for case, extra in (("stable", []), ("changing", ["--speed-at", CHANGE])):
        print(f"\n{case}: 1,024 workers, half 4x slower, 3840x2160, 3600 s serial"
              + (", every eighth worker at speed 0.125 from 2 s" if extra else ""))
        print(f"{'strategy':<18} {'elapsed_s':>9} {'speed-up':>9} {'ASU':>7} {'MASU from':<20} "
              f"{'msgs/worker':>11}")
        results[case] = {}
        for s in strategies:
            r = simulate(args.prt, s, extra, tmp)
            results[case][s] = r
            print(f"{s:<18} {r['elapsed_s']:9.3f} {r['speedup']:9.1f} {r['asu']:7.4f} "
                  f"{r['masu_basis']:<20} {r['messages'] / r['workers_count']:11.1f}")
        if extra:
            any_run = next(iter(results[case].values()))
            speeds = [1 / w["slowdown"] for w in any_run["workers"]]
            startup = min(r["first_pixel_s"] for r in results[case].values())
            t = oracle(speeds, 3600, startup)
            print(f"{'oracle':<18} {t:9.3f}   (a split knowing the schedule; start-up "
                  f"{startup:.3f} s)")
            for s, r in results[case].items():
                r["vs_oracle"] = r["elapsed_s"] / t
            print("elapsed over the oracle's: " + ", ".join(
                f"{s} {r['vs_oracle']:.2f}" for s, r in results[case].items()))
    if args.json:
        with open(args.json, "w") as f:
            json.dump({c: {s: {k: v for k, v in r.items() if k != "workers"} for s, r in rs.items()}
                       for c, rs in results.items()}, f, indent=2)


if __name__ == "__main__":
    sys.exit(main())
