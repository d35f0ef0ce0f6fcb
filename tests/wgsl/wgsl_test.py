"""hexc's WGSL in headless Chromium's WebGPU (Dawn, with Tint as its compiler, on SwiftShader): Tint accepts every WGSL file
hexc writes for the examples, the golden feature materials and the execution cases, optimised and --debug, fragment and
vertex stages, its uniformity analysis included; and Dawn draws every execution case (tests/execution/cases/), every case
of the feature variants' tables (VARIANTS) and every slot of the examples and MaterialX documents, each pixel within the
tolerance the lavapipe check derives for it, against
the same fp64 reference, from the same texels and mip levels (hexc-expect, tests/execution/expect.cpp, writes them and
the WGSL drawn).

Usage: wgsl_test.py HEXC HEXC_EXPECT   (from the source root, after `npm ci --prefix tests/node`, which installs naga-wasm)

One Chromium validates and draws everything: dawn.node (npm `webgpu`), started once per file, aborted in 13 of 48 runs
under load, and one dawn.node process validating many files crashed or hung too (docs/verification.md, "WGSL").
"""
import base64
import functools
import glob
import http.server
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import threading
import time
import unittest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "engines"))
from web_support import NODE_MODULES, WEBGPU_FLAGS, Handler, browser_or_skip, quit_browser, wait_for  # noqa: E402

HEXC = None
EXPECT = None  # hexc-expect (tests/execution/expect.cpp)
CASES = os.path.join("tests", "execution", "cases")
# The feature variants' tables whose cases hexc-expect checks as their lavapipe tests do (checks.h, "Feature variants
# as data"): odd texture sizes, packed slots and adaptive taps.
VARIANTS = tuple(os.path.join("tests", "execution", t) for t in ("odd_sizes", "packed", "adaptive"))
# The layered materials' cases (tests/execution/layers_test.cpp, layer_checks.h) drawn, as hexc-expect's FILE:CASE:
# one, two and eight layers (two splat maps), packed layers, the arrays' fallback to separate textures and a normal
# array, vertex-colour weights alone and times the splat map, the linear blend where three layers overlap, and the height
# blend at its default width, narrow and wide, with a normal role and under both weights. Left out, to keep the test's
# time: four_layers_linear and four_layers_separate (the images of eight_layers' and four_layers_sizes' code paths) and
# two_layers_vertex (four_layers_vertex's path).
LAYERS = [os.path.join("tests", "execution", "layers", f) for f in (
    "one.json:one_layer", "two.json:two_layers_linear", "two.json:two_layers_linear_soft", "eight.json:eight_layers",
    "four_packed.json:four_layers_packed", "four_sizes.json:four_layers_sizes", "four_sizes.json:four_layers_sizes_normal",
    "four_vertex.json:four_layers_vertex", "two_both.json:two_layers_both", "four_height.json:four_layers_height",
    "four_height.json:four_layers_height_soft", "four_height_narrow.json:four_layers_height_narrow",
    "four_height_wide.json:four_layers_height_wide", "four_height.json:four_layers_normal",
    "four_both_height.json:four_layers_both_height")]
# The material files whose slots tests/execution/outputs_test.cpp checks one at a time (slotOf, checkSlot): the examples
# (ExampleSlots, every slot) and the MaterialX documents (MaterialXDocuments).
EXAMPLES = ("rock", "rock_blend", "rock_normal", "rock_triplanar", "tiles", "tiles_stepped")
DOCUMENTS = ("materials/mtlx/rock.mtlx", "materials/mtlx/preview_surface.mtlx")


def slot_inputs():
    """hexc-expect's MATERIAL:SLOT inputs, one for each slot outputs_test.cpp checks."""
    inputs = []
    for name in EXAMPLES:
        path = "materials/%s.json" % name
        with open(path) as f:
            inputs += ["%s:%s" % (path, slot["name"]) for slot in json.load(f)["slots"]]
    return inputs + ["%s:%s" % (f, slot) for f in DOCUMENTS for slot in ("albedo", "normal", "roughness")]


def hexc(*args, env=None):
    result = subprocess.run([HEXC, *args, "-q"], capture_output=True, text=True, env=env)
    if result.returncode != 0:
        raise AssertionError("hexc %s failed: %s" % (" ".join(args), result.stderr))


def case_material(folder, name):
    """The execution case's material as a file in `folder` (its paths read from materials/, like the examples')."""
    with open(os.path.join(CASES, name + ".json")) as f:
        material = json.load(f)["material"]
    path = os.path.join(folder, name + ".json")
    with open(path, "w") as f:
        json.dump(material, f)
    return path


def differing(first, second):
    """The files under `first` (but the stamps, .NAME.hexc-stamp) whose bytes differ from the same path under `second`."""
    found = []
    for folder, _, names in os.walk(first):
        for name in sorted(n for n in names if not n.startswith(".")):
            path = os.path.join(folder, name)
            with open(path, "rb") as f, open(os.path.join(second, os.path.relpath(path, first)), "rb") as g:
                if f.read() != g.read():
                    found.append(os.path.relpath(path, first))
    return found


class Wgsl(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.mkdtemp(prefix="hexc-wgsl-test-")
        cls.cases = os.path.join(cls.folder, "cases")
        os.makedirs(cls.cases)
        os.symlink(os.path.abspath(os.path.join("materials", "textures")), os.path.join(cls.cases, "textures"))
        roots = {"/wgsl/": os.path.abspath(os.path.dirname(__file__)), "/out/": cls.folder}
        cls.httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Handler, roots=roots))
        threading.Thread(target=cls.httpd.serve_forever, daemon=True).start()
        cls.driver = browser_or_skip(WEBGPU_FLAGS)
        cls.driver.get("http://127.0.0.1:%d/wgsl/webgpu.html" % cls.httpd.server_address[1])
        wait_for(lambda: cls.driver.execute_script("return window.hexcReady;"), "the WebGPU page to load")
        cls.files = cls.compile_all(os.path.join(cls.folder, "tint"))

    @classmethod
    def compile_all(cls, folder, env=None):
        """The WGSL of every example, golden material, case, MaterialX document and scene, in both modes, with a vertex
        stage where asked (scenes: fragments only), written under `folder` by naga as `env` has hexc run it: their paths."""
        examples = sorted(p for p in glob.glob("materials/*.json") if not p.endswith("schema.json") and "engine_rock" not in p)
        examples += sorted(glob.glob("tests/golden/materials/*.json"))
        cases = [case_material(cls.cases, os.path.basename(p)[:-5]) for p in sorted(glob.glob(os.path.join(CASES, "*.json")))]
        cls.inputs = len(examples) + len(cases)
        files = []
        for mode in ([], ["--debug"]):
            for group, inputs, extra in (("examples", examples, ["--vertex"]), ("cases", cases, ["--vertex"]),
                                         ("mtlx", sorted(glob.glob("materials/mtlx/*.mtlx")), ["--vertex"]),
                                         ("scenes", sorted(glob.glob("materials/scenes/*.json")), [])):
                out = os.path.join(folder, group + "".join(mode))
                hexc(*inputs, "--targets", "wgsl", *extra, *mode, "-o", out, env=env)
                files += sorted(glob.glob(os.path.join(out, "*.wgsl")))
        return files

    @classmethod
    def tearDownClass(cls):
        quit_browser(cls.driver)
        cls.httpd.shutdown()
        cls.httpd.server_close()
        shutil.rmtree(cls.folder, ignore_errors=True)

    def call(self, function, *args):
        result = self.driver.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            "window.hexcWgsl[arguments[0]](...arguments[1]).then(done, (e) => done({error: String(e && e.stack || e)}));", function, args)
        if isinstance(result, dict) and "error" in result:
            raise AssertionError("the page failed: " + result["error"])
        return result

    def test_tint_accepts_every_wgsl_file_hexc_writes(self):
        files = self.files
        # The control: a sample in a branch on a stage input, which Tint's uniformity analysis must refuse.
        control = os.path.join(os.path.dirname(__file__), "nonuniform.wgsl")
        codes = []
        for path in files + [control]:
            with open(path) as f:
                codes.append(f.read())
        started = time.monotonic()
        verdicts = self.call("validate", codes)
        print("Tint validated %d WGSL files in %.1f s" % (len(files), time.monotonic() - started))
        self.assertIn("uniform control flow", " ".join(verdicts[-1]["errors"]))
        rejected = {path: v["errors"] for path, v in zip(files, verdicts) if v["errors"]}
        self.maxDiff = None
        self.assertEqual(rejected, {})
        # Every example, golden material and case, in both modes, with a vertex stage where asked (scenes: fragments only).
        self.assertGreater(len(files), 2 * 2 * self.inputs)
        print("Tint accepted all %d" % len(files))

    def test_naga_built_in_writes_what_naga_in_node_writes(self):
        """With naga built into hexc, the files Tint validates are, byte for byte, those naga in Node.js writes
        (HEXC_NAGA=node): every WGSL file and manifest (the stamps differ: they key the route)."""
        if "built in" not in subprocess.run([HEXC, "--version"], capture_output=True, text=True).stdout:
            self.skipTest("naga is not built into this hexc")
        started = time.monotonic()
        node = self.compile_all(os.path.join(self.folder, "node"), env={**os.environ, "HEXC_NAGA": "node"})
        print("naga in Node.js wrote %d WGSL files in %.1f s" % (len(node), time.monotonic() - started))
        built_in, by_node = os.path.join(self.folder, "tint"), os.path.join(self.folder, "node")
        self.assertEqual([os.path.relpath(p, by_node) for p in node], [os.path.relpath(p, built_in) for p in self.files])
        self.assertEqual(differing(built_in, by_node), [])
        # The control: one byte more in one file, and the comparison names that file.
        with open(node[0], "a") as f:
            f.write("\n")
        self.assertEqual(differing(built_in, by_node), [os.path.relpath(node[0], by_node)])

    def test_dawn_draws_every_case_within_its_bounds(self):
        """Every execution case (tests/execution/cases/, and the feature variants' tables: VARIANTS, LAYERS) and the
        examples' and MaterialX documents' slots (as
        outputs_test.cpp checks them), drawn by Dawn, each pixel held to the tolerance its lavapipe check derives for it
        (checks.h), against the same fp64 reference, with the same texels and mip levels: hexc-expect writes them, and
        the WGSL drawn (tests/execution/expect.cpp)."""
        inputs = [p for folder in (CASES,) + VARIANTS for p in sorted(glob.glob(os.path.join(folder, "*.json")))] + LAYERS + slot_inputs()
        out = os.path.join(self.folder, "draw")
        started = time.monotonic()
        subprocess.run([EXPECT, *inputs, "-o", out], check=True)
        print("hexc-expect wrote %d cases' WGSL, references, tolerances and textures in %.1f s" % (len(inputs), time.monotonic() - started))
        # Colours and weights in 1/255, slopes (derivative) as they are; the bound is the worst pixel's (largest error/bound).
        print("%-36s %-10s %10s %10s %10s %8s" % ("case", "output", "max", "mean", "bound", "max/bnd"))
        compiles = []
        for path in sorted(glob.glob(os.path.join(out, "*.expect.json"))):
            name = os.path.basename(path)[:-len(".expect.json")]
            with open(path) as f:
                expect = json.load(f)
            compiles.append((name, expect["compile_ms"]))
            with self.subTest(case=name):
                errors, ratios, bound = self.draw(name, expect, out)
                worst = max(range(len(ratios)), key=ratios.__getitem__)
                unit = 1 if expect["output"] == "derivative" or expect["channels"] == 2 else 255  # 2: a layered normal role's slopes
                print("%-36s %-10s %10.3f %10.4f %10.3f %8.3f" % (name, expect["output"], max(errors) * unit, sum(errors) / len(errors) * unit,
                                                                  bound * unit, ratios[worst]))
                self.assertLessEqual(ratios[worst], 1.0)
        self.assertEqual(len(glob.glob(os.path.join(out, "*.expect.json"))), len(inputs))
        print("slowest WGSL compile (SPIR-V, naga, vertex stage): %s, %.0f ms" % max(compiles, key=lambda c: c[1]))

    def render(self, stem, expect, out):
        """Draws the shader hexc-expect wrote as `stem` (stem.manifest.json, its WGSL) over the case's view, with the case's
        textures: RGBA float pixels, top row first."""
        width, height = expect["width"], expect["height"]
        with open(os.path.join(out, stem + ".manifest.json")) as f:
            manifest = json.load(f)
        fragment, vertex = manifest["targets"]["wgsl"], manifest["vertex"]["wgsl"]
        # The page feeds hexc's vertex stage the inputs its manifest lists, as the harness's draw does (webgpu.js, triangle).
        attributes = [{"location": a["location"], "feeds": a["feeds"]} for a in manifest["vertex"]["attributes"]]
        group = fragment["sampler"]["group"]
        self.assertEqual({t["group"] for t in fragment["textures"].values()}, {group})  # one bind group, as the page binds
        textures = []
        for texture, place in fragment["textures"].items():
            given = expect["textures"][texture]
            layers = [expect["textures"][t]["levels"] for t in given["array"]] if "array" in given else [given["levels"]]
            layers = [[dict(level, url="/out/draw/" + level["file"]) for level in levels] for levels in layers]
            textures.append({"binding": place["binding"], "format": given["format"], "layers": layers, "array": "array" in given})
        with open(os.path.join(out, fragment["file"])) as f, open(os.path.join(out, vertex["file"])) as g:
            result = self.call("render", {"fragment": f.read(), "vertex": g.read(), "fragmentEntry": fragment["entry_point"],
                                          "vertexEntry": vertex["entry_point"], "attributes": attributes, "textures": textures, "sampler": fragment["sampler"],
                                          "width": width, "height": height, "rect": expect["uv"]})
        return struct.unpack("<%df" % (width * height * 4), base64.b64decode(result["pixels"]))

    def draw(self, name, expect, out):
        """Draws the case with Dawn: each pixel's largest error over the case's channels and its largest error/tolerance
        (a tolerance a pixel, or one a channel: tolerance_channels), and the tolerance where that ratio is largest."""
        width, height, channels, per = expect["width"], expect["height"], expect["channels"], expect["tolerance_channels"]
        gpu = self.render(name, expect, out)
        ref, tolerances = (raw_floats(os.path.join(out, expect[key])) for key in ("reference", "tolerance"))
        if "adaptive" in expect:
            tolerances = self.adaptive(expect, out, gpu, tolerances)
        # Channel by channel, over whole images (a loop per pixel and channel costs seconds over all cases).
        tolerance = [tolerances[min(c, per - 1)::per] for c in range(channels)]
        errors = [[d if d == d else math.inf for d in (abs(g - r) for g, r in zip(gpu[c::4], ref[c::4]))] for c in range(channels)]
        ratios = [[e / t for e, t in zip(errors[c], tolerance[c])] for c in range(channels)]
        worst_ratios = list(map(max, *ratios)) if channels > 1 else ratios[0]
        worst = max(range(width * height), key=worst_ratios.__getitem__)
        channel = max(range(channels), key=lambda c: ratios[c][worst])
        # Not vacuous: a blank draw would fail at one pixel in twenty or more (normal_minified, whose tolerances are wide
        # against its minified slopes: 9%).
        blank = sum(map(any, zip(*([abs(r) > t for r, t in zip(ref[c::4], tolerance[c])] for c in range(channels)))))
        self.assertGreater(blank, width * height / 20)
        return list(map(max, *errors)) if channels > 1 else errors[0], worst_ratios, tolerance[channel][worst]

    def adaptive(self, expect, out, gpu, tolerances):
        """Adaptive taps as cases_test.cpp's AdaptiveTaps checks them, on Dawn: 1. the taps fetched (the weights output's
        non-zero weights) differ from the reference's at no more than 1% of the pixels, and something is skipped. Returns
        check 2's tolerances: the other-taps one where Dawn fetches other taps than the reference. Check 3 (adaptive
        against exact 3-tap on the same GPU) is lavapipe's only: a third shader a case would cost about 10 s here."""
        a, pixels = expect["adaptive"], expect["width"] * expect["height"]
        weights = self.render(a["weights"], expect, out)
        with open(os.path.join(out, a["fetched"]), "rb") as f:
            fetched = f.read()
        gpu_fetched = [w > 0 for p in range(pixels) for w in weights[p * 4:p * 4 + 3]]
        differs = [gpu_fetched[p * 3:p * 3 + 3] != [bool(x) for x in fetched[p * 3:p * 3 + 3]] for p in range(pixels)]
        print("  fetches per pixel %.3f (reference %.3f), %d pixels fetch other taps" % (
            sum(gpu_fetched) / pixels, sum(fetched) / pixels, sum(differs)))
        self.assertLessEqual(sum(differs), pixels // 100)
        self.assertLess(sum(gpu_fetched) / pixels, 3.0)  # something is skipped
        other = raw_floats(os.path.join(out, a["other_taps"]))
        return [o if d else t for d, o, t in zip(differs, other, tolerances)]


def raw_floats(path):
    with open(path, "rb") as f:
        data = f.read()
    return struct.unpack("<%df" % (len(data) // 4), data)


if __name__ == "__main__":
    HEXC = os.path.abspath(sys.argv.pop(1))
    EXPECT = os.path.abspath(sys.argv.pop(1))
    if not os.path.isdir(os.path.join(NODE_MODULES, "naga-wasm")):
        print("no naga-wasm in %s: run `npm ci --prefix tests/node`" % NODE_MODULES)
        sys.exit(1 if os.environ.get("HEXC_REQUIRE_BROWSER") == "1" else 77)
    os.environ["HEXC_NODE_PATH"] = os.path.abspath(NODE_MODULES)
    unittest.main(verbosity=2)
