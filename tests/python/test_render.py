"""hexc.render and hexc.preview (docs/python.md) against the files `hexc render` and `hexc preview` write for the same
options: the fp64 reference and lavapipe, linear and sRGB. Each comparison also runs on a view that must differ.
Lavapipe's tests skip without a Vulkan device, unless HEXC_REQUIRE_VULKAN=1. Run as test_hexc.py is (CTest's
python_render)."""
import os
import subprocess

import numpy as np
import pytest

import hexc

HEXC = os.environ.get("HEXC_EXE", "build/hexc")
ROCK = "materials/rock.json"


def read_pfm(path):
    """A PFM file hexc wrote as (height, width, 3) float32, row 0 at the top (the file stores the bottom row first)."""
    data = open(path, "rb").read()
    kind, size, scale, pixels = data.split(b"\n", 3)
    width, height = map(int, size.split())
    assert kind == b"PF" and float(scale) < 0  # RGB, little-endian
    return np.frombuffer(pixels, dtype="<f4").reshape(height, width, 3)[::-1]


def command_line(tmp_path, command, material, args):
    """The image `hexc COMMAND MATERIAL ARGS -o IMAGE.pfm` writes (RGB: PFM holds no alpha)."""
    out = tmp_path / ("%s.pfm" % command)
    run = subprocess.run([HEXC, command, material, *args, "-o", str(out)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return read_pfm(out)


@pytest.fixture(scope="module")
def context():
    return hexc.Context("")


def lavapipe(call):
    """`call()`, skipped when there is no Vulkan device, unless HEXC_REQUIRE_VULKAN=1."""
    try:
        return call()
    except RuntimeError as e:
        if os.environ.get("HEXC_REQUIRE_VULKAN") == "1":
            raise
        pytest.skip(str(e))


# (Python's keywords, the command line's arguments): the same view; the first window is not the default one.
VIEWS = {
    "albedo": (dict(output="albedo", size=(64, 48), uv_rect=(0.25, 0.5, 1.75, 2.0)),
               ["--output", "albedo", "--size", "64x48", "--uv-rect", "0.25,0.5,1.75,2.0"]),
    "weights": (dict(output="weights", size=(40, 40), uv_rect=(-1.0, 0.0, 2.0, 3.0)),
                ["--output", "weights", "--size", "40x40", "--uv-rect", "-1,0,2,3"]),
    "normal srgb": (dict(output="normal", slot="normal", size=(32, 32), encoding="srgb"),
                    ["--output", "normal", "--slot", "normal", "--size", "32x32", "--encoding", "srgb"]),
}


@pytest.mark.parametrize("view", sorted(VIEWS))
def test_reference_is_the_command_lines_file(context, tmp_path, view):
    keywords, args = VIEWS[view]
    material = "materials/rock_normal.json" if "normal" in view else ROCK
    image = context.render(material, reference=True, **keywords)
    height, width = keywords["size"][1], keywords["size"][0]
    assert image.shape == (height, width, 4) and image.dtype == np.float32
    expected = command_line(tmp_path, "render", material, args + ["--reference"])
    assert np.array_equal(image[..., :3], expected)  # exact: the same fp64 reference rounded to float once
    # Negative control: another uv window shows other texels.
    moved = context.render(material, reference=True, **dict(keywords, uv_rect=(0.5, 0.5, 2.0, 2.0)))
    assert not np.array_equal(moved[..., :3], expected)


def test_reference_top_row_first_and_linear(context):
    # The albedo's first row is v near V0 and its last near V1: a window of one row's height at the top of another
    # shows that row.
    whole = context.render(ROCK, output="albedo", size=(16, 16), reference=True)
    top = context.render(ROCK, output="albedo", size=(16, 1), uv_rect=(0.0, 0.0, 1.0, 1.0 / 16), reference=True)
    bottom = context.render(ROCK, output="albedo", size=(16, 1), uv_rect=(0.0, 15.0 / 16, 1.0, 1.0), reference=True)
    assert np.array_equal(top[0], whole[0]) and np.array_equal(bottom[0], whole[-1])
    assert not np.array_equal(top[0], whole[-1])  # negative control: the rows differ
    srgb = context.render(ROCK, output="albedo", size=(16, 16), reference=True, encoding="srgb")
    assert (srgb[..., :3] > whole[..., :3]).all()  # the sRGB transfer function raises every value in (0, 1)


@pytest.mark.parametrize("view", ["albedo", "weights"])
def test_lavapipe_is_the_command_lines_file(context, tmp_path, view):
    keywords, args = VIEWS[view]
    image = lavapipe(lambda: context.render(ROCK, **keywords))
    # Lavapipe gives the same pixels twice for the same shader and view: the comparison is exact.
    assert np.array_equal(image[..., :3], command_line(tmp_path, "render", ROCK, args))
    moved = lavapipe(lambda: context.render(ROCK, **dict(keywords, uv_rect=(0.5, 0.5, 2.0, 2.0))))
    assert not np.array_equal(moved, image)


def test_preview_is_the_command_lines_sheet(context, tmp_path):
    sheet = lavapipe(lambda: context.preview(ROCK, cell=48))
    assert sheet.shape == (2 * (48 + 28), 4 * 48, 4) and sheet.dtype == np.float32
    assert np.array_equal(sheet[..., :3], command_line(tmp_path, "preview", ROCK, ["--cell", "48"]))
    linear = context.preview(ROCK, cell=48, encoding="linear")
    assert not np.array_equal(linear, sheet)  # negative control: the encoding is applied


def test_bad_input_and_options(context):
    with pytest.raises(hexc.CompileError) as raised:
        context.render("materials/no_such_material.json", output="albedo", reference=True)
    assert raised.value.diagnostics[0].code == "HX100"
    with pytest.raises(ValueError, match="--size"):
        context.render(ROCK, output="albedo", size=(0, 4), reference=True)
    with pytest.raises(ValueError, match="--reference"):
        context.render(ROCK, reference=True)  # the reference covers slots, not the template's shading
