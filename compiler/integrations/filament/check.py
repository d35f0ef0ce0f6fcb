#!/usr/bin/env python3
"""The Filament engine test (CTest label `engine`): Filament 1.9's own compiler (matc -a opengl -p desktop) and
renderer (hexc-filament-render, render.cpp: the OpenGL backend, headless, under one Xvfb server), every frame with a
red marker Filament draws over the screen's top-left corner (marker.mat, a second renderable):

- the matrix: the Filament package of every material under materials/ (engine_check.matrix_materials) compiled by
  matc, but the ones the docs say a package refuses (hexc must refuse them);
- drawn against hexc's fp64 reference (engine_check.drawn_materials, and at one origin the golden histogram material:
  its Gaussian textures and tables the package's OpenEXR files, loaded as float textures), at each uv origin docs/conventions.md gives
  for Filament, on a mesh with that convention: a GL-convention mesh (uv (0, 0) at the bottom-left, v up) with the
  package built with --uv-bottom-left, and a mesh with uv (0, 0) at the top-left (glTF's) with the package built
  without it. Each function is shown unlit (a value view: the package's .mat with shadingModel unlit and baseColor
  the function's value, one matc run per package), within the bound derived in engine_check.py; the probe's bumps
  lit by a Filament directional light from the right and from the top: 15 of 15 lit from the light's side; the
  layered material weighed by the vertex colour (engine_check.layered_material(weights="vertex")) on a mesh whose corners
  carry engine_check.VERTEX_COLORS, which its functions read with getColor();
- negative controls, which must fail: the package built for the other uv origin, a mesh mirrored in u, the normal
  map of the other green convention, the albedo decoded twice, a NaN value; the layered material with two layers'
  textures exchanged and with a splat channel swapped; the histogram slot's own texture bound in place of its
  Gaussian texture; the vertex-weighed one with the mesh's red and green vertex
  colour channels exchanged.

Post-processing is off: Filament then writes the linear value straight into the 8-bit swap chain (with it on, its
read-back under llvmpipe is not the frame). The frame is used as readPixels returns it (top row first, Renderer.h),
and every image must show the marker at its top-left.
    check.py HEXC RENDERER WORKDIR"""
import functools
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import engine_check as ec  # noqa: E402

ROOT = Path(__file__).resolve().parents[3]
SIZE = 256
ORIGINS = {"top-left": [], "bottom-left": ["--uv-bottom-left"]}
# The variants matc leaves out of the harness's own materials (the marker, the value views) and of the matrix's
# compile-only packages: hexc's functions are the same text in every variant, and a package compiled with all its
# variants costs about 7 times the CPU. The lit packages drawn are compiled as the docs say, with every variant.
FILTER = ["-V", "directionalLighting,dynamicLighting,shadowReceiver,skinning,vsm,fog"]
TOP = "0,1,0.5"
LIGHTS = {"right": "1,0,0.5", "top": TOP}
RUN = {"env": dict(os.environ)}  # the Xvfb display and the compiled marker, set by main()


@functools.lru_cache(maxsize=None)  # a package is written once, for the matrix and the checks that draw it
def package(hexc, material, work, origin):
    out = work / Path(material).stem / origin
    run = subprocess.run([hexc, str(material), "--engine", "filament", "-q", "--no-cache", "-o", str(out), *ORIGINS[origin]],
                         capture_output=True, text=True)
    return (out / "filament") if run.returncode == 0 else run.stderr


def matc(mat, *options):
    """The compiled package, or matc's complaint."""
    filamat = mat.with_suffix(".filamat")
    run = subprocess.run(["matc", "-a", "opengl", "-p", "desktop", *options, "-o", str(filamat), str(mat)], capture_output=True, text=True)
    return filamat if run.returncode == 0 else (run.stdout + run.stderr)[-3000:]


def texture_args(pkg, swap=None):
    """UNIFORM=FILE[:srgb] of each texture the manifest names (engine_check.package_textures)."""
    return [f"{u}={path}{':srgb' if srgb else ''}" for u, (path, srgb) in ec.package_textures(pkg, swap).items()]


def mesh_uv(rect, origin, mirror=False):
    """The uv at the quad's top-left and bottom-right corners that shows hexc's uv rectangle `rect` (top-left origin,
    v down) on a mesh of the uv `origin`: a GL-convention mesh's v runs up, so its uv there is (u, 1 - v)."""
    u0, v0, u1, v1 = rect if origin == "top-left" else (rect[0], 1 - rect[1], rect[2], 1 - rect[3])
    return ",".join(map(str, (u1, v0, u0, v1) if mirror else (u0, v0, u1, v1)))


def render(renderer, filamat, out, textures, uv, *options):
    run = subprocess.run([renderer, str(filamat), str(out), str(SIZE), "--no-post", "--marker", str(RUN["marker"]), "--uv", uv,
                          *options, *textures], capture_output=True, text=True, timeout=300, env=RUN["env"])
    if run.returncode != 0:
        sys.exit(f"FAIL Filament did not render {filamat}:\n{run.stdout[-2000:]}{run.stderr[-2000:]}")
    return out


def value_material(pkg, functions):
    """The package's .mat, unlit, showing function number materialParams.hexcShow at the mesh's uv; number
    len(functions) shows the first one times NaN (a negative control). One matc run for all of a package's functions."""
    mat = next(pkg.glob("*.mat"))
    text = mat.read_text()
    shows = ""
    for i, f in enumerate(functions + functions[:1]):
        args = "uv, getColor()" if f["parameters"] == "vec2 uv, vec4 color" else "uv"  # as the package's material() passes it
        value = {"vec4": "{}.rgb", "float": "vec3({})", "vec3": "{} * 0.5 + 0.5"}[f["returns"]].format(f"{f['name']}({args})")
        if i == len(functions):
            value = f"({value}) * intBitsToFloat(0x7fc00000)"  # a quiet NaN
        shows += f"        if (materialParams.hexcShow == {i}) material.baseColor = vec4({value}, 1.0);\n"
    head = text[:text.index("    void material(")]
    head = head.replace("shadingModel : lit", "shadingModel : unlit").replace("parameters : [", "parameters : [\n        { type : int, name : hexcShow },", 1)
    view = pkg.parent / "values.mat"  # beside the package, not in it
    view.write_text(head + "    void material(inout MaterialInputs material) {\n        vec2 uv = getUV0();\n        prepareMaterial(material);\n"
                    + shows + "    }\n}\n")
    return view


class Views:
    """Each drawn material's value view at each uv origin, compiled once."""

    def __init__(self, hexc, renderer, work):
        self.hexc, self.renderer, self.work, self.compiled, self.controls = hexc, renderer, work, {}, 0

    def get(self, material, origin):
        key = (str(material), origin)
        if key not in self.compiled:
            pkg = package(self.hexc, material, self.work, origin)
            functions = [f for f in ec.manifest(pkg)["functions"] if f["returns"] != "vec2"]  # a derivative: its normal is shown
            filamat = matc(value_material(pkg, functions), *FILTER)
            if not isinstance(filamat, Path):
                sys.exit(f"FAIL matc {pkg}/values.mat:\n{filamat}")
            self.compiled[key] = (pkg, functions, filamat, ec.rect_for(ec.manifest(pkg), SIZE))
        return self.compiled[key]

    def check(self, material, origin, mesh=None, control=None, function=0, swap=None, mirror=False, colors=None):
        """Renders function number `function` of the view of (material, origin) on a mesh of uv convention `mesh` (with
        the vertex `colors`, engine_check.VERTEX_COLORS' order)."""
        pkg, functions, filamat, rect = self.get(material, origin)
        f = functions[function % len(functions)]  # number len(functions): the first, times NaN
        self.controls += bool(control)
        name = f"{Path(material).stem}_{origin}_{mesh or origin}_{function}" + (f"_control{self.controls}" if control else "")
        colored = ["--colors", ",".join(str(c) for corner in colors for c in corner)] if colors else []
        out = render(self.renderer, filamat, self.work / f"{name}.png", texture_args(pkg, swap),
                     mesh_uv(rect, mesh or origin, mirror), "--int", f"hexcShow={function}", *colored)
        view = {"package": pkg, "origin": origin if not mesh else f"{origin} package on a {mesh} mesh", "size": SIZE, "rect": rect,
                "relative": 0.0, "encode": ec.linear}
        return ec.value_verdict(self.hexc, material, f, out, view, control)

    def all(self, material, origin):
        return sum(self.check(material, origin, function=i) for i in range(len(self.get(material, origin)[1])))


@functools.lru_cache(maxsize=None)  # a package drawn lit again (a negative control) is compiled once: 6 s with every variant
def lit_filamat(pkg):
    """The package's .mat compiled by matc as the docs say, with every variant."""
    filamat = matc(next(pkg.glob("*.mat")))
    if not isinstance(filamat, Path):
        sys.exit(f"FAIL matc {pkg}:\n{filamat}")
    return filamat


def lit(hexc, renderer, work, material, origin, mesh=None, swap=None, lights=LIGHTS):
    """The package as the docs say to build it for `origin`, lit from each of `lights`: side -> image, on a mesh of
    `mesh`'s uv convention (`origin`'s unless given)."""
    pkg = package(hexc, material, work, origin)
    filamat = lit_filamat(pkg)
    return {side: render(renderer, filamat, work / f"{material.stem}_{origin}_{mesh or origin}_{side}{'_swap' if swap else ''}.png",
                         texture_args(pkg, swap), mesh_uv([0, 0, 1, 1], mesh or origin), "--light", light)
            for side, light in lights.items()}


def matrix(hexc, work):
    """Every material's package (as for a GL-convention mesh, the docs' advice) compiled by matc; the refused ones
    refused by hexc."""
    failed = 0
    for material in ec.matrix_materials(ROOT):
        pkg = package(hexc, material, work, "bottom-left")
        if ec.refused(material, "filament"):
            failed += ec.row(f"matrix: {material.name} skipped", "refused by hexc, as the docs say: " + ec.refused(material, "filament"),
                             isinstance(pkg, str))
            continue
        compiled = matc(next(pkg.glob("*.mat")), *FILTER) if not isinstance(pkg, str) else pkg
        failed += ec.row(f"matrix: {material.name} compiled by matc", "compiled" if isinstance(compiled, Path) else compiled.strip(),
                         isinstance(compiled, Path))
    return failed


def check(hexc, renderer, work):
    failed = matrix(hexc, work)
    views, drawn = Views(hexc, renderer, work), ec.drawn_materials(ROOT, work)
    probe, bumps = drawn[4], ec.probe_material(work / "probe", "gl", albedo=False)
    histogram = ec.histogram_material(ROOT)
    for material in drawn + [histogram]:
        failed += views.all(material, "bottom-left")
    for material in (probe, drawn[5], drawn[3]):  # the probe, plain and hex-tiled with a DirectX map; the layered one
        failed += views.all(material, "top-left")
    for material, origin in ((bumps, "bottom-left"), (bumps, "top-left"), (ec.probe_material(work / "probe", "dx", albedo=False), "bottom-left")):
        for side, out in lit(hexc, renderer, work, material, origin).items():
            failed += ec.lit_verdict(out, f"{material.stem}, {origin}", side)
    for material in (probe, drawn[3], ROOT / "materials" / "terrain" / "terrain.json"):  # docs/engines.md's screenshots
        lit(hexc, renderer, work, material, "bottom-left", lights={"upper-right": "0.4,0.4,0.8"})
    decoded = ec.srgb_decoded_copy(work / "probe" / "probe_albedo.png", work / "probe" / "probe_albedo_decoded.png")
    failed += views.check(probe, "top-left", "bottom-left", "v flipped: the package built without --uv-bottom-left")
    failed += views.check(probe, "bottom-left", control="u mirrored: a mesh whose u runs right to left", mirror=True)
    failed += views.check(probe, "bottom-left", control="sRGB decoded twice: a linearised copy of the albedo bound as sRGB",
                              swap={"albedo": decoded})
    failed += views.check(probe, "bottom-left", control="a NaN value: the albedo function times NaN", function=2)
    for what, swap in ec.layered_controls(drawn[3].parent).items():  # the layered view's albedo role, function 0
        failed += views.check(drawn[3], "top-left", control=what, swap=swap)
    failed += views.check(histogram, "bottom-left", control="the histogram slot's own texture bound in place of its Gaussian texture",
                          swap={"albedo": ROOT / "materials" / "textures" / "rock_albedo.png"})
    vertex = ec.layered_material(drawn[3].parent, weights="vertex")  # its roles on a mesh of VERTEX_COLORS (getColor())
    failed += sum(views.check(vertex, "top-left", function=i, colors=ec.VERTEX_COLORS) for i in range(len(views.get(vertex, "top-left")[1])))
    failed += views.check(vertex, "top-left", control="a vertex colour channel swapped: the mesh's red and green exchanged",
                          colors=ec.VERTEX_COLORS_SWAPPED)
    flipped = lit(hexc, renderer, work, bumps, "top-left", mesh="bottom-left")["top"]
    failed += ec.lit_verdict(flipped, "v flipped: the bumps package built without --uv-bottom-left, on a GL mesh", "top", True)
    green = lit(hexc, renderer, work, bumps, "bottom-left", swap={"normal": work / "probe" / "probe_normal_dx.png"})["top"]
    failed += ec.lit_verdict(green, "green inverted: the DirectX map bound to the green-up slot", "top", True)
    return failed


def main(argv):
    hexc, renderer, work = argv[1], argv[2], Path(argv[3])
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    start = time.monotonic()
    shutil.copy(Path(__file__).parent / "marker.mat", work / "marker.mat")
    RUN["marker"] = matc(work / "marker.mat", *FILTER)
    # One X server for every render (xvfb-run would start one per render, a few seconds each), stopped at the end.
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", "1", "-screen", "0", "640x480x24", "-nolisten", "tcp"], stdout=subprocess.PIPE, text=True)
    try:
        RUN["env"]["DISPLAY"] = ":" + xvfb.stdout.readline().strip()
        print("| check | figure | result |\n|---|---|---|")
        failed = check(hexc, renderer, work)
    finally:
        xvfb.terminate()
        xvfb.wait()
    print(f"Filament: packages compiled by matc and rendered in {time.monotonic() - start:.1f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
