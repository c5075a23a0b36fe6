#!/usr/bin/env python3
"""How the per-pixel cost of a path-traced scene differs from the paper's renderer's: what the
balancers face.

    bench/cost_spread.py [--scene scenes/models/street.glb] [--width 160 --height 120]
                         [--spp 16] [--prt build/prt] [--out build/cost-spread]

Renders the scene serially on one thread with each integrator (`--integrator hall` and
`path`) and `--cost-map`, reads the maps (PRTCOST1: a header, then a float32 per pixel) and
prints, per integrator: the total seconds, the mean pixel, its coefficient of variation, the
median, the 90th and 99th percentiles and the costliest pixel as multiples of the mean, and the
share of the whole render held by the costliest 1 % of pixels. Writes OUT/cost_spread.csv.
"""
import argparse
import csv
import os
import struct
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_costs(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"PRTCOST1":
        raise SystemExit("%s is not a cost map" % path)
    w, h = struct.unpack("<II", data[8:16])
    return list(struct.unpack("<%df" % (w * h), data[16:16 + 4 * w * h]))


def spread(costs):
    n = len(costs)
    total = sum(costs)
    mean = total / n
    sd = (sum((c - mean) ** 2 for c in costs) / n) ** 0.5
    s = sorted(costs)
    at = lambda q: s[min(n - 1, int(q * n))]
    top = s[n - max(1, n // 100):]
    return {"total_s": total, "mean_ms": 1e3 * mean, "cv": sd / mean,
            "median_x": at(0.5) / mean, "p90_x": at(0.9) / mean, "p99_x": at(0.99) / mean,
            "max_x": s[-1] / mean, "top1pct_share": sum(top) / total}


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--scene", default=os.path.join(ROOT, "scenes/models/street.glb"))
    p.add_argument("--width", type=int, default=160)
    p.add_argument("--height", type=int, default=120)
    p.add_argument("--spp", type=int, default=16)
    p.add_argument("--prt", default=os.path.join(ROOT, "build", "prt"))
    p.add_argument("--out", default=os.path.join(ROOT, "build", "cost-spread"))
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for integrator in ("hall", "path"):
        costs = os.path.join(a.out, integrator + ".costs")
        subprocess.run([a.prt, "render", a.scene, "--integrator", integrator, "--spp",
                        str(a.spp), "--width", str(a.width), "--height", str(a.height),
                        "--threads", "1", "-q", "-o", os.path.join(a.out, integrator + ".png"),
                        "--cost-map", costs], check=True)
        row = {"scene": os.path.basename(a.scene), "integrator": integrator, "spp": a.spp}
        row.update(spread(read_costs(costs)))
        rows.append(row)
        print("%-5s total %.2f s, mean %.3f ms, CV %.2f, median %.2fx, p90 %.2fx, p99 %.2fx, "
              "max %.1fx the mean; the costliest 1%% of pixels hold %.1f%% of the time" % (
                  integrator, row["total_s"], row["mean_ms"], row["cv"], row["median_x"],
                  row["p90_x"], row["p99_x"], row["max_x"], 100 * row["top1pct_share"]))
    with open(os.path.join(a.out, "cost_spread.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
