#!/usr/bin/env python3
"""Model files at scale: the figures docs/results.md gives for scenes from model files.

    bench/models.py [--prt build/prt] [--runs 3] [--triangles 1000000] [--instances 1000]

Writes two glTF files into a temporary directory, with nothing but the standard library:

  big.glb        one textured mesh of about --triangles triangles (a bumpy sphere with texture
                 coordinates and normals) and a 1024 x 1024 PNG texture, a camera and a light;
  instances.glb  one mesh of 100,000 triangles placed by --instances nodes (a grid of them),
                 the way a file with many copies of one model holds them.

and measures, as medians of --runs runs (the range beside):

  load-and-send  `prt render big.glb --workers 3` of a tiny image (32 x 24, no speed index):
                 reading the file, decoding the texture, building every worker's tree and
                 sending each worker the scene, the time to the image; beside it the serial
                 render of the same image (one tree, nothing sent);
  instances      the peak resident memory (/usr/bin/time -f %M) of a serial render of
                 instances.glb at 64 x 48, and that of the same mesh placed once.

Both are whole-process figures on this machine; workers are threads of one process, so the
three trees are built two at a time on the two cores.
"""

import argparse
import json
import math
import os
import statistics
import struct
import subprocess
import sys
import tempfile
import time
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def png(width, height, pixel):
    """An RGB PNG whose pixel (x, y) is pixel(x, y) -> (r, g, b) bytes."""
    rows = bytearray()
    for y in range(height):
        rows.append(0)
        for x in range(width):
            rows.extend(pixel(x, y))
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(bytes(rows), 6)) + chunk(b"IEND", b"")


def sphere_mesh(triangles):
    """A bumpy unit sphere of about `triangles` triangles: positions, normals, uvs, indices."""
    n = max(4, int(math.sqrt(triangles / 2)))
    rings, segments = n, n
    positions, normals, uvs = bytearray(), bytearray(), bytearray()
    for i in range(rings + 1):
        v = i / rings
        theta = v * math.pi
        for j in range(segments + 1):
            u = j / segments
            phi = u * 2 * math.pi
            d = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            r = 1 + 0.03 * math.sin(7 * phi) * math.sin(5 * theta)
            positions += struct.pack("<3f", r * d[0], r * d[1], r * d[2])
            normals += struct.pack("<3f", *d)
            uvs += struct.pack("<2f", 4 * u, 2 * v)
    indices = bytearray()
    for i in range(rings):
        for j in range(segments):
            a = i * (segments + 1) + j
            b = a + segments + 1
            if i > 0:  # the first ring's first triangle would meet at the pole
                indices += struct.pack("<3I", a, b, a + 1)
            if i < rings - 1:
                indices += struct.pack("<3I", a + 1, b, b + 1)
    count = (rings + 1) * (segments + 1)
    return positions, normals, uvs, indices, count, len(indices) // 12


def glb(path, mesh, nodes, texture=None):
    """A .glb of one mesh (positions, normals, uvs, indices), `nodes` translations, a camera."""
    positions, normals, uvs, indices, count, triangles = mesh
    blob = bytearray()
    views = []
    def view(data):
        while len(blob) % 4:
            blob.append(0)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data)})
        blob.extend(data)
        return len(views) - 1
    accessors = [
        {"bufferView": view(positions), "componentType": 5126, "count": count, "type": "VEC3",
         "min": [-1.1, -1.1, -1.1], "max": [1.1, 1.1, 1.1]},
        {"bufferView": view(normals), "componentType": 5126, "count": count, "type": "VEC3"},
        {"bufferView": view(uvs), "componentType": 5126, "count": count, "type": "VEC2"},
        {"bufferView": view(indices), "componentType": 5125, "count": triangles * 3, "type": "SCALAR"},
    ]
    material = {"pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0.6}}
    doc = {"asset": {"version": "2.0", "generator": "bench/models.py"},
           "buffers": [{"byteLength": 0}], "bufferViews": views, "accessors": accessors,
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                       "indices": 3, "material": 0}]}],
           "materials": [material],
           "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "aspectRatio": 4 / 3, "znear": 0.1}}],
           "extensionsUsed": ["KHR_lights_punctual"],
           "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3000}]}},
           "scenes": [{"nodes": list(range(len(nodes) + 2))}]}
    if texture is not None:
        doc["images"] = [{"bufferView": view(texture), "mimeType": "image/png"}]
        doc["textures"] = [{"source": 0}]
        material["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    extent = max(max(abs(c) for c in t) for t in nodes) + 1.5
    doc["nodes"] = [{"mesh": 0, "translation": list(t)} for t in nodes]
    doc["nodes"].append({"camera": 0, "translation": [0, extent * 0.6, extent * 2.2],
                         "rotation": [-0.13, 0, 0, 0.99]})
    doc["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}},
                         "rotation": [-0.5, 0.3, 0.1, 0.8]})
    doc["buffers"][0]["byteLength"] = len(blob)
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    while len(blob) % 4:
        blob.append(0)
    with open(path, "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(blob)))
        f.write(struct.pack("<I4s", len(text), b"JSON") + text)
        f.write(struct.pack("<I4s", len(blob), b"BIN\0") + bytes(blob))


def median_range(values, unit):
    return f"{statistics.median(values):.2f} {unit} ({min(values):.2f}-{max(values):.2f})"


def timed(command):
    start = time.monotonic()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.monotonic() - start


def peak_mib(command):
    result = subprocess.run(["/usr/bin/time", "-f", "%M"] + command, check=True,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    return int(result.stderr.strip().splitlines()[-1]) / 1024


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--prt", default=os.path.join(ROOT, "build", "prt"))
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--triangles", type=int, default=1_000_000)
    parser.add_argument("--instances", type=int, default=1000)
    args = parser.parse_args()
    prt = os.path.abspath(args.prt)
    with tempfile.TemporaryDirectory(prefix="prt-models-") as work:
        texture = png(1024, 1024, lambda x, y: bytes((((x * 7) ^ (y * 3)) & 255,
                                                      (x // 32 + y // 32) % 2 * 160 + 60, 90)))
        big = os.path.join(work, "big.glb")
        mesh = sphere_mesh(args.triangles)
        glb(big, mesh, [(0, 0, 0)], texture)
        side = math.ceil(math.sqrt(args.instances))
        grid = [(2.5 * (k % side), 0, 2.5 * (k // side)) for k in range(args.instances)]
        small = sphere_mesh(100_000)
        instances = os.path.join(work, "instances.glb")
        glb(instances, small, grid)
        once = os.path.join(work, "once.glb")
        glb(once, small, [(0, 0, 0)])
        print(f"big.glb: {mesh[5]:,} triangles, 1024 x 1024 texture, {os.path.getsize(big) / 2**20:.1f} MiB; "
              f"instances.glb: {small[5]:,} triangles x {len(grid)} nodes, {os.path.getsize(instances) / 2**20:.1f} MiB")
        tiny = ["--width", "32", "--height", "24", "-q", "-o", os.path.join(work, "out.png")]
        parallel = [prt, "render", big, "--workers", "3", "--speed-index", "none"] + tiny
        serial = [prt, "render", big, "--threads", "1"] + tiny
        timed(serial)  # warm the file cache
        p = [timed(parallel) for _ in range(args.runs)]
        s = [timed(serial) for _ in range(args.runs)]
        print(f"load, build and send to 3 workers, to the image: {median_range(p, 's')}; "
              f"serially (one tree, nothing sent): {median_range(s, 's')}")
        small_image = ["--width", "64", "--height", "48", "-q", "-o", os.path.join(work, "i.png")]
        m = [peak_mib([prt, "render", instances] + small_image) for _ in range(args.runs)]
        o = [peak_mib([prt, "render", once] + small_image) for _ in range(args.runs)]
        print(f"peak memory, {len(grid)} instances of 100k triangles: {median_range(m, 'MiB')}; "
              f"the mesh placed once: {median_range(o, 'MiB')}")


if __name__ == "__main__":
    sys.exit(main())
