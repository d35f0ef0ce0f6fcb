"""hexc's WGSL in headless Chromium's WebGPU (Dawn, with Tint as its compiler, on SwiftShader): Tint accepts every WGSL file
hexc writes for the examples, the golden feature materials and the execution cases, optimised and --debug, fragment and
vertex stages, its uniformity analysis included; and Dawn draws the execution cases' materials within the bounds the
WebGL page is held to against the fp64 reference (tests/edit/page_test.py).

Usage: wgsl_test.py HEXC   (from the source root, after `npm ci --prefix tests/node`, which installs naga-wasm)

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
from web_support import (E_S, NODE_MODULES, WEBGPU_FLAGS, Handler, blend_tolerance, browser_or_skip, quit_browser, read_pfm,  # noqa: E402
                         texture_bounds, wait_for)

HEXC = None
CASES = os.path.join("tests", "execution", "cases")
# The named views of tests/execution/ (cases_test.cpp) that read mip level 0 only (the page uploads level 0 alone):
# magnified, 0.75 texel per pixel of a 256^2 texture at tiling 4; origin, the paper's hash near the origin.
VIEWS = {"magnified": (192, [0.3, 0.45, 0.3 + 192 * 0.75 / 1024, 0.45 + 192 * 0.75 / 1024]), "origin": (192, [0.0, 0.0, 0.02, 0.02])}


def hexc(*args):
    result = subprocess.run([HEXC, *args, "-q"], capture_output=True, text=True)
    if result.returncode != 0:
        raise AssertionError("hexc %s failed: %s" % (" ".join(args), result.stderr))


def case_material(folder, name, template=None):
    """The execution case's material as a file in `folder` (its paths read from materials/, like the examples')."""
    with open(os.path.join(CASES, name + ".json")) as f:
        case = json.load(f)
    material = dict(case["material"], **({"template": template} if template else {}))
    path = os.path.join(folder, name + ".json")
    with open(path, "w") as f:
        json.dump(material, f)
    return case, material, path


def drawn_cases():
    """The execution cases Dawn draws: one colour or scalar slot's falloff blend seen in a level-0 view. Left out, each
    for a reason docs/verification.md ("WGSL") gives with its figures: height blending, whose bound needs the
    reference's per-pixel heights, which `hexc render` does not give; normal slots, whose bound here takes
    rock_normal.png's whole derivative range for the samples' spread (234/255, where the execution tests use each
    pixel's)."""
    names = []
    for path in sorted(glob.glob(os.path.join(CASES, "*.json"))):
        with open(path) as f:
            case = json.load(f)
        text = json.dumps(case["material"])
        if case["rule"] == "falloff" and case["view"] in VIEWS and "height_blend" not in text:
            names.append(os.path.basename(path)[:-5])
    return names


class Wgsl(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.mkdtemp(prefix="hexc-wgsl-test-")
        cls.cases = os.path.join(cls.folder, "cases")
        os.makedirs(cls.cases)
        os.symlink(os.path.abspath(os.path.join("materials", "textures")), os.path.join(cls.cases, "textures"))
        roots = {"/wgsl/": os.path.abspath(os.path.dirname(__file__)), "/out/": cls.folder, "/materials/": os.path.abspath("materials")}
        cls.httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Handler, roots=roots))
        threading.Thread(target=cls.httpd.serve_forever, daemon=True).start()
        cls.driver = browser_or_skip(WEBGPU_FLAGS)
        cls.driver.get("http://127.0.0.1:%d/wgsl/webgpu.html" % cls.httpd.server_address[1])
        wait_for(lambda: cls.driver.execute_script("return window.hexcReady;"), "the WebGPU page to load")

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
        examples = sorted(p for p in glob.glob("materials/*.json") if not p.endswith("schema.json") and "engine_rock" not in p)
        examples += sorted(glob.glob("tests/golden/materials/*.json"))
        cases = [case_material(self.cases, os.path.basename(p)[:-5])[2] for p in sorted(glob.glob(os.path.join(CASES, "*.json")))]
        files = []
        for mode in ([], ["--debug"]):
            for group, inputs, extra in (("examples", examples, ["--vertex"]), ("cases", cases, ["--vertex"]),
                                         ("mtlx", sorted(glob.glob("materials/mtlx/*.mtlx")), ["--vertex"]),
                                         ("scenes", sorted(glob.glob("materials/scenes/*.json")), [])):
                out = os.path.join(self.folder, "tint", group + "".join(mode))
                hexc(*inputs, "--targets", "wgsl", *extra, *mode, "-o", out)
                files += sorted(glob.glob(os.path.join(out, "*.wgsl")))
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
        self.assertGreater(len(files), 2 * 2 * (len(examples) + len(cases)))
        print("Tint accepted all %d" % len(files))

    def test_dawn_draws_the_cases_within_the_reference_bounds(self):
        names = drawn_cases()
        materials = {name: case_material(self.cases, name, template="value") for name in names}
        out = os.path.join(self.folder, "draw")
        started = time.monotonic()
        # Baked: every setting a constant, so the shader reads only its textures and sampler (no parameter block).
        hexc(*(m[2] for m in materials.values()), "--targets", "wgsl", "--vertex", "--bake", "-o", out)
        print("hexc wrote %d cases' WGSL (fragment and vertex) in %.1f s" % (len(names), time.monotonic() - started))
        print("%-32s %10s %10s %10s" % ("case", "max /255", "mean /255", "bound /255"))
        for name in names:
            with self.subTest(case=name):
                errors, bound = self.draw_and_compare(*materials[name], out)
                worst, mean = max(errors), sum(errors) / len(errors)
                print("%-32s %10.3f %10.4f %10.3f" % (name, worst * 255, mean * 255, bound * 255))
                self.assertLessEqual(worst, bound)

    def draw_and_compare(self, case, material, path, out):
        """Draws the case's first slot with Dawn: every channel's error against the reference, and the bound."""
        name, slot = material["name"], material["slots"][0]
        size, rect = VIEWS[case["view"]]
        with open(os.path.join(out, name + ".manifest.json")) as f:
            manifest = json.load(f)
        fragment, vertex = manifest["targets"]["wgsl"], manifest["vertex"]["wgsl"]
        # The page feeds hexc's vertex stage a position at location 0 and the uv at location 1.
        self.assertEqual([(a["location"], a["feeds"]) for a in manifest["vertex"]["attributes"]], [(0, "gl_Position"), (1, "v_uv")])
        group = fragment["sampler"]["group"]
        self.assertEqual({t["group"] for t in fragment["textures"].values()}, {group})  # one bind group, as the page binds
        srgb = {s["name"]: s["colorspace"] == "srgb" for s in manifest["slots"]}
        textures = [{"binding": t["binding"], "srgb": srgb[n], "url": "/materials/" + next(s["texture"] for s in material["slots"] if s["name"] == n)}
                    for n, t in fragment["textures"].items()]
        with open(os.path.join(out, fragment["file"])) as f, open(os.path.join(out, vertex["file"])) as g:
            result = self.call("render", {"fragment": f.read(), "vertex": g.read(), "fragmentEntry": fragment["entry_point"],
                                          "vertexEntry": vertex["entry_point"], "textures": textures, "sampler": fragment["sampler"],
                                          "width": size, "height": size, "rect": rect})
        data = base64.b64decode(result["pixels"])
        gpu = struct.unpack("<%df" % (size * size * 4), data)
        reference = os.path.join(out, name + ".pfm")
        hexc("render", path, "--reference", "--output", "albedo", "--slot", slot["name"], "--size", "%dx%d" % (size, size),
             "--uv-rect", ",".join(map(str, rect)), "-o", reference)
        ref = [value for row in read_pfm(reference)[2] for value in row]
        hex = {**material.get("hextiling", {}), **slot.get("hextiling", {})}
        spread = texture_bounds(os.path.join("materials", slot["texture"]), srgb[slot["name"]])[0]
        # page_test.py's falloff bound: level-0 samples within e_s, the luminance metric too, the blend's spread over the
        # texture's whole range. Scalar slots show (s, s, s, 1), so three channels for every slot.
        bound, channels = blend_tolerance(E_S, E_S, hex, spread), 3
        errors = [abs(gpu[p * 4 + c] - ref[p][c]) for p in range(size * size) for c in range(channels)]
        errors = [e if e == e else math.inf for e in errors]
        self.assertGreater(max(abs(r[c]) for r in ref for c in range(channels)), 10 * bound)  # not a blank image
        return errors, bound


if __name__ == "__main__":
    HEXC = os.path.abspath(sys.argv.pop(1))
    if not os.path.isdir(os.path.join(NODE_MODULES, "naga-wasm")):
        print("no naga-wasm in %s: run `npm ci --prefix tests/node`" % NODE_MODULES)
        sys.exit(1 if os.environ.get("HEXC_REQUIRE_BROWSER") == "1" else 77)
    os.environ["HEXC_NODE_PATH"] = os.path.abspath(NODE_MODULES)
    unittest.main(verbosity=2)
