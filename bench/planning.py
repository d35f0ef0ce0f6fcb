#!/usr/bin/env python3
"""Planning time and peak memory of large inputs: `hexc --list-outputs` (read, check, plan: nothing compiled) of a
scene of 1,000 and 10,000 variants and of a MaterialX document of 10,000 materials. It measures and never fails.

    python3 bench/planning.py build/hexc [--sizes 1000,10000] [--materials 10000]

Each row: the variants (or materials), the wall and processor time and the peak resident memory of the child,
from wait4's resource usage. Run from the source root; the inputs are generated in a temporary folder.
"""
import argparse
import os
import pathlib
import re
import subprocess
import tempfile
import time

ROCK_MTLX = pathlib.Path("materials/mtlx/rock.mtlx")


def scene(folder, variants):
    """A scene of `variants` variants: variants/4 copies of rock.json (each its own name) under 4 passes."""
    textures = pathlib.Path("materials/textures").resolve()
    rock = pathlib.Path("materials/rock.json").read_text().replace("textures/", str(textures) + "/")
    names = []
    for i in range(variants // 4):
        name = f"m{i}"
        (folder / f"{name}.json").write_text(rock.replace('"name": "rock"', f'"name": "{name}"'))
        names.append(f'"{name}.json"')
    passes = '[{"name": "main"}, {"name": "depth", "template": "depth", "slots": []}, ' \
             '{"name": "shadow", "template": "shadow", "slots": ["albedo"]}, {"name": "weights", "template": "weights"}]'
    path = folder / "big.scene.json"
    path.write_text('{"scene": "big", "materials": [' + ", ".join(names) + '], "passes": ' + passes + "}\n")
    return path


def materialx(folder, materials):
    """A MaterialX document of `materials` materials: rock.mtlx's graph, shader and material, each renamed."""
    text = ROCK_MTLX.read_text()
    body = text[text.index("<nodegraph"):text.index("</materialx>")]
    prefix = str(ROCK_MTLX.parent.resolve() / "../textures") + "/"
    body = body.replace('fileprefix="../textures/"', f'fileprefix="{prefix}"')
    parts = ['<?xml version="1.0"?>\n<materialx version="1.39" colorspace="lin_rec709">\n']
    for i in range(materials):
        parts.append(re.sub(r'(name|nodegraph|nodename)="(NG_rock|SR_rock|rock)"', rf'\1="\2_{i}"', body))
    parts.append("</materialx>\n")
    path = folder / "big.mtlx"
    path.write_text("".join(parts))
    return path


def measure(hexc, path, out):
    start = time.monotonic()
    child = subprocess.Popen([hexc, str(path), "-o", str(out), "--list-outputs"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    listing = child.stdout.read()
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.monotonic() - start
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"hexc failed on {path}: {child.stderr.read().decode()[:400]}")
    outputs = listing.count(b'"' + str(out).encode())
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024, outputs


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("hexc")
    parser.add_argument("--sizes", default="1000,10000", help="scene variants, comma-separated")
    parser.add_argument("--materials", default="10000", help="MaterialX materials, comma-separated")
    args = parser.parse_args()
    print(f"{'input':<34} {'wall s':>8} {'cpu s':>8} {'peak MiB':>9} {'outputs':>8}")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        cases = [(f"scene of {n} variants", scene, n) for n in map(int, args.sizes.split(",") if args.sizes else [])]
        cases += [(f"MaterialX, {n} materials", materialx, n) for n in map(int, args.materials.split(",") if args.materials else [])]
        for label, make, n in cases:
            folder = tmp / f"{make.__name__}{n}"
            folder.mkdir()
            wall, cpu, peak, outputs = measure(os.path.abspath(args.hexc), make(folder, n), folder / "out")
            print(f"{label:<34} {wall:8.2f} {cpu:8.2f} {peak:9.0f} {outputs:8d}", flush=True)


if __name__ == "__main__":
    main()
