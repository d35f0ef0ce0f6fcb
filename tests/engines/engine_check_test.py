"""engine_check.compare, the judge of every engine test, on images whose answer is known: an engine image equal to
the reference passes, one a channel off fails, and a reference with a NaN is refused rather than passed (NaN compares
as in bound). Run: engine_check_test.py DIR."""
import math
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "compiler" / "integrations"))
import engine_check as ec  # noqa: E402

W, H = 8, 6


def reference(nan_at=None):
    rows = [[[x / (W - 1), y / (H - 1), 0.25] for x in range(W)] for y in range(H)]
    if nan_at:
        rows[nan_at[1]][nan_at[0]][1] = math.nan
    return W, H, rows


def engine_png(folder, swap=False):
    _, _, rows = reference()
    path = Path(folder) / ("swapped.png" if swap else "engine.png")
    pixel = lambda x, y: tuple(round(255 * ec.srgb(c)) for c in rows[y][x])
    ec.write_png(path, W, H, (lambda x, y: pixel(x, y)[::-1]) if swap else pixel)
    return path


def main(folder):
    same = ec.compare(engine_png(folder), reference(), normal=False, relative=0, amplify=1)
    assert same["pixels_over_bound"] == 0 and same["max_over_bound"] <= 1, same
    swapped = ec.compare(engine_png(folder, swap=True), reference(), normal=False, relative=0, amplify=1)
    assert swapped["pixels_over_bound"] > 0, swapped
    try:
        ec.compare(engine_png(folder), reference(nan_at=(3, 2)), normal=False, relative=0, amplify=1)
    except ValueError as e:
        assert "(3, 2)" in str(e), e
    else:
        raise AssertionError("a reference with a NaN was judged")
    print(f"equal: {same['max_over_bound']:.3f} of bound; channels swapped: {swapped['pixels_over_bound']} values "
          "over; NaN reference refused")


if __name__ == "__main__":
    with tempfile.TemporaryDirectory(dir=sys.argv[1] if len(sys.argv) > 1 else None) as d:
        main(d)
