"""hexc's `threejs-webgpu` package drawn by three.js's WebGPURenderer (its node system, WGSL) in headless Chromium's
WebGPU (Dawn on SwiftShader), every frame with a red marker three.js draws at the screen's top-left, read back from the
canvas's texture as it holds it (compiler/integrations/threejs/test/webgpu.js), and judged with engine_check.py, as the
Godot and Filament tests judge theirs:

- value views: each function of the probe (plain-tiled: the F upright; and hex-tiled with a DirectX map), of rock and
  of the layered material (three layers under a splat map) shown unlit on a square with three.js's own uv ((0, 0) at the
  bottom-left), against `hexc render`'s fp64 reference within engine_check's bound (a layered role's: layered_errors,
  which also holds the image against the reference flipped in u and in v: both must be over it), and of the same
  layers weighed by the vertex colour on a square whose corners carry engine_check.VERTEX_COLORS; on a square without
  colours, the same layers draw what white corners draw (three.js's vertexColor() is white there), and not what
  black ones do;
- lit: the probe's bumps under a three.js DirectionalLight from the right and from the top, 15 of 15 lit from the
  light's side, for a green-up and a DirectX map;
- negative controls, which must fail: the textures uploaded with three.js's default flipY (v flipped), a mesh whose u
  runs right to left (u mirrored), a mesh with glTF's uv (v down), a layer's texture swapped for another's, the
  vertex colours' red and green exchanged, and the bumps lit with the textures flipped.

Usage: webgpu_test.py HEXC [--screenshot PNG]   (from the source root, after `npm ci --prefix tests/node`; the terrain's
screenshot goes beside PNG, <PNG without .png>-terrain.png)
"""
import base64
import functools
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from web_support import NODE_MODULES, WEBGPU_FLAGS, FileServer, Page  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "compiler", "integrations"))
import engine_check as ec  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
SIZE = 128
MARKER = int(SIZE * ec.MARKER_FRACTION)
# three.js's WebGPURenderer draws the scene into a half-float target (outputBufferType HalfFloatType) and converts it to
# the canvas's sRGB in an output pass: 11 bits of mantissa, so a value is kept within 2^-11 of itself.
HALF_FLOAT = 2 ** -11
LIGHTS = {"right": [1, 0, 0.5], "top": [0, 1, 0.5]}


class Run:
    """hexc's packages served to one page of headless Chromium with three.js's WebGPU driver."""

    def __init__(self, hexc, work):
        self.hexc, self.work = hexc, work
        # naga for the WGSL: built in, or else tests/node's naga-wasm in Node.js (docs/cli.md, "WGSL").
        self.env = {**os.environ, "HEXC_NODE_PATH": os.environ.get("HEXC_NODE_PATH") or os.path.abspath(NODE_MODULES)}
        self.server = FileServer(work)
        self.page = Page(self.server, "threejs&driver=webgpu", WEBGPU_FLAGS)

    def close(self):
        self.page.quit()
        self.server.stop()

    @functools.lru_cache(maxsize=None)  # a package is written once for every view of it
    def package(self, material, bottom_left=False):
        out = self.work / "pkg" / (Path(material).stem + ("_bl" if bottom_left else ""))
        subprocess.run([self.hexc, str(material), "--engine", "threejs-webgpu", "-q", "--no-cache", "-o", str(out)] +
                       (["--uv-bottom-left"] if bottom_left else []), check=True, env=self.env)
        return out / "threejs-webgpu"

    def draw(self, name, pkg, size=SIZE, **config):
        """The canvas of the driver's render of `pkg` as a PNG (rows as the canvas holds them), and three.js's errors."""
        module = "/pkg/" + str(pkg.relative_to(self.work)) + "/" + next(pkg.glob("*.three-webgpu.js")).name
        result = self.page.run(module=module, width=size, height=size, **{"marker": MARKER, **config})
        data = base64.b64decode(result["pixels"])
        out = self.work / f"{name}.png"
        ec.write_png(out, size, size, lambda x, y: data[(y * size + x) * 4:(y * size + x) * 4 + 3])
        return out, json.loads(result["errors"])


def three_uv(rect):
    """The square's uv in three.js's convention (v up) [u0, v at the top, u1, v at the bottom] that shows hexc's uv
    rectangle `rect` (v down, the top-left package): the package takes v = 1 - three.js's v."""
    u0, v0, u1, v1 = rect
    return [u0, 1 - v0, u1, 1 - v1]


def value(run, material, f, control=None, name=None, **config):
    """The verdict on `f`'s unlit view of `material`'s package (engine_check.value_verdict); True if it failed."""
    pkg = run.package(material)
    rect = ec.rect_for(ec.manifest(pkg), SIZE)
    out, errors = run.draw(name or f"{Path(material).stem}_{f['name']}", pkg, view=f["name"], **{"uv": three_uv(rect), **config})
    view = {"package": pkg, "origin": "top-left", "size": SIZE, "rect": rect, "relative": HALF_FLOAT, "encode": ec.srgb}
    return ec.value_verdict(run.hexc, material, f, out, view, control, errors)


def shown_functions(pkg):
    """The package's functions a user shows: all but the normal slots' height derivatives (their normals are shown)."""
    return [f for f in ec.manifest(pkg)["functions"] if f["returns"] != "vec2"]


def draw(run):
    """The drawn materials' value views and the probe's bumps lit; the failed checks."""
    probe_gl, probe_dx = ec.probe_material(run.work / "probe"), ec.probe_material(run.work / "probe", "dx", True)
    failed = 0
    for material in (probe_gl, probe_dx, ROOT / "materials" / "rock.json", ec.layered_material(run.work / "layered")):
        for f in shown_functions(run.package(material)):
            failed += value(run, material, f)
    vertex = ec.layered_material(run.work / "layered", weights="vertex")
    for f in shown_functions(run.package(vertex)):
        failed += value(run, vertex, f, colors=ec.VERTEX_COLORS)
    for convention in ("gl", "dx"):
        bumps = ec.probe_material(run.work / "probe", convention, albedo=False)
        for side, light in LIGHTS.items():
            out, errors = run.draw(f"{bumps.stem}_{side}", run.package(bumps), uv=[0, 1, 1, 0], light=light)
            failed += ec.lit_verdict(out, f"probe bumps ({convention} map) on a three.js square", side, errors=errors)
    return failed


def largest_difference(a, b):
    """The largest difference of two PNGs' colour channels, in 8-bit steps."""
    (_, _, n, rows_a), (_, _, _, rows_b) = ec.read_png(a), ec.read_png(b)
    return max(abs(p - q) for ra, rb in zip(rows_a, rows_b) for i, (p, q) in enumerate(zip(ra, rb)) if i % n < 3)


def uncoloured(run):
    """The vertex-weighed layers' albedo on a square without colours: three.js's vertexColor() reads white where the
    geometry has no `color` (docs/engines.md, "A mesh without vertex colours"), so it draws what white corners draw,
    within one 8-bit step (the same shader on the same texels, the colour exactly 1 either way but for the
    interpolation's rounding, which can move a value across an 8-bit rounding boundary). Black corners (layer 0 alone)
    must not pass the same check: the control."""
    vertex = ec.layered_material(run.work / "layered", weights="vertex")
    pkg = run.package(vertex)
    albedo = next(f for f in shown_functions(pkg) if f["role"] == "albedo")
    uv = three_uv(ec.rect_for(ec.manifest(pkg), SIZE))
    drawn = {}
    for name, colors in (("none", None), ("white", [(1, 1, 1, 1)] * 4), ("black", [(0, 0, 0, 0)] * 4)):
        drawn[name], errors = run.draw(f"uncoloured_{name}", pkg, view=albedo["name"], uv=uv, **({"colors": colors} if colors else {}))
        if errors:
            return ec.row(f"layers weighed by the vertex colour, corners {name}", "; ".join(errors), False)
    same, control = largest_difference(drawn["none"], drawn["white"]), largest_difference(drawn["none"], drawn["black"])
    return (ec.row("layers weighed by the vertex colour on a square without colours, against white corners",
                   f"largest difference {same}/255, bound 1/255", same <= 1) +
            ec.row("control: the same against black corners (layer 0 alone)", f"largest difference {control}/255: "
                   + ("the check fails as it must" if control > 1 else "within the bound"), control > 1))


def controls(run):
    """Wrong variants a user could make, each of which the checks must fail; the checks that did not."""
    probe, layered = run.work / "probe" / "probe_gl.json", run.work / "layered" / "layered.json"
    albedo = next(f for f in ec.manifest(run.package(probe))["functions"] if f.get("slot") == "albedo")
    rect = three_uv(ec.rect_for(ec.manifest(run.package(probe)), SIZE))
    failed = 0
    for what, config in (("v flipped: the textures uploaded with three.js's default flipY", {"flipY": True}),
                         ("u mirrored: a mesh whose u runs right to left", {"uv": [rect[2], rect[1], rect[0], rect[3]]}),
                         ("v flipped: a mesh with glTF's uv (v down), as three.js's GLTFLoader keeps it",
                          {"uv": [rect[0], 1 - rect[1], rect[2], 1 - rect[3]]})):
        failed += value(run, probe, albedo, what, f"control_{failed}_{len(what)}", **config)
    pkg = run.package(layered)
    role = next(f for f in ec.manifest(pkg)["functions"] if f.get("role") == "albedo")
    failed += value(run, layered, role, "a layer swapped: moss's albedo bound in clay's place", "control_layer",
                    swap={"hexcTex_clay_albedo": "hexcTex_moss_albedo"})
    vertex = run.work / "layered" / "layered_vertex.json"
    failed += value(run, vertex, next(f for f in shown_functions(run.package(vertex)) if f["role"] == "albedo"),
                    "a vertex colour channel swapped: the square's red and green exchanged", "control_vertex",
                    colors=ec.VERTEX_COLORS_SWAPPED)
    bumps = run.work / "probe" / "probe_gl_bumps.json"
    out, _ = run.draw("control_bumps", run.package(bumps), uv=[0, 1, 1, 0], light=LIGHTS["top"], flipY=True)
    failed += ec.lit_verdict(out, "v flipped: the bumps uploaded with three.js's default flipY", "top", control=True)
    return failed


def screenshot(run, path):
    """The rock, and the terrain beside it (<PNG>-terrain.png), on a sphere, lit by three.js from the upper right, as the
    canvas shows it: for docs/engines.md."""
    failed = 0
    for name, material, png in (("rock", "rock.json", path), ("terrain", "terrain/terrain.json", path[:-4] + "-terrain.png")):
        out, errors = run.draw("screenshot_" + name, run.package(ROOT / "materials" / material, bottom_left=True), 192, sphere=True,
                               light=[1, 1, 1.5], marker=0)
        shutil.copyfile(out, png)
        failed += ec.row(f"screenshot: {name} on a lit sphere", "; ".join(errors) or "no error", not errors)
    return failed


def main(argv):
    hexc = os.path.abspath(argv[1])
    shot = os.path.abspath(argv[argv.index("--screenshot") + 1]) if "--screenshot" in argv else None
    work = Path(tempfile.mkdtemp(prefix="hexc-webgpu-"))
    start = time.monotonic()
    run = Run(hexc, work)
    try:
        print("| check | figure | result |\n|---|---|---|")
        failed = draw(run) + uncoloured(run) + controls(run) + (screenshot(run, shot) if shot else 0)
    finally:
        run.close()
        shutil.rmtree(work, ignore_errors=True)
    print(f"three.js WebGPU: {'FAIL' if failed else 'pass'} in {time.monotonic() - start:.1f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
