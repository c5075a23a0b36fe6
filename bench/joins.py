#!/usr/bin/env python3
"""Workers that join a running render: a render that starts on one slow worker and gains two
faster ones at a third of the serial time, per strategy, against the ideal for that schedule.

The ideal (the report's ideal_s) is a perfect balance of the run's work over the workers, each
counted from its arrival, at their true emulated speeds: the T with
sum_i s_i max(0, T - arrival_i) = W.

Simulated (prt simulate, the synthetic complex-scene map, 60 s of serial work): speeds 0.25
(the starting worker) and 1, 1 (the joiners, at 20 s). Deterministic: one run each.

Real (local threads, scenes/complex.scene, --case A at --size): --slowdown 4,2,2, i.e. 0.25 +
0.5 + 0.5 = 1.25 cores' worth, which fits this 2-core machine beside the master (the
emulation is only faithful while the workers' combined speed fits the free cores). The
joiners arrive at a third of the serial time S measured first on one thread. Two ideals:
the schedule's, from S (T with 0.25 T + 0.5 (T - t) x 2 = S: the same yardstick for every
strategy), and the run's own ideal_s (from the work it did: a strategy whose pixel order
costs more per pixel, such as the interleaved orders, is measured against its own cost).
--runs rounds, round-robin over the strategies; medians are quoted.

Usage: bench/joins.py [--prt build/prt] [--runs 3] [--size 240x180]
                      [--strategies adaptive,stealing,...] [--skip-real] [--json out.json]
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

STRATEGIES = ["adaptive", "stealing", "self", "guided", "factoring", "awf-b", "awf-c", "af",
              "reservoir", "reservoir-scatter", "hybrid", "hybrid-weighted", "scatter",
              "scatter-weighted", "blocks"]


def simulated(prt, strategy, tmp):
    report = os.path.join(tmp, "sim.json")
    subprocess.run([prt, "simulate", "--workers", "1", "--speeds", "0.25,1,1", "--join-at",
                    "20:2", "--strategy", strategy, "--report", report, "--quiet"],
                   check=True, stdout=subprocess.DEVNULL)
    with open(report) as f:
        return json.load(f)


def real(prt, scene, size, strategy, join_at, tmp):
    report = os.path.join(tmp, "real.json")
    w, h = size.split("x")
    subprocess.run([prt, "render", scene, "--case", "A", "--width", w, "--height", h, "-o",
                    os.path.join(tmp, "img.pfm"), "--quiet", "--workers", "1", "--slowdown",
                    "4,2,2", "--join-at", f"{join_at:.3f}:2", "--strategy", strategy,
                    "--report", report],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(report) as f:
        return json.load(f)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--prt", default=os.path.join(root, "build", "prt"))
    ap.add_argument("--scene", default=os.path.join(root, "scenes", "complex.scene"))
    ap.add_argument("--size", default="240x180")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--strategies", default=",".join(STRATEGIES))
    ap.add_argument("--skip-real", action="store_true")
    ap.add_argument("--json")
    a = ap.parse_args()
    strategies = a.strategies.split(",")
    out = {"simulated": {}, "real": {}}
    with tempfile.TemporaryDirectory() as tmp:
        print("simulated: speeds 0.25 from the start, 1 and 1 from 20 s; 60 s of serial work")
        print(f"{'strategy':18} {'elapsed_s':>10} {'ideal_s':>8} {'ratio':>6} {'joiners_px':>10}")
        for s in strategies:
            r = simulated(a.prt, s, tmp)
            joiners = sum(w["pixels"] for w in r["workers"][1:])
            ratio = r["elapsed_s"] / r["ideal_s"]
            out["simulated"][s] = {"elapsed_s": r["elapsed_s"], "ideal_s": r["ideal_s"],
                                   "ratio": ratio, "joiner_pixels": joiners}
            print(f"{s:18} {r['elapsed_s']:10.2f} {r['ideal_s']:8.2f} {ratio:6.2f} {joiners:10}")
        if a.skip_real:
            return finish(a, out)
        w, h = a.size.split("x")
        t0 = time.perf_counter()
        subprocess.run([a.prt, "render", a.scene, "--case", "A", "--width", w, "--height", h,
                        "--threads", "1", "-o", os.path.join(tmp, "serial.pfm"), "--quiet"],
                       check=True)
        serial = time.perf_counter() - t0
        join_at = serial / 3
        print(f"\nreal: serial {serial:.2f} s on one thread; --slowdown 4,2,2, joiners at "
              f"{join_at:.2f} s; {a.runs} rounds")
        schedule = join_at + (serial - 0.25 * join_at) / 1.25
        print(f"the schedule's ideal: {schedule:.2f} s")
        ratios = {s: [] for s in strategies}
        own = {s: [] for s in strategies}
        elapsed = {s: [] for s in strategies}
        for _ in range(a.runs):
            for s in strategies:
                r = real(a.prt, a.scene, a.size, s, join_at, tmp)
                ratios[s].append(r["elapsed_s"] / schedule)
                own[s].append(r["elapsed_s"] / r["ideal_s"])
                elapsed[s].append(r["elapsed_s"])
        print(f"{'strategy':18} {'elapsed_s':>10} {'/ideal':>7} {'/own':>6}  (medians)")
        for s in strategies:
            e, q, o = (statistics.median(x[s]) for x in (elapsed, ratios, own))
            out["real"][s] = {"elapsed_s": e, "ratio": q, "own_ratio": o, "ratios": ratios[s]}
            print(f"{s:18} {e:10.2f} {q:7.2f} {o:6.2f}")
        out["real_serial_s"] = serial
        out["real_schedule_ideal_s"] = schedule
    return finish(a, out)


def finish(a, out):
    if a.json:
        with open(a.json, "w") as f:
            json.dump(out, f, indent=2)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
