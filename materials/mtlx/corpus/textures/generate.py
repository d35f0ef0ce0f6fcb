#!/usr/bin/env python3
"""Writes the corpus's stand-in textures (materials/mtlx/corpus/*.mtlx read them): small, odd-sized and
non-square, so that nothing in a document's reading depends on the examples' 256x256 maps. Deterministic:
run it again and the files do not change.  python3 generate.py [OUTDIR]"""
import math
import struct
import sys
import zlib
from pathlib import Path


def png(path, width, height, channels, pixel):
    rows = b"".join(b"\0" + bytes(v for x in range(width) for v in pixel(x, y)) for y in range(height))
    color_type = {1: 0, 3: 2, 4: 6}[channels]

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", width, height, 8, color_type, 0, 0, 0)
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def wave(x, y, w, h, fx, fy):
    return 0.5 + 0.5 * math.sin(2 * math.pi * (fx * x / w + fy * y / h))


def main():
    out = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).parent)
    # Colour: three waves of different directions, so that every channel varies.
    png(out / "stone_color.png", 37, 23, 3, lambda x, y: [round(255 * wave(x, y, 37, 23, a, b)) for a, b in ((1, 0), (0, 1), (1, 1))])
    # Packed data, glTF's layout: occlusion in r, roughness in g, metalness in b.
    png(out / "stone_orm.png", 29, 41, 3, lambda x, y: [round(255 * wave(x, y, 29, 41, a, b)) for a, b in ((2, 1), (1, 2), (1, -1))])
    # A tangent-space normal map of the height sin(2 pi (x/w + y/h)), whose slopes are not zero on average per axis.
    def normal(x, y, w=31, h=19):
        gx = math.cos(2 * math.pi * (x / w + y / h)) * 0.5
        n = (-gx, -gx, 1.0)
        length = math.sqrt(sum(c * c for c in n))
        return [round(255 * (0.5 + 0.5 * c / length)) for c in n]
    png(out / "stone_normal.png", 31, 19, 3, normal)
    png(out / "stone_gray.png", 17, 13, 1, lambda x, y: [round(255 * wave(x, y, 17, 13, 1, 1))])


if __name__ == "__main__":
    main()
