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
     makes the same decisions; and once with ideal speed indices, --speed-index I0 (each
     worker's I0 / speed), I0 being the real runs' median of speed index over slowdown.

  4. per real run, the replay again with the cost map scaled to the compute the real run
     actually did (--serial-seconds = sum over workers of busy time / slowdown): on a busy or
     small machine the emulated slow workers compute more slowly than the map says (cores
     shared between workers, preemptions stretched k-fold by the slowdown, timer wake-ups),
     and this calibration separates that from what the simulator predicts: how the work is
     shared out, and the waiting.

Prints per strategy the real elapsed time (median of the runs, with min and max), the
replayed simulations' median and its error, the calibrated replays' median and its error, the
inflation of the real compute over the map, and the simulation with ideal speed indices. The
target is an error within 10 %.

Faithfulness: the real runs need 1/2+1/2+1/4+1/4 = 1.5 free cores for the slowdown emulation
to hold, and the cost map is the compute time of an unloaded core. On a loaded machine the
real runs stretch and the error grows: run it when the machine is otherwise idle (the load
average is printed at the start and the end).

Usage: bench/sim/validate.py [--prt build/prt] [--case A] [--runs 3] [--slowdown 2,2,4,4]
                             [--strategies scatter,hybrid,...] [--json FILE]
"""
import argparse
import json
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


def main():
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--prt", default=os.path.join(root, "build", "prt"))
    ap.add_argument("--scene", default=os.path.join(root, "scenes", "complex.scene"))
    ap.add_argument("--case", default="A")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--slowdown", default="2,2,4,4")
    ap.add_argument("--batch", default="128")
    ap.add_argument("--strategies", default=",".join(STRATEGIES))
    ap.add_argument("--json", help="also write the raw results here")
    args = ap.parse_args()
    slowdowns = [float(k) for k in args.slowdown.split(",")]
    speeds = ",".join(f"{1 / k:.9g}" for k in slowdowns)
    workers = str(len(slowdowns))
    tmp = tempfile.mkdtemp(prefix="prt-validate-")
    image = os.path.join(tmp, "image.pfm")
    cost_map = os.path.join(tmp, "complex.cost")
    report = os.path.join(tmp, "report.json")
    print(f"load average at the start: {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores")

    run([args.prt, "render", args.scene, "--case", args.case, "--threads", "1",
         "--cost-map", cost_map, "-o", image, "--quiet"])

    results = {}
    for strategy in args.strategies.split(","):
        common = ["--strategy", strategy, "--batch", args.batch]
        real = []
        for _ in range(args.runs):
            run([args.prt, "render", args.scene, "--case", args.case, "--workers", workers,
                 "--slowdown", args.slowdown, "--report", report, "-o", image, "--quiet"] + common)
            real.append(load(report))
        simulated, calibrated, inflation = [], [], []
        for r in real:
            replay = [args.prt, "simulate", "--cost-map", cost_map, "--workers", workers,
                      "--speeds", speeds, "--speed-indices",
                      ",".join(f"{w['speed_index_s']:.6f}" for w in r["workers"]),
                      "--report", report, "--quiet"] + common
            run(replay)
            simulated.append(load(report))
            compute = sum(w["busy_s"] / w["slowdown"] for w in r["workers"])
            inflation.append(compute / simulated[-1]["serial_s"])
            run(replay + ["--serial-seconds", f"{compute:.6f}"])
            calibrated.append(load(report))
        base_index = statistics.median(w["speed_index_s"] / w["slowdown"]
                                       for r in real for w in r["workers"])
        run([args.prt, "simulate", "--cost-map", cost_map, "--workers", workers, "--speeds", speeds,
             "--speed-index", f"{base_index:.6f}", "--report", report, "--quiet"] + common)
        ideal = load(report)
        elapsed = [r["elapsed_s"] for r in real]
        med = statistics.median(elapsed)
        sim = statistics.median(r["elapsed_s"] for r in simulated)
        cal = statistics.median(r["elapsed_s"] for r in calibrated)
        results[strategy] = {
            "real_elapsed_s": elapsed,
            "real_median_s": med,
            "simulated_elapsed_s": [r["elapsed_s"] for r in simulated],
            "simulated_s": sim,
            "error": sim / med - 1,
            "calibrated_s": cal,
            "calibrated_error": cal / med - 1,
            "inflation": statistics.median(inflation),
            "ideal_simulated_s": ideal["elapsed_s"],
            "ideal_error": ideal["elapsed_s"] / med - 1,
            "speed_index_s": base_index,
            "serial_s": ideal["serial_s"],
            "real_messages": statistics.median(r["messages"] for r in real),
            "simulated_messages": statistics.median(r["messages"] for r in simulated),
        }
        r = results[strategy]
        print(f"{strategy:<10} real {med:7.3f} s ({min(elapsed):.3f}..{max(elapsed):.3f})  "
              f"simulated {sim:7.3f} s ({100 * r['error']:+.1f} %)  "
              f"calibrated {cal:7.3f} s ({100 * r['calibrated_error']:+.1f} %)", flush=True)

    serial = next(iter(results.values()))["serial_s"] if results else 0
    print(f"\ncost map: {serial:.3f} s serial (case {args.case}, one thread); "
          f"{workers} workers, --slowdown {args.slowdown}; median of {args.runs} real runs")
    print(f"{'strategy':<10} {'real_s':>8} {'sim_s':>8} {'error':>8} {'calib_s':>8} {'error':>8} "
          f"{'inflation':>9} {'ideal_s':>8} {'msgs real':>10} {'msgs sim':>9}")
    for s, r in results.items():
        print(f"{s:<10} {r['real_median_s']:8.3f} {r['simulated_s']:8.3f} {100 * r['error']:+7.1f}% "
              f"{r['calibrated_s']:8.3f} {100 * r['calibrated_error']:+7.1f}% "
              f"{r['inflation']:9.2f} {r['ideal_simulated_s']:8.3f} "
              f"{r['real_messages']:10.0f} {r['simulated_messages']:9.0f}")
    worst = max((abs(r["error"]) for r in results.values()), default=0)
    worst_cal = max((abs(r["calibrated_error"]) for r in results.values()), default=0)
    print(f"largest error {100 * worst:.1f} %, calibrated {100 * worst_cal:.1f} % (target 10 %); "
          f"load average at the end: {os.getloadavg()[0]:.2f}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"slowdown": slowdowns, "case": args.case, "results": results}, f, indent=2)


if __name__ == "__main__":
    main()
