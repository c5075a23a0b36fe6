#!/usr/bin/env python3
"""What spot checks cost: the same render with --verify 0 (off), the default 1 and a higher
rate, interleaved run by run, on the local driver.

Each pixel checked is rendered twice (once by its worker, once by another or by the master),
so the work grows by about the sampled share (4 times the rate for a worker's first checks,
the rate after, half of it once trusted), plus a message each way per check batch, and the
render cannot end before the last checks are back. Two figures per rate, as ratios to
--verify 0 measured in the same round: the elapsed time (what a user waits) and the workers'
busy time summed (the CPU spent, less noisy on a shared machine). Medians over --runs rounds,
with the range; the rates take turns at running first in a round.

The scene is scenes/complex.scene (--case A) on --workers worker threads at full speed; on this
2-core machine the workers and the master share the cores, so elapsed times carry the
machine's noise: the busy-time ratio is the steadier figure.

Usage: bench/verify.py [--prt build/prt] [--runs 5] [--size 480x360] [--workers 2]
                       [--rates 0,1,5] [--json out.json]
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile


def render(prt, scene, size, workers, rate, tmp):
    report = os.path.join(tmp, "r.json")
    w, h = size.split("x")
    subprocess.run([prt, "render", scene, "--case", "A", "--width", w, "--height", h, "-o",
                    os.path.join(tmp, "img.pfm"), "--quiet", "--workers", str(workers),
                    "--verify", str(rate), "--report", report, "--no-checkpoint"],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(report) as f:
        r = json.load(f)
    return {"elapsed_s": r["elapsed_s"], "busy_s": sum(x["busy_s"] for x in r["workers"]),
            "verified": r["verified_pixels"], "referee": r["referee_checks"],
            "pixels": r["width"] * r["height"]}


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--prt", default=os.path.join(root, "build", "prt"))
    ap.add_argument("--scene", default=os.path.join(root, "scenes", "complex.scene"))
    ap.add_argument("--size", default="480x360")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--rates", default="0,1,5")
    ap.add_argument("--json")
    a = ap.parse_args()
    rates = [float(x) for x in a.rates.split(",")]
    if rates[0] != 0:
        rates = [0.0] + rates
    rounds = []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(a.runs):
            # Each round in another order: the first run of a round is not always the same rate.
            order = rates[i % len(rates):] + rates[:i % len(rates)]
            rounds.append({rate: render(a.prt, a.scene, a.size, a.workers, rate, tmp)
                           for rate in order})
    print(f"spot checks on {a.scene} (case A, {a.size}, {a.workers} workers), "
          f"{a.runs} rounds; ratios to --verify 0 in the same round")
    print(f"{'--verify':>8} {'checked':>8} {'share':>7} {'elapsed':>22} {'busy (CPU)':>22}")
    out = {}
    for rate in rates:
        el = [r[rate]["elapsed_s"] / r[0.0]["elapsed_s"] for r in rounds]
        busy = [r[rate]["busy_s"] / r[0.0]["busy_s"] for r in rounds]
        checked = statistics.median(r[rate]["verified"] for r in rounds)
        share = checked / rounds[0][rate]["pixels"]
        out[rate] = {"elapsed_ratio": statistics.median(el), "elapsed_range": [min(el), max(el)],
                     "busy_ratio": statistics.median(busy), "busy_range": [min(busy), max(busy)],
                     "verified_pixels": checked, "share": share,
                     "elapsed_s": statistics.median(r[rate]["elapsed_s"] for r in rounds)}
        print(f"{rate:8g} {checked:8.0f} {100 * share:6.2f}% "
              f"{statistics.median(el):8.3f} [{min(el):.3f}-{max(el):.3f}] "
              f"{statistics.median(busy):8.3f} [{min(busy):.3f}-{max(busy):.3f}]")
    if a.json:
        with open(a.json, "w") as f:
            json.dump({str(k): v for k, v in out.items()}, f, indent=2)


if __name__ == "__main__":
    main()
