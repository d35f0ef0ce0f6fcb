#!/usr/bin/env python3
"""hexc's MaterialX mode against MaterialX's own shader generator, in headless Chromium (ctest `materialx_parity`).

For each MaterialX document of materials/mtlx/ that hexc reads in MaterialX mode, and for generated documents spanning
tiling, scale, rotation, offset, falloff (0.75 and 0.875 among them), falloffcontrast, the ranges, colour spaces and
normal maps, each texture slot alone (a copy of the document with only that shader input connected):

- MaterialX's ESSL of the node that feeds it, from npm @needle-tools/materialx 1.4.6 (MaterialX 1.39.4 in WebAssembly,
  pinned in tests/node's lock file; `npm ci --prefix tests/node` installs it), through tests/materialx/mx_generate.mjs
  (one Node.js process for every document);
- hexc's GLSL ES 3.00 of the same document with the `value` template (`hexc DOC --template value.glsl
  --glsl-version 300es`),

both drawn by tests/materialx/parity.html in Debian's Chromium (WebGL 2 on SwiftShader) over the same uv rectangle,
on the same textures and sampler (a full mip chain, trilinear, repeat), magnified (0.75 texel per pixel) and minified
(4 texels per pixel), into float framebuffers. An sRGB texture is uploaded as stored for MaterialX (it decodes in its
shader) and for hexc where its manifest says `"decode": "shader"` (MaterialX mode), else in an sRGB format.

Held (derivations next to the bounds below): colour and scalar slots within 2/255 of MaterialX per channel; normal maps
within NORMAL_BOUND per component of the unit normal.

Alpha is not compared: MaterialX 1.39.4's hextiledimage_color4 (this package) blends alpha as the taps' mean, where
MaterialX's main branch, which hexc follows, weighs it like the colour (docs/materialx.md); the documents here are color3.

The test starts what it needs (a file server on 127.0.0.1 over the repository, Chromium) and installs nothing; without
Chromium, node or the npm package it exits 77 (skipped), unless HEXC_REQUIRE_BROWSER=1. It prints the parity table.
Usage: parity_test.py HEXC [PNG_DIR]   (PNG_DIR: also write each view, MaterialX's image left of hexc's)
"""
import functools
import http.server
import json
import math
import os
import struct
import subprocess
import sys
import tempfile
import threading
import xml.etree.ElementTree as ET
import zlib

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "edit"))
import edit_support  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = os.path.join(ROOT, "tests", "node", "node_modules", "@needle-tools", "materialx", "package.json")
SIZE = 64  # pixels per side of each view

# Colour: the bound. Both shaders run the same maths on the same filtered texels in float32 (mediump is
# float32 on SwiftShader); the bound covers rounding order and MaterialX's float hash, and is what a person sees as
# "the same" on an 8-bit display.
COLOR_BOUND = 2 / 255
# Normals: a unit normal n = normalize(N - sum w_i g_i) with g_i = -m_i.xy / m_i.z from texels m = 2 b - 1. A texel-
# space difference e (the colour bound, 2/255) is 2 e in m; the slope g_i moves by 2 e (1 + |g|) / m_z (the quotient
# rule, as the execution tests' derivative rule), and normalising a vector (-g, 1) of length >= 1 moves it by at most
# that. With the maps' steepest texel |g| <= 1 and m_z >= 0.7 (rock_normal, stone_normal): 2 * 2/255 * 2 / 0.7.
NORMAL_BOUND = 2 * (2 / 255) * 2 / 0.7


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    return struct.unpack(">II", head[16:24])


# ---- Documents -------------------------------------------------------------------------------------------------------

SHADER_TYPES = ("surfaceshader", "displacementshader")


def absolute_prefixes(root, folder):
    """Every fileprefix made absolute (the copies live in a temporary folder), the document's own folder by default."""
    for element in root.iter():
        if "fileprefix" in element.attrib:
            element.set("fileprefix", os.path.join(folder, element.get("fileprefix")))
    if "fileprefix" not in root.attrib:
        root.set("fileprefix", folder + "/")


def slot_copies(path, out_dir):
    """(name, copy's path, MaterialX target) per connected shader input: a copy of the document with only that input
    connected; the target is NODEGRAPH/OUTPUT or the node's name, for mx_generate.mjs."""
    tree = ET.parse(path)
    root = tree.getroot()
    absolute_prefixes(root, os.path.dirname(os.path.abspath(path)))
    shaders = [e for e in root if e.get("type") in SHADER_TYPES]
    connected = [(s, i) for s in shaders for i in s.findall("input") if i.get("nodegraph") or i.get("nodename")]
    copies = []
    materials = [e for e in root if e.get("type") == "material"]
    for shader, keep in connected:
        # Only the input kept, and only the materials of its shader (hexc refuses a material without slots).
        removed = [(s, i) for s, i in connected if i is not keep]
        removed += [(root, m) for m in materials if not any(i.get("nodename") == shader.get("name") for i in m.findall("input"))]
        for s, i in removed:
            s.remove(i)
        name = "%s.%s.%s" % (os.path.splitext(os.path.basename(path))[0], shader.get("name"), keep.get("name"))
        out = os.path.join(out_dir, name + ".mtlx")
        tree.write(out, xml_declaration=True, encoding="unicode")
        for s, i in removed:
            s.append(i)  # (order does not matter to either reader)
        target = keep.get("nodegraph") + "/" + keep.get("output") if keep.get("nodegraph") else keep.get("nodename")
        copies.append((name, out, target))
    return copies


def generated_documents(out_dir):
    """Documents spanning MaterialX's hextiledimage and hextilednormalmap inputs, on the project's textures."""
    textures = os.path.join(ROOT, "materials", "textures")
    cases = {
        "gen_defaults": ("hextiledimage", "color3", "rock_albedo.png", "srgb_texture", {}),
        "gen_falloff_075": ("hextiledimage", "color3", "rock_albedo.png", "srgb_texture",
                            {"tiling": ("vector2", "4, 4"), "falloff": ("float", "0.75"), "rotation": ("float", "0.8"),
                             "rotationrange": ("vector2", "20, 200"), "scale": ("float", "0.6"), "offset": ("float", "0.6")}),
        "gen_falloff_0875_linear": ("hextiledimage", "color3", "rock_albedo.png", "lin_rec709",
                                    {"tiling": ("vector2", "3, 5"), "falloff": ("float", "0.875"), "falloffcontrast": ("float", "0.9"),
                                     "lumacoeffs": ("color3", "0.2126, 0.7152, 0.0722"), "scalerange": ("vector2", "0.7, 1.6")}),
        "gen_contrast_0_raw": ("hextiledimage", "color3", "rock_roughness.png", "raw",
                               {"tiling": ("vector2", "2.5, 2.5"), "falloffcontrast": ("float", "0"), "falloff": ("float", "0.3"),
                                "offsetrange": ("vector2", "0, 0.5"), "rotationrange": ("vector2", "-90, 90")}),
        "gen_normal": ("hextilednormalmap", "vector3", "rock_normal.png", None,
                       {"tiling": ("vector2", "4, 4"), "falloff": ("float", "0.75"), "rotation": ("float", "1"), "scale": ("float", "1.4")}),
        "gen_normal_flip": ("hextilednormalmap", "vector3", "rock_normal.png", None,
                            {"tiling": ("vector2", "3, 3"), "flip_g": ("boolean", "true"), "rotationrange": ("vector2", "0, 90"),
                             "offset": ("float", "0.3")}),
    }
    out = []
    for name, (node, type_, texture, colorspace, inputs) in cases.items():
        shader_input = "normal" if type_ == "vector3" else "base_color"
        file_input = '<input name="file" type="filename" value="%s"%s />' % (
            os.path.join(textures, texture), ' colorspace="%s"' % colorspace if colorspace else "")
        rest = "".join('<input name="%s" type="%s" value="%s" />' % (k, t, v) for k, (t, v) in inputs.items())
        text = ('<?xml version="1.0"?>\n<materialx version="1.39" colorspace="lin_rec709">'
                '<nodegraph name="NG"><%s name="tex" type="%s">%s%s</%s><output name="out" type="%s" nodename="tex" /></nodegraph>'
                '<standard_surface name="SR" type="surfaceshader"><input name="%s" type="%s" nodegraph="NG" output="out" />'
                '</standard_surface><surfacematerial name="M" type="material">'
                '<input name="surfaceshader" type="surfaceshader" nodename="SR" /></surfacematerial></materialx>\n') % (
            node, type_, file_input, rest, node, type_, shader_input, type_)
        path = os.path.join(out_dir, name + ".mtlx")
        with open(path, "w") as f:
            f.write(text)
        out.append((name, path, "NG/out"))
    return out


# ---- The two shaders ---------------------------------------------------------------------------------------------------

HEXC_VERTEX = """#version 300 es
in vec2 a_position;
in vec2 a_uv;
out highp vec2 v_uv;
void main() { gl_Position = vec4(a_position, 0.0, 1.0); v_uv = a_uv; }
"""


def url(path):
    return "/" + os.path.relpath(path, ROOT)


def hexc_program(hexc, doc, out_dir):
    """hexc's value shader of the document's one slot: (program for the page, manifest slot) or (None, why)."""
    r = subprocess.run([hexc, doc, "--template", os.path.join(ROOT, "templates", "builtin", "value.glsl"), "--targets", "glsl",
                        "--glsl-version", "300es", "-q", "-o", out_dir], capture_output=True, text=True)
    if r.returncode != 0:
        return None, r.stderr.strip().splitlines()[-1] if r.stderr.strip() else "hexc failed"
    manifest_path = [f for f in os.listdir(out_dir) if f.endswith(".manifest.json")][0]
    with open(os.path.join(out_dir, manifest_path)) as f:
        manifest = json.load(f)
    for name in os.listdir(out_dir):
        os.remove(os.path.join(out_dir, name)) if name.endswith(".manifest.json") else None
    glsl = manifest["targets"]["glsl"]
    with open(os.path.join(out_dir, glsl["file"])) as f:
        fragment = f.read()
    slot = manifest["slots"][0]
    if slot["hextiling"]["mode"] != "materialx":
        return None, "slot in hexc's %s mode" % slot["hextiling"]["mode"]
    texture = os.path.join(os.path.dirname(doc), slot["texture"]) if not os.path.isabs(slot["texture"]) else slot["texture"]
    params = manifest["parameters"]
    return ({"vertex": HEXC_VERTEX, "fragment": fragment, "uniforms": [],
             "block": {"name": params["block"], "size": params["size"], "members": params["members"]} if params.get("members") else None,
             "textures": [{"uniform": t["uniform"], "url": url(texture), "srgb": slot["colorspace"] == "srgb" and slot.get("decode") != "shader"}
                          for t in glsl["textures"].values()]}, slot)


def materialx_program(generator, doc, target):
    """MaterialX's program of `target` in `doc`, from the mx_generate.mjs process `generator` (one for every document)."""
    generator.stdin.write(json.dumps([doc, target]) + "\n")
    generator.stdin.flush()
    answer = generator.stdout.readline()
    if not answer:
        generator.log.seek(0)
        raise RuntimeError("mx_generate.mjs stopped (exit %s): %s" % (generator.wait(), generator.log.read()[-2000:]))
    g = json.loads(answer)
    if "error" in g:
        raise RuntimeError("mx_generate.mjs %s %s: %s" % (doc, target, g["error"][-2000:]))
    files = [u for u in g["uniforms"] if u["type"] == "filename"]
    return {"vertex": g["vertex"], "fragment": g["pixel"], "block": None,
            "uniforms": [u for u in g["uniforms"] if u["type"] != "filename"],
            "textures": [{"uniform": u["name"], "url": url(u["value"]), "srgb": False} for u in files]}


# ---- Comparison ----------------------------------------------------------------------------------------------------------

def unit(x, y, z):
    n = math.sqrt(x * x + y * y + z * z)
    return (x / n, y / n, z / n)


def errors(kind, materialx, hexc):
    """Per pixel the largest difference over the compared components: colour rgb, scalar r, normal the unit normal's
    three (hexc's value is the derivative d, whose normal is normalize(-d.x, -d.y, 1); MaterialX's is its output)."""
    out = []
    for p in range(0, len(materialx), 4):
        a, b = materialx[p:p + 4], hexc[p:p + 4]
        if kind == "normal":
            m, h = unit(*a[:3]), unit(-b[0], -b[1], 1.0)
            out.append(max(abs(m[c] - h[c]) for c in range(3)))
        else:
            out.append(max(abs(a[c] - b[c]) for c in range(1 if kind == "scalar" else 3)))
    return out


def write_png(path, images, kind):
    """MaterialX's image beside hexc's (left, right), as a person sees them: colour sRGB-encoded, a normal as
    0.5 + 0.5 n (hexc's from its derivative), row 0 at the top."""
    def shown(image, c, p, hexc):
        if kind == "normal":
            n = unit(-image[p], -image[p + 1], 1.0) if hexc else unit(*image[p:p + 3])
            return 0.5 + 0.5 * n[c]
        x = min(max(image[p + (0 if kind == "scalar" else c)], 0.0), 1.0)
        return 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055
    rows = b""
    for y in reversed(range(SIZE)):
        row = bytearray([0])
        for side, image in enumerate(images):
            for x in range(SIZE):
                row += bytes(round(255 * shown(image, c, (y * SIZE + x) * 4, side == 1)) for c in range(3))
        rows += bytes(row)
    chunk = lambda tag, data: struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2 * SIZE, SIZE, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def view_rect(slot, view):
    """uv over SIZE pixels: 0.75 texel per pixel (magnified) or 4 (minified), from the slot's tiling and texture size."""
    texels = 0.75 if view == "magnified" else 4.0
    width = slot["size"][0] * slot["hextiling"]["tiling"][0]
    span = SIZE * texels / width
    return [0.3, 0.45, 0.3 + span, 0.45 + span * slot["hextiling"]["tiling"][0] / slot["hextiling"]["tiling"][1]
            * slot["size"][0] / slot["size"][1]]


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def serve(root):
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(QuietHandler, directory=root))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def main(argv):
    hexc = os.path.abspath(argv[1])
    png_dir = os.path.abspath(argv[2]) if len(argv) > 2 else None
    missing = [what for what, ok in (("node", subprocess.run(["which", "node"], capture_output=True).returncode == 0),
                                      ("npm package @needle-tools/materialx (npm ci --prefix tests/node)", os.path.exists(PACKAGE)))
               if not ok]
    if missing:
        print("no " + ", ".join(missing))
        return 1 if os.environ.get("HEXC_REQUIRE_BROWSER") == "1" else 77
    work = tempfile.mkdtemp(prefix="hexc-mtlx-parity-")
    docs = []
    for folder in (os.path.join(ROOT, "materials", "mtlx"), os.path.join(ROOT, "materials", "mtlx", "corpus")):
        for name in sorted(os.listdir(folder)):
            if name.endswith(".mtlx"):
                docs += slot_copies(os.path.join(folder, name), work)
    docs += generated_documents(work)

    driver = edit_support.browser_or_skip()
    server = serve(ROOT)
    # Its stderr to a file, which no amount of Node's warnings fills as it would a pipe no one reads.
    log = tempfile.TemporaryFile("w+")
    generator = subprocess.Popen(["node", os.path.join(HERE, "mx_generate.mjs")], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                 stderr=log, text=True)
    generator.log = log
    failures, rows, skipped = [], [], []
    try:
        driver.get("http://127.0.0.1:%d/tests/materialx/parity.html" % server.server_address[1])
        for name, doc, target in docs:
            out_dir = os.path.join(work, name)
            os.makedirs(out_dir, exist_ok=True)
            hexc_side, slot = hexc_program(hexc, doc, out_dir)
            if hexc_side is None:
                skipped.append("%s (%s)" % (name, slot))
                continue
            mx_side = materialx_program(generator, doc, target)
            kind = slot["kind"]
            bound = NORMAL_BOUND if kind == "normal" else COLOR_BOUND
            for view in ("magnified", "minified"):
                case = {"width": SIZE, "height": SIZE, "rect": view_rect(slot, view), "programs": [mx_side, hexc_side]}
                result = driver.execute_async_script("window.renderPair(arguments[0]).then(arguments[1]);", case)
                if "error" in result:
                    failures.append("%s %s: %s" % (name, view, result["error"][:2000]))
                    continue
                if png_dir:
                    write_png(os.path.join(png_dir, "%s.%s.png" % (name, view)), result["images"], kind)
                e = errors(kind, *result["images"])
                worst, mean = max(e), sum(e) / len(e)
                rows.append((name, kind, view, worst, mean, bound))
                print("  %s %s: max %.3f/255 mean %.4f/255" % (name, view, worst * 255, mean * 255), flush=True)
                if not worst <= bound:
                    failures.append("%s %s: %.2f/255 over the bound %.2f/255" % (name, view, worst * 255, bound * 255))
    finally:
        generator.stdin.close()
        generator.wait()
        generator.stdout.close()
        log.close()
        edit_support.quit_browser(driver)
        server.shutdown()

    print("%-50s %-7s %-10s %12s %12s %10s" % ("document.shader.input", "kind", "view", "max /255", "mean /255", "bound"))
    for name, kind, view, worst, mean, bound in rows:
        print("%-50s %-7s %-10s %12.3f %12.4f %10.2f" % (name, kind, view, worst * 255, mean * 255, bound * 255))
    for s in skipped:
        print("not in MaterialX mode or not read by hexc: " + s)
    for f in failures:
        print("FAIL " + f)
    return 1 if failures or not rows else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
