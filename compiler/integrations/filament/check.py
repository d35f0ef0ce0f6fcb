#!/usr/bin/env python3
"""The Filament engine test (CTest label `engine`): hexc writes the Filament package of each material given and of
engine_check.py's mixed material (non-square textures, a DirectX normal map, packed slots), at both uv origins;
Filament's own compiler compiles each .mat (matc -a opengl -p desktop). hexc-filament-render (render.cpp) renders
with Filament's OpenGL backend, headless, under one Xvfb server: each function of the package unlit (a value view of the
.mat: shadingModel unlit, baseColor the function's value), against hexc's fp64 reference within the bound derived in
engine_check.py, and the package itself lit by a Filament directional light: a dome normal map lit from the light's
side. Post-processing is off: Filament then writes the linear value straight into the 8-bit swap chain (with it on,
its read-back under llvmpipe is not the frame).
    check.py HEXC RENDERER WORKDIR MATERIAL.json ..."""
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import engine_check as ec  # noqa: E402

SIZE = 256
ORIGINS = {"top-left": [], "bottom-left": ["--uv-bottom-left"]}


def package(hexc, material, work, origin):
    out = work / Path(material).stem / origin
    subprocess.run([hexc, str(material), "--engine", "filament", "-q", "--no-cache", "-o", str(out), *ORIGINS[origin]], check=True)
    pkg = out / "filament"
    return pkg, next(pkg.glob("*.mat"))


def matc(mat):
    filamat = mat.with_suffix(".filamat")
    run = subprocess.run(["matc", "-a", "opengl", "-p", "desktop", "-o", str(filamat), str(mat)], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"FAIL matc {mat}:\n{run.stdout[-3000:]}{run.stderr[-3000:]}")
    return filamat


def texture_args(material, pkg, manifest):
    files = {s["name"]: (pkg / s["texture"], s.get("colorspace") == "srgb") for s in manifest["slots"]}
    for p in manifest.get("packed_textures", []):
        files[p["name"]] = (pkg / p["file"], p["colorspace"] == "srgb")
    return [f"{w['uniform']}={files[n][0].resolve()}{':srgb' if files[n][1] else ''}" for n, w in manifest["targets"]["glsl"]["textures"].items()]


def render(renderer, filamat, out, textures, *options):
    run = subprocess.run([renderer, str(filamat), str(out), str(SIZE), "--no-post", *options, *textures],
                         capture_output=True, text=True, timeout=300, env=ENV)
    if run.returncode != 0:
        sys.exit(f"FAIL Filament did not render {filamat}:\n{run.stdout[-2000:]}{run.stderr[-2000:]}")


def value_material(mat_text, functions, rect, origin):
    """The package's .mat, unlit, showing function number materialParams.hexcShow at the image point the reference
    shows (one matc run for all of a package's functions)."""
    u0, v0, u1, v1 = rect
    uv = f"vec2({u0}, {v0}) + getUV0() * vec2({u1 - u0}, {v1 - v0})"
    if origin == "bottom-left":  # the engine's uv of that image point: (u, 1 - v)
        uv = f"vec2(({uv}).x, 1.0 - ({uv}).y)"
    shows = ""
    for i, f in enumerate(functions):
        value = {"vec4": "{}.rgb", "float": "vec3({})", "vec3": "{} * 0.5 + 0.5"}[f["returns"]].format(f"{f['name']}(uv)")
        shows += f"        if (materialParams.hexcShow == {i}) material.baseColor = vec4({value}, 1.0);\n"
    head = mat_text[:mat_text.index("    void material(")]
    head = head.replace("shadingModel : lit", "shadingModel : unlit").replace("parameters : [", "parameters : [\n        { type : int, name : hexcShow },", 1)
    return head + "    void material(inout MaterialInputs material) {\n        vec2 uv = " + uv + ";\n        prepareMaterial(material);\n" + shows + "    }\n}\n"


ENV = dict(os.environ)


def main(argv):
    # One X server for every render (xvfb-run would start one per render, a few seconds each), stopped at the end.
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", "1", "-screen", "0", "640x480x24", "-nolisten", "tcp"], stdout=subprocess.PIPE, text=True)
    try:
        ENV["DISPLAY"] = ":" + xvfb.stdout.readline().strip()
        return check(argv)
    finally:
        xvfb.terminate()
        xvfb.wait()


def check(argv):
    hexc, renderer, work, materials = argv[1], argv[2], Path(argv[3]), argv[4:]
    shutil.rmtree(work, ignore_errors=True)
    materials = materials + [ec.mixed_material(work / "mixed"), ec.layered_material(work / "layered")]
    start, failed = time.monotonic(), 0
    print("| material | uv origin | function | mean error (8-bit) | max error | max / bound |")
    print("|---|---|---|---|---|---|")
    for material in materials:
        for origin in ORIGINS:
            pkg, mat = package(hexc, material, work, origin)
            manifest = ec.manifest(pkg)
            textures = texture_args(material, pkg, manifest)
            lit = matc(mat)
            if origin == "top-left":  # the package as a user loads it, lit by Filament: docs/engines.md's screenshot
                render(renderer, lit, work / f"{Path(material).stem}_lit.png", textures, "--light", "0.4,0.4,0.8")
            functions = [f for f in manifest["functions"] if f["returns"] != "vec2"]  # a derivative: its normal is shown
            rect = [0.0, 0.0] + [min(1.0, 0.7 * SIZE / max(s["hextiling"]["tiling"][i] * s["size"][i] for s in manifest["slots"] for i in (0, 1)))] * 2
            view = pkg / "values.mat"
            view.write_text(value_material(mat.read_text(), functions, rect, origin))
            values = matc(view)
            for i, f in enumerate(functions):
                out = pkg / f"{f['name']}.png"
                render(renderer, values, out, textures, "--int", f"hexcShow={i}")
                r = ec.check_function(hexc, material, manifest, f, SIZE, rect, out, 0.0, ec.linear)
                row, bad = ec.result_row(material, origin, f, r)
                failed += bad
                print(row, flush=True)
    dome = ec.dome_material(work / "dome")
    for origin in ORIGINS:
        pkg, mat = package(hexc, dome, work, origin)
        if origin == "bottom-left":  # a GL-convention mesh: its uv of the image point is (u, 1 - v)
            mat.write_text(mat.read_text().replace("vec2 uv = getUV0();", "vec2 uv = vec2(getUV0().x, 1.0 - getUV0().y);"))
        filamat = matc(mat)
        for side, light in {"right": "1,0,0.5", "top": "0,1,0.5"}.items():
            out = pkg / f"dome_{side}.png"
            render(renderer, filamat, out, texture_args(dome, pkg, ec.manifest(pkg)), "--light", light)
            q = ec.quadrant_means(out)
            opposite = {"right": "left", "top": "bottom"}[side]
            ok = q[side] > q[opposite] + 20
            failed += not ok
            print(f"| dome | {origin} | lit from the {side} | {side} side {q[side]:.0f}, {opposite} side {q[opposite]:.0f} | | {'ok' if ok else 'FAIL'} |")
    print(f"Filament: packages compiled by matc and rendered in {time.monotonic() - start:.1f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
