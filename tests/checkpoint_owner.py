#!/usr/bin/env python3
"""Exits 0 once the checkpoint CK holds a pixel that worker W rendered, 1 if it does not
within SECONDS (default 0: looked at once), or as soon as process PID, when given, has ended:
how the join tests know a joiner has done some work before they kill it.

    checkpoint_owner.py CK W [SECONDS [PID]]

Reads the layout of src/farm/checkpoint.h: "PRTCKPT1", the u64 key, the u16-length
description, i32 width and height, the done set as runs (u64 count, then first/count/stride
u64 triples), the colours, an i16 owner per done pixel, and a trailing u64 checksum. A file
that is missing or being written counts as holding nothing yet."""
import os
import struct
import sys
import time


def rendered_by(path, worker):
    try:
        d = open(path, "rb").read()
        n = struct.unpack_from("<H", d, 16)[0]
        at = 18 + n + 8
        runs = struct.unpack_from("<Q", d, at)[0]
        done = sum(struct.unpack_from("<QQQ", d, at + 8 + 24 * i)[1] for i in range(runs))
        owners = struct.unpack_from("<%dh" % done, d, len(d) - 8 - 2 * done)
        return worker in owners
    except Exception:
        return False


def alive(pid):
    try:
        os.kill(pid, 0)
        return True
    except ProcessLookupError:
        return False
    except PermissionError:
        return True


path, worker = sys.argv[1], int(sys.argv[2])
deadline = time.monotonic() + (float(sys.argv[3]) if len(sys.argv) > 3 else 0)
pid = int(sys.argv[4]) if len(sys.argv) > 4 else None
while True:
    if rendered_by(path, worker):
        sys.exit(0)
    if time.monotonic() >= deadline or (pid is not None and not alive(pid)):
        sys.exit(1)
    time.sleep(0.1)
