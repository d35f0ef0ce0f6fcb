#!/usr/bin/env python3
"""The Godot 3 engine test (CTest label `engine`): hexc writes the Godot 3 package of each material given and of
engine_check.py's mixed material (non-square textures, a DirectX normal map, packed slots) and layered material
(three layers on a painted splat map: a flipped u or v must fail), at both uv origins; Godot 3 (Debian's godot3, GLES3 on llvmpipe, under xvfb-run) renders each slot's value through the package's
functions, unlit, which must match hexc's fp64 reference within the bound derived in engine_check.py; and the
package's own shader, lit by Godot, shows a dome normal map lit from the light's side.
    check.py HEXC WORKDIR MATERIAL.json ..."""
import json
import shutil
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import engine_check as ec  # noqa: E402

SIZE = 256
# Godot 3 renders 3D into a half-float buffer (rendering/quality/depth/hdr, on by default) before its sRGB output:
# 11 bits of mantissa, so a value is kept within 2^-11 of itself.
HDR_BUFFER = 2 ** -11
ORIGINS = {"top-left": [], "bottom-left": ["--uv-bottom-left"]}


def package(hexc, material, work, origin):
    out = work / Path(material).stem / origin
    subprocess.run([hexc, str(material), "--engine", "godot3", "-q", "--no-cache", "-o", str(out), *ORIGINS[origin]], check=True)
    return out / "godot3"


def textures(material, pkg, manifest):
    """uniform -> the file Godot loads and whether it is sRGB, from the manifest."""
    files = {s["name"]: (pkg / s["texture"], s.get("colorspace") == "srgb") for s in manifest["slots"]}
    for p in manifest.get("packed_textures", []):
        files[p["name"]] = (pkg / p["file"], p["colorspace"] == "srgb")
    return {where["uniform"]: {"path": str(files[name][0].resolve()), "srgb": files[name][1]}
            for name, where in manifest["targets"]["glsl"]["textures"].items()}


def value_shader(shader, function, returns, rect, origin):
    """The package's shader, unshaded, showing `function` at the image point the reference shows."""
    head = shader[:shader.index("void fragment()")].replace("shader_type spatial;", "shader_type spatial;\nrender_mode unshaded;", 1)
    u0, v0, u1, v1 = rect
    uv = f"vec2({u0}, {v0}) + UV * vec2({u1 - u0}, {v1 - v0})"
    if origin == "bottom-left":  # the engine's uv of that image point: (u, 1 - v)
        uv = f"vec2(({uv}).x, 1.0 - ({uv}).y)"
    show = {"vec4": "{}.rgb", "float": "vec3({})", "vec3": "{} * 0.5 + 0.5"}[returns].format(f"{function}({uv})")
    return head + "void fragment() {\n    ALBEDO = " + show + ";\n}\n"


def rect_for(manifest):
    """A uv rectangle the size of which puts about 0.7 texels on a pixel: every fetch is from the full-resolution level
    (lod < 0), so the comparison does not depend on how the engine makes mip levels."""
    texels = max(s["hextiling"]["tiling"][i] * s["size"][i] for s in manifest["slots"] for i in (0, 1))
    side = min(1.0, 0.7 * SIZE / texels)
    return [0.0, 0.0, side, side]


def render(project, jobs):
    (project / "job.json").write_text(json.dumps({"jobs": jobs}))
    run = subprocess.run(["xvfb-run", "-a", "godot3", "--path", str(project)], capture_output=True, text=True, timeout=300)
    errors = [line for line in (run.stdout + run.stderr).splitlines() if "SHADER ERROR" in line or "HEXC-ERROR" in line]
    if errors or any(not Path(j["out"]).exists() for j in jobs):
        sys.exit("FAIL Godot did not render:\n" + "\n".join(errors or (run.stdout + run.stderr).splitlines()[-20:]))


def main(argv):
    hexc, work, materials = argv[1], Path(argv[2]), argv[3:]
    shutil.rmtree(work, ignore_errors=True)
    project = work / "project"
    shutil.copytree(Path(__file__).parent / "project", project)
    materials = materials + [ec.mixed_material(work / "mixed"), ec.layered_material(work / "layered")]
    start = time.monotonic()
    jobs, checks = [], []
    dome = ec.dome_material(work / "dome")
    for material in materials:
        for origin in ORIGINS:
            pkg = package(hexc, material, work, origin)
            manifest = ec.manifest(pkg)
            shader = next(pkg.glob("*.shader")).read_text()
            rect = rect_for(manifest)
            if origin == "top-left":  # the package as a user loads it, lit by Godot: docs/engines.md's screenshot
                jobs.append({"shader": str(next(pkg.glob("*.shader"))), "textures": textures(material, pkg, manifest),
                             "out": str(work / f"{Path(material).stem}_lit.png"), "light": [0.4, 0.4, 0.8]})
            for f in manifest["functions"]:
                if f["returns"] == "vec2":
                    continue  # the derivative: its normal function is checked
                view = pkg / (f["name"] + ".shader")
                view.write_text(value_shader(shader, f["name"], f["returns"], rect, origin))
                out = pkg / (f["name"] + ".png")
                jobs.append({"shader": str(view), "textures": textures(material, pkg, manifest), "out": str(out)})
                checks.append((material, origin, f, rect, out))
    for origin in ORIGINS:
        pkg = package(hexc, dome, work, origin)
        manifest = ec.manifest(pkg)
        shader = next(pkg.glob("*.shader")).read_text()
        if origin == "bottom-left":  # a GL-convention mesh: its uv of the image point UV is (u, 1 - v)
            shader = shader.replace("(UV)", "(vec2(UV.x, 1.0 - UV.y))")
        (pkg / "dome_lit.shader").write_text(shader)
        for side, light in {"right": [1, 0, 0.5], "top": [0, 1, 0.5]}.items():
            out = pkg / f"dome_{side}.png"
            jobs.append({"shader": str(pkg / "dome_lit.shader"), "textures": textures(dome, pkg, manifest),
                         "out": str(out), "light": light})
            checks.append((None, origin, side, None, out))
    render(project, jobs)
    failed = 0
    print("| material | uv origin | function | mean error (8-bit) | max error | max / bound |")
    print("|---|---|---|---|---|---|")
    for material, origin, f, rect, out in checks:
        if material is None:
            q = ec.quadrant_means(out)
            opposite = {"right": "left", "top": "bottom"}[f]
            ok = q[f] > q[opposite] + 20
            failed += not ok
            print(f"| dome | {origin} | lit from the {f} | {f} side {q[f]:.0f}, {opposite} side {q[opposite]:.0f} | | {'ok' if ok else 'FAIL'} |")
            continue
        r = ec.check_function(hexc, material, ec.manifest(out.parent), f, SIZE, rect, out, HDR_BUFFER)
        row, bad = ec.result_row(material, origin, f, r)
        failed += bad
        print(row, flush=True)
    print(f"Godot 3: {len(jobs)} renders and their checks in {time.monotonic() - start:.1f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
