"""hexc's packages for the web engines (three.js, Babylon.js), run in headless Chromium (WebGL 2 on SwiftShader): the
probe (engine_check.py) drawn upright and lit from the light's side as the canvas's own PNG shows it, with an engine-drawn
marker at the screen's top-left, and each wrong variant a user can make failing that check; each slot's value through
the engine's own material input matches hexc's fp64 reference, and a dome normal map under a known light is lit from
the light's side, with the package written for either uv origin; a layered material's roles within engine_check.py's
layered bound per pixel, lit by the engine, its layers or splat channels swapped failing, and weighed by the vertex
colour (the engine's own, from the square's), its red and green channels swapped failing, and on a square without
vertex colours refused (three.js) or said to be drawn with WebGL's default colour (Babylon.js); every example compiles
in the engine; Babylon's package on its WebGPU engine (WGSL, Chromium's WebGPU on SwiftShader) draws what it draws on WebGL 2,
and its vertex-weighed albedo within the same bound.

Usage: web_test.py HEXC ENGINE [--screenshot PNG] [TEST ...]   (from the source root; ENGINE is threejs or babylon)
"""
import functools
import glob
import itertools
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from web_support import (E_S, NODE_MODULES, WEBGPU_FLAGS, FileServer, Page, blend_tolerance, read_pfm, srgb_to_linear,  # noqa: E402
                         texture_bounds, write_dome_normal_map, write_png)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "compiler", "integrations"))
import engine_check as ec  # noqa: E402

HEXC = ENGINE = SCREENSHOT = None
SERVER = PAGE = None
PACKAGES = None

# Rock's textures are 256^2 at tiling 4: 1024 texels per uv unit. 96 pixels over 96 * 0.75 / 1024 uv is 0.75 texel per
# pixel: magnified, every fetch reads mip level 0 only, so the mip chain the engine builds plays no part.
SIZE = 96
MODULE_SUFFIX = {"threejs": "three", "babylon": "babylon"}  # the package's module: <material>.<suffix>.js
ORIGINS = ("top-left", "bottom-left")


def package(material, origin):
    """The folder hexc writes `material`'s package for ENGINE into, for the given uv origin; its module's URL."""
    with open(material) as f:
        name = json.load(f)["name"]
    folder = os.path.join(PACKAGES, "%s-%s" % (name, origin))
    if not os.path.isdir(folder):
        origin_flag = ["--uv-bottom-left"] if origin == "bottom-left" else []
        subprocess.run([HEXC, material, "--engine", ENGINE, *origin_flag, "-o", folder, "-q"], check=True)
    return "/pkg/%s-%s/%s/%s.%s.js" % (name, origin, ENGINE, name, MODULE_SUFFIX[ENGINE])


def wgsl_package(material):
    """Babylon's top-left package of `material` with its WGSL form (`--targets wgsl`), for Babylon's WebGPU engine; its
    module's URL."""
    name = Path(material).stem
    folder = os.path.join(PACKAGES, "%s-top-left-wgsl" % name)
    if not os.path.isdir(folder):
        env = {**os.environ, "HEXC_NODE_PATH": os.environ.get("HEXC_NODE_PATH") or os.path.abspath(NODE_MODULES)}
        subprocess.run([HEXC, material, "--engine", ENGINE, "--targets", "wgsl", "-o", folder, "-q"], check=True, env=env)
    return "/pkg/%s-top-left-wgsl/%s/%s.%s.js" % (name, ENGINE, name, MODULE_SUFFIX[ENGINE])


def engine_uv(rect, origin):
    """The engine's uv (v up the image) at the top and bottom edges of hexc's uv rectangle [u0, v0, u1, v1] (v down the
    image): [u0, v at the top, u1, v at the bottom]. With the origin at the bottom-left hexc takes the engine's uv as it
    is and flips v itself (v_hexc = 1 - v); with the origin at the top-left the package does."""
    u0, v0, u1, v1 = rect
    return [u0, 1 - v0, u1, 1 - v1]


@functools.lru_cache(maxsize=None)  # the probe's variants share their references
def cached_reference(material, slot, output, rect, size):
    path = os.path.join(PACKAGES, "%s-%s-%s.pfm" % (os.path.basename(material), slot, output))
    subprocess.run([HEXC, "render", material, "--reference", "--output", output, "--slot", slot, "--size", "%dx%d" % size,
                    "--uv-rect", ",".join(map(str, rect)), "-o", path, "-q"], check=True)
    return read_pfm(path)[2]


def reference(material, slot, output, rect, size=(SIZE, SIZE)):
    """hexc's fp64 reference of `slot` over hexc's uv rectangle `rect`: rows top first of linear RGB."""
    return cached_reference(material, slot, output, tuple(rect), tuple(size))


def slot_of(material, name):
    with open(material) as f:
        doc = json.load(f)
    entry = next(s for s in doc["slots"] if s["name"] == name)
    texture = os.path.join(os.path.dirname(material), entry["texture"])
    srgb = entry.get("colorspace", "srgb" if entry["kind"] == "color" else "linear") == "srgb"
    return {**doc.get("hextiling", {}), **entry.get("hextiling", {})}, texture, srgb


def dome_material(folder):
    """One rotated, hex-tiled normal slot of a dome normal map (web_support.write_dome_normal_map)."""
    os.makedirs(os.path.join(folder, "textures"), exist_ok=True)
    write_dome_normal_map(os.path.join(folder, "textures", "dome_normal.png"))
    path = os.path.join(folder, "dome.json")
    with open(path, "w") as f:
        json.dump({"name": "dome", "hextiling": {"tiling": [2, 2], "rotation": 1.0},
                   "slots": [{"name": "normal", "texture": "textures/dome_normal.png", "kind": "normal"}]}, f)
    return path


def lit_material(folder):
    """Rock's albedo and a dome normal map at tiling 14, both magnified in the test's uv rectangle (0.07 uv: 72 of rock's
    texels and 63 of the dome's across 96 pixels), so that the light shows the domes on the rock."""
    os.makedirs(os.path.join(folder, "textures"), exist_ok=True)
    write_dome_normal_map(os.path.join(folder, "textures", "dome_normal.png"))
    path = os.path.join(folder, "lit.json")
    with open(path, "w") as f:
        json.dump({"name": "lit", "hextiling": {"tiling": [4, 4], "rotation": 1.0},
                   "slots": [{"name": "albedo", "texture": os.path.abspath("materials/textures/rock_albedo.png"), "kind": "color"},
                             {"name": "normal", "texture": "textures/dome_normal.png", "kind": "normal", "hextiling": {"tiling": [14, 14]}}]}, f)
    return path


def slot_tolerance(material, slot, output):
    """The bound on |engine - reference| of a slot's value on the canvas (linear, 8-bit), at mip level 0."""
    hex, texture, srgb = slot_of(material, slot)
    spread, max_deriv, min_z = texture_bounds(texture, srgb)
    # The canvas is RGBA8 and takes the linear value as it is: rounding to 8 bits adds at most 0.5/255.
    # Texture filtering as in hexc edit's page test (tests/edit/page_test.py): E_S per sample, through the
    # blend's weights by blend_tolerance (no blend without hex-tiling). SwiftShader and ANGLE filter as lavapipe does at
    # level 0, and an sRGB texture is decoded before filtering (three.js: SRGB8_ALPHA8; Babylon: useSRGBBuffer).
    blend = blend_tolerance if hex.get("enabled", True) else lambda ex, em, hex, spread: ex
    if output == "normal":
        # Listing 9's derivative d = -xy / z is off by at most ed = 2 E_S (1 + max|d|) / min z per texel, the
        # slope metric by sqrt(2) ed, the blend's samples spread by 2 max|d| per component. n = (-d, 1) / |(-d, 1)|
        # moves by at most |dd| (the normalisation's derivative has norm 1 / |(-d, 1)| <= 1), and |dd| <=
        # sqrt(2) times the per-component bound; the encoding n * 0.5 + 0.5 halves it. The engine's tangent frame
        # on this camera-facing square is exact to float32 rounding (T = +x, B = +y, N = +z).
        ed = 2 * E_S * (1 + max_deriv) / min_z
        return 0.5 * math.sqrt(2) * blend(ed, math.sqrt(2) * ed, hex, 2 * max_deriv) + 0.5 / 255
    return blend(E_S, E_S, hex, spread) + 0.5 / 255


# The probe (engine_check.probe_material) in absolute screen orientation: a canvas of the albedo's aspect at 2 pixels a
# texel (magnified: mip level 0 only), the square filling it with the engine's own uv (0, 0) at the bottom-left, and a
# red marker of MARKER pixels that the engine draws at the screen's top-left in the same frame.
PROBE_SIZE = (2 * ec.PROBE_ALBEDO[0], 2 * ec.PROBE_ALBEDO[1])
MARKER = 12
GL_UV = [0.0, 1.0, 1.0, 0.0]  # the square's uv [u0, v at the top, u1, v at the bottom]: three.js's and Babylon's own
# The wrong variants a user can make, and what the driver does for each: the package's textures uploaded with the
# engine's default row order, a mesh whose uv run right to left, a slot whose value is NaN (the other two, the green
# convention and an sRGB file decoded twice, are materials: probe_variants).
ENGINE_VARIANTS = {"flipped v (textures loaded with the engine's default flipY / invertY)": {"threejs": {"flipY": True}, "babylon": {"invertY": True}},
                   "mirrored u (a mesh with u running right to left)": {"uv": [1.0, 1.0, 0.0, 0.0]},
                   "flipped v (a mesh with glTF's uv, v down, as three.js's GLTFLoader keeps it)": {"uv": [0.0, 0.0, 1.0, 1.0]},
                   "a NaN slot": {"nan": True}}


def probe_variants(folder):
    """The probe materials: (name, material, the material meant, uv origin, engine options), the right ones first,
    then the wrong ones (with probe_check's `first_failure`)."""
    gl, dx = ec.probe_material(folder, "gl"), ec.probe_material(folder, "dx")
    with open(dx) as f:
        wrong_green = json.load(f)
    wrong_green["name"] = "probe_dx_declared_gl"  # the DirectX map without `flip_y`: the other green convention
    del wrong_green["slots"][1]["flip_y"]
    with open(gl) as f:
        twice = json.load(f)
    twice["name"] = "probe_srgb_twice"  # an albedo saved decoded (linear) and still declared sRGB: decoded twice
    twice["slots"][0]["texture"] = "probe_albedo_decoded.png"
    ec.write_png(os.path.join(folder, "probe_albedo_decoded.png"), *ec.PROBE_ALBEDO,
                 lambda x, y: tuple(round(255 * srgb_to_linear(c / 255)) for c in ec.probe_glyph(x, y)))
    written = []
    for doc in (wrong_green, twice):
        written.append(os.path.join(folder, doc["name"] + ".json"))
        with open(written[-1], "w") as f:
            json.dump(doc, f)
    gl, dx = str(gl), str(dx)
    right = [("GL normal map, %s package" % o, gl, gl, o, {}) for o in ORIGINS] + [("DX normal map, top-left package", dx, dx, "top-left", {})]
    # Each wrong one stops at the first view that fails it, but for the two that show every view failing it (the
    # flipped upload, the other green): so each part of the check is seen to fail.
    wrong = [(name, gl, gl, "top-left", options.get(ENGINE, options), i > 0) for i, (name, options) in enumerate(ENGINE_VARIANTS.items())]
    wrong += [("green inverted (a DirectX map declared green up)", written[0], dx, "top-left", {}, False),
              ("sRGB decoded twice (a decoded albedo declared sRGB)", written[1], gl, "top-left", {}, True)]
    return right, wrong


def normal_only(material):
    """The probe's normal slot alone (its albedo's glyph would outweigh the light on the bumps' sides)."""
    with open(material) as f:
        doc = json.load(f)
    doc["name"] += "_normal"
    doc["slots"] = [s for s in doc["slots"] if s["kind"] == "normal"]
    path = material.replace(".json", "_normal.json")
    with open(path, "w") as f:
        json.dump(doc, f)
    return path


def marker_shown(png):
    """Whether the marker is where the engine drew it, at the screen's top-left, and at no other corner."""
    w, h, n, rows = ec.read_png(png)
    def red(x0, y0):
        return all(rows[y][x * n] >= 250 and rows[y][x * n + 1] <= 5 and rows[y][x * n + 2] <= 5
                   for y in range(y0, y0 + MARKER) for x in range(x0, x0 + MARKER))
    return red(0, 0) and not any(red(x, y) for x, y in ((w - MARKER, 0), (0, h - MARKER), (w - MARKER, h - MARKER)))


def view_error(png, ref, tolerance, marker=MARKER):
    """(max error, values over `tolerance`) of the engine's screenshot against the reference, in 8-bit steps, outside
    the marker's square."""
    _, _, n, rows = ec.read_png(png)
    errors = [abs(rows[y][x * n + c] - 255 * ref[y][x][c]) for y in range(len(ref)) for x in range(len(ref[0]))
              for c in range(3) if x >= marker or y >= marker]
    return max(errors), sum(e > 255 * tolerance for e in errors)


def probe_check(name, material, meant, origin, options, first_failure=False):
    """`material`'s probe drawn by the engine, judged as the screen shows it: the albedo and the normal (value views,
    linear) against `hexc render` of the same view of the material `meant` (a user's wrong file is judged against what
    they meant, not against itself) within slot_tolerance, the marker at the top-left of each screenshot, and
    the normal map alone lit from the top-right by the engine's light: all 15 bumps brighter on their top and on their
    right side (engine_check.bumps_lit). Prints the figures; returns what failed (with `first_failure`, the views after
    the first that fails are not drawn)."""
    tag = "".join(c if c.isalnum() else "_" for c in name)
    config = {"width": PROBE_SIZE[0], "height": PROBE_SIZE[1], "uv": GL_UV, "marker": MARKER, **options}
    figures, failed = [], []
    for view in ("albedo", "normal", "lit"):
        if failed and first_failure:
            break
        png = os.path.join(PACKAGES, "%s_%s.png" % (tag, view))
        if view == "lit":
            PAGE.screenshot(png, module=package(normal_only(material), origin), light=[1.0, 1.0, 1.0], encoding="srgb",
                            **{k: v for k, v in config.items() if k != "nan"})
            lit = {side: ec.bumps_lit(png, side) for side in ("top", "right")}
            figures.append("bumps lit from the top %d/15, from the right %d/15" % (lit["top"], lit["right"]))
            failed += [] if lit["top"] == lit["right"] == 15 else ["lit bumps"]
        else:
            PAGE.screenshot(png, module=package(material, origin), input=view, encoding="linear", **config)
            tolerance = slot_tolerance(meant, view, view)
            worst, over = view_error(png, reference(meant, view, view, [0, 0, 1, 1], PROBE_SIZE), tolerance)
            figures.append("%s max %.1f/255 (bound %.2f), %d values over" % (view, worst, 255 * tolerance, over))
            failed += [view] if over else []
        failed += [] if marker_shown(png) else ["marker in the %s view" % view]
    print("  %s probe, %s: %s -> %s" % (ENGINE, name, "; ".join(figures), ", ".join(failed) or "pass"))
    return failed


def correlation(a, b):
    ma, mb = sum(a) / len(a), sum(b) / len(b)
    cov = sum((x - ma) * (y - mb) for x, y in zip(a, b))
    spread = math.sqrt(sum((x - ma) ** 2 for x in a) * sum((y - mb) ** 2 for y in b))
    return cov / spread if spread else 0.0  # a flat image follows nothing


# The layered material (engine_check.layered_material: three layers of 64 x 64 textures hex-tiled twice, 128 texels per
# uv unit, and a 32 x 32 splat map) over the uv rectangle from hexc's uv (0, 0) where a pixel covers 0.7 texel: every
# fetch is from mip level 0, as the Godot 3 and Filament checks draw it.
LAYERED_RECT = [0.0, 0.0, 0.7 * SIZE / 128, 0.7 * SIZE / 128]


def layered_view(material, origin, function, control=None, files=None, colors=None, webgpu_page=None):
    """engine_check's layered check (value_verdict: per pixel, within the bound layered_errors derives from the layers
    and the splat map or the vertex colour, a flip of u or of v caught, the marker at the top-left) of the engine's
    unlit value of a layered package's role `function` (engine_check.py's manifest entry) as the canvas's PNG shows it.
    `files`: the package's textures loaded from other files; `colors`: the square's vertex colours (a negative control,
    named `control`, must fail). `webgpu_page`: drawn there by Babylon's WebGPU engine from the package's WGSL
    (wgsl_package). True if the verdict is a failure of the test."""
    name = Path(material).stem
    tag = "%s_%s_%s%s" % (origin, function["name"], "".join(c for c in control or "" if c.isalnum())[:24], "_wgsl" if webgpu_page else "")
    png = os.path.join(PACKAGES, "%s_%s.png" % (name, tag))
    folder = "%s-%s%s" % (name, origin, "-wgsl" if webgpu_page else "")
    view = {"package": os.path.join(PACKAGES, folder, ENGINE), "origin": origin, "size": SIZE,
            "rect": LAYERED_RECT, "relative": 0.0, "encode": ec.linear}  # the value written out linear to an 8-bit canvas
    config = dict(module=wgsl_package(material) if webgpu_page else package(material, origin), width=SIZE, height=SIZE,
                  uv=engine_uv(LAYERED_RECT, origin), input=function["role"], encoding="linear",
                  marker=int(SIZE * ec.MARKER_FRACTION), files=files, colors=colors)
    if webgpu_page:  # no 2D canvas to take a PNG of: the frame as the driver reads it back, top row first
        rows = webgpu_page.render(**config, webgpu=True)
        ec.write_png(png, SIZE, SIZE, lambda x, y: rows[y][x][:3])
    else:
        PAGE.screenshot(png, **config)
    return ec.value_verdict(HEXC, material, function, Path(png), view, control)


def swapped_splat(material):
    """`material`'s splat map with its red and green channels swapped, written into its top-left package: the `files`
    (layered_view) that load it in place of the package's own."""
    name = Path(material).stem
    swapped = os.path.join(PACKAGES, "%s-top-left" % name, ENGINE, "%s.splat0.swapped.png" % name)
    w, h, n, rows = ec.read_png(os.path.join(os.path.dirname(material), "splat.png"))
    ec.write_png(swapped, w, h, lambda x, y: (rows[y][x * n + 1], rows[y][x * n], rows[y][x * n + 2]))
    return {"%s.splat0.png" % name: os.path.basename(swapped)}


def lit_by_the_normal(material, origin):
    """The layered package lit by the engine from +x and from -x (diffuse): per pixel, (out(+x) - out(-x)) / (out(+x) +
    out(-x)), which for out = albedo I (n . L) is n_x / n_z whatever the albedo (a single image over the unlit albedo
    would not do: Babylon's PBR adds terms the albedo does not scale). Its correlation with the reference's n_x / n_z,
    with -n_x / n_z (the normal mirrored in x, as a tangent frame or a normal map read the wrong way round lights it:
    the check must fail on it), and the pixels it is taken over (clipped at 255 or too dark to divide left out)."""
    config = dict(module=package(material, origin), width=SIZE, height=SIZE, uv=engine_uv(LAYERED_RECT, origin),
                  encoding="linear", diffuse=True)
    plus, minus = (PAGE.render(**config, light=light) for light in ([1.0, 0.0, 1.0], [-1.0, 0.0, 1.0]))
    normals = [n for row in reference(material, "normal", "normal", LAYERED_RECT) for n in row]
    pixels = [(p[:3], m[:3]) for rp, rm in zip(plus, minus) for p, m in zip(rp, rm)]
    kept = [i for i, (p, m) in enumerate(pixels) if sum(p) + sum(m) > 60 and max(p + m) < 255]
    ratio = [(sum(pixels[i][0]) - sum(pixels[i][1])) / (sum(pixels[i][0]) + sum(pixels[i][1])) for i in kept]
    slope = [(2 * normals[i][0] - 1) / (2 * normals[i][2] - 1) for i in kept]
    return correlation(ratio, slope), correlation(ratio, [-x for x in slope]), len(kept)


class Engine(unittest.TestCase):
    def setUp(self):
        self.started = time.monotonic()

    def tearDown(self):
        print("  %s: %.1f s" % (self.id().rsplit(".", 1)[-1], time.monotonic() - self.started))

    def test_values_match_the_reference(self):
        """Each slot through the engine's input, unlit, against the fp64 reference (linear values, 8-bit canvas)."""
        rock, dome, tiles = "materials/rock.json", dome_material(PACKAGES), "materials/tiles.json"
        mixed = str(ec.mixed_material(os.path.join(PACKAGES, "mixed")))  # packed, 300 x 170, a DirectX normal map
        probe = str(ec.probe_material(os.path.join(PACKAGES, "probe_hex"), "dx", hextiling=True))  # 96 x 64, 100 x 60
        # (material, slot, the engine input the driver reads, the reference's output, texels per uv unit along u)
        cases = (("albedo", rock, "albedo", "albedo", 1024), ("roughness", rock, "roughness", "albedo", 1024),
                 ("normal", dome, "normal", "normal", 128), ("albedo", tiles, "albedo", "albedo", 768),
                 ("albedo", mixed, "albedo", "albedo", 900), ("roughness", mixed, "roughness", "albedo", 900),
                 ("normal", mixed, "normal", "normal", 900), ("albedo", probe, "albedo", "albedo", 288),
                 ("normal", probe, "normal", "normal", 300))
        for (slot, material, engine_input, output, texels), origin in itertools.product(cases, ORIGINS):
            with self.subTest(material=os.path.basename(material), slot=slot, origin=origin):
                rect = [0.3, 0.45, 0.3 + SIZE * 0.75 / texels, 0.45 + SIZE * 0.75 / texels]
                got = PAGE.render(module=package(material, origin), width=SIZE, height=SIZE, uv=engine_uv(rect, origin),
                                  input=engine_input, encoding="linear")
                ref = reference(material, slot, output, rect)
                tolerance = slot_tolerance(material, slot, output)
                errors = [abs(g[c] / 255 - r[c]) for gr, rr in zip(got, ref) for g, r in zip(gr, rr) for c in range(3)]
                worst, mean = max(errors), sum(errors) / len(errors)
                print("  %s %-10s %-9s %-11s max error %.2f/255, mean %.3f/255, bound %.2f/255"
                      % (ENGINE, os.path.basename(material), slot, origin, worst * 255, mean * 255, tolerance * 255))
                self.assertLessEqual(worst, tolerance)
                self.assertGreater(max(r[c] for row in ref for r in row for c in range(3)) - min(r[c] for row in ref for r in row for c in range(3)),
                                   10 * tolerance)  # not flat

    def test_dome_is_lit_from_the_light_side(self):
        """A dome normal map, hex-tiled with rotation, under one directional light from +x, then from +y (up the
        screen), for a package of each uv origin: the brightness follows n . L of the reference's normals, and the
        side of each dome that faces the light is the brighter one."""
        dome = dome_material(PACKAGES)
        rect = [0.1, 0.2, 1.1, 1.2]  # 128 texels across 96 pixels at tiling 2: minified a little, several domes
        normals = reference(dome, "normal", "normal", rect)  # tangent space, y up the screen
        for origin in ORIGINS:
            for light in ([1.0, 0.0, 1.0], [0.0, 1.0, 1.0]):
                with self.subTest(origin=origin, light=light):
                    got = PAGE.render(module=package(dome, origin), width=SIZE, height=SIZE, uv=engine_uv(rect, origin), light=light,
                                      encoding="linear")
                    brightness = [p[0] / 255 for row in got for p in row]
                    axis = 0 if light[0] else 1
                    tilt = [2 * n[axis] - 1 for row in normals for n in row]  # the normal's component towards the light
                    towards = [b for b, t in zip(brightness, tilt) if t > 0.05]
                    away = [b for b, t in zip(brightness, tilt) if t < -0.05]
                    r = correlation(brightness, tilt)
                    print("  %s %s light %s: correlation with the reference's tilt %.3f, mean towards %.3f, away %.3f"
                          % (ENGINE, origin, light, r, sum(towards) / len(towards), sum(away) / len(away)))
                    # Lambert on a grey surface is linear in n . L = (n_axis + n_z) / sqrt(2); n_z varies far less than
                    # n_axis over a dome of slope 0.4 (1 - n_z <= 0.08 where |n_axis| reaches 0.37), so the brightness
                    # follows the tilt closely; a normal lit upside down follows it with the opposite sign.
                    self.assertGreater(r, 0.9)
                    self.assertGreater(sum(towards) / len(towards), sum(away) / len(away) + 0.1)

    def test_layered_material(self):
        """A layered material (engine_check.layered_material: glyph-like asymmetric layers, a painted splat map) through
        the engine's inputs, at both uv origins: each role's value within engine_check's layered bound per pixel, the
        same images against the reference flipped in u and in v over it, and the material lit by the engine from +x and
        -x: their ratio follows the reference's slope; the same layers weighed by the vertex colour (layered_vertex) on a
        square whose corners carry engine_check.VERTEX_COLORS, which the package reads from the engine's own vertex
        colour, and (three.js) by the splat map times that colour (layered_both). Negative controls, which must fail the
        layered check: two layers' normal maps exchanged in the engine, the splat map's red and green channels swapped
        (for layered and layered_both), the square's red and green vertex colour channels swapped."""
        material = str(ec.layered_material(os.path.join(PACKAGES, "layered")))
        failed = 0
        for origin in ORIGINS:
            package(material, origin)
            failed += sum(layered_view(material, origin, f)
                          for f in ec.manifest(os.path.join(PACKAGES, "layered-" + origin, ENGINE))["functions"]
                          if f["returns"] != "vec2")  # the derivative: its normal function is checked
            r, mirrored, pixels = lit_by_the_normal(material, origin)
            failed += ec.row("layered, %s, lit from +x and -x" % origin, "correlation of the lights' ratio with the "
                             "reference's n_x / n_z %.3f (%d pixels; > 0.9 required), with the normal mirrored in x %.3f "
                             "(must be below 0.9)" % (r, pixels, mirrored), r > 0.9 and mirrored < 0.9)
        functions = {f["name"]: f for f in ec.manifest(os.path.join(PACKAGES, "layered-top-left", ENGINE))["functions"]}
        controls = (("two layers' normal maps exchanged in the engine (clay's and moss's)", "hexc_normal_normal",
                     {"layered.clay_normal.png": "layered.moss_normal.png", "layered.moss_normal.png": "layered.clay_normal.png"}),
                    ("the splat map's red and green channels swapped", "hexc_albedo", swapped_splat(material)))
        for control, name, files in controls:
            failed += layered_view(material, "top-left", functions[name], control, files)
        # Weighed by the vertex colour, and (three.js only) by the splat map times it: the product is hexc's code, the
        # same GLSL in both web packages, and the colour reaches it as in the vertex case, which both engines draw.
        for weights in ("vertex", "both") if ENGINE == "threejs" else ("vertex",):
            coloured = str(ec.layered_material(os.path.join(PACKAGES, "layered"), weights=weights))
            package(coloured, "top-left")  # the colour does not depend on the uv origin, which the splat map's views check
            roles = [f for f in ec.manifest(os.path.join(PACKAGES, "layered_%s-top-left" % weights, ENGINE))["functions"]
                     if f["returns"] != "vec2"]
            albedo = next(f for f in roles if f["role"] == "albedo")
            failed += sum(layered_view(coloured, "top-left", f, colors=ec.VERTEX_COLORS) for f in roles)
            failed += layered_view(coloured, "top-left", albedo, "the square's red and green vertex colour channels swapped",
                                   colors=ec.VERTEX_COLORS_SWAPPED)
            if weights == "both":
                failed += layered_view(coloured, "top-left", albedo, "the splat map's red and green channels swapped",
                                       swapped_splat(coloured), colors=ec.VERTEX_COLORS)
        self.assertEqual(failed, 0)

    def test_vertex_weighed_without_a_vertex_colour(self):
        """Layers weighed by the vertex colour on a square without one (docs/engines.md#vertex-colours-as-weights), where
        WebGL's default colour, (0, 0, 0, 1), draws the first layer over the whole square: three.js's package refuses
        to draw it, throwing an Error that names the mesh and its missing attribute; Babylon.js's draws it and says so
        with console.error (which the driver reports as a failure). The same square with its vertex colours draws with
        neither (what is refused is the missing attribute)."""
        vertex = str(ec.layered_material(os.path.join(PACKAGES, "layered"), weights="vertex"))
        config = dict(module=package(vertex, "top-left"), width=SIZE, height=SIZE, uv=engine_uv(LAYERED_RECT, "top-left"),
                      input="albedo", encoding="linear")
        said = {"threejs": r'the driver failed: Error: hexc: layered_vertex weighs its layers by the vertex colour, and the '
                           r'geometry of mesh "[^"]+" has no `color` attribute: give it one',
                "babylon": r'hexc: layered_vertex weighs its layers by the vertex colour, and mesh \\?"[^"\\]+\\?" has no `color` '
                           r'vertex buffer: it is drawn with the colour \(0, 0, 0, 1\); give it one'}
        with self.assertRaisesRegex(AssertionError, said[ENGINE]) as refused:
            PAGE.render(**config)
        print("  %s, no vertex colour: %s" % (ENGINE, str(refused.exception).splitlines()[0]))
        PAGE.render(**config, colors=ec.VERTEX_COLORS)

    def test_package_files_and_a_slot_without_input(self):
        """The package's files; a slot the engine has no input for is reported (HX204) and listed in the module's
        data, not dropped silently."""
        folder = os.path.join(PACKAGES, "unmapped")
        os.makedirs(folder)
        material = os.path.join(folder, "wet.json")
        textures = os.path.abspath("materials/textures")
        with open(material, "w") as f:
            json.dump({"name": "wet", "slots": [
                {"name": "albedo", "texture": os.path.join(textures, "rock_albedo.png"), "kind": "color"},
                {"name": "wetness", "texture": os.path.join(textures, "rock_roughness.png"), "kind": "scalar", "channel": "r"}]}, f)
        out = os.path.join(folder, "out")
        run = subprocess.run([HEXC, material, "--engine", ENGINE, "-o", out], check=True, capture_output=True, text=True)
        self.assertIn("warning[HX204]", run.stderr)
        self.assertIn("slot `wetness` has no %s input" % {"threejs": "three.js", "babylon": "Babylon.js"}[ENGINE], run.stderr)
        suffix = MODULE_SUFFIX[ENGINE]
        self.assertEqual(sorted(os.listdir(os.path.join(out, ENGINE))),
                         sorted(["wet.albedo.png", "wet.manifest.json", "wet.%s.js" % suffix, "wet.wetness.png"]))
        with open(os.path.join(out, ENGINE, "wet.%s.js" % suffix)) as f:
            module = f.read()
        start = module.index("const hexc = ") + len("const hexc = ")
        data = json.loads(module[start:module.index(";\n", start)])
        self.assertEqual(data["unmapped"], ["wetness"])
        self.assertEqual([s["name"] for s in data["slots"]], ["albedo"])

    def test_webgpu_matches_webgl2(self):
        """Babylon only: the package's WGSL form on Babylon's WebGPU engine draws what its GLSL form draws on WebGL 2, rock's
        albedo under a dome normal map lit from +x and from -x; both renders show the albedo and the normal map. And
        the layers weighed by the vertex colour (layered_vertex), its albedo within engine_check's layered bound as on
        WebGL 2, and failing it with the square's red and green vertex colour channels swapped; the layers under the
        splat map (layered), each role within its bound, failing it with two layers' normal maps exchanged."""
        if ENGINE != "babylon":
            self.skipTest("the WGSL form is Babylon's")
        material = lit_material(os.path.join(PACKAGES, "lit"))
        env = {**os.environ, "HEXC_NODE_PATH": os.environ.get("HEXC_NODE_PATH") or os.path.abspath(NODE_MODULES)}
        subprocess.run([HEXC, material, "--engine", ENGINE, "--targets", "wgsl", "-o", os.path.join(PACKAGES, "lit-wgsl"), "-q"],
                       check=True, env=env)
        module = "/pkg/lit-wgsl/babylon/lit.babylon.js"
        rect = [0.3, 0.45, 0.3 + SIZE * 0.75 / 1024, 0.45 + SIZE * 0.75 / 1024]
        config = dict(module=module, width=SIZE, height=SIZE, uv=engine_uv(rect, "top-left"), encoding="linear", diffuse=True)
        lights = ([1.0, 0.0, 1.0], [-1.0, 0.0, 1.0])
        webgl2 = [PAGE.render(**config, light=light) for light in lights]
        webgpu_page = Page(SERVER, ENGINE, WEBGPU_FLAGS)
        try:
            webgpu = [webgpu_page.render(**config, light=light, webgpu=True) for light in lights]
            vertex = str(ec.layered_material(os.path.join(PACKAGES, "layered"), weights="vertex"))
            wgsl_package(vertex)
            albedo = next(f for f in ec.manifest(os.path.join(PACKAGES, "layered_vertex-top-left-wgsl", ENGINE))["functions"]
                          if f["role"] == "albedo")
            failed = layered_view(vertex, "top-left", albedo, colors=ec.VERTEX_COLORS, webgpu_page=webgpu_page)
            failed += layered_view(vertex, "top-left", albedo, "the square's red and green vertex colour channels swapped",
                                   colors=ec.VERTEX_COLORS_SWAPPED, webgpu_page=webgpu_page)
            # The layers under the splat map (the normal role a 2D array texture, the albedo a texture per layer), each
            # role within its bound, and two layers' normal maps exchanged failing it, as on WebGL 2.
            layered = str(ec.layered_material(os.path.join(PACKAGES, "layered")))
            wgsl_package(layered)
            roles = [f for f in ec.manifest(os.path.join(PACKAGES, "layered-top-left-wgsl", ENGINE))["functions"] if f["returns"] != "vec2"]
            failed += sum(layered_view(layered, "top-left", f, webgpu_page=webgpu_page) for f in roles)
            failed += layered_view(layered, "top-left", next(f for f in roles if f["name"] == "hexc_normal_normal"),
                                   "two layers' normal maps exchanged in the engine (clay's and moss's)",
                                   {"layered.clay_normal.png": "layered.moss_normal.png", "layered.moss_normal.png": "layered.clay_normal.png"},
                                   webgpu_page=webgpu_page)
        finally:
            webgpu_page.quit()
        self.assertEqual(failed, 0)
        # Each render is out = albedo * I * (n . L) per channel (PBRMaterial's diffuse with specularIntensity 0, no ambient;
        # its energy-conservation factor is <= 1), I = 2.5 the driver's light, |L| = 1. Each engine's albedo and normal
        # are within test_values_match_the_reference's bounds of the exact ones (ea; en for the normal as a vector, before
        # the 0.5 of its encoding), so two engines differ by at most twice those, through |d out| <= I (|da| + |dn|)
        # (albedo <= 1, |n . L| <= 1), plus each canvas's rounding to 8 bits (0.5/255 each). ANGLE (WebGL 2) and Dawn
        # (WebGPU) both draw on SwiftShader here, and WGSL's and GLSL ES 3.00's f32 rules differ only within these
        # rounding terms: the bound is the filtering's, and loose.
        spread, _, _ = texture_bounds("materials/textures/rock_albedo.png", True)
        ea = blend_tolerance(E_S, E_S, {"tiling": [4, 4], "rotation": 1.0}, spread)
        _, max_deriv, min_z = texture_bounds(os.path.join(PACKAGES, "lit", "textures", "dome_normal.png"), False)
        ed = 2 * E_S * (1 + max_deriv) / min_z
        en = math.sqrt(2) * blend_tolerance(ed, math.sqrt(2) * ed, {"tiling": [14, 14], "rotation": 1.0}, 2 * max_deriv)
        tolerance = 2.5 * 2 * (ea + en) + 2 * 0.5 / 255
        for light, gl, gpu in zip(lights, webgl2, webgpu):
            errors = [abs(a[c] - b[c]) / 255 for ra, rb in zip(gl, gpu) for a, b in zip(ra, rb) for c in range(3)]
            print("  babylon WebGPU vs WebGL 2, light %s: max difference %.2f/255, mean %.3f/255, bound %.2f/255"
                  % (light, max(errors) * 255, sum(errors) / len(errors) * 255, tolerance * 255))
            self.assertLessEqual(max(errors), tolerance)
        # The normal map: for out = albedo I (n . L), (out(+x) - out(-x)) / (out(+x) + out(-x)) = n_x / n_z whatever the
        # albedo, so it follows the reference's normals (pixels clipped at 255 or too dark to divide left out). The albedo:
        # out(+x) + out(-x) = albedo I sqrt(2) n_z, and n_z varies far less than rock's albedo, so it follows the albedo.
        normals = [n for row in reference(material, "normal", "normal", rect) for n in row]
        albedo = [sum(a) for row in reference(material, "albedo", "albedo", rect) for a in row]
        for name, (plus, minus) in (("WebGL 2", webgl2), ("WebGPU", webgpu)):
            pixels = [(p[:3], m[:3]) for rp, rm in zip(plus, minus) for p, m in zip(rp, rm)]
            kept = [i for i, (p, m) in enumerate(pixels) if sum(p) + sum(m) > 60 and max(p + m) < 255]
            ratio = [(sum(pixels[i][0]) - sum(pixels[i][1])) / (sum(pixels[i][0]) + sum(pixels[i][1])) for i in kept]
            slope = [(2 * normals[i][0] - 1) / (2 * normals[i][2] - 1) for i in kept]
            r_normal, r_albedo = correlation(ratio, slope), correlation([sum(p) + sum(m) for p, m in pixels], albedo)
            print("  babylon %s: correlation with the reference's n_x / n_z %.3f (%d pixels), with its albedo %.3f"
                  % (name, r_normal, len(kept), r_albedo))
            self.assertGreater(r_normal, 0.9)
            self.assertGreater(r_albedo, 0.9)

    def test_probe_upright_and_lit_from_the_light_side(self):
        """The probe (an F glyph, a hue gradient, 5 x 3 bumps) at each uv origin and in both green conventions passes
        probe_check as the screen shows it; each wrong variant a user can make fails it."""
        right, wrong = probe_variants(os.path.join(PACKAGES, "probe"))
        for name, *variant in right:
            with self.subTest(name):
                self.assertEqual(probe_check(name, *variant), [])
        for name, *variant in wrong:
            with self.subTest("negative control: " + name):
                self.assertNotEqual(probe_check(name, *variant), [])

    def test_read_back_order_is_checked_by_the_marker(self):
        """The other tests read the canvas with readPixels, whose rows WebGL documents bottom first (its origin is the
        framebuffer's lower left), and turn them top first (Page.render). The marker the engine draws at the screen's
        top-left checks that: those rows equal the canvas's own PNG and show the marker at the top-left; the rows in
        the order readPixels returns them show it at the bottom-left, and the check fails on them."""
        probe = str(ec.probe_material(os.path.join(PACKAGES, "readback"), "gl"))
        config = dict(module=package(probe, "top-left"), width=PROBE_SIZE[0], height=PROBE_SIZE[1], uv=GL_UV, marker=MARKER,
                      input="albedo", encoding="linear")
        rows = [[c for p in row for c in p[:3]] for row in PAGE.render(**config)]
        shot = os.path.join(PACKAGES, "readback", "canvas.png")
        PAGE.screenshot(shot, **config)
        _, _, n, png = ec.read_png(shot)
        self.assertEqual(rows, [[row[x * n + c] for x in range(PROBE_SIZE[0]) for c in range(3)] for row in png])
        for order, shown in (("top_first", rows), ("as_read", rows[::-1])):
            path = os.path.join(PACKAGES, "readback", order + ".png")
            write_png(path, *PROBE_SIZE, shown)
            self.assertEqual(marker_shown(path), order == "top_first", order)

    def test_basic_material_ignores_the_slots_it_has_no_input_for(self):
        """three.js only: applyHexc on a MeshBasicMaterial (not lit: no normalMap, no roughnessMap) draws rock's albedo
        and says, for each slot it leaves out, that the material type has no input for it."""
        if ENGINE != "threejs":
            self.skipTest("three.js's material types")
        rect = [0.3, 0.45, 0.3 + SIZE * 0.75 / 1024, 0.45 + SIZE * 0.75 / 1024]
        path = os.path.join(PACKAGES, "basic.png")
        result = PAGE.screenshot(path, module=package("materials/rock.json", "top-left"), width=SIZE, height=SIZE,
                                 uv=engine_uv(rect, "top-left"), encoding="linear", materialType="MeshBasicMaterial")
        for slot, property in (("normal", "normalMap"), ("roughness", "roughnessMap")):
            self.assertIn("hexc: MeshBasicMaterial has no %s, so slot %s of rock is ignored" % (property, slot), "\n".join(result["warnings"]))
        tolerance = slot_tolerance("materials/rock.json", "albedo", "albedo")
        worst, over = view_error(path, reference("materials/rock.json", "albedo", "albedo", rect), tolerance, marker=0)
        print("  three.js MeshBasicMaterial: rock's albedo max error %.2f/255, bound %.2f/255; warnings: %s"
              % (worst, 255 * tolerance, result["warnings"]))
        self.assertEqual(over, 0)

    def test_every_example_compiles_in_the_engine(self):
        """Every example material under materials/ through the package (top-left, then bottom-left, alternately),
        compiled by the engine and drawn lit once: no shader error, not a flat image (the terrain, layered, among them;
        those weighed by the vertex colour on a square with engine_check.py's corner colours).
        Only what docs/engines.md says the package refuses is left out (triplanar materials: HX300), and it is listed."""
        examples = sorted(glob.glob("materials/*.json") + glob.glob("materials/terrain/*.json") + glob.glob("materials/mtlx/*.mtlx"))
        drawn, skipped = [], []
        for i, material in enumerate(examples):
            doc = {}
            if material.endswith(".json"):
                with open(material) as f:
                    doc = json.load(f)
                if "slots" not in doc and "layers" not in doc:
                    continue  # the schema: not a material
            origin = ORIGINS[i % 2]
            run = subprocess.run([HEXC, material, "--engine", ENGINE, "-q", "-o", os.path.join(PACKAGES, "matrix", str(i))]
                                 + (["--uv-bottom-left"] if origin == "bottom-left" else []), capture_output=True, text=True)
            refused = {"projection": "triplanar, no functions output: HX300, docs/engines.md"}
            why = [refused[k] for k in refused if k in doc or k in doc.get("hextiling", {})]
            if run.returncode and "error[HX300]" in run.stderr and why:
                skipped.append("%s (%s)" % (material, why[0]))
                continue
            with self.subTest(material):
                self.assertEqual(run.returncode, 0, run.stderr)
                name = next(n for n in os.listdir(os.path.join(PACKAGES, "matrix", str(i), ENGINE)) if n.endswith(".%s.js" % MODULE_SUFFIX[ENGINE]))
                coloured = doc.get("layer_blend", {}).get("weights", "splat") != "splat"  # a mesh without colours is refused
                got = PAGE.render(module="/pkg/matrix/%d/%s/%s" % (i, ENGINE, name), width=32, height=32, uv=GL_UV,
                                  light=[1.0, 1.0, 0.3], encoding="srgb",  # grazing: a normal map alone shows
                                  colors=ec.VERTEX_COLORS if coloured else None)
                values = [p[c] for row in got for p in row for c in range(3)]
                self.assertGreater(max(values) - min(values), 10, "a flat image")
                drawn.append("%s (%s)" % (material, origin))
        print("  %s: %d examples compiled and drawn: %s" % (ENGINE, len(drawn), ", ".join(drawn)))
        print("  %s: skipped as the docs say: %s" % (ENGINE, ", ".join(skipped) or "none"))
        print("  %s: not examples: materials/invalid (refused by design), materials/mtlx/corpus and materials/mtlx/invalid "
              "(the MaterialX importer's cases), materials/scenes and materials/layouts (a scene, a layout)" % ENGINE)

    def test_lit_screenshot(self):
        """The rock, and the terrain beside it (<PNG>-terrain.png), on a sphere, lit by the engine from the upper right,
        sRGB as a canvas shows it: for docs/engines.md."""
        if not SCREENSHOT:
            self.skipTest("no --screenshot")
        size = 192
        for material, path in (("materials/rock.json", SCREENSHOT), ("materials/terrain/terrain.json", SCREENSHOT[:-4] + "-terrain.png")):
            got = PAGE.render(module=package(material, "bottom-left"), width=size, height=size, uv=[0, 1, 1, 0],
                              light=[1.0, 1.0, 1.5], encoding="srgb", sphere=True)
            write_png(path, size, size, [[c for p in row for c in p[:3]] for row in got])


def main():
    global HEXC, ENGINE, SCREENSHOT, SERVER, PAGE, PACKAGES
    args = sys.argv[1:]
    if "--screenshot" in args:
        i = args.index("--screenshot")
        SCREENSHOT = os.path.abspath(args[i + 1])
        del args[i:i + 2]
    HEXC, ENGINE = os.path.abspath(args[0]), args[1]
    PACKAGES = tempfile.mkdtemp(prefix="hexc-%s-" % ENGINE)
    SERVER = FileServer(PACKAGES)
    try:
        PAGE = Page(SERVER, ENGINE)
        try:
            result = unittest.main(argv=[sys.argv[0], "-v", *args[2:]], exit=False).result  # then test names, if any
        finally:
            PAGE.quit()
    finally:
        SERVER.stop()
        shutil.rmtree(PACKAGES, ignore_errors=True)
    sys.exit(0 if result.wasSuccessful() else 1)


if __name__ == "__main__":
    main()
