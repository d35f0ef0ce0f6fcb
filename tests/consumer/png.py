#!/usr/bin/env python3
"""Writes an RGB PNG of W x H whose texels depend on SEED, with Python's standard library only (for texture edits in
the build-system tests). It tiles, as a texture hexc hex-tiles must (its waves have whole periods across the image,
so hexc's seam check, HX132, stays silent):
    png.py FILE W H SEED"""
import math
import struct
import sys
import zlib

file, w, h, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])


def texel(x, y, c):
    u = 2 * math.pi * ((c + 1) * x / w + seed / 7)
    v = 2 * math.pi * (2 * y / h + seed / 5 + c / 3)
    return round(127.5 + 60 * math.sin(u) + 60 * math.cos(v))


rows = b"".join(b"\0" + bytes(texel(x, y, c) for x in range(w) for c in range(3)) for y in range(h))


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


png = chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b"")
open(file, "wb").write(b"\x89PNG\r\n\x1a\n" + png)
