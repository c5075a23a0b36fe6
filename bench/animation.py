#!/usr/bin/env python3
"""A frame sequence as one job against whole frames per machine.

    bench/animation.py [PRT] [--frames 0-47] [--runs 3] [--size 160x120] [--spp 2]

Renders an animated scene (scenes/keyframes.scene: camera, a ball, a box and a light keyed)
on 4 emulated workers slowed 2,2,4,4 (together 1.5 cores: faithful on a machine with 2 free
cores) with the default strategy and with `--strategy frames` (whole frames to whole
machines, as Flamenco or Deadline hand them out), and serially on one thread. The emulation
ceiling is a static split by the true speeds: the serial time over the workers' combined
speed (1.5). Prints the median job time of each over --runs runs and the ratios, and the
per-frame cost of preparing a frame (scene evaluation and tree rebuild) from a worker's
point of view, measured serially.
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("prt", nargs="?", default=os.path.join(root, "build", "prt"))
    p.add_argument("--scene", default=os.path.join(root, "scenes", "keyframes.scene"))
    p.add_argument("--frames", default="0-47")
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--size", default="160x120")
    p.add_argument("--spp", type=int, default=2)
    a = p.parse_args()
    w, h = a.size.split("x")
    common = [a.scene, "--width", w, "--height", h, "--spp", str(a.spp), "--frames", a.frames,
              "-q"]
    slow = "2,2,4,4"
    speed = sum(1 / float(k) for k in slow.split(","))
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "f_####.png")

        def timed(extra):
            start = time.monotonic()
            subprocess.run([a.prt, "render", *common, "-o", out, *extra], check=True)
            return time.monotonic() - start

        def job(strategy):
            report = os.path.join(work, "r.json")
            subprocess.run([a.prt, "render", *common, "-o", out, "--workers", "4", "--slowdown",
                            slow, "--strategy", strategy, "--report", report], check=True)
            return json.load(open(report))["elapsed_s"]

        serial, adaptive, frames = [], [], []
        for _ in range(a.runs):
            serial.append(timed(["--threads", "1"]))
            adaptive.append(job("adaptive"))
            frames.append(job("frames"))
        s, ad, fr = (statistics.median(x) for x in (serial, adaptive, frames))
        ceiling = s / speed
        print(f"scene {os.path.basename(a.scene)}, frames {a.frames}, {a.size}, {a.spp} spp; "
              f"workers slowed {slow} (combined speed {speed:g}); medians of {a.runs} runs")
        print(f"serial, one thread        {s:8.3f} s")
        print(f"emulation ceiling         {ceiling:8.3f} s  (serial / {speed:g})")
        print(f"adaptive (default)        {ad:8.3f} s  {ad / ceiling:.3f} x the ceiling")
        print(f"frames (whole frames)     {fr:8.3f} s  {fr / ceiling:.3f} x the ceiling")
        print(f"adaptive is {fr / ad:.2f} x faster than whole frames")


if __name__ == "__main__":
    main()
