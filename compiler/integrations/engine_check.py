"""What the engine tests share (compiler/integrations/<engine>/check.py): PNG and PFM reading, hexc's fp64 reference,
the derived bound of an engine's 8-bit sRGB output against it, the materials they draw (the probe among them), the
screen marker and the verdicts of their checks. Python's standard library only."""
import functools
import json
import math
import struct
import subprocess
import zlib
from pathlib import Path


def read_png(path):
    """An 8-bit, non-interlaced grey, RGB or RGBA PNG as (width, height, channels, rows of bytes)."""
    data = Path(path).read_bytes()
    at, idat = 8, b""
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            w, h, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour in (0, 2, 6), f"{path}: PNG colour type {colour}, depth {depth}"
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    n = {0: 1, 2: 3, 6: 4}[colour]
    raw, stride, rows, prev = zlib.decompress(idat), w * n, [], bytearray(w * n)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - n] if i >= n else 0
            b, c = prev[i], prev[i - n] if i >= n else 0
            p = a + b - c
            pred = [0, a, b, (a + b) // 2, a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else b if abs(p - b) <= abs(p - c) else c][f]
            line[i] = (line[i] + pred) & 255
        rows.append(line)
        prev = line
    return w, h, n, rows


def write_png(path, w, h, pixel):
    """An RGB PNG whose pixel (x, y), y = 0 the top row, is pixel(x, y) -> (r, g, b) bytes."""
    rows = b"".join(b"\0" + bytes(c for x in range(w) for c in pixel(x, y)) for y in range(h))
    chunk = lambda kind, body: struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                           chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def read_pfm(path):
    """A colour PFM as (width, height, rows top first of [r, g, b] floats)."""
    data = Path(path).read_bytes()
    parts = data.split(b"\n", 3)
    w, h = map(int, parts[1].split())
    scale = float(parts[2])
    fmt = "<" if scale < 0 else ">"
    floats = struct.unpack(fmt + "f" * (w * h * 3), parts[3][:w * h * 12])
    rows = [[floats[(y * w + x) * 3:(y * w + x) * 3 + 3] for x in range(w)] for y in range(h)]
    return w, h, rows[::-1]  # PFM stores the bottom row first


def reference(hexc, material, output, slot, size, rect, out):
    """hexc's fp64 CPU reference of `slot` (`output`: albedo or normal) over uv `rect`, linear, as a PFM (rendered once
    for the same arguments and material text: a test that checks several views of one material asks for its layers'
    references again)."""
    return _reference(hexc, str(material), Path(material).read_text(), output, slot, size, tuple(rect), str(out))


@functools.lru_cache(maxsize=None)
def _reference(hexc, material, text, output, slot, size, rect, out):  # `text`: a rewritten material is another key
    subprocess.run([hexc, "render", material, "--reference", "-q", "--output", output, "--slot", slot, "--size",
                    f"{size}x{size}", "--uv-rect", ",".join(map(str, rect)), "-o", out], check=True)
    return read_pfm(out)


def srgb(x):
    x = min(max(x, 0.0), 1.0)
    return 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055


# The bound on |engine - 255 srgb(reference)| at a pixel, in 8-bit steps (the engines here write sRGB-encoded 8-bit
# pixels of the linear value the function returns):
#   0.5   the engine rounds its output to 8 bits (the reference is compared as floats);
#   filtering: llvmpipe filters an 8-bit texture in fixed point: a bilinear fetch is two lerps whose weights have 8-bit
#   fractions (each off by at most 1/512 of the texel range) and its result has 8 bits (off by 0.5/255): e = 2/512 +
#   0.5/255 in the texture's value (linear, after an sRGB texture's decoding); the blend of three fetches by weights
#   summing to 1 stays within e. A normal map's value is a normal's component n * 0.5 + 0.5: a texel error e is 2e on
#   n, which moves the slope -n.xy / n.z by at most 2e (1 + |n.xy| / n.z) / n.z <= 4e / n.z^2 on the pixel's normal,
#   and normalize(-d, 1) moves by no more than d does: so 2e / n.z^2 in the output's n * 0.5 + 0.5;
#   the blend's weights depend on the taps' own values (falloffcontrast c, exponent g, gain k = log2(1 / (1 - falloff))):
#   a tap's weight goes as (1 - c + c l)^g of its luminance l, d ln w / dl <= g c / (1 - c), and the value
#   v = sum w_i s_i / sum w_i moves by (w_i / sum w)(s_i - v) d ln w_i / dl <= g c / (4 (1 - c)) per unit of l
#   (w (1 - w) <= 1/4, |s_i - v| <= 1); the gain's curve is at most k steep: so a tap's error e becomes up to
#   e (1 + max(k, 1) g c / (4 (1 - c))) in the blend (`amplification`);
#   the engine's own colour buffer before its sRGB output: `relative`, e.g. 2^-11 of the value for a half float.
#   Both are carried through the sRGB encoding at the pixel's value: 255 * (srgb(v + err) - srgb(v)) is the largest
#   the encoding makes of err above v, and below v the step down (srgb is concave, so that one is larger): both taken.
FILTER_ERROR = 2 / 512 + 0.5 / 255


def bound(value, err, encode=srgb):
    return 0.5 + 255 * max(encode(value + err) - encode(value), encode(value) - encode(max(value - err, 0.0)))


def amplification(slot):
    """How much the blend can magnify a tap's error (above), from the slot's settings in the manifest."""
    h = slot["hextiling"]
    if not h["enabled"]:
        return 1.0
    c, g = h["falloffcontrast"], h["exponent"]
    k = math.log2(1 / (1 - h["falloff"])) if h["falloff"] < 1 else 16
    return 1 + max(k, 1) * g * c / (4 * (1 - c))


def linear(x):
    return min(max(x, 0.0), 1.0)


def compare(engine_png, ref, normal, relative, amplify, encode=srgb, errors=None, marker=0):
    """Per channel of RGB: (mean error, max error, max error / bound, pixels over bound) of the engine's 8-bit image,
    `encode`d (srgb, or linear as it is), against the linear reference. `errors`, if given, are the per-pixel errors
    of the value before the engine's output (rows of floats; a layered role's, layered_errors), instead of a slot's.
    `marker`: the side of the square at the image's top-left that the engine's marker covers, left out."""
    w, h, n, rows = read_png(engine_png)
    rw, rh, ref_rows = ref
    assert (w, h) == (rw, rh), f"engine image {w}x{h}, reference {rw}x{rh}"
    total = worst = worst_ratio = 0.0
    over = 0
    for y in range(h):
        for x in range(w):
            if x < marker and y < marker:
                continue
            v = ref_rows[y][x]
            # A non-finite reference is a defect of what the engine is judged against: NaN would compare as in bound.
            if not all(math.isfinite(c) for c in v[:3]):
                raise ValueError(f"the reference is not finite at ({x}, {y}): {tuple(v[:3])}")
            nz = max(2 * v[2] - 1, 0.05) if normal else 1.0
            err = errors[y][x] if errors else amplify * (2 * FILTER_ERROR / (nz * nz) if normal else FILTER_ERROR)
            for c in range(3):
                e = abs(rows[y][x * n + c] - 255 * encode(v[c]))
                b = bound(v[c], err + relative * abs(v[c]), encode)
                total += e
                worst = max(worst, e)
                worst_ratio = max(worst_ratio, e / b)
                over += e > b
    return {"mean": total / (w * h - min(marker, w) * min(marker, h)) / 3, "max": worst, "max_over_bound": worst_ratio,
            "pixels_over_bound": over}


def mixed_material(folder):
    """The engine tests' second material, written into `folder`: 300 x 170 textures (non-square), a DirectX-convention
    normal map (green down: flip_y) of bumps, and an sRGB albedo and a roughness that hexc packs into one texture
    (albedo's RGB, roughness in alpha), all hex-tiled with rotation."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    w, h = 300, 170

    def albedo(x, y):
        return ((x * 255) // w, (y * 255) // h, 128 + 100 * (((x // 20) + (y // 20)) % 2) - 50)

    def roughness(x, y):
        v = 60 + int(120 * (0.5 + 0.5 * math.sin(x * 0.09) * math.cos(y * 0.13)))
        return (v, v, v)

    def normal(x, y):  # the slope of sin(2 pi x / 50) sin(2 pi y / 34), y of the map down the image (DirectX)
        k = 0.6
        dx = k * math.cos(2 * math.pi * x / 50) * math.sin(2 * math.pi * y / 34)
        dy = k * math.sin(2 * math.pi * x / 50) * math.cos(2 * math.pi * y / 34)
        n = (-dx, -dy, 1.0)
        length = math.sqrt(sum(c * c for c in n))
        return tuple(round(255 * (c / length * 0.5 + 0.5)) for c in n)

    for name, pixel in {"albedo": albedo, "roughness": roughness, "normal": normal}.items():
        write_png(folder / f"mixed_{name}.png", w, h, pixel)
    material = {"name": "mixed", "pack": True, "hextiling": {"tiling": [3, 3], "rotation": 1.0},
                "slots": [{"name": "albedo", "kind": "color", "texture": "mixed_albedo.png", "colorspace": "srgb"},
                          {"name": "roughness", "kind": "scalar", "texture": "mixed_roughness.png", "channel": "r"},
                          {"name": "normal", "kind": "normal", "texture": "mixed_normal.png", "flip_y": True}]}
    (folder / "mixed.json").write_text(json.dumps(material, indent=2))
    return folder / "mixed.json"


def manifest(package_dir):
    return json.loads(next(Path(package_dir).glob("*.manifest.json")).read_text())


def package_textures(pkg, swap=None):
    """uniform -> (the file an engine loads for it, whether it is sRGB), from the package's manifest: a slot's texture,
    a packed texture, a histogram slot's Gaussian texture in place of its own and its table beside (linear); `swap`
    gives a slot another file."""
    m = manifest(pkg)
    files = {s["name"]: (pkg / s["texture"], s.get("colorspace") == "srgb") for s in m["slots"]}
    for p in m.get("packed_textures", []):
        files[p["name"]] = (pkg / p["file"], p["colorspace"] == "srgb")
    for s in m["slots"]:
        if "histogram" in s:
            files[s["name"]] = (pkg / s["histogram"]["gaussian"]["file"], False)
            files[s["name"] + ".lut"] = (pkg / s["histogram"]["lut"]["file"], False)
    for name, path in (swap or {}).items():
        files[name] = (path, files[name][1])
    return {where["uniform"]: (Path(files[name][0]).resolve(), files[name][1]) for name, where in m["targets"]["glsl"]["textures"].items()}


LAYERS = ["clay", "moss", "slate"]


def layered_material(folder, arrays=True, weights="splat"):
    """The engine tests' layered material, written into `folder`: three layers (albedo, sRGB, and a green-up normal map
    each, 64 x 64, hex-tiled twice across uv) blended linearly by a painted 32 x 32 splat map (RGB: one layer a
    channel, linear). The splat map is asymmetric both ways, so that a flipped u or v shows: clay (red) fills a block
    at the top-left with a hard border, the rest goes from moss (green) at the top to slate (blue) at the bottom
    through a soft border. Without `arrays`, the same as `layered_separate`, its roles a texture per slot
    (`"arrays": "off"`): a package's fallback where it binds arrays. With `weights` "vertex", `layered_vertex`: the same
    layers weighed by the vertex colour instead (channel i weighs layer i; drawn with VERTEX_COLORS); "both",
    `layered_both`: by the splat map's channel times the vertex colour's."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    size = 64

    def splat(x, y):
        clay = 1.0 if x < 12 and y < 20 else 0.0
        moss = (1 - clay) * min(max(1.6 * (1 - y / 31) - 0.3, 0.0), 1.0)
        return tuple(round(255 * c) for c in (clay, moss, 1 - clay - moss))

    albedos = {"clay": lambda x, y: (170 + 40 * ((x // 8 + y // 8) % 2), 110, 70),
               "moss": lambda x, y: (60, 120 + 60 * ((x // 4) % 2), 50),
               "slate": lambda x, y: (90 + (x * 7 + y * 13) % 60, 100, 140)}
    periods = {"clay": 16, "moss": 32, "slate": 64}

    def normal(period):  # the slope of a sine ridge pattern along both axes, green up
        def pixel(x, y):
            k = 0.5
            dx = k * math.cos(2 * math.pi * x / period)
            dy = -k * math.sin(2 * math.pi * y / period)
            n = (-dx, -dy, 1.0)
            length = math.sqrt(sum(c * c for c in n))
            return tuple(round(255 * (c / length * 0.5 + 0.5)) for c in n)
        return pixel

    write_png(folder / "splat.png", 32, 32, splat)
    layers = []
    for name in LAYERS:
        write_png(folder / f"{name}_albedo.png", size, size, albedos[name])
        write_png(folder / f"{name}_normal.png", size, size, normal(periods[name]))
        layers.append({"name": name, "slots": [
            {"name": "albedo", "kind": "color", "texture": f"{name}_albedo.png", "colorspace": "srgb"},
            {"name": "normal", "kind": "normal", "texture": f"{name}_normal.png"}]})
    name = f"layered_{weights}" if weights != "splat" else "layered" if arrays else "layered_separate"
    source = {"weights": weights, **({"splat": ["splat.png"]} if weights != "vertex" else {})}
    material = {"name": name, "hextiling": {"tiling": 2, "rotation": 1.0}, "layers": layers,
                "layer_blend": {**source, "mode": "linear", **({} if arrays else {"arrays": "off"})}}
    (folder / f"{name}.json").write_text(json.dumps(material, indent=2))
    return folder / f"{name}.json"


# The vertex colours of a quad that fills the view, at its top-left, top-right, bottom-left and bottom-right corners:
# hexc's harness's colour (1 - x, x, y, 1 - y) at (x, y) across and down the view (docs/material-format.md#layers),
# which the fp64 reference interpolates as the rasteriser does (each channel is affine in x and y, so a quad of two
# triangles carries it exactly). VERTEX_COLORS_SWAPPED: red and green exchanged, clay's and moss's weights with them
# (a negative control: the check must fail on it).
VERTEX_COLORS = [(1, 0, 0, 1), (0, 1, 0, 1), (1, 0, 1, 0), (0, 1, 1, 0)]
VERTEX_COLORS_SWAPPED = [(c[1], c[0], c[2], c[3]) for c in VERTEX_COLORS]
# The error of an engine's interpolated vertex colour at a pixel centre: the corners are 0 or 1, held exactly (float
# attributes, or 8-bit unorm), and the rasteriser evaluates the plane a + b x + c y in float32, a few ulp of 1 (2^-23
# each) off; 2^-16 is above any such sum.
VERTEX_COLOR_ERROR = 2 ** -16


def vertex_color(x, y, size):
    """VERTEX_COLORS interpolated at pixel (x, y) of a `size`-pixel view, at the pixel's centre."""
    u, v = (x + 0.5) / size, (y + 0.5) / size
    return (1 - u, u, v, 1 - v)


def layered_errors(hexc, material, manifest, role, normal, size, rect, work):
    """Per pixel, the bound on the error of a layered role's value before the engine's output (linear; for a normal role
    in n * 0.5 + 0.5), from the fp64 references of its layers' slots and of the splat map (`hexc render --reference`),
    or of the vertex colour (VERTEX_COLORS, each weight off by VERTEX_COLOR_ERROR instead of e), or of their product
    (weights "both": p c - p' c' = (p - p') c + p' (c - c'), each weight off by e + VERTEX_COLOR_ERROR (1 + e), as
    p, c <= 1 and p' <= 1 + e).
    As in tests/execution/layers_test.cpp, with the engines' filtering error e = FILTER_ERROR on every fetch:
      - each layer's value errs by its slot's error (as for a slot: amplification(slot) e; a normal's slope by
        4 e / n_z^2 times that, n_z the layer's own), and the blend, whose weights sum to 1, by the largest of them;
      - each splat weight s_i errs by e; w_i = s_i / S (S the sum of the kept s_i) moves so that the blend, whose
        weight changes sum to 0, moves by <= n e spread / S (spread: the largest difference between the layers'
        values in a channel; for a normal, between their slopes);
      - a layer whose s_i is within e of skip_below may be kept on one side and dropped on the other: its weight
        <= (skip + e) / S, times spread;
      - a normal: normalize(-d, 1) moves by no more than the slope d does, and n * 0.5 + 0.5 by half that."""
    skip = manifest["layers"]["skip_below"] if "skip_below" in manifest.get("layers", {}) else 0.5 / 255
    slots = {s["name"]: s for s in manifest["slots"]}
    output = "derivative" if normal else "albedo"
    values = [reference(hexc, material, output, f"{l}_{role}", size, rect, work / f"{l}_{role}.ref.pfm")[2] for l in LAYERS]
    weighed = manifest["layers"]["weights"]
    colour = weighed != "splat"
    splat = None if weighed == "vertex" else reference(hexc, material, "albedo", "splat0", size, rect, work / "splat0.ref.pfm")[2]
    amplify = max(amplification(slots[f"{l}_{role}"]) for l in LAYERS)
    e, n = FILTER_ERROR, len(LAYERS)
    ew = {"splat": e, "vertex": VERTEX_COLOR_ERROR, "both": e + VERTEX_COLOR_ERROR * (1 + e)}[weighed]  # a weight's error
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            s = [(splat[y][x][i] if splat else 1.0) * (vertex_color(x, y, size)[i] if colour else 1.0) for i in range(n)]
            S = max(sum(v for v in s if v >= skip), 1e-3)
            layer = [values[i][y][x] for i in range(n)]
            channels = 2 if normal else 3
            spread = max(max(v[c] for v in layer) - min(v[c] for v in layer) for c in range(channels))
            own = amplify * (max(4 * e * (1 + v[0] ** 2 + v[1] ** 2) for v in layer) if normal else e)  # 1 / n_z^2 = 1 + |d|^2
            weights = n * ew * spread / S + sum((skip + ew) / S * spread for v in s if abs(v - skip) <= ew)
            row.append(0.5 * (own + weights) if normal else own + weights)
        rows.append(row)
    return rows


def rect_for(manifest, size):
    """A uv rectangle from (0, 0) whose side puts about 0.7 texels on a pixel of a `size`-pixel view of the package
    `manifest` describes: every fetch is from the full-resolution level (lod < 0), so the comparison does not depend on
    how the engine makes mip levels."""
    texels = max(s["hextiling"]["tiling"][i] * s["size"][i] for s in manifest["slots"] for i in (0, 1))
    side = min(1.0, 0.7 * size / texels)
    return [0.0, 0.0, side, side]


def check_function(hexc, material, manifest, function, size, rect, out, relative, encode=srgb, marker=0):
    """The engine's image `out` of a package's `function` against hexc's fp64 reference: compare()'s figures (`marker`
    as there). For a layered material's role, the bound is layered_errors', and `flip_caught` says whether the same
    image compared with the reference flipped in u, and in v, is over the bound (so that the splat map's orientation
    is checked)."""
    normal = function["returns"] == "vec3"
    output = "normal" if normal else "albedo"
    if "slot" in function:
        ref = reference(hexc, material, output, function["slot"], size, rect, out.with_suffix(".ref.pfm"))
        slot = next(s for s in manifest["slots"] if s["name"] == function["slot"])
        return compare(out, ref, normal, relative, amplification(slot), encode, marker=marker)
    ref = reference(hexc, material, output, function["role"], size, rect, out.with_suffix(".ref.pfm"))
    errors = layered_errors(hexc, material, manifest, function["role"], normal, size, rect, out.parent)
    r = compare(out, ref, normal, relative, 1.0, encode, errors, marker)
    w, h, rows = ref
    flipped = [(w, h, [row[::-1] for row in rows]), (w, h, rows[::-1])]
    r["flip_caught"] = all(compare(out, f, normal, relative, 1.0, encode, errors, marker)["pixels_over_bound"] > 0 for f in flipped)
    return r


# The probe: textures unlike the examples, to judge an engine's image in absolute orientation. Non-square, so that a
# transposed or stretched read shows; asymmetric in u and in v, so that a flip or a mirror shows (a noise texture
# hides both). Image coordinates here: x right, y down, the PNG's first row the texture's first row (v = 0 in hexc's
# top-left uv origin).
PROBE_ALBEDO = (96, 64)  # the "F" glyph, a hue gradient along the bottom, a grey patch on the right
PROBE_BUMPS = (5, 3)  # columns and rows of bumps in the normal maps
PROBE_NORMAL = (100, 60)  # 20 texels a bump


def probe_glyph(x, y):
    """The probe albedo's texel (x, y) as sRGB bytes: a dark "F" at the top-left on a warm ground, a grey patch at the
    right, a hue gradient (red at the left through green to blue at the right) along the bottom."""
    if y >= 46:
        h = 3 * x / PROBE_ALBEDO[0]  # 0 .. 3: red, green, blue corners of the hue circle
        k = [max(0.0, 1 - min(abs(h - c), 3 - abs(h - c))) for c in (0.0, 1.0, 2.0)]
        return tuple(round(40 + 200 * v) for v in k)
    if 74 <= x < 92 and 6 <= y < 40:
        return (128, 128, 128)
    in_f = (8 <= x < 16 and 6 <= y < 40) or (8 <= x < 50 and 6 <= y < 14) or (8 <= x < 38 and 21 <= y < 28)
    return (30, 30, 40) if in_f else (225, 205, 170)


def probe_height(x, y):
    """The probe's height field at image point (x, y) in texels: a bump of radius 8 at the centre of each 20-texel cell,
    h = cos^2(pi r / 16) inside, 0 outside; its slope (dh/dx, dh/dy), y down the image."""
    cx, cy = (math.floor(x / 20) + 0.5) * 20, (math.floor(y / 20) + 0.5) * 20
    dx, dy = x - cx, y - cy
    r = math.hypot(dx, dy)
    if r >= 8 or r == 0:
        return 0.0, 0.0
    dh_dr = -2 * math.cos(math.pi * r / 16) * math.sin(math.pi * r / 16) * math.pi / 16 * 4  # 4x: a clear relief
    return dh_dr * dx / r, dh_dr * dy / r


def probe_normal(green_up):
    """The bumps' normal map, green up (OpenGL: n = (-dh/dx, +dh/dy_down, 1)) or down (DirectX: -dh/dy_down), as bytes."""
    def pixel(x, y):
        sx, sy = probe_height(x + 0.5, y + 0.5)
        n = (-sx, sy if green_up else -sy, 1.0)
        length = math.sqrt(sum(c * c for c in n))
        return tuple(round(255 * (c / length * 0.5 + 0.5)) for c in n)
    return pixel


def probe_material(folder, convention="gl", hextiling=False, albedo=True):
    """The probe as a material in `folder`: the glyph albedo (sRGB) and the bump normal map in `convention` ("gl":
    green up; "dx": green down, `flip_y`), plain tiled once across uv unless `hextiling` (then hex-tiled 3 times with
    rotation, as a user would). Plain tiling keeps the F and the bumps whole, so that orientation is judged by eye and
    by bumps_lit() as well as against `hexc render`. Without `albedo`, the normal map alone (a white surface): what
    bumps_lit() counts in a lit image, which the F's dark strokes would otherwise bias."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    write_png(folder / "probe_albedo.png", *PROBE_ALBEDO, probe_glyph)
    write_png(folder / f"probe_normal_{convention}.png", *PROBE_NORMAL, probe_normal(convention == "gl"))
    name = f"probe_{convention}" + ("_hex" if hextiling else "") + ("" if albedo else "_bumps")
    tiling = {"tiling": 3, "rotation": 1.0} if hextiling else {"enabled": False}
    normal = {"name": "normal", "kind": "normal", "texture": f"probe_normal_{convention}.png"}
    if convention == "dx":
        normal["flip_y"] = True
    colour = [{"name": "albedo", "kind": "color", "texture": "probe_albedo.png", "colorspace": "srgb"}] if albedo else []
    material = {"name": name, "hextiling": tiling, "slots": colour + [normal]}
    (folder / f"{name}.json").write_text(json.dumps(material, indent=2))
    return folder / f"{name}.json"


def bumps_lit(png, side, rect=(0.0, 0.0, 1.0, 1.0)):
    """How many of the probe's 5 x 3 bumps are brighter on `side` ("top", "bottom", "left", "right" of the screen) than
    on the opposite side, by more than 8 levels, in an image of the probe lit from that side. `rect` is the part of the
    image (x0, y0, x1, y1 as fractions, y down the screen) that shows the normal map once, upright: an engine that draws
    the map flipped or with the wrong green lights the bumps from the other side, and the count drops to 0."""
    w, h, n, rows = read_png(png)
    cols, lines = PROBE_BUMPS
    x0, y0, x1, y1 = rect[0] * w, rect[1] * h, rect[2] * w, rect[3] * h
    cw, ch = (x1 - x0) / cols, (y1 - y0) / lines

    def mean(cx, cy, ox, oy):  # a small square at offset (ox, oy) of a bump's radius from its centre
        px, py = cx + ox * cw * 0.25, cy + oy * ch * 0.25
        vals = [sum(rows[int(py) + j][(int(px) + i) * n + c] for c in range(3)) / 3 for j in (-1, 0, 1) for i in (-1, 0, 1)]
        return sum(vals) / len(vals)

    offset = {"top": (0, -1), "bottom": (0, 1), "left": (-1, 0), "right": (1, 0)}[side]
    lit = 0
    for j in range(lines):
        for i in range(cols):
            cx, cy = x0 + (i + 0.5) * cw, y0 + (j + 0.5) * ch
            lit += mean(cx, cy, *offset) > mean(cx, cy, -offset[0], -offset[1]) + 8
    return lit


# The marker an engine test has the engine draw over the screen's top-left corner, in the same frame as the material:
# a red square a sixteenth of the image's side. Where it shows in the saved image says how the read-back is oriented.
MARKER_FRACTION = 1 / 16


def marker_corner(png):
    """The corner of the image where the engine's red marker square is ("top-left", "top-right", "bottom-left",
    "bottom-right"), or None: every pixel of the square, but its border pixel, red (r > 200, g and b < 50)."""
    w, h, n, rows = read_png(png)
    side = int(w * MARKER_FRACTION)
    for name, (x0, y0) in {"top-left": (0, 0), "top-right": (w - side, 0), "bottom-left": (0, h - side),
                           "bottom-right": (w - side, h - side)}.items():
        pixels = [rows[y][x * n:x * n + 3] for y in range(y0 + 1, y0 + side - 1) for x in range(x0 + 1, x0 + side - 1)]
        if all(p[0] > 200 and p[1] < 50 and p[2] < 50 for p in pixels):
            return name
    return None


def srgb_decoded_copy(png, out):
    """A copy of an sRGB PNG whose bytes hold the decoded (linear) values: what an export that linearises an image
    gives. Bound as sRGB, as the package asks for its slot, it is decoded twice (a negative control)."""
    w, h, n, rows = read_png(png)
    decode = lambda b: round(255 * ((b / 255) / 12.92 if b <= 10 else ((b / 255 + 0.055) / 1.055) ** 2.4))
    write_png(out, w, h, lambda x, y: tuple(decode(rows[y][x * n + c]) for c in range(3)))
    return Path(out)


def layered_controls(folder):
    """The layered material's (layered_material, in `folder`) wrong bindings, slot -> file, each of which its check must
    fail: two layers' textures exchanged (clay's and moss's albedo), and a splat channel swapped (a copy of the splat
    map with green and blue exchanged: moss shows at the bottom, slate at the top). Not the same pair: a splat map with
    red and green exchanged draws what clay's and moss's textures exchanged draw."""
    folder = Path(folder)
    w, h, n, rows = read_png(folder / "splat.png")
    write_png(folder / "splat_swapped.png", w, h, lambda x, y: (rows[y][x * n], rows[y][x * n + 2], rows[y][x * n + 1]))
    return {"a layer swapped: clay's and moss's albedo textures exchanged":
            {"clay_albedo": folder / "moss_albedo.png", "moss_albedo": folder / "clay_albedo.png"},
            "a splat channel swapped: the splat map's green and blue exchanged": {"splat0": folder / "splat_swapped.png"}}


def drawn_materials(root, work):
    """The materials every executed engine draws against the fp64 reference: the examples rock (sRGB albedo, normal
    and roughness, hex-tiled with rotation) and tiles (rotation 0), the mixed material (non-square, packed, a DirectX
    normal map), the layered one, the probe plain-tiled (the F upright) and the probe hex-tiled with a DirectX map."""
    return [Path(root) / "materials" / "rock.json", Path(root) / "materials" / "tiles.json", mixed_material(work / "mixed"),
            layered_material(work / "layered"), probe_material(work / "probe"), probe_material(work / "probe", "dx", True)]


def histogram_material(root):
    """The golden histogram material: every slot blended by histogram, its Gaussian textures and tables the package's
    OpenEXR files, which the engines load as float textures."""
    return Path(root) / "tests" / "golden" / "materials" / "histogram.json"


def refused(material, engine):
    """Why the docs say `engine`'s package refuses `material`, or None: a test asserts hexc refuses it and prints why."""
    if Path(material).stem == "rock_triplanar":
        return "a triplanar material has no functions output (docs/engines.md#slots-and-engine-inputs)"
    return None


def matrix_materials(root):
    """Every material under materials/ an engine package is compiled from: the JSON materials (but the JSON Schema),
    the terrain, and the MaterialX documents beside them. Left out: materials/invalid/ (each must fail to parse),
    materials/mtlx/corpus/ (the MaterialX importer's test corpus: several invalid by design, textures not there),
    scenes and layouts (not materials)."""
    m = Path(root) / "materials"
    return sorted([p for p in m.glob("*.json") if p.name != "material.schema.json"] + list((m / "terrain").glob("*.json")) +
                  list((m / "mtlx").glob("*.mtlx")))


def row(what, figure, ok):
    """A line of an engine test's table of checks; True if the check failed."""
    print(f"| {what} | {figure} | {'ok' if ok else 'FAIL'} |", flush=True)
    return not ok


def value_verdict(hexc, material, function, out, view, control=None, errors=()):
    """The verdict on an engine's value view `out` of a package's `function` against the reference: `view` holds the
    package folder, the uv origin, the size and uv rectangle shown, and the engine's `relative` buffer error and
    `encode`ing (check_function). It passes within the bound, with the marker at the top-left and no shader error; a
    `control` (a wrong variant, named) must be over the bound. True if the verdict is a failure of the test."""
    size = view["size"]
    r = check_function(hexc, material, manifest(view["package"]), function, size, view["rect"], out, view["relative"],
                       view["encode"], int(size * MARKER_FRACTION))
    over = r["pixels_over_bound"] > 0 or r.get("flip_caught") is False
    what = f"{Path(material).stem}, {view['origin']}, {function['name']}"
    if control:
        return row(f"control: {control} ({what})", f"{r['pixels_over_bound']} values over the bound, max / bound "
                   f"{r['max_over_bound']:.1f}: the check fails as it must" if over else "within the bound", over)
    corner = marker_corner(out)
    flips = {None: "", True: "; a flipped u or v caught", False: "; a flipped u or v would pass"}[r.get("flip_caught")]
    return row(what, f"mean {r['mean']:.3f}, max {r['max']:.2f}, max / bound {r['max_over_bound']:.2f}, "
               f"{r['pixels_over_bound']} over{flips}; marker at the {corner}{'; ' + ' '.join(errors) if errors else ''}",
               not over and not errors and corner == "top-left")


def lit_verdict(out, what, side, control=False, errors=()):
    """The verdict on a lit image of the probe's bumps: 15 of 15 lit from the light's `side`, the marker at the
    top-left; a control must light fewer. True if the verdict is a failure of the test."""
    lit, corner = bumps_lit(out, side), marker_corner(out)
    if control:
        return row(f"control: {what}, lit from the {side}", f"{lit} of 15 bumps lit from the {side}", lit < 15)
    return row(f"{what}, lit from the {side}", f"{lit} of 15 bumps lit from the {side}; marker at the {corner}",
               lit == 15 and corner == "top-left" and not errors)
