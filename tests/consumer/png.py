#!/usr/bin/env python3
"""Writes an RGB PNG of W x H whose texels depend on SEED, with Python's standard library only (for texture edits in
the build-system tests):
    png.py FILE W H SEED"""
import struct
import sys
import zlib

file, w, h, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
rows = b"".join(b"\0" + bytes((x * 7 + y * 3 + seed * (c + 1)) % 256 for x in range(w) for c in range(3)) for y in range(h))


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


png = chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b"")
open(file, "wb").write(b"\x89PNG\r\n\x1a\n" + png)
