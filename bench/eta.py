#!/usr/bin/env python3
"""How honest the ETA is: its error over a run on the complex scene.

    bench/eta.py [PRT] [--runs 5] [--size 640x480] [--case D]

Renders scenes/complex.scene with --serve on a free loopback port and polls /status.json
five times a second. Once the run is over its true length T is known, and at each tenth of
it (10 % .. 90 % of T) the ETA the run showed then is compared with the time that in fact
remained: error = |ETA - remaining| / remaining. Beside it, the naive ETA a pixel count gives
(elapsed x pixels left / pixels done), which is what a progress bar without cost estimates
shows. Three ways to render: serial on every core, the default strategy on 2 workers, and
self-scheduling (scan-line chunks, the order a naive estimate suffers from most) on 2
workers. Prints, per way and per tenth, the median error of --runs runs and its range; the
target is an error within 25 % after 20 % of the run.

The workers are emulated at a 4x slowdown (2 x 1/4 of a core: faithful on a 2-core machine
even when it is half busy) so that a run lasts long enough for its estimate to matter; the
serial render runs on one thread.
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import tempfile
import time
import urllib.request

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)

WAYS = {
    "serial, 1 thread": ["--threads", "1"],
    "adaptive (default), 2 workers": ["--workers", "2", "--slowdown", "4,4"],
    "self (scan-line chunks), 2 workers": ["--workers", "2", "--slowdown", "4,4", "--strategy", "self"],
}


def one_run(prt, way, size, case, work):
    width, height = size.split("x")
    err_path = os.path.join(work, "err.txt")
    with open(err_path, "w") as err:
        proc = subprocess.Popen(
            [prt, "render", os.path.join(root, "scenes", "complex.scene"), "--case", case,
             "--width", width, "--height", height, "--serve", "127.0.0.1:0",
             "-o", os.path.join(work, "eta.pfm"), "-q", "--no-checkpoint"] + WAYS[way],
            stdout=subprocess.DEVNULL, stderr=err)
    url = None
    while url is None and proc.poll() is None:
        m = re.search(r"live page at (http://\S+/)", open(err_path).read())
        url = m.group(1) if m else None
        time.sleep(0.01)
    samples = []
    while proc.poll() is None:
        try:
            with urllib.request.urlopen(url + "status.json", timeout=2) as r:
                s = json.load(r)
            if s["phase"] == "rendering":
                samples.append((s["elapsed_s"], s["pixels_done"], s["pixels_total"], s["eta_s"]))
            if s["phase"] in ("finished", "failed"):
                total = s["elapsed_s"]
                break
        except OSError:
            pass
        time.sleep(0.2)
    proc.wait()
    if proc.returncode != 0:
        raise SystemExit("prt failed: " + open(err_path).read())
    errors = {}
    for tenth in range(1, 10):
        t = tenth / 10 * total
        at = min(samples, key=lambda x: abs(x[0] - t))
        elapsed, done, all_, eta = at
        left = total - elapsed
        naive = elapsed * (all_ - done) / done if done else None
        errors[tenth] = (abs(eta - left) / left if eta is not None else None,
                         abs(naive - left) / left if naive is not None else None)
    return total, errors


def describe(values):
    values = [v for v in values if v is not None]
    if not values:
        return "   n/a"
    return "%5.0f%% (%.0f-%.0f)" % (100 * statistics.median(values), 100 * min(values), 100 * max(values))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("prt", nargs="?", default=os.path.join(root, "build", "prt"))
    p.add_argument("--runs", type=int, default=5)
    p.add_argument("--size", default="640x480")
    p.add_argument("--case", default="D")
    a = p.parse_args()
    with tempfile.TemporaryDirectory() as work:
        for way in WAYS:
            runs = [one_run(a.prt, way, a.size, a.case, work) for _ in range(a.runs)]
            print("%s: run %.1f s (median of %d)" % (way, statistics.median(r[0] for r in runs), a.runs))
            print("  at    ETA error (median, range)   pixel-count ETA error")
            for tenth in range(1, 10):
                print("  %d%%   %-26s %s" % (10 * tenth, describe([r[1][tenth][0] for r in runs]),
                                             describe([r[1][tenth][1] for r in runs])))


if __name__ == "__main__":
    main()
