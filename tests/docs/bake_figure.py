#!/usr/bin/python3
"""Makes docs/bake-rock.png (docs/cli.md#hexc-bake): the rock albedo repeated 12 x 12 beside its bake (K = 4) repeated
3 x 3, the same area of surface at the same scale, so that the source's repetition and the bake's lack of it show.

    /usr/bin/python3 tests/docs/bake_figure.py HEXC     (from the source root; needs Pillow, Debian's python3-pil)
"""
import os
import subprocess
import sys
import tempfile

from PIL import Image

CELL = 64  # pixels per repeat of the source texture in the figure


def main():
    hexc = sys.argv[1]
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([hexc, "bake", "materials/rock.json", "-q", "--size", str(4 * CELL), "-o", out], check=True)
        bake = Image.open(os.path.join(out, "rock.albedo.png")).convert("RGB")
        source = Image.open("materials/textures/rock_albedo.png").convert("RGB").resize((CELL, CELL), Image.BOX)
        side = 12 * CELL
        figure = Image.new("RGB", (2 * side + 16, side), (255, 255, 255))
        for i in range(12):
            for j in range(12):
                figure.paste(source, (i * CELL, j * CELL))
        for i in range(3):
            for j in range(3):
                figure.paste(bake, (side + 16 + i * bake.width, j * bake.height))
        figure.save("docs/bake-rock.png", optimize=True)


if __name__ == "__main__":
    main()
