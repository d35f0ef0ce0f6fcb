"""Every view hexc edit's page offers, for every example material, in headless Chromium against `hexc render`.

The views (compiler/edit/page: the Show list and the light): the material hex-tiled (its template's shading), plain
tiling, the split of plain tiling, hex-tiling and weights, and each slot's values and weights; and the light moved on the
ground plane. Each is read back from the page's float framebuffer in texture space (the view `hexc render` draws, the
light the templates' own) and must be finite, not constant, and within a derived bound of `hexc render`'s image of the
same output: the fp64 reference (--reference) for a slot's values and weights, lavapipe (`--output shaded`) for the
template's shading, of the material and of its copy with every slot plain tiled. Where no bound is derived (UNBOUNDED
says why), and everywhere besides, the view must follow `hexc render`'s image (check_follows). The moving light has no `hexc render` counterpart: it is checked on the ground plane against the
normal map the page shows there (see check_light). Every check is run once more on deliberately wrong images (flipped in
v, a NaN, constant, channels swapped, the light's normals mirrored) and must fail on each.

MaterialX documents are not edited (hexc edit refuses them, docs/edit.md), so materials/mtlx is not among the examples.

Usage: views_test.py HEXC  (from the source root)
"""
import glob
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import page_test  # noqa: E402
from edit_support import SMALL_WINDOW, Server, read_pfm, run_with_browser, wait_idle  # noqa: E402
from page_test import E_S, blend_tolerance, read_view, texture_bounds as page_texture_bounds  # noqa: E402

HEXC = None
DRIVER = None

# Small views keep the suite's time: 48 x 48 pixels, magnified (at most 0.75 texel per pixel for every slot, so every
# fetch reads mip level 0 and WebGL's own mip chain plays no part).
SIZE = 48


BOUNDS = {}


def texture_bounds(server, slot, srgb):
    """page_test's texture_bounds, once per texture (a few hundred thousand operations in Python each)."""
    key = (server.token, slot, srgb)  # the token is new with every server
    if key not in BOUNDS:
        BOUNDS[key] = page_texture_bounds(server, slot, srgb)
    return BOUNDS[key]


def examples():
    found = sorted(set(glob.glob("materials/*.json")) - {"materials/material.schema.json"}) + sorted(glob.glob("materials/*/*.json"))
    return [m for m in found if not m.startswith(("materials/scenes/", "materials/layouts/", "materials/invalid/"))]


def render(material, output, rect, out, slot=None, reference=False):
    """`hexc render` of `output` over the uv rectangle `rect`, as rows top first."""
    command = [HEXC, "render", material, "--output", output, "--size", "%dx%d" % (SIZE, SIZE), "--uv-rect", ",".join(map(repr, rect)),
               "-o", out, "-q"] + (["--slot", slot] if slot else []) + (["--reference"] if reference else [])
    subprocess.run(command, check=True, capture_output=True)
    return read_pfm(out)[2]


# ---- The checks --------------------------------------------------------------------------------------------------

def check_image(gpu, ref, bound, channels):
    """What is wrong with a view's image against `hexc render`'s (empty when nothing): a value that is not finite, an
    image flat where `hexc render`'s varies (constant), an error over the bound (a number, or one per pixel). Returns
    (problems, the worst error over its bound)."""
    bounds = bound if isinstance(bound, list) else [[bound] * len(gpu[0]) for _ in gpu]
    if not all(v is not None and math.isfinite(v) for row in gpu for p in row for v in p[:channels]):
        return ["not finite"], math.inf  # the page reads NaN back as null
    problems = []
    span = lambda image: max(max(p[c] for row in image for p in row) - min(p[c] for row in image for p in row) for c in range(channels))
    if span(gpu) <= 1 / 255 < span(ref):  # a view may be flat where hexc render's is (one tile's weights)
        problems.append("constant: its values span %.4f, within an 8-bit step" % span(gpu))
    ratio, worst = 0.0, (0.0, 0.0)
    for gr, rr, br in zip(gpu, ref, bounds):
        for g, r, b in zip(gr, rr, br):
            e = max(abs(g[c] - r[c]) for c in range(channels))
            if e / b > ratio:
                ratio, worst = e / b, (e, b)
    if ratio > 1:
        problems.append("off by %.4f (%.2f/255) where the bound is %.4f (%.2f/255)" % (worst[0], worst[0] * 255, worst[1], worst[1] * 255))
    return problems, ratio


def check_follows(gpu, ref, channels):
    """Every view, and alone where no bound is derived (see UNBOUNDED): finite, not constant, and following `hexc render`'s
    image: in each channel and each difference of two channels, the correlation of their values over the pixels above
    0.9 (a flip, a swapped channel or another slot's image falls far below: the negative controls). A bound derived from a steep normal map's texels is
    wide (it grows as 1 / min z); this keeps such a view from passing with a wrong picture. A channel flat in `hexc
    render`'s image (a scalar's alpha) is left out. Returns (problems, the lowest correlation)."""
    if not all(v is not None and math.isfinite(v) for row in gpu for p in row for v in p[:channels]):
        return ["not finite"], math.nan
    lowest = 1.0
    pixels = lambda image, f: [f(p) for row in image for p in row]
    # Each channel, and each difference of two channels where it varies in hexc render's image (a colour's hue; two
    # channels swapped leave each channel's correlation high in a texture whose channels move together, and turn
    # their difference over).
    signals = [lambda p, c=c: p[c] for c in range(channels)] + [lambda p, c=c: p[c] - p[c + 1] for c in range(channels - 1)]
    for k, f in enumerate(signals):
        a, b = pixels(gpu, f), pixels(ref, f)
        if max(b) - min(b) > (1 if k < channels else 10) / 255:
            lowest = min(lowest, correlation(a, b))
    return ([] if lowest > 0.9 else ["does not follow hexc render's image: correlation %.3f" % lowest]), lowest


def correlation(a, b):
    ma, mb = sum(a) / len(a), sum(b) / len(b)
    cov = sum((x - ma) * (y - mb) for x, y in zip(a, b))
    spread = math.sqrt(sum((x - ma) ** 2 for x in a) * sum((y - mb) ** 2 for y in b))
    return cov / spread if spread else 0.0  # a flat image follows nothing


def check_light(east, west, derivative, elevation):
    """The moving light, which `hexc render` does not have (it lights from the templates' own direction): the page turns
    the surface frame so that the light at azimuth a and elevation e lights the template's normal n as
    L = (cos e cos a, cos e sin a, sin e) would in the plane's frame (tangent +x, bitangent +y). The lit template's
    diffuse term from the east (a = 0) and the west (a = 180) is albedo (cos e n_x + sin e n_z) and albedo
    (-cos e n_x + sin e n_z), over an ambient 0.15 albedo each, with n = (-d, 1) / |(-d, 1)| from the normal slot's
    derivative d. So the difference of the two images over their sum, which takes the albedo out, is
    cos e n_x / (0.15 + sin e n_z) but for the specular term: its correlation with that, from the slot's values on the
    same pixels, must exceed 0.9 (the specular term, not in the model, keeps it below 1). Returns (problems,
    correlation)."""
    ratio, model = [], []
    for re, rw, rd in zip(east, west, derivative):
        for e, w, d in zip(re, rw, rd):
            if not all(v is not None and math.isfinite(v) for v in e[:3] + w[:3] + d[:2]):
                return ["not finite"], math.nan
            total = sum(e[:3]) + sum(w[:3])
            if total > 0.05:  # a pixel dark under both lights tells nothing
                length = math.sqrt(1 + d[0] * d[0] + d[1] * d[1])
                ratio.append((sum(e[:3]) - sum(w[:3])) / total)
                model.append(math.cos(elevation) * -d[0] / length / (0.15 + math.sin(elevation) / length))
    r = correlation(ratio, model) if len(ratio) > 16 else 0.0
    return ([] if r > 0.9 else ["the light does not follow the normal map: correlation %.3f" % r]), r


# ---- Bounds --------------------------------------------------------------------------------------------------------
# Each view's image is held to `hexc render`'s within a bound derived from texture filtering (tests/edit/page_test.py:
# E_S per 8-bit sample, carried through the falloff blend by blend_tolerance).

def settings(doc, entry):
    """A slot's effective hex-tiling settings: the material's, its layer's, its own."""
    return {**doc.get("hextiling", {}), **(entry["layer"] or {}).get("hextiling", {}), **entry["slot"].get("hextiling", {})}


def slot_entries(doc):
    """The slots as the page and hexc name them: the material's own, then each layer's as <layer>_<slot>."""
    own = [{"name": s["name"], "slot": s, "layer": None} for s in doc.get("slots", [])]
    return own + [{"name": "%s_%s" % (l["name"], s["name"]), "slot": s, "layer": l} for l in doc.get("layers", []) for s in l["slots"]]


def slot_bounds(server, doc, entry):
    """(what `hexc render` calls the slot's values, channels, the values' bound, the weights' bound).
    Values: a colour or scalar slot's blend is off by blend_tolerance(E_S, E_S) over its texture's range; a normal
    slot's derivative d = -xy / z, with x, y, z = 2 * texel - 1 each off by 2 E_S, by ed = 2 E_S (1 + max|d|) / min z per
    sample, its slope metric by sqrt(2) ed, its samples spread by 2 max|d| per component (Listing 9).
    Weights: the three tile weights W_c, proportional to delta_c w_c^gamma, move with the metric's factors delta_j >=
    1 - beta, each off by at most beta e_m, as dW_c / d(delta_j) = W_c (delta_cj - W_j) / delta_j, so by at most
    beta e_m / (1 - beta) * sum_j W_c |delta_cj - W_j| = beta e_m / (1 - beta) * 2 W_c (1 - W_c) <= beta e_m / (1 - beta)
    / 2, times the gain's slope k (blend_tolerance over a spread of 1/2), plus float rounding of the lattice's
    barycentrics, 1e-5 (uv scaled by at most 4096 texels: 2^-24 * 4096 * a few operations)."""
    slot, hex = entry["slot"], settings(doc, entry)
    srgb = slot.get("colorspace", "srgb" if slot["kind"] == "color" else "linear") == "srgb"
    spread, max_deriv, min_z = texture_bounds(server, entry["name"], srgb)
    if slot["kind"] == "normal":
        ed = 2 * E_S * (1 + max_deriv) / min_z
        em = math.sqrt(2) * ed
        values = ("derivative", 3 if doc.get("hextiling", {}).get("projection") == "triplanar" else 2,
                  blend_tolerance(ed, em, hex, 2 * max_deriv))
    else:
        em = E_S
        values = ("albedo", 3, blend_tolerance(E_S, E_S, hex, spread))
    if hex.get("enabled", True) is False:
        values = values[:2] + (ed if slot["kind"] == "normal" else E_S,)
    return values + (blend_tolerance(1e-5, em, hex, 0.5),)


# The lit template (templates/builtin/lit.glsl) in the texture-space view's frame (tangent +x, bitangent +y, normal +z,
# as `hexc render` and the page's flat view give it): out = albedo (0.15 + diffuse) + 0.04 specular, diffuse =
# max(N . L, 0), specular = max(N . H, 0)^p (p + 8) / (8 pi) diffuse, p = 2 / r^4 - 2 with r = clamp(roughness, 0.02, 1),
# N = (n.x, -n.y, n.z), n = normalize(-d, 1) from the normal slot's derivative d.
LIGHT = [1 / math.sqrt(6), 1 / math.sqrt(6), 2 / math.sqrt(6)]
HALF = [c / math.sqrt(sum(x * x for x in [LIGHT[0], LIGHT[1], LIGHT[2] + 1])) for c in [LIGHT[0], LIGHT[1], LIGHT[2] + 1]]


def lit_interval(albedo, ea, d, en, roughness, er):
    """The range of each of lit's output channels over its inputs within their errors: albedo within ea per channel, N
    within en (as a vector), roughness within er. Interval arithmetic on non-negative factors: N . L and N . H move by at
    most en (unit L and H), max(., 0) and the clamps move by no more than their argument, x^p (x in [0, 1]) grows with x
    and falls with p, and p falls with r."""
    length = math.sqrt(1 + d[0] * d[0] + d[1] * d[1])
    normal = [-d[0] / length, d[1] / length, 1 / length]
    dot = lambda a, b: sum(x * y for x, y in zip(a, b))
    clip = lambda x: min(1.0, max(0.0, x))
    diffuse = [clip(dot(normal, LIGHT) - en), clip(dot(normal, LIGHT) + en)]
    x = [clip(dot(normal, HALF) - en), clip(dot(normal, HALF) + en)]
    r = [min(1.0, max(0.02, roughness - er)), min(1.0, max(0.02, roughness + er))]
    p = [2 / r[1] ** 4 - 2, 2 / r[0] ** 4 - 2]  # low, high
    power = [x[0] ** p[1] if x[0] > 0 else 0.0, x[1] ** p[0] if p[0] > 0 else 1.0]
    specular = [power[k] * (p[k] + 8) / 25.1327412 * diffuse[k] for k in (0, 1)]
    return [[max(0.0, a - ea) * (0.15 + diffuse[0]) + 0.04 * specular[0], (a + ea) * (0.15 + diffuse[1]) + 0.04 * specular[1]]
            for a in albedo]


def shaded_bound(template, refs, errors):
    """Per pixel, the bound between the page's shading and lavapipe's: each computes the template from slot values
    within `errors` of the fp64 reference's (`refs`: the references of the slots it reads, by role; `errors`: their
    values' bounds), so the two differ by at most the width of the template's range over those inputs. unlit writes the
    albedo: twice its bound."""
    if template == "unlit":
        return [[2 * errors["albedo"]] * SIZE for _ in range(SIZE)]
    rows = []
    for y in range(SIZE):
        row = []
        for x in range(SIZE):
            albedo = refs["albedo"][y][x][:3] if "albedo" in refs else [0.5] * 3
            d = refs["normal"][y][x][:2] if "normal" in refs else [0.0, 0.0]
            r = refs["roughness"][y][x][0] if "roughness" in refs else 0.5
            # |dn| <= |dd| (normalize(-d, 1) has a Jacobian of norm <= 1), |dd| <= sqrt(2) times the per-component bound.
            ranges = lit_interval(albedo, errors.get("albedo", 0.0), d, math.sqrt(2) * errors.get("normal", 0.0), r, errors.get("roughness", 0.0))
            row.append(max(hi - lo for lo, hi in ranges))
        rows.append(row)
    return rows


def plain_copy(material, folder):
    """The material with every slot plain tiled (`enabled` false at the material, in each layer and slot), as the page's
    plain tiling view shows it (vk::plainTiled), its files named by absolute paths. A slot's `height_blend` weighs tiles,
    which plain tiling has not: the file drops it (a file may not hold both, HX112)."""
    with open(material) as f:
        doc = json.load(f)
    base = os.path.dirname(os.path.abspath(material))
    absolute = lambda p: os.path.join(base, p)
    for holder in [doc] + doc.get("layers", []) + doc.get("slots", []) + [s for l in doc.get("layers", []) for s in l["slots"]]:
        holder["hextiling"] = {**holder.get("hextiling", {}), "enabled": False}
        holder.pop("height_blend", None)
        if "texture" in holder:
            holder["texture"] = absolute(holder["texture"])
    if "layer_blend" in doc and "splat" in doc["layer_blend"]:
        doc["layer_blend"]["splat"] = [absolute(p) for p in doc["layer_blend"]["splat"]]
    if doc.get("template", "").endswith(".glsl"):
        doc["template"] = absolute(doc["template"])
    doc.pop("$schema", None)
    out = os.path.join(folder, "plain_" + os.path.basename(material))
    with open(out, "w") as f:
        json.dump(doc, f)
    return out


# UNBOUNDED: the views whose error no bound derived here covers, held to check_follows alone (views_of decides):
# - a slot that blends its tiles by height (rock_blend's albedo and normal, their values and weights, and the material's
#   shading) moves with 1 / sum_j W_j f_j (tests/execution/checks.h, heightTolerance), which only the reference's
#   per-pixel details give;
# - a layered material's shading moves with its layers' weights, whose bound needs the reference's per-pixel splat
#   weights and heights (tests/execution/layer_checks.h);
# - a triplanar material's shading perturbs the normal by a world-space surface gradient, which lit_interval does not
#   model.


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def set_view(**view):
    DRIVER.execute_script("window.hexcEdit.setView(arguments[0]);", view)


class Views(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="hexc-edit-views-")
        self.figures = {}  # view -> [(material, slot, figure)]
        self.control = {}  # rock's values of albedo and normal: (image, reference, bound, channels), for the negative controls

    def tearDown(self):
        shutil.rmtree(self.folder, ignore_errors=True)

    def record(self, view, where, problems, figure):
        self.figures.setdefault(view, []).append((where, figure))
        self.assertFalse(problems, "%s of %s" % (view, where))

    def judge(self, view, where, gpu, ref, bound, channels, follows=False):
        """`follows`: no bound derived, check_follows alone; else check_image and check_follows."""
        if not follows:
            self.record(view, where, *check_image(gpu, ref, bound, channels))
        self.record(view + " (correlation)", where, *check_follows(gpu, ref, channels))

    def read(self, **view):
        set_view(**view)
        wait_idle(DRIVER)
        return read_view(SIZE, SIZE)

    def test_every_view_of_every_example(self):
        started = time.monotonic()
        for material in examples():
            with self.subTest(material=material):
                began = time.monotonic()
                server = Server(HEXC, material, "--root", "materials")
                try:
                    DRIVER.get(server.url)
                    state = wait_idle(DRIVER, 1, "the page of " + material)
                    self.assertEqual(state["status"], "ready", state["shown"])
                    self.views_of(material, server)
                finally:
                    server.stop()
                    print("  %s: %.1f s" % (material, time.monotonic() - began))
        print("  %-26s %-44s %s" % ("view", "worst (error / bound, or correlation)", "over"))
        for view, figures in sorted(self.figures.items()):
            where, figure = max(figures, key=lambda f: f[1]) if "correlation" not in view else min(figures, key=lambda f: f[1])
            print("  %-26s %-44s %d cases" % (view, "%.3f at %s" % (figure, where), len(figures)))
        print("  %.1f s" % (time.monotonic() - started))
        self.negative_controls()

    def views_of(self, material, server):
        with open(material) as f:
            doc = json.load(f)
        entries = slot_entries(doc)
        base = os.path.dirname(material)
        tiling = lambda e: settings(doc, e).get("tiling", 1)
        texels = max(max(png_size(os.path.join(base, e["slot"]["texture"]))) * max(tiling(e) if isinstance(tiling(e), list) else [tiling(e)])
                     for e in entries)
        span = SIZE * 0.75 / texels  # at most 0.75 texel per pixel in every slot: level 0 only
        rect = [0.3, 0.45, 0.3 + span, 0.45 + span]
        flat = dict(shape="flat", rect=rect)
        out = lambda name: os.path.join(self.folder, name + ".pfm")
        triplanar = doc.get("hextiling", {}).get("projection") == "triplanar"
        layered = "layers" in doc
        height = any("height_blend" in e["slot"] for e in entries)
        refs, errors, weights = {}, {}, {}
        for e in entries:
            output, channels, bound, weights_bound = slot_bounds(server, doc, e)
            if triplanar and e["slot"]["kind"] == "normal":
                bound *= math.sqrt(2)  # the planes' derivatives lifted to a world gradient: per component, at most |dd|
            DRIVER.execute_script("window.hexcEdit.selectSlot(arguments[0]);", e["name"])
            where = "%s %s" % (material, e["name"])
            values = self.read(output="values", **flat)
            ref = render(material, output, rect, out("values"), e["name"], reference=True)
            self.judge("values", where, values, ref, bound, channels, follows="height_blend" in e["slot"])
            if material == "materials/rock.json":
                self.control[e["name"]] = (values, ref, bound, channels)
            refs[e["slot"]["name"]], errors[e["slot"]["name"]] = ref, bound
            ref = render(material, "weights", rect, out("weights"), e["name"], reference=True)
            weights[e["name"]] = (ref, weights_bound, "height_blend" in e["slot"])
            self.judge("weights", where, self.read(output="weights", **flat), *weights[e["name"]][:2], 3, follows=weights[e["name"]][2])
        template = "unlit" if doc.get("template") == "unlit" else "lit"  # any other is shown with lit (engine_rock's)
        unbounded = layered or triplanar or height
        hex_ref = render(material, "shaded", rect, out("shaded"))
        hex_bound = None if unbounded else shaded_bound(template, refs, errors)
        self.judge("hex-tiled", material, self.read(output="hex", **flat), hex_ref, hex_bound, 3, follows=unbounded)
        plain = plain_copy(material, self.folder)
        plain_ref = render(plain, "shaded", rect, out("plain"))
        plain_bound = None
        if not (layered or triplanar):  # plain tiling blends nothing: each sample's own error
            plain_refs, plain_errors = {}, {}
            for e in entries:
                output, _, _, _ = slot_bounds(server, doc, e)
                plain_refs[e["name"]] = render(plain, output, rect, out("plain_values"), e["name"], reference=True)
                _, max_deriv, min_z = texture_bounds(server, e["name"], False)
                plain_errors[e["name"]] = 2 * E_S * (1 + max_deriv) / min_z if output == "derivative" else E_S
            plain_bound = shaded_bound(template, plain_refs, plain_errors)
        self.judge("plain tiling", material, self.read(output="plain", **flat), plain_ref, plain_bound, 3, follows=plain_bound is None)
        # The split: plain tiling, hex-tiling and the selected slot's weights side by side, each as its own view.
        DRIVER.execute_script("window.hexcEdit.selectSlot(arguments[0]);", entries[0]["name"])
        split = self.read(output="split", split=[1 / 3, 2 / 3], **flat)
        w_ref, w_bound, w_follows = weights[entries[0]["name"]]
        for (left, right), ref, bound, follows, name in (((0, SIZE // 3), plain_ref, plain_bound, plain_bound is None, "plain"),
                                                         ((SIZE // 3, 2 * SIZE // 3), hex_ref, hex_bound, unbounded, "hex"),
                                                         ((2 * SIZE // 3, SIZE), w_ref, w_bound, w_follows, "weights")):
            cut = lambda rows: [row[left:right] for row in rows]
            self.judge("split: " + name, material, cut(split), cut(ref), cut(bound) if isinstance(bound, list) else bound, 3, follows=follows)
        self.light(material, doc, entries, template, triplanar, layered)

    def light(self, material, doc, entries, template, triplanar, layered):
        """The light moved on the ground plane: no `hexc render` counterpart (see check_light)."""
        # Close enough that the normal map is magnified: the shading of filtered normals is then the shading of the
        # normals the values view shows.
        plane = dict(shape="plane", camera={"azimuth": -70, "elevation": 25, "distance": 0.05})
        east = self.read(output="hex", light={"azimuth": 0, "elevation": 55}, **plane)
        west = self.read(output="hex", light={"azimuth": 180, "elevation": 55}, **plane)
        normal = next((e for e in entries if e["slot"]["kind"] == "normal"), None)
        for image in (east, west):
            problems = ["not finite"] if not all(v is not None and math.isfinite(v) for row in image for p in row for v in p[:3]) else []
            problems += ["constant"] if not problems and max(p[0] for row in image for p in row) - min(p[0] for row in image for p in row) < 1e-3 else []
            self.record("light: finite, not constant", material, problems, 0.0)
        if template == "unlit" or triplanar:
            # unlit reads no light; a triplanar material's light stays fixed (its frame is the world's).
            self.record("light: unlit, triplanar fixed", material, [] if east == west else ["the image moved with the light"], 0.0)
        elif normal and not layered:
            DRIVER.execute_script("window.hexcEdit.selectSlot(arguments[0]);", normal["name"])
            derivative = self.read(output="values", **plane)
            problems, r = check_light(east, west, derivative, math.radians(55))
            self.record("light (correlation)", material, problems, r)
            self.light_control = (east, west, derivative)
        elif normal:
            # A layered normal role: its blend is not a view of the page, so the image must move with the light.
            self.record("light: layered, moves", material, [] if east != west else ["the light moved nothing"], 0.0)

    def negative_controls(self):
        """Each check run on deliberately wrong images must fail: the values of rock's albedo flipped in v, with a NaN,
        constant, with two channels swapped; rock's normal's derivative with x and y swapped; the same wrong images
        against check_follows; the light's normals mirrored in u and with x and y swapped."""
        controls = {}
        for slot in ("albedo", "normal"):
            gpu, ref, bound, channels = self.control[slot]
            self.assertEqual(check_image(gpu, ref, bound, channels)[0], [])  # the right image passes
            self.assertEqual(check_follows(gpu, ref, channels)[0], [])
            swapped = [[[p[1], p[0]] + p[2:] for p in row] for row in gpu]
            wrong = {"flipped in v": gpu[::-1], "swapped channels": swapped,
                     "a NaN": [[[None] + p[1:] if (x, y) == (7, 5) else p for x, p in enumerate(row)] for y, row in enumerate(gpu)],
                     "constant": [[gpu[0][0]] * SIZE for _ in range(SIZE)]}
            for name, image in wrong.items():
                for check, (problems, _) in (("check_image", check_image(image, ref, bound, channels)),
                                             ("check_follows", check_follows(image, ref, channels))):
                    controls["%s %s, %s" % (slot, name, check)] = problems
        east, west, derivative = self.light_control
        mirrored = [row[::-1] for row in derivative]
        swapped = [[[p[1], p[0]] + p[2:] for p in row] for row in derivative]
        for name, d in (("mirrored in u", mirrored), ("x and y swapped", swapped)):
            controls["light, normals " + name] = check_light(east, west, d, math.radians(55))[0]
        for name, problems in sorted(controls.items()):
            print("  negative control %-44s fails: %s" % (name, "; ".join(problems) or "NO"))
        self.assertEqual([name for name, problems in controls.items() if not problems], [], "negative controls that pass")


if __name__ == "__main__":
    run_with_browser(sys.modules[__name__], page_test, window=SMALL_WINDOW)
