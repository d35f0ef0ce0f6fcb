"""hexc edit's page in headless Chromium (WebGL 2 on ANGLE and SwiftShader): it compiles and links hexc's GLSL ES 3.00
for every example, its pixels match the fp64 reference, a slider changes the image as a compile with that value does,
save round-trips, a broken edit shows its diagnostic, and a change on disk reloads the material.

Usage: page_test.py HEXC  (from the source root)
"""
import glob
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import unittest
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from edit_support import SMALL_WINDOW, Server, read_pfm, rock_copy, run_with_browser, wait_for, wait_idle, page_state  # noqa: E402

HEXC = None
DRIVER = None

# Rock's textures are 256^2 at tiling 4: 1024 texels per uv unit. 96 pixels over 96 * 0.75 / 1024 uv is 0.75 texel per
# pixel: magnified, every fetch reads mip level 0 only, so the mip chain WebGL builds plays no part.
SIZE = 96
RECT = [0.3, 0.45, 0.3 + SIZE * 0.75 / 1024, 0.45 + SIZE * 0.75 / 1024]
# The terrain's layer views read back at W x W pixels, its whole splat map in texture space.
W = 24


def write_png(path, width, height, rows):
    """An 8-bit RGB PNG of `rows` (lists of r, g, b values, top row first)."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    raw = b"".join(b"\x00" + bytes(row) for row in rows)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) + chunk(b"IDAT", zlib.compress(raw))
                + chunk(b"IEND", b""))

# ---- Tolerances ----------------------------------------------------------------------------------------------------
# The page reads its float framebuffer (RGBA32F), so the shader's values come back unrounded; what differs from the fp64
# reference is texture filtering. Assumed no finer than lavapipe's (tests/execution/checks.h, sampleError):
# 8-bit bilinear weights put a magnified sample of 8-bit texels within half a weight step per axis plus the rounding
# of the result, e_s = 1.2/255. (An sRGB texture is decoded before filtering, by the reference too; at level 0 no
# stored mip adds its rounding.)
E_S = 1.2 / 255


def blend_tolerance(ex, em, hex, spread):
    """The falloff blend R = sum W_j x_j moves with its samples (ex) and through its weights: W_j is proportional to
    delta_j w_j^gamma with delta = (1 - beta) + beta * metric, so a metric error em moves R by at most
    em * beta / (1 - beta) * sum_j W_j |x_j - R| <= em * beta / (1 - beta) * spread, the gain of Eq. 5 multiplying weight
    changes by at most its steepest slope k = log2(1 / (1 - falloff)) (1 at or below 0.5). `spread` bounds |x_j - R| by
    the range of the texture's values (the execution tests use each pixel's own samples; the page gives none, so this is
    the bound over the whole texture)."""
    beta = hex.get("falloffcontrast", 0.6)
    k = max(1.0, math.log2(1.0 / (1.0 - hex.get("falloff", 0.5))))
    return ex + em * k * beta / (1.0 - beta) * spread


def srgb_to_linear(c):
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def texture_bounds(server, slot, srgb):
    """Largest value range of an RGB channel (linear), and for a normal map its largest |dH/du|, |dH/dv| and least z."""
    status, headers, data = server.request("GET", "/api/texture/" + slot)
    assert status == 200, data
    lo, hi = [math.inf] * 3, [-math.inf] * 3
    max_deriv, min_z = 0.0, 1.0
    for i in range(0, len(data), 4):
        rgb = [data[i + c] / 255 for c in range(3)]
        values = [srgb_to_linear(c) for c in rgb] if srgb else rgb
        for c in range(3):
            lo[c], hi[c] = min(lo[c], values[c]), max(hi[c], values[c])
        z = 2 * rgb[2] - 1
        if z > 0:
            min_z = min(min_z, z)
            max_deriv = max(max_deriv, abs(2 * rgb[0] - 1) / z, abs(2 * rgb[1] - 1) / z)
    return max(h - l for h, l in zip(hi, lo)), max_deriv, min_z


def load(server):
    DRIVER.get(server.url)
    return wait_idle(DRIVER, 1, "the page of " + server.url)


def read_view(width, height):
    """The current view's pixels as the page's float framebuffer holds them, rows top first."""
    flat = DRIVER.execute_script("return window.hexcEdit.readFloat(arguments[0], arguments[1]);", width, height)
    rows = [[flat[(y * width + x) * 4:(y * width + x) * 4 + 4] for x in range(width)] for y in range(height)]
    return rows[::-1]  # WebGL reads the bottom row first


def edit_control(pointer, value, kind="select", event="change"):
    """Sets a control of the panel as a user does: its element's value, then the event the page listens to."""
    DRIVER.execute_script("const e = document.querySelector(`[data-pointer=\"${arguments[0]}\"] ${arguments[2]}`);"
                          "e.value = arguments[1]; e.dispatchEvent(new Event(arguments[3]));", pointer, value, kind, event)


class Page(unittest.TestCase):
    def setUp(self):
        self.folder, self.material, self.original = rock_copy("hexc-edit-page-")
        self.servers = []

    def tearDown(self):
        for s in self.servers:
            s.stop()
        shutil.rmtree(self.folder, ignore_errors=True)

    def serve(self, material):
        self.servers.append(Server(HEXC, material))
        return self.servers[-1]

    def test_every_example_compiles_and_links(self):
        examples = sorted(set(glob.glob("materials/*.json")) - {"materials/material.schema.json"})
        self.assertGreaterEqual(len(examples), 7)
        for material in examples:
            with self.subTest(material=material):
                server = self.serve(material)
                state = load(server)
                self.assertEqual(state["status"], "ready", state["shown"])
                self.assertEqual(sorted(state["programs"]), ["hex", "plain", "values", "weights"])
                self.assertFalse([d for d in state["shown"] if "error" in d], state["shown"])
                pixels = read_view(8, 8)  # drawn: not the background everywhere
                self.assertTrue(any(abs(p[0] - 0.18) > 0.01 for row in pixels for p in row))
                template = DRIVER.find_element("id", "template").text
                if "engine" in material:  # its template declares resources of its own
                    self.assertIn("shown with template lit", template)
                server.stop()
                self.servers.remove(server)

    def gentle_normal_material(self):
        """A material of one normal map with gentle slopes, |dH/du|, |dH/dv| <= 0.4: rock's steepest texels (slopes near
        the horizontal) make the bound of Listing 9's division too wide to tell anything (it grows as 1 / min z)."""
        size = 128
        rows = []
        for y in range(size):
            row = []
            for x in range(size):
                n = [-0.4 * math.cos(2 * math.pi * 2 * (x + 0.5) / size), -0.4 * math.cos(2 * math.pi * 3 * (y + 0.5) / size), 1.0]
                length = math.sqrt(sum(c * c for c in n))
                row += [round((c / length * 0.5 + 0.5) * 255) for c in n]
            rows.append(row)
        write_png(os.path.join(self.folder, "textures", "gentle_normal.png"), size, size, rows)
        material = os.path.join(self.folder, "gentle.json")
        with open(material, "w") as f:
            json.dump({"name": "gentle", "hextiling": {"tiling": [4, 4]},
                       "slots": [{"name": "normal", "texture": "textures/gentle_normal.png", "kind": "normal"}]}, f)
        return material

    def test_values_match_the_reference(self):
        gentle = self.gentle_normal_material()
        # (material, slot, what `hexc render` calls its values, texels per uv unit)
        for material, slot, output, texels in ((self.material, "albedo", "albedo", 1024), (self.material, "roughness", "albedo", 1024),
                                               (gentle, "normal", "derivative", 512)):
            with self.subTest(slot=slot):
                server = self.serve(material)
                load(server)
                # 0.75 texel per pixel: magnified, every fetch reads mip level 0 only (WebGL's mip chain plays no part).
                rect = [0.3, 0.45, 0.3 + SIZE * 0.75 / texels, 0.45 + SIZE * 0.75 / texels]
                DRIVER.execute_script("window.hexcEdit.setView({shape: 'flat', output: 'values', rect: arguments[0]});", rect)
                compiles = page_state(DRIVER)["compiles"]
                DRIVER.execute_script("window.hexcEdit.selectSlot(arguments[0]);", slot)
                # The views of every slot are one program: selecting a slot links it again, with no compile.
                self.assertEqual(wait_idle(DRIVER, compiles)["compiles"], compiles)
                gpu = read_view(SIZE, SIZE)
                reference = os.path.join(self.folder, slot + ".pfm")
                subprocess.run([HEXC, "render", material, "--reference", "--output", output, "--slot", slot, "--size", "%dx%d" % (SIZE, SIZE),
                                "--uv-rect", ",".join(map(str, rect)), "-o", reference, "-q"], check=True)
                _, _, ref = read_pfm(reference)
                with open(material) as f:
                    doc = json.load(f)
                entry = next(s for s in doc["slots"] if s["name"] == slot)
                hex = {**doc["hextiling"], **entry.get("hextiling", {})}
                srgb = entry.get("colorspace", "srgb" if entry["kind"] == "color" else "linear") == "srgb"
                spread, max_deriv, min_z = texture_bounds(server, slot, srgb)
                if output == "derivative":
                    # Listing 9: d = -xy / z with x, y, z = 2 * texel - 1 each off by 2 e_s, so |dd| <= 2 e_s (1 + max|d|) / min z;
                    # the slope metric moves by at most sqrt(2) |dd|; the samples' spread per component is at most 2 max|d|.
                    ed = 2 * E_S * (1 + max_deriv) / min_z
                    tolerance, channels = blend_tolerance(ed, math.sqrt(2) * ed, hex, 2 * max_deriv), 2
                else:
                    tolerance, channels = blend_tolerance(E_S, E_S, hex, spread), 3
                errors = [abs(g[c] - r[c]) for gr, rr in zip(gpu, ref) for g, r in zip(gr, rr) for c in range(channels)]
                worst, mean = max(errors), sum(errors) / len(errors)
                print("  %-9s max error %.5f (%.2f/255), mean %.6f, tolerance %.5f (%.2f/255)" % (slot, worst, worst * 255, mean, tolerance,
                                                                                                  tolerance * 255))
                self.assertLessEqual(worst, tolerance)
                self.assertGreater(max(abs(r[c]) for row in ref for r in row for c in range(channels)), 10 * tolerance)  # not flat

    def test_slider_changes_the_image_as_a_compile_with_that_value(self):
        server = self.serve(self.material)
        load(server)
        DRIVER.execute_script("window.hexcEdit.setView({shape: 'flat', output: 'hex', rect: arguments[0]});", RECT)
        state = wait_idle(DRIVER)
        before = read_view(SIZE, SIZE)
        # The slider spans falloff's range, 1e-6 to 1 - 1e-6, in steps of 0.001: at 0.6 it reads 0.5999998, which the panel
        # rounds to the 4 digits a slider resolves, 0.6.
        edit_control("/hextiling/falloff", "0.6", "input[type=range]", "input")
        wait_for(lambda: page_state(DRIVER)["liveEdits"] == state["liveEdits"] + 1, "the slider's edit")
        moved = wait_idle(DRIVER)
        self.assertEqual(moved["compiles"], state["compiles"], "a slider must not compile")
        after = read_view(SIZE, SIZE)
        self.assertNotEqual(before, after, "falloff 0.6 must change the image")
        DRIVER.find_element("id", "save").click()
        wait_for(lambda: DRIVER.find_element("id", "status").text == "saved", "the save")
        with open(self.material, "rb") as f:
            self.assertEqual(f.read(), self.original.replace(b'"falloff": 0.75', b'"falloff": 0.6'))
        load(server)  # the saved material, compiled with 0.6 from the start
        DRIVER.execute_script("window.hexcEdit.setView({shape: 'flat', output: 'hex', rect: arguments[0]});", RECT)
        wait_idle(DRIVER)
        self.assertEqual(read_view(SIZE, SIZE), after)

    def test_the_cost_line_counts_the_shipped_shader(self):
        server = self.serve(self.material)
        load(server)
        line = wait_for(lambda: "fetches/pixel" in DRIVER.find_element("id", "cost").text and DRIVER.find_element("id", "cost").text, "the cost line")
        # What `hexc MATERIAL -o DIR` writes, disassembled by SPIRV-Tools' spirv-dis: texture fetches and the instructions
        # inside its functions (spirv-opt inlines all into main, so each runs at most once per pixel).
        out = os.path.join(self.folder, "shipped")
        subprocess.run([HEXC, self.material, "-o", out, "--target", "spirv", "-q", "--no-cache"], check=True)
        text = subprocess.run(["spirv-dis", os.path.join(out, "rock.frag.spv")], check=True, capture_output=True, text=True).stdout
        fetches = instructions = 0
        inside = False
        for words in (l.split() for l in text.splitlines()):
            op = words[2] if len(words) > 2 and words[1] == "=" else (words[0] if words else "")
            inside |= op == "OpFunction"
            instructions += inside and op.startswith("Op")
            inside &= op != "OpFunctionEnd"
            fetches += op.startswith("OpImageSample") or op in ("OpImageFetch", "OpImageGather")
        self.assertRegex(line, r"^%d fetches/pixel · %d SPIR-V instructions · compiled in \d+ ms$" % (fetches, instructions))

    def test_terrain_shows_its_layers(self):
        """materials/terrain: the layered material drawn on the ground plane, the cost line with its layers' fetches per
        pixel as the shipped manifest counts them, every layer's slots in the panel (inheriting their layer's settings),
        and an edit of a layer's slot compiled and drawn."""
        self.servers.append(Server(HEXC, "materials/terrain/terrain.json", "--root", "materials"))
        state = load(self.servers[-1])
        self.assertEqual(state["status"], "ready", state["shown"])
        self.assertEqual(sorted(state["programs"]), ["hex", "plain", "values", "weights"])
        out = os.path.join(self.folder, "terrain")
        subprocess.run([HEXC, "materials/terrain/terrain.json", "-o", out, "--target", "spirv", "-q", "--no-cache"], check=True)
        with open(os.path.join(out, "terrain.manifest.json")) as f:
            fetches = json.load(f)["layers"]["fetches_per_pixel"]
        line = wait_for(lambda: "fetches/pixel" in DRIVER.find_element("id", "cost").text and DRIVER.find_element("id", "cost").text, "the cost line")
        self.assertIn(" · layers %.1f expected / %d worst fetches/pixel · " % (fetches["expected"], fetches["worst"]), line)
        options = DRIVER.execute_script("return [...document.querySelectorAll('#slot-select option')].map(o => o.textContent);")
        self.assertEqual(options, ["%s_%s (%s)" % (layer, role, kind) for layer in ("grass", "sand", "pebbles", "snow")
                                   for role, kind in (("albedo", "color"), ("normal", "normal"), ("height", "scalar"))])
        DRIVER.execute_script("window.hexcEdit.selectSlot('sand_albedo');")
        tiling = '[data-pointer="/layers/1/slots/0/hextiling/tiling"] .default'
        self.assertIn("default 6", DRIVER.find_element("css selector", tiling).get_attribute("textContent"))  # the sand layer's own
        # The sand albedo's values in texture space: hex-tiled with three taps, then with one. Each is a picture (finite,
        # not flat: tests/edit/views_test.py holds every layer's views to `hexc render`), and the edit changes it.
        DRIVER.execute_script("window.hexcEdit.setView({shape: 'flat', output: 'values', rect: [0, 0, 1, 1]});")
        state = wait_idle(DRIVER, state["compiles"])
        before = read_view(24, 24)
        edit_control("/layers/1/slots/0/hextiling/taps", "1")
        wait_for(lambda: DRIVER.execute_script("return window.hexcEdit.document().layers[1].slots[0].hextiling.taps === 1;"), "the edit")
        after_edit = wait_idle(DRIVER, state["compiles"] + 1, "the edit's compile")
        self.assertEqual(after_edit["status"], "ready", after_edit["shown"])
        after = read_view(24, 24)
        for image in (before, after):
            values = [p[c] for row in image for p in row for c in range(3)]
            self.assertTrue(all(v is not None and math.isfinite(v) for v in values), "NaN in the sand albedo's values")  # null: NaN
            self.assertGreater(max(values) - min(values), 0.05, "the sand albedo's values are flat")
        self.assertNotEqual(after, before)
        self.layer_blend_controls(after_edit["compiles"])

    def layer_blend_controls(self, compiles):
        """The terrain's layer blend in the panel (its page still open, to start no other): the width a uniform, set
        without a compile as a compile with that width draws it; a width outside (0, 1] refused with a message; the mode
        a compile that changes the layer weight view, which in linear mode is the splat map as the splat map view reads
        it, kept and renormalised; and every one of these edits a step of the undo history."""
        original = DRIVER.execute_script("return window.hexcEdit.document().layer_blend;")
        DRIVER.execute_script("window.hexcEdit.selectLayer(0);"
                              "window.hexcEdit.setView({shape: 'flat', output: 'layer', rect: [0, 0, 1, 1]});")
        state = wait_idle(DRIVER, compiles)
        self.assertEqual(sorted(state["programs"]), ["hex", "layer", "plain", "splat", "values", "weights"])
        height_02 = read_view(W, W)
        number = '[data-pointer="/layer_blend/width"] input[type=number]'
        edit_control("/layer_blend/width", "0.5", "input[type=number]")
        moved = wait_idle(DRIVER)
        self.assertEqual((moved["compiles"], moved["liveEdits"]), (state["compiles"], state["liveEdits"] + 1), "the width is a uniform")
        height_05 = read_view(W, W)
        self.assertNotEqual(height_05, height_02, "the width must change the layer weights")
        DRIVER.execute_script("window.hexcEdit.setView({output: 'splat'}); window.hexcEdit.setView({output: 'layer'});")
        wait_idle(DRIVER)
        self.assertEqual(read_view(W, W), height_05, "a view linked again keeps the width set live")
        for typed, shown in (("1.5", "1.5"), ("0", "0"), ("-0.1", "-0.1")):
            edit_control("/layer_blend/width", typed, "input[type=number]")
            self.assertEqual(DRIVER.find_element("id", "status").text,
                             "/layer_blend/width: %s is outside (0, 1], the range the material format allows; width stays 0.5; "
                             "edited (not saved)" % shown)
            self.assertEqual(DRIVER.find_element("css selector", number).get_attribute("value"), "0.5")
        refused = page_state(DRIVER)
        self.assertEqual((refused["compiles"], refused["liveEdits"]), (moved["compiles"], moved["liveEdits"]))
        self.assertEqual(DRIVER.execute_script("return window.hexcEdit.document().layer_blend.width;"), 0.5)
        edit_control("/layer_blend/mode", '"linear"')
        linear = wait_idle(DRIVER, moved["compiles"] + 1, "the mode's compile")
        self.assertEqual(linear["status"], "ready", linear["shown"])
        blend = DRIVER.execute_script("return window.hexcEdit.document().layer_blend;")
        self.assertEqual((blend["mode"], "height" in blend), ("linear", False))  # `height` is refused in linear mode
        weights = [read_view(W, W)]
        self.assertNotEqual(weights[0], height_05, "the mode must change the layer weights")
        DRIVER.execute_script("window.hexcEdit.setView({output: 'splat'});")
        wait_idle(DRIVER)
        splat = read_view(W, W)
        DRIVER.execute_script("window.hexcEdit.selectLayer(1); window.hexcEdit.setView({output: 'layer'});")
        wait_idle(DRIVER)
        weights.append(read_view(W, W))
        self.assertNotEqual(weights[1], weights[0], "layer 1's weights must differ from layer 0's")
        # Linear mode: w_i = s_i / sum_j s_j over the s_j >= skip_below (half an 8-bit step), the splat map's texels as the
        # splat map view reads them, at the same uv with the same gradients: the same filtered sample, so what differs is
        # fp32 rounding of a sum of four and a division (a few ulps of 1: 1e-5 is 80 of them). Wrong layer: must fail.
        def worst(layer, image):
            kept = [[[c if c >= 0.5 / 255 else 0.0 for c in p] for p in row] for row in splat]
            return max(abs(image[y][x][0] - (k[layer] / sum(k) if sum(k) > 0 else float(layer == 0)))
                       for y, row in enumerate(kept) for x, k in enumerate(row))
        for layer in (0, 1):
            print("  layer %d's weight against the splat map: max error %.2e" % (layer, worst(layer, weights[layer])))
            self.assertLess(worst(layer, weights[layer]), 1e-5)
            self.assertGreater(worst(1 - layer, weights[layer]), 0.1, "the check must fail on the other layer's weights")
        DRIVER.execute_script("window.hexcEdit.selectLayer(0);")
        DRIVER.find_element("id", "undo").click()  # the mode: height again, its `height` back, with width 0.5 compiled in
        undone = wait_idle(DRIVER, linear["compiles"] + 1, "the undo's compile")
        self.assertEqual(DRIVER.execute_script("return window.hexcEdit.document().layer_blend;"), dict(original, width=0.5))
        self.assertEqual(read_view(W, W), height_05, "the width compiled in must draw as the width set live")
        DRIVER.find_element("id", "undo").click()  # the width
        wait_idle(DRIVER, undone["compiles"] + 1, "the second undo's compile")
        self.assertEqual(DRIVER.execute_script("return window.hexcEdit.document().layer_blend;"), original)
        self.assertEqual(read_view(W, W), height_02)

    def test_vertex_colours_weigh_the_layers(self):
        """A layered material weighed by vertex colours alone, which the page paints (templates/edit/view.vert.glsl):
        in the texture-space view, layer 0 (flat red) gives way to layer 1 (flat blue) across the window, linearly:
        weights 1 - t and t with t the pixel's place across it, as `hexc render` paints them, on a window that is not
        the one from -1 to 1 (where painting by u, as on the meshes, gives the same)."""
        for name, rgb in (("red", [255, 0, 0]), ("blue", [0, 0, 255])):
            write_png(os.path.join(self.folder, "textures", name + ".png"), 4, 4, [rgb * 4] * 4)
        material = os.path.join(self.folder, "painted.json")
        with open(material, "w") as f:
            json.dump({"name": "painted", "template": "unlit", "layer_blend": {"weights": "vertex"},
                       "layers": [{"name": n, "slots": [{"name": "albedo", "kind": "color", "texture": "textures/%s.png" % n}]}
                                  for n in ("red", "blue")]}, f)
        state = load(self.serve(material))
        self.assertEqual(state["status"], "ready", state["shown"])
        DRIVER.execute_script("window.hexcEdit.setView({shape: 'flat', output: 'hex', rect: [0.2, 0.3, 0.7, 0.8]});")
        wait_idle(DRIVER, state["compiles"])
        width = 16
        # Flat textures filter to their texel exactly (0 and 1 decode exactly from sRGB), so what is left is fp32: the
        # interpolated colour and the weights' renormalisation, each within a few ulps of 1; 1e-4 is 800 ulps.
        for x, pixel in enumerate(read_view(width, 4)[2]):
            t = (x + 0.5) / width
            self.assertAlmostEqual(pixel[0], 1 - t, delta=1e-4, msg="red at column %d" % x)
            self.assertAlmostEqual(pixel[2], t, delta=1e-4, msg="blue at column %d" % x)

    def test_capture_writes_the_same_frame_every_time(self):
        frames = [os.path.join(self.folder, "frame%d.png" % i) for i in range(2)]
        for frame in frames:
            run = subprocess.run([HEXC, "edit", self.material, "--capture", frame, "--size", "64x48"], capture_output=True, text=True, timeout=600)
            self.assertEqual(run.returncode, 0, run.stderr)
        with open(frames[0], "rb") as a, open(frames[1], "rb") as b:
            png = a.read()
            self.assertEqual(png, b.read())  # a deterministic camera and renderer: the same bytes
        self.assertEqual(png[:8], b"\x89PNG\r\n\x1a\n")
        self.assertEqual(struct.unpack(">II", png[16:24]), (64, 48))
        with open(self.material, "wb") as f:  # a material that does not compile: its diagnostics, exit 1, no file
            f.write(self.original.replace(b'"kind": "scalar"', b'"kind": "scalr"'))
        broken = os.path.join(self.folder, "broken.png")
        run = subprocess.run([HEXC, "edit", self.material, "--capture", broken, "--size", "64x48"], capture_output=True, text=True, timeout=600)
        self.assertEqual(run.returncode, 1, run.stderr)
        self.assertRegex(run.stderr, r"rock\.json:\d+:\d+: error\[HX1\d\d\]: /slots/2/kind")
        self.assertFalse(os.path.exists(broken))

    def test_a_broken_edit_shows_the_located_diagnostic(self):
        server = self.serve(self.material)
        state = load(server)
        edit_control("/hextiling/mode", '"paper"')
        state = wait_idle(DRIVER, state["compiles"] + 1)
        self.assertEqual(state["status"], "ready", state["shown"])
        edit_control("/hextiling/mask", '"checker"')
        state = wait_idle(DRIVER, state["compiles"] + 1)
        self.assertEqual(state["status"], "error")
        # Located in the material as it would be saved (the page's two keys added to its hextiling), one per slot.
        self.assertEqual(len(state["shown"]), 3, state["shown"])
        for i, shown in enumerate(state["shown"]):
            self.assertRegex(shown, r"rock\.json:\d+:\d+: error\[HX112\]: /slots/%d(/hextiling)?: mask `checker` needs mode `stable`" % i)
        self.assertTrue(DRIVER.find_element("id", "diagnostics").is_displayed())
        pixels = read_view(8, 8)  # the last program that compiled still draws
        self.assertTrue(any(abs(p[0] - 0.18) > 0.01 for row in pixels for p in row))
        with open(self.material, "rb") as f:
            self.assertEqual(f.read(), self.original)

    def test_a_change_on_disk_reloads_and_keeps_the_view(self):
        server = self.serve(self.material)
        state = load(server)
        camera = {"azimuth": 12, "elevation": 21, "distance": 3.5}
        DRIVER.execute_script("window.hexcEdit.setView({shape: 'sphere', camera: arguments[0]});", camera)
        DRIVER.execute_script("window.hexcEdit.selectSlot('normal');")
        with open(self.material, "wb") as f:  # as another editor saves it
            f.write(self.original.replace(b'"falloff": 0.75', b'"falloff": 0.65'))
        state = wait_idle(DRIVER, state["compiles"] + 1, "the reload after the file changed")
        value = DRIVER.execute_script("return document.querySelector('[data-pointer=\"/hextiling/falloff\"] input[type=number]').value;")
        self.assertEqual(value, "0.65")
        view = DRIVER.execute_script("return window.hexcEdit.view();")
        self.assertEqual((view["shape"], view["camera"]), ("sphere", camera))
        self.assertEqual(DRIVER.execute_script("return document.getElementById('slot-select').value;"), "1")  # normal, kept
        texture = os.path.join(self.folder, "textures", "rock_normal.png")
        os.utime(texture, (os.stat(texture).st_atime, os.stat(texture).st_mtime + 5))  # a texture tool rewrote it
        wait_idle(DRIVER, state["compiles"] + 1, "the reload after a texture changed")

    def test_a_page_on_another_port_gets_nothing(self):
        # After the artist opened the page (its cookie set), a page served from another port of 127.0.0.1 is the same
        # site, so Chromium sends it the cookie. Whether a cross-origin image or script loads is visible to that page
        # (onload / onerror) for resources of a type that loads, such as the page's own style sheet and script: each must
        # be refused, and a save it posts must change nothing.
        server = self.serve(self.material)
        load(server)
        origin = "http://127.0.0.1:%d" % server.port
        page = ("<!doctype html><title>waiting</title><body><script>"
                "const results = {}; const done = () => { if (Object.keys(results).length == 3) document.title = JSON.stringify(results); };"
                "for (const [name, tag, path] of [['style', 'link', '/edit.css'], ['script', 'script', '/edit.js']]) {"
                "  const e = document.createElement(tag); e.onload = () => { results[name] = 'loaded'; done(); };"
                "  e.onerror = () => { results[name] = 'refused'; done(); };"
                "  if (tag == 'link') { e.rel = 'stylesheet'; e.href = '%s' + path; } else e.src = '%s' + path; document.body.appendChild(e); }"
                "fetch('%s/api/save', {method: 'POST', credentials: 'include', mode: 'no-cors', headers: {'Content-Type': 'text/plain'},"
                "  body: JSON.stringify({document: {name: 'taken'}, version: 0})}).then(() => { results.save = 'sent'; done(); },"
                "  () => { results.save = 'failed'; done(); });"
                "</script></body>") % (origin, origin, origin)
        other = os.path.join(self.folder, "other")
        os.makedirs(other)
        with open(os.path.join(other, "index.html"), "w") as f:
            f.write(page)
        attacker = subprocess.Popen([sys.executable, "-u", "-m", "http.server", "0", "--bind", "127.0.0.1", "--directory", other],
                                    stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        try:
            port = int(wait_for(lambda: attacker.stdout.readline().split(" port ")[1].split(" ")[0], "the other page's server"))
            DRIVER.get("http://127.0.0.1:%d/index.html" % port)
            results = json.loads(wait_for(lambda: DRIVER.title if DRIVER.title.startswith("{") else None, "the other page's requests"))
        finally:
            attacker.terminate()
            attacker.wait()
            attacker.stdout.close()
        self.assertEqual((results["style"], results["script"]), ("refused", "refused"), results)
        self.assertEqual(server.request("GET", "/api/version")[0], 200)  # still serving
        with open(self.material, "rb") as f:
            self.assertEqual(f.read(), self.original)


if __name__ == "__main__":
    run_with_browser(sys.modules[__name__], window=SMALL_WINDOW)
