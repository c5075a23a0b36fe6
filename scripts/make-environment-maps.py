"""Writes the small HDR environment maps the tests read (scenes/maps/), with writers other
than prt's: the Radiance RGBE file by the encoding of its specification (Ward, Graphics Gems
II, "Real Pixels"), the OpenEXR file by ffmpeg from a PFM.

  scenes/maps/sky.hdr   Radiance RGBE, flat scan lines, 64 x 32 texels
  scenes/maps/sky.exr   OpenEXR, half floats, ZIP (ffmpeg's exr encoder), the same texels

The map is equirectangular in Blender's layout: a blue sky over the horizon, brighter towards
it, a dark brown ground under it, and a sun of 2 x 2 texels (radiance about 400) at azimuth
90 degrees (columns 47-48 of 64: Blender's +y, glTF's and prt's +z) and 45 degrees above the
horizon (rows 7-8 from the top).

Command (Python 3 and ffmpeg):  python3 scripts/make-environment-maps.py scenes/maps
"""
import math
import os
import struct
import subprocess
import sys
import tempfile

W, H = 64, 32
SUN_COLUMNS, SUN_ROWS = (47, 48), (7, 8)  # rows from the top


def texel(column, row):
    elevation = (0.5 - (row + 0.5) / H) * math.pi
    if column in SUN_COLUMNS and row in SUN_ROWS:
        return (400.0, 380.0, 340.0)
    if elevation > 0:
        return (0.25 + 0.3 * (1 - elevation), 0.45 + 0.3 * (1 - elevation), 0.9)
    return (0.12, 0.10, 0.08)


def rgbe(color):
    top = max(color)
    if top < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(top)
    scale = mantissa * 256.0 / top
    return bytes([int(c * scale) for c in color] + [exponent + 128])


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    with open(os.path.join(out, "sky.hdr"), "wb") as f:
        f.write(b"#?RADIANCE\n# sky.hdr: scripts/make-environment-maps.py\n"
                b"FORMAT=32-bit_rle_rgbe\n\n")
        f.write(b"-Y %d +X %d\n" % (H, W))
        for row in range(H):
            f.write(b"".join(rgbe(texel(column, row)) for column in range(W)))
    with tempfile.TemporaryDirectory() as tmp:
        pfm = os.path.join(tmp, "sky.pfm")
        with open(pfm, "wb") as f:
            f.write(b"PF\n%d %d\n-1.0\n" % (W, H))
            # The PFM specification puts the bottom row first, but ffmpeg 5.1's reader takes
            # the first row for the top (an EXR it writes from a PFM in the standard order is
            # upside down, as Blender and prt read EXR): the rows go top first here.
            for row in range(H):
                for column in range(W):
                    f.write(struct.pack("<3f", *texel(column, row)))
        subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", pfm, "-c:v", "exr", "-compression",
                        "zip16", "-format", "half", os.path.join(out, "sky.exr")], check=True)


main()
