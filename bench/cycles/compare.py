#!/usr/bin/env python3
"""Compares a render with a reference, as PRT's image comparison does (src/image/image_compare.h):

    bench/cycles/compare.py REFERENCE.pfm IMAGE.pfm [--png SIDE.png] [--diff-scale 4]
                            [--json-only]

Both images are linear float PFM files (PRT writes one with `-o x.pfm`; Cycles' references
are written by bench/cycles/render_cycles.py; a .pfm.gz is read too). Reports

  - PSNR in dB over the R, G, B samples of their 8-bit sRGB encodings (clamp to [0, 1], the
    sRGB curve, round to nearest): 10 log10(255^2 / MSE), "inf" when identical;
  - the mean linear luminance (Rec. 709: 0.2126 R + 0.7152 G + 0.0722 B) of each and their
    ratio IMAGE / REFERENCE;

as one JSON line and one line for people, and writes REFERENCE | IMAGE | |difference| x
--diff-scale (in 8-bit codes) side by side as a PNG. A reference whose size is a whole
multiple k of the image's (the same k across and down) is first averaged over k x k blocks:
with a box pixel filter that is exactly the reference at the image's size, so a test can
render small and still use a committed reference.

Python's standard library only (no NumPy), so that it runs wherever PRT's tests run.
Exits 2 with a message naming the file on an unreadable, truncated or mismatched image.
"""
import argparse
import array
import gzip
import json
import math
import os
import struct
import sys
import tempfile
import zlib

LUMA = (0.2126, 0.7152, 0.0722)


class ImageError(Exception):
    pass


class Image:
    """Linear RGB floats, top row first, 3 per pixel."""

    def __init__(self, width, height, data):
        assert len(data) == 3 * width * height
        self.width, self.height, self.data = width, height, data


def read_pfm(path):
    try:
        opener = gzip.open if path.endswith(".gz") else open
        with opener(path, "rb") as f:
            raw = f.read()
    except (OSError, EOFError) as e:
        raise ImageError("cannot read '%s': %s" % (path, e)) from None
    # Header: magic, width, height, scale, whitespace-separated, one whitespace byte after.
    tokens, pos = [], 0
    while len(tokens) < 4:
        while pos < len(raw) and raw[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while pos < len(raw) and not raw[pos:pos + 1].isspace():
            pos += 1
        if start == pos:
            raise ImageError("'%s': truncated PFM header" % path)
        tokens.append(raw[start:pos])
    pos += 1
    magic = tokens[0]
    if magic not in (b"PF", b"Pf"):
        raise ImageError("'%s' is not a PFM file (expected magic number PF or Pf)" % path)
    try:
        width, height, scale = int(tokens[1]), int(tokens[2]), float(tokens[3])
    except ValueError:
        raise ImageError("'%s': bad PFM header" % path) from None
    if not (0 < width <= 32768 and 0 < height <= 32768) or scale == 0 or not math.isfinite(scale):
        raise ImageError("'%s': bad PFM size or scale (%d x %d, %g)" % (path, width, height, scale))
    channels = 3 if magic == b"PF" else 1
    row = channels * width
    need = 4 * row * height
    if len(raw) - pos < need:
        raise ImageError("truncated PFM file '%s' (expected %d bytes of pixel data, found %d)"
                         % (path, need, len(raw) - pos))
    values = array.array("f")
    values.frombytes(raw[pos:pos + need])
    if (scale < 0) != (sys.byteorder == "little"):
        values.byteswap()
    data = array.array("f", bytes(4 * 3 * width * height))
    for file_row in range(height):  # PFM stores the bottom row first
        y = height - 1 - file_row
        src = values[file_row * row:(file_row + 1) * row]
        if channels == 3:
            data[3 * width * y:3 * width * (y + 1)] = src
        else:
            for c in range(3):
                data[3 * width * y + c:3 * width * (y + 1):3] = src
    return Image(width, height, data)


def write_pfm(path, image):
    out = array.array("f")
    for y in range(image.height - 1, -1, -1):
        out.extend(image.data[3 * image.width * y:3 * image.width * (y + 1)])
    if sys.byteorder != "little":
        out.byteswap()
    atomic_write(path, b"PF\n%d %d\n-1.0\n" % (image.width, image.height) + out.tobytes())


def atomic_write(path, payload):
    directory = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=".compare.", dir=directory)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(payload)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def srgb_encode(v):
    return 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055


def srgb8(v):
    """Linear -> 8-bit sRGB code as PRT's linearToSrgb8: clamp, encode, round; NaN -> 0."""
    if not v > 0:  # also NaN
        return 0
    if v >= 1:
        return 255
    return int(srgb_encode(v) * 255 + 0.5)


def srgb8_decode(code):
    e = code / 255
    return e / 12.92 if e <= 0.04045 else ((e + 0.055) / 1.055) ** 2.4


def codes(image):
    table = {}
    out = bytearray(len(image.data))
    for i, v in enumerate(image.data):
        c = table.get(v)
        if c is None:
            c = table[v] = srgb8(v)
        out[i] = c
    return out


def box_downsample(image, k):
    w, h = image.width // k, image.height // k
    data = array.array("f", bytes(4 * 3 * w * h))
    inv = 1.0 / (k * k)
    src, sw = image.data, image.width
    for y in range(h):
        for x in range(w):
            for c in range(3):
                s = 0.0
                for dy in range(k):
                    base = 3 * ((y * k + dy) * sw + x * k) + c
                    for dx in range(k):
                        s += src[base + 3 * dx]
                data[3 * (y * w + x) + c] = s * inv
    return Image(w, h, data)


def match_size(reference, image, reference_name="the reference", image_name="the image"):
    if (reference.width, reference.height) == (image.width, image.height):
        return reference
    k = reference.width // image.width if image.width else 0
    if k >= 1 and reference.width == k * image.width and reference.height == k * image.height:
        return box_downsample(reference, k)
    raise ImageError("%s is %d x %d and %s %d x %d: not the same size, nor a whole multiple"
                     % (reference_name, reference.width, reference.height, image_name,
                        image.width, image.height))


def psnr(a, b):
    ca, cb = codes(a), codes(b)
    total = sum((x - y) * (x - y) for x, y in zip(ca, cb))
    if total == 0:
        return math.inf
    mse = total / len(ca)
    return 10 * math.log10(255 * 255 / mse)


def mean_luminance(image):
    d = image.data
    n = image.width * image.height
    finite = [v if math.isfinite(v) else 0.0 for v in d]
    return (LUMA[0] * math.fsum(finite[0::3]) + LUMA[1] * math.fsum(finite[1::3]) +
            LUMA[2] * math.fsum(finite[2::3])) / n


def non_finite(image):
    return sum(1 for v in image.data if not math.isfinite(v))


def png_bytes(width, height, rows):
    """rows: one bytes object of 3 * width 8-bit codes per row, top first."""
    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body +
                struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))
    raw = b"".join(b"\x00" + r for r in rows)
    return (b"\x89PNG\r\n\x1a\n" +
            chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def side_by_side_png(path, reference, image, diff_scale):
    w, h = image.width, image.height
    ca, cb = codes(reference), codes(image)
    rows = []
    for y in range(h):
        s, e = 3 * w * y, 3 * w * (y + 1)
        diff = bytes(min(255, int(abs(x - z) * diff_scale + 0.5)) for x, z in zip(ca[s:e], cb[s:e]))
        rows.append(bytes(ca[s:e]) + bytes(cb[s:e]) + diff)
    atomic_write(path, png_bytes(3 * w, h, rows))


def compare(reference_path, image_path, png=None, diff_scale=4.0):
    reference = read_pfm(reference_path)
    image = read_pfm(image_path)
    scaled = match_size(reference, image, "reference '%s'" % reference_path,
                        "image '%s'" % image_path)
    lr, li = mean_luminance(scaled), mean_luminance(image)
    result = {
        "reference": reference_path, "image": image_path,
        "width": image.width, "height": image.height,
        "reference_block": reference.width // image.width,
        "psnr_db": psnr(scaled, image),
        "luminance_reference": lr, "luminance_image": li,
        "luminance_ratio": li / lr if lr > 0 else math.inf,
        "non_finite_samples": non_finite(image),
    }
    if png:
        side_by_side_png(png, scaled, image, diff_scale)
        result["png"] = png
    return result


def json_line(result):
    clean = {k: (("inf" if v > 0 else "-inf") if isinstance(v, float) and math.isinf(v) else
                 round(v, 6) if isinstance(v, float) else v)
             for k, v in result.items()}
    return json.dumps(clean, sort_keys=True)


def human_line(result):
    p = result["psnr_db"]
    return ("%s against %s: PSNR %s dB, mean luminance %.5f / %.5f = %.4f%s" % (
        result["image"], result["reference"], "inf" if math.isinf(p) else "%.2f" % p,
        result["luminance_image"], result["luminance_reference"], result["luminance_ratio"],
        ", %d non-finite samples" % result["non_finite_samples"]
        if result["non_finite_samples"] else ""))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("reference", help="the reference's PFM (Cycles)")
    p.add_argument("image", help="the PFM to judge (PRT)")
    p.add_argument("--png", help="write reference | image | difference side by side here")
    p.add_argument("--diff-scale", type=float, default=4.0,
                   help="the difference's 8-bit codes are multiplied by this (default 4)")
    p.add_argument("--json-only", action="store_true", help="print the JSON line alone")
    a = p.parse_args(argv)
    try:
        result = compare(a.reference, a.image, a.png, a.diff_scale)
    except ImageError as e:
        print("compare.py: %s" % e, file=sys.stderr)
        return 2
    print(json_line(result))
    if not a.json_only:
        print(human_line(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
