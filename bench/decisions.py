#!/usr/bin/env python3
"""What each strategy's decisions cost as the workers grow, and how fast that cost grows.

Runs build/bench/prt_bench_decisions (bench/decision_bench.cpp: every strategy, 1,024 to
65,536 workers, half of them 4x slower; the "4k" workload hands out a 3840x2160 image for
50,000 strategy calls, the "end" one runs 256 tasks per worker to the end, steals and losses
included), --runs times, and prints per strategy and workload the median microseconds per
hand-out, steal, loss and decision at each worker count, with the growth exponent k of a
least-squares fit cost ~ W^k over the worker counts (k near 0: O(1) or O(log W) per
decision; near 1: a walk over all workers per decision, W^2 for a whole run).

Usage: bench/decisions.py [--bench build/bench/prt_bench_decisions] [--runs 3]
                          [--filter REGEX] [--json out.json]
"""
import argparse
import json
import math
import statistics
import subprocess
import tempfile

FIGURES = ["handout_us", "steal_us", "lost_us", "query_us", "decision_us"]


def run_once(bench, regex):
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        subprocess.run([bench, "--benchmark_filter=" + regex, "--benchmark_out=" + out.name,
                        "--benchmark_out_format=json"], check=True, stdout=subprocess.DEVNULL)
        with open(out.name) as f:
            return json.load(f)["benchmarks"]


def exponent(points):
    """Least-squares slope of log(cost) over log(W), over the points with a cost."""
    xs = [math.log(w) for w, c in points if c > 0]
    ys = [math.log(c) for w, c in points if c > 0]
    if len(xs) < 2:
        return None
    mx, my = statistics.fmean(xs), statistics.fmean(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bench", default="build/bench/prt_bench_decisions")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--filter", default="BM_Decisions/")
    parser.add_argument("--json")
    args = parser.parse_args()
    samples = {}  # (workload, strategy, workers) -> figure -> [values]
    for _ in range(args.runs):
        for b in run_once(args.bench, args.filter):
            _, workload, strategy, workers = b["name"].split("/")[:4]
            key = (workload, strategy, int(workers))
            for f in FIGURES:
                samples.setdefault(key, {}).setdefault(f, []).append(b.get(f, 0.0))
    medians = {k: {f: statistics.median(v) for f, v in figs.items()} for k, figs in samples.items()}
    sizes = sorted({k[2] for k in medians})
    rows = []
    for workload in sorted({k[0] for k in medians}):
        strategies = sorted({k[1] for k in medians if k[0] == workload})
        print(f"\nworkload {workload}: us per call, median of {args.runs}; k: cost ~ W^k")
        print(f"{'strategy':<18} {'figure':<12}" + "".join(f"{w:>10}" for w in sizes) + f"{'k':>7}")
        for s in strategies:
            for f in FIGURES:
                points = [(w, medians[(workload, s, w)][f]) for w in sizes
                          if (workload, s, w) in medians]
                if all(c == 0 for _, c in points):
                    continue
                k = exponent(points)
                cells = "".join(f"{c:>10.2f}" for _, c in points)
                print(f"{s:<18} {f:<12}{cells}{(f'{k:7.2f}' if k is not None else '      -')}")
                rows.append({"workload": workload, "strategy": s, "figure": f,
                             "points": points, "exponent": k})
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
