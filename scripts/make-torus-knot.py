#!/usr/bin/env python3
"""Writes scenes/models/torus-knot.obj: a (2, 3) torus knot, a tube of radius 0.2 swept
along the knot (major radius 1, minor 0.45), with vertex normals. 96 x 12 segments: 2,304
triangles, closed and wound counter-clockwise seen from outside. The committed file is this
script's output; run it again to regenerate it (python3 scripts/make-torus-knot.py)."""
import math
import pathlib

P, Q = 2, 3
SEGMENTS, SIDES = 96, 12
TUBE = 0.2


def centre(t):
    r = 1 + 0.45 * math.cos(Q * t)
    return (r * math.cos(P * t), 0.45 * math.sin(Q * t), r * math.sin(P * t))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(a):
    n = math.sqrt(sum(x * x for x in a))
    return tuple(x / n for x in a)


vertices, normals = [], []
for i in range(SEGMENTS):
    t = 2 * math.pi * i / SEGMENTS
    c = centre(t)
    tangent = unit(sub(centre(t + 1e-4), centre(t - 1e-4)))
    side = unit(cross(tangent, (0.0, 1.0, 0.0)))
    up = cross(side, tangent)
    for j in range(SIDES):
        a = 2 * math.pi * j / SIDES
        n = tuple(math.cos(a) * s + math.sin(a) * u for s, u in zip(side, up))
        normals.append(n)
        vertices.append(tuple(ci + TUBE * ni for ci, ni in zip(c, n)))

lines = ["# (2, 3) torus knot, written by scripts/make-torus-knot.py"]
lines += ["v %.6f %.6f %.6f" % v for v in vertices]
lines += ["vn %.6f %.6f %.6f" % n for n in normals]
for i in range(SEGMENTS):
    for j in range(SIDES):
        a = i * SIDES + j + 1
        b = ((i + 1) % SEGMENTS) * SIDES + j + 1
        c = ((i + 1) % SEGMENTS) * SIDES + (j + 1) % SIDES + 1
        d = i * SIDES + (j + 1) % SIDES + 1
        # Outward: the normal points away from the tube's centre line.
        lines.append("f %d//%d %d//%d %d//%d" % (a, a, c, c, d, d))
        lines.append("f %d//%d %d//%d %d//%d" % (a, a, b, b, c, c))
out = pathlib.Path(__file__).resolve().parent.parent / "scenes" / "models" / "torus-knot.obj"
out.parent.mkdir(parents=True, exist_ok=True)
out.write_text("\n".join(lines) + "\n")
print("wrote %s: %d vertices, %d triangles" % (out, len(vertices), 2 * SEGMENTS * SIDES))
