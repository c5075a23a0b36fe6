#!/usr/bin/env python3
"""Exits 0 when the checkpoint CK holds a pixel that worker W rendered, 1 otherwise (also
when CK is missing or being written): how the join tests know a joiner has done some work.

    checkpoint_owner.py CK W

Reads the layout of src/farm/checkpoint.h: "PRTCKPT1", the u64 key, the u16-length
description, i32 width and height, the done set as runs (u64 count, then first/count/stride
u64 triples), the colours, an i16 owner per done pixel, and a trailing u64 checksum."""
import struct
import sys

try:
    d = open(sys.argv[1], "rb").read()
    n = struct.unpack_from("<H", d, 16)[0]
    at = 18 + n + 8
    runs = struct.unpack_from("<Q", d, at)[0]
    done = sum(struct.unpack_from("<QQQ", d, at + 8 + 24 * i)[1] for i in range(runs))
    owners = struct.unpack_from("<%dh" % done, d, len(d) - 8 - 2 * done)
    sys.exit(0 if int(sys.argv[2]) in owners else 1)
except Exception:
    sys.exit(1)
