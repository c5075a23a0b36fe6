#!/usr/bin/env python3
"""bench/cycles/compare.py on synthetic images whose answers are known: the PSNR of a known
code difference, the luminance ratio of a scaled image, PFM's row order and byte orders, the
box downsampling of a reference, the side-by-side PNG's pixels, and bad input refused with
the file named and nothing written.

    compare_test.py [REPO_ROOT]
"""
import array
import json
import math
import os
import struct
import subprocess
import sys
import tempfile
import unittest
import zlib

ROOT = sys.argv.pop(1) if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
SCRIPT = os.path.join(ROOT, "bench", "cycles", "compare.py")
sys.path.insert(0, os.path.dirname(SCRIPT))
import compare  # noqa: E402


def solid(width, height, rgb):
    return compare.Image(width, height, array.array("f", list(rgb) * (width * height)))


def pfm_bytes(width, height, rows_top_first, magic=b"PF", big_endian=False):
    """rows_top_first: lists of floats; written bottom row first, as PFM stores them."""
    out = b""
    for row in reversed(rows_top_first):
        out += struct.pack((">" if big_endian else "<") + "%df" % len(row), *row)
    scale = b"1.0" if big_endian else b"-1.0"
    return magic + b"\n%d %d\n" % (width, height) + scale + b"\n" + out


def decode_png(data):
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack_from(">I4s", data, pos)
        body = data[pos + 8:pos + 8 + length]
        crc, = struct.unpack_from(">I", data, pos + 8 + length)
        assert crc == zlib.crc32(kind + body) & 0xFFFFFFFF, kind
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour = header[:4]
    assert (depth, colour) == (8, 2)
    raw = zlib.decompress(idat)
    stride = 3 * width + 1
    rows = []
    for y in range(height):
        assert raw[y * stride] == 0  # filter "none", as compare.py writes
        rows.append(raw[y * stride + 1:(y + 1) * stride])
    return width, height, rows


class CompareTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.dir, name)

    def write(self, name, data):
        with open(self.path(name), "wb") as f:
            f.write(data)
        return self.path(name)

    def test_psnr_of_a_known_code_difference(self):
        # Every pixel: codes (128, 60, 200) against (128 + d, 60, 200): MSE = d^2 / 3.
        for d in (1, 5, 40):
            a = solid(7, 5, [compare.srgb8_decode(c) for c in (128, 60, 200)])
            b = solid(7, 5, [compare.srgb8_decode(c) for c in (128 + d, 60, 200)])
            self.assertEqual(set(compare.codes(b)[0::3]), {128 + d})
            expected = 10 * math.log10(255 ** 2 * 3 / d ** 2)
            self.assertAlmostEqual(compare.psnr(a, b), expected, places=9)

    def test_identical_images_have_infinite_psnr(self):
        a = solid(3, 2, (0.2, 0.5, 0.9))
        self.assertEqual(compare.psnr(a, a), math.inf)
        self.assertIn('"psnr_db": "inf"', compare.json_line({"psnr_db": math.inf}))

    def test_the_encoding_clamps_and_rounds_as_prt(self):
        self.assertEqual(compare.srgb8(-1.0), 0)
        self.assertEqual(compare.srgb8(float("nan")), 0)
        self.assertEqual(compare.srgb8(1.0), 255)
        self.assertEqual(compare.srgb8(7.5), 255)
        for c in range(256):  # decode then encode is the identity on codes
            self.assertEqual(compare.srgb8(compare.srgb8_decode(c)), c)

    def test_luminance_ratio_of_a_scaled_image(self):
        a = solid(4, 4, (0.1, 0.2, 0.3))
        b = solid(4, 4, (0.2, 0.4, 0.6))
        la = 0.2126 * 0.1 + 0.7152 * 0.2 + 0.0722 * 0.3
        self.assertAlmostEqual(compare.mean_luminance(a), la, places=7)
        self.assertAlmostEqual(compare.mean_luminance(b) / compare.mean_luminance(a), 2.0, places=6)

    def test_pfm_rows_run_bottom_to_top_in_either_byte_order(self):
        top, bottom = [1.0, 0.0, 0.0, 0.5, 0.5, 0.5], [0.0, 0.0, 1.0, 0.25, 0.0, 0.75]
        for big in (False, True):
            image = compare.read_pfm(self.write("o.pfm", pfm_bytes(2, 2, [top, bottom], big_endian=big)))
            self.assertEqual((image.width, image.height), (2, 2))
            self.assertEqual(list(image.data[:6]), top)
            self.assertEqual(list(image.data[6:]), bottom)
        grey = compare.read_pfm(self.write("g.pfm", pfm_bytes(1, 2, [[0.25], [0.5]], magic=b"Pf")))
        self.assertEqual(list(grey.data), [0.25] * 3 + [0.5] * 3)
        # compare.py's own writer reads back bit for bit.
        compare.write_pfm(self.path("w.pfm"), image)
        self.assertEqual(compare.read_pfm(self.path("w.pfm")).data, image.data)

    def test_a_reference_of_a_whole_multiple_size_is_box_averaged(self):
        rows = [[float(4 * y + x) for x in range(4) for _ in range(3)] for y in range(4)]
        big = compare.Image(4, 4, array.array("f", [v for r in rows for v in r]))
        small = compare.match_size(big, solid(2, 2, (0, 0, 0)))
        # Block (0, 0) holds 0, 1, 4, 5: mean 2.5; (1, 0): 2, 3, 6, 7: 4.5; ...
        self.assertEqual(list(small.data[0::3]), [2.5, 4.5, 10.5, 12.5])
        with self.assertRaises(compare.ImageError):
            compare.match_size(big, solid(3, 3, (0, 0, 0)))
        with self.assertRaises(compare.ImageError):
            compare.match_size(big, solid(2, 1, (0, 0, 0)))

    def test_the_side_by_side_png_shows_reference_image_and_scaled_difference(self):
        ref = self.write("ref.pfm", pfm_bytes(2, 1, [[compare.srgb8_decode(c) for c in
                                                      (100, 100, 100, 10, 20, 30)]]))
        img = self.write("img.pfm", pfm_bytes(2, 1, [[compare.srgb8_decode(c) for c in
                                                      (110, 100, 90, 10, 20, 200)]]))
        result = compare.compare(ref, img, self.path("side.png"), 4.0)
        with open(self.path("side.png"), "rb") as f:
            width, height, rows = decode_png(f.read())
        self.assertEqual((width, height), (6, 1))
        self.assertEqual(list(rows[0]), [100, 100, 100, 10, 20, 30, 110, 100, 90, 10, 20, 200,
                                         40, 0, 40, 0, 0, 255])
        self.assertAlmostEqual(result["psnr_db"],
                               10 * math.log10(255 ** 2 * 6 / (100 + 100 + 170 ** 2)), places=9)

    def test_the_command_prints_a_json_line_and_a_line_for_people(self):
        ref = self.write("r.pfm", pfm_bytes(1, 1, [[0.5, 0.5, 0.5]]))
        img = self.write("i.pfm", pfm_bytes(1, 1, [[0.25, 0.25, 0.25]]))
        done = subprocess.run([sys.executable, SCRIPT, ref, img], capture_output=True, text=True)
        self.assertEqual(done.returncode, 0, done.stderr)
        first, second = done.stdout.splitlines()
        self.assertAlmostEqual(json.loads(first)["luminance_ratio"], 0.5, places=6)
        self.assertIn("mean luminance", second)

    def test_bad_input_is_refused_with_the_file_named_and_nothing_written(self):
        good = self.write("good.pfm", pfm_bytes(2, 2, [[0.1] * 6, [0.2] * 6]))
        cases = {
            "short.pfm": (pfm_bytes(2, 2, [[0.1] * 6, [0.2] * 6])[:-5], "truncated PFM file"),
            "magic.pfm": (b"P6\n1 1\n255\n\x01\x02\x03", "not a PFM file"),
            "scale.pfm": (b"PF\n1 1\n0\n" + bytes(12), "bad PFM size or scale"),
            "header.pfm": (b"PF\n1", "truncated PFM header"),
            "size.pfm": (pfm_bytes(3, 1, [[0.1] * 9]), "not the same size"),
        }
        for name, (data, message) in cases.items():
            bad = self.write(name, data)
            for ref, img in ((bad, good), (good, bad)):
                done = subprocess.run([sys.executable, SCRIPT, ref, img, "--png",
                                       self.path("out.png")], capture_output=True, text=True)
                self.assertEqual(done.returncode, 2, (name, done.stdout, done.stderr))
                self.assertIn(message, done.stderr, name)
                self.assertIn(name, done.stderr)
                self.assertNotIn("Traceback", done.stderr)
                self.assertFalse(os.path.exists(self.path("out.png")))
        done = subprocess.run([sys.executable, SCRIPT, self.path("missing.pfm"), good],
                              capture_output=True, text=True)
        self.assertEqual(done.returncode, 2)
        self.assertIn("missing.pfm", done.stderr)
        leftovers = [n for n in os.listdir(self.dir) if n.startswith(".compare.")]
        self.assertEqual(leftovers, [])


if __name__ == "__main__":
    unittest.main(verbosity=2)
