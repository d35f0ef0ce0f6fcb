"""What the web engines' tests share: a local file server for the page, the engines and a package; the page in headless
Chromium; PNG texels; the dome normal map.

The server serves, on 127.0.0.1 only: /integrations/ (compiler/integrations: the page and the engines' test drivers),
/node_modules/ (tests/node's pinned npm packages, installed by `npm ci --prefix tests/node`) and /pkg/ (a folder of
packages hexc wrote). Chromium is driven as hexc edit's tests drive it (tests/edit/edit_support.py).
"""
import base64
import functools
import http.server
import math
import os
import struct
import sys
import threading
import zlib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "edit"))
from edit_support import CHROMIUM_FLAGS, browser_or_skip, quit_browser, read_pfm, wait_for  # noqa: E402,F401
from page_test import E_S, blend_tolerance, srgb_to_linear, write_png  # noqa: E402,F401

NODE_MODULES = os.path.join("tests", "node", "node_modules")
# Chromium's WebGPU needs the new headless mode; --disable-gpu would leave it no adapter (SwiftShader's Vulkan is its GPU).
WEBGPU_FLAGS = ["--headless=new", "--enable-unsafe-webgpu"] + [f for f in CHROMIUM_FLAGS if f not in ("--headless", "--disable-gpu")]


class Handler(http.server.SimpleHTTPRequestHandler):
    """Serves each URL prefix of `roots` from its folder; nothing else."""

    def __init__(self, *args, roots, **kwargs):
        self.roots = roots
        super().__init__(*args, **kwargs)

    def translate_path(self, path):
        path = path.split("?", 1)[0].split("#", 1)[0]
        for prefix, folder in self.roots.items():
            if path.startswith(prefix):
                rest = os.path.normpath(path[len(prefix):]).lstrip("/")
                if rest.startswith(".."):
                    break
                return os.path.join(folder, rest)
        return "/nonexistent"

    def log_message(self, *args):
        pass


class FileServer:
    """The page, the engines and the packages over HTTP on 127.0.0.1 (module scripts need http, not file:)."""

    def __init__(self, packages):
        missing = [p for p in ("three", "@babylonjs/core") if not os.path.isdir(os.path.join(NODE_MODULES, p))]
        if missing:
            raise RuntimeError("no %s in %s: run `npm ci --prefix tests/node`" % (", ".join(missing), NODE_MODULES))
        roots = {"/integrations/": os.path.abspath(os.path.join("compiler", "integrations")),
                 "/node_modules/": os.path.abspath(NODE_MODULES), "/pkg/": os.path.abspath(packages)}
        Handler.extensions_map = {**Handler.extensions_map, ".js": "text/javascript", ".mjs": "text/javascript"}
        self.httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Handler, roots=roots))
        self.thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)
        self.thread.start()
        self.url = "http://127.0.0.1:%d" % self.httpd.server_address[1]

    def stop(self):
        self.httpd.shutdown()
        self.httpd.server_close()


class Page:
    """The engine's test page in headless Chromium: `render` runs its driver and returns 8-bit RGBA rows, top first."""

    def __init__(self, server, engine, flags=CHROMIUM_FLAGS):
        self.driver = browser_or_skip(flags)
        self.driver.get("%s/integrations/page.html?engine=%s" % (server.url, engine))
        ready = wait_for(lambda: self.driver.execute_script("return window.hexcReady;"), "the %s driver to load" % engine)
        if ready is not True:
            raise RuntimeError("the %s driver did not load: %s" % (engine, ready))

    def run(self, **config):
        """The driver's answer to `config`, failed unless the engine compiled the material's shaders."""
        result = self.driver.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            "window.hexcDriver.render(arguments[0]).then(done, (e) => done({error: String(e && e.stack || e)}));", config)
        if "error" in result:
            raise AssertionError("the driver failed: " + result["error"])
        if result.get("errors", "[]") != "[]":
            raise AssertionError("the engine's shader compile failed: " + result["errors"])
        return result

    def render(self, **config):
        """The frame as readPixels returns it, the bottom row first, turned to rows top first as WebGL documents the
        order (readPixels' origin is the framebuffer's lower left): 8-bit RGBA lists."""
        result = self.run(**config)
        width, height = config["width"], config["height"]
        data = base64.b64decode(result["pixels"])
        rows = [[list(data[(y * width + x) * 4:(y * width + x) * 4 + 4]) for x in range(width)] for y in range(height)]
        return rows[::-1]

    def screenshot(self, path, **config):
        """The frame as a user's screenshot of the canvas has it (toDataURL's PNG, as the screen shows it), written to
        `path` as it comes; the driver's answer (its console warnings)."""
        result = self.run(**config, png=True)
        with open(path, "wb") as f:
            f.write(base64.b64decode(result.pop("png")))
        return result

    def quit(self):
        quit_browser(self.driver)


def read_png(path):
    """(width, height, channels, rows top first of texel lists) of an 8-bit, non-interlaced PNG (grey, grey+alpha, RGB
    or RGBA), as the test textures are."""
    with open(path, "rb") as f:
        data = f.read()
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or interlace or colour not in (0, 2, 4, 6):
        raise ValueError("%s: only 8-bit non-interlaced PNGs are read here" % path)
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
    raw, stride, rows, previous = zlib.decompress(idat), width * channels, [], [0] * width * channels
    for y in range(height):
        kind, line = raw[y * (stride + 1)], list(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = previous[i], previous[i - channels] if i >= channels else 0
            predictor = [0, a, b, (a + b) // 2, a + b - c][kind]
            if kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                predictor = a if pa <= pb and pa <= pc else b if pb <= pc else c
            line[i] = (line[i] + predictor) & 255
        rows.append([line[x * channels:(x + 1) * channels] for x in range(width)])
        previous = line
    return width, height, channels, rows


def texture_bounds(path, srgb):
    """Largest value range of a colour channel (linear), and for a normal map its largest |dH/du|, |dH/dv| and least z."""
    _, _, channels, rows = read_png(path)
    colour = min(channels, 3)
    lo, hi = [math.inf] * colour, [-math.inf] * colour
    max_deriv, min_z = 0.0, 1.0
    for row in rows:
        for texel in row:
            values = [srgb_to_linear(t / 255) if srgb else t / 255 for t in texel[:colour]]
            lo, hi = [min(a, b) for a, b in zip(lo, values)], [max(a, b) for a, b in zip(hi, values)]
            if channels >= 3:
                x, y, z = (2 * t / 255 - 1 for t in texel[:3])
                if z > 0:
                    min_z = min(min_z, z)
                    max_deriv = max(max_deriv, abs(x) / z, abs(y) / z)
    return max(h - l for h, l in zip(hi, lo)), max_deriv, min_z


def write_dome_normal_map(path, width=64, height=64, slope=0.4, directx=False):
    """A normal map of one smooth dome, H = A (1 - r^2)^2 inside r < 1 (r from the texture's centre in units of 0.45 of
    its shorter side, in texels), flat outside; A makes the steepest slope `slope` (|dH/dr| peaks at r = 1/sqrt(3)).
    Green up (y up the image), or down with `directx`."""
    radius = 0.45 * min(width, height)
    peak = 4 / math.sqrt(3) * (2 / 3)  # max of 4 r (1 - r^2) over [0, 1]
    rows = []
    for j in range(height):
        row = []
        for i in range(width):
            x, y = (i + 0.5 - width / 2) / radius, (height / 2 - (j + 0.5)) / radius  # y up the image
            r2 = x * x + y * y
            g = slope / peak * 4 * (1 - r2) if r2 < 1 else 0.0  # dH/dx = -g x, dH/dy = -g y (in units of the radius)
            n = [g * x, -g * y if directx else g * y, 1.0]  # (-dH/dx, -dH/dy, 1): tilted away from the centre
            length = math.sqrt(sum(c * c for c in n))
            row += [round((c / length * 0.5 + 0.5) * 255) for c in n]
        rows.append(row)
    write_png(path, width, height, rows)
