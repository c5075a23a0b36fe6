#!/usr/bin/env python3
"""What preparing a frame costs a worker on a 100 k-triangle animated scene.

    bench/frame_overhead.py [PRT] [--triangles 100000] [--frames 0-3] [--runs 3]

Writes a torus of about --triangles triangles as an OBJ file (made here: a mesh no other
tool has to supply), and a scene that imports it twice with keyed placements (one spinning,
one flying past), a keyed camera and a keyed light, over a floor. Renders --frames serially on
one thread at 640x480, case A (DRT 1, 8 samples), and reads the run's own split of its time:
rendering, and preparing frames (evaluating the scene at the frame's time and building the
World, the meshes' trees kept from frame to frame; the first frame builds them). Prints the
medians of --runs runs and the preparation's share of a frame's rendering time, for the first
frame and for each later one. Serial on one thread, so the figure is
what one worker pays per frame; it does not depend on free cores.
"""
import argparse
import math
import os
import re
import statistics
import subprocess
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)


def torus_obj(path, triangles):
    # u x v quads, two triangles each: u = 2 v.
    v = max(3, math.ceil(math.sqrt(triangles / 4)))
    u = 2 * v
    with open(path, "w") as f:
        f.write("# torus, %d triangles\n" % (2 * u * v))
        for i in range(u):
            a = 2 * math.pi * i / u
            for j in range(v):
                b = 2 * math.pi * j / v
                r = 1 + 0.35 * math.cos(b)
                f.write("v %.6f %.6f %.6f\n" % (r * math.cos(a), 0.35 * math.sin(b), r * math.sin(a)))
        for i in range(u):
            for j in range(v):
                p = i * v + j + 1
                q = ((i + 1) % u) * v + j + 1
                p2 = i * v + (j + 1) % v + 1
                q2 = ((i + 1) % u) * v + (j + 1) % v + 1
                f.write("f %d %d %d\nf %d %d %d\n" % (p, q, q2, p, q2, p2))
    return 2 * u * v


def main():
    p = argparse.ArgumentParser()
    p.add_argument("prt", nargs="?", default=os.path.join(root, "build", "prt"))
    p.add_argument("--triangles", type=int, default=100000)
    p.add_argument("--frames", default="0-3")
    p.add_argument("--runs", type=int, default=3)
    a = p.parse_args()
    with tempfile.TemporaryDirectory() as work:
        obj = os.path.join(work, "torus.obj")
        count = torus_obj(obj, a.triangles // 2)  # imported twice
        scene = os.path.join(work, "moving.scene")
        with open(scene, "w") as f:
            f.write(f"""camera {{ eye 0 2 -6 look_at 0 0.5 0 fov 45 key 4 {{ eye 4 3 -4 }} }}
image {{ width 640 height 480 }}
light point {{ position 3 6 -5 key 4 {{ position -3 6 -5 }} }}
import {{ file "{obj}" translate -1.2 0.6 0 key 4 {{ translate -1.2 0.6 0 rotate 0 180 0 }} }}
import {{ file "{obj}" translate 2.5 0.6 2 key 4 {{ translate -2.5 1.2 2 rotate 90 0 0 }} }}
plane {{ point 0 0 0 normal 0 1 0 surface {{ color 0.6 0.6 0.6 diffuse 0.8 }} }}
""")
        out = os.path.join(work, "f_####.png")
        rendering, preparing, first = [], [], []
        frames = None
        for _ in range(a.runs):
            text = subprocess.run([a.prt, "render", scene, "--case", "A", "--threads", "1",
                                   "--fps", "1", "--frames", a.frames, "-o", out],
                                  check=True, capture_output=True, text=True).stdout
            m = re.search(r"(\d+) frames of .*?: ([\d.]+) s rendering, ([\d.]+) s preparing "
                          r"frames \(([\d.]+) s the first", text)
            frames = int(m.group(1))
            rendering.append(float(m.group(2)))
            preparing.append(float(m.group(3)))
            first.append(float(m.group(4)))
        r, s, f0 = (statistics.median(x) for x in (rendering, preparing, first))
        later = (s - f0) / (frames - 1)
        print(f"{2 * count} triangles (a {count}-triangle torus imported twice, both keyed), "
              f"640x480 case A, {frames} frames, one thread; medians of {a.runs} runs")
        print(f"rendering          {r:8.3f} s  ({r / frames:.3f} s per frame)")
        print(f"preparing frames   {s:8.3f} s  (the first {f0 * 1e3:.1f} ms, building the trees; "
              f"each later one {later * 1e3:.1f} ms)")
        print(f"a later frame's preparation is {100 * later / (r / frames):.2f} % of its "
              f"rendering time; the first's {100 * f0 / (r / frames):.2f} %")


if __name__ == "__main__":
    main()
