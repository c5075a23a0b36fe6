#!/usr/bin/env python3
"""Validates the simulator against real runs: the complex scene rendered by the local driver
with every strategy on emulated slow workers, and the same runs simulated from a cost map of
the same scene recorded on this machine.

  1. prt render SCENE --case A --threads 1 --cost-map MAP     (the per-pixel costs, once)
  2. per strategy, --runs times:
       prt render SCENE --case A --workers 4 --slowdown 2,2,4,4 --strategy S --report R.json
  3. per real run, the same run simulated:
       prt simulate --cost-map MAP --workers 4 --speeds 0.5,0.5,0.25,0.25 --strategy S
         --speed-indices I1,I2,I3,I4 --report R.json
     replaying the speed indices the real workers measured (and set up for), so the strategy
     makes the same decisions.
  4. the same replays with the per-batch overhead h (--batch-overhead-us) of this machine,
     measured once from the scatter runs, whose shares are known (worker w renders the pixels
     w, w + c, w + 2c, ...): h = sum of (busy - slowdown * cost of the share) over sum of
     (slowdown * batches). An emulated worker pays per batch for what the map does not hold:
     cold caches after its sleep while other workers ran, packing and sending results, the
     timer's late wake-up. One constant for the machine, not a fit per strategy.
  5. for diagnosis, the replays with the map scaled to the compute each real run actually did
     (--serial-seconds = sum over workers of busy / slowdown); "inflation" is that compute
     over the map's total.

Prints per strategy the real elapsed time (median of the runs, with min and max) and the
simulated ones with their errors. The target is within 10 %.

Faithfulness: the real runs need 1/2+1/2+1/4+1/4 = 1.5 free cores for the slowdown emulation
to hold; on a loaded machine the real runs stretch and the error grows: run it when the
machine is otherwise idle (the load average is printed at the start and the end).

Usage: bench/sim/validate.py [--prt build/prt] [--case A] [--runs 3] [--slowdown 2,2,4,4]
                             [--strategies scatter,hybrid,...] [--json FILE]
"""
import argparse
import array
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

STRATEGIES = ["scatter", "hybrid", "reservoir", "blocks", "self", "guided", "factoring"]


def run(cmd):
    result = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if result.returncode != 0:
        sys.exit(f"failed ({result.returncode}): {' '.join(cmd)}\n{result.stderr}")
    return result.stdout


def load(path):
    with open(path) as f:
        return json.load(f)


def read_cost_map(path):
    """The per-pixel seconds of a cost map file (format: src/sim/cost_map_file.h)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"PRTCOST1":
        sys.exit(f"{path}: not a cost map")
    costs = array.array("f")
    costs.frombytes(data[16:])
    return costs


def batch_overhead(scatter_runs, costs, batch):
    """Seconds per batch at full speed that the scatter runs spent beyond the map's costs."""
    excess = weight = 0.0
    for report in scatter_runs:
        c = len(report["workers"])
        for w in report["workers"]:
            k = w["slowdown"]
            share = math.fsum(costs[w["worker"]::c])
            batches = math.ceil(w["pixels"] / batch)
            excess += w["busy_s"] - k * share
            weight += k * batches
    return max(0.0, excess / weight) if weight else 0.0


def main():
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--prt", default=os.path.join(root, "build", "prt"))
    ap.add_argument("--scene", default=os.path.join(root, "scenes", "complex.scene"))
    ap.add_argument("--case", default="A")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--slowdown", default="2,2,4,4")
    ap.add_argument("--batch", type=int, default=128)
    ap.add_argument("--strategies", default=",".join(STRATEGIES))
    ap.add_argument("--json", help="also write the raw results here")
    args = ap.parse_args()
    slowdowns = [float(k) for k in args.slowdown.split(",")]
    speeds = ",".join(f"{1 / k:.9g}" for k in slowdowns)
    workers = str(len(slowdowns))
    strategies = args.strategies.split(",")
    if "scatter" in strategies:  # first: it calibrates the batch overhead
        strategies.remove("scatter")
        strategies.insert(0, "scatter")
    tmp = tempfile.mkdtemp(prefix="prt-validate-")
    image = os.path.join(tmp, "image.pfm")
    cost_map = os.path.join(tmp, "complex.cost")
    report = os.path.join(tmp, "report.json")
    print(f"load average at the start: {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores")

    run([args.prt, "render", args.scene, "--case", args.case, "--threads", "1",
         "--cost-map", cost_map, "-o", image, "--quiet"])
    costs = read_cost_map(cost_map)

    def simulate(strategy, real_report, extra):
        indices = ",".join(f"{w['speed_index_s']:.6f}" for w in real_report["workers"])
        run([args.prt, "simulate", "--cost-map", cost_map, "--workers", workers, "--speeds",
             speeds, "--speed-indices", indices, "--strategy", strategy, "--batch",
             str(args.batch), "--report", report, "--quiet"] + extra)
        return load(report)

    results = {}
    overhead_us = 0.0
    for strategy in strategies:
        real = []
        for _ in range(args.runs):
            run([args.prt, "render", args.scene, "--case", args.case, "--workers", workers,
                 "--slowdown", args.slowdown, "--strategy", strategy, "--batch", str(args.batch),
                 "--report", report, "-o", image, "--quiet"])
            real.append(load(report))
        if strategy == "scatter":
            overhead_us = 1e6 * batch_overhead(real, costs, args.batch)
            print(f"batch overhead from the scatter runs: {overhead_us:.0f} us at full speed")
        plain = [simulate(strategy, r, []) for r in real]
        with_h = [simulate(strategy, r, ["--batch-overhead-us", f"{overhead_us:.3f}"])
                  for r in real]
        computes = [sum(w["busy_s"] / w["slowdown"] for w in r["workers"]) for r in real]
        scaled = [simulate(strategy, r, ["--serial-seconds", f"{c:.6f}"])
                  for r, c in zip(real, computes)]
        elapsed = [r["elapsed_s"] for r in real]
        med = statistics.median(elapsed)
        row = {"real_elapsed_s": elapsed, "real_median_s": med,
               "serial_s": plain[0]["serial_s"],
               "inflation": statistics.median(c / plain[0]["serial_s"] for c in computes),
               "real_messages": statistics.median(r["messages"] for r in real),
               "simulated_messages": statistics.median(r["messages"] for r in plain)}
        for key, reports in (("simulated", plain), ("with_overhead", with_h), ("scaled", scaled)):
            sim = statistics.median(r["elapsed_s"] for r in reports)
            row[key + "_s"] = sim
            row[key + "_error"] = sim / med - 1
        results[strategy] = row
        print(f"{strategy:<10} real {med:7.3f} s ({min(elapsed):.3f}..{max(elapsed):.3f})  "
              f"simulated {row['simulated_s']:7.3f} s ({100 * row['simulated_error']:+.1f} %)  "
              f"with h {row['with_overhead_s']:7.3f} s "
              f"({100 * row['with_overhead_error']:+.1f} %)", flush=True)

    serial = next(iter(results.values()))["serial_s"] if results else 0
    print(f"\ncost map: {serial:.3f} s serial (case {args.case}, one thread); {workers} workers, "
          f"--slowdown {args.slowdown}; median of {args.runs} real runs; "
          f"h = {overhead_us:.0f} us per batch")
    print(f"{'strategy':<10} {'real_s':>7} {'sim_s':>7} {'error':>7} {'sim+h_s':>7} {'error':>7} "
          f"{'scaled_s':>8} {'error':>7} {'inflation':>9} {'msgs real':>9} {'msgs sim':>8}")
    for s, r in results.items():
        print(f"{s:<10} {r['real_median_s']:7.3f} {r['simulated_s']:7.3f} "
              f"{100 * r['simulated_error']:+6.1f}% {r['with_overhead_s']:7.3f} "
              f"{100 * r['with_overhead_error']:+6.1f}% {r['scaled_s']:8.3f} "
              f"{100 * r['scaled_error']:+6.1f}% {r['inflation']:9.2f} "
              f"{r['real_messages']:9.0f} {r['simulated_messages']:8.0f}")
    for key, name in (("simulated", "plain"), ("with_overhead", "with h"), ("scaled", "scaled")):
        worst = max((abs(r[key + "_error"]) for r in results.values()), default=0)
        print(f"largest error {name}: {100 * worst:.1f} %", end="; ")
    print(f"(target 10 %); load average at the end: {os.getloadavg()[0]:.2f}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"slowdown": slowdowns, "case": args.case, "batch_overhead_us": overhead_us,
                       "results": results}, f, indent=2)


if __name__ == "__main__":
    main()
