"""hexc.build (docs/python.md): a scene built with a progress callback writes what `hexc SCENE -o DIR` writes; an
exception raised by the callback stops the build with nothing written and no temporaries left, and is raised to the
caller. Run as test_hexc.py is (CTest's python_module)."""
import os
import subprocess

import pytest

import hexc

HEXC = os.environ.get("HEXC_EXE", "build/hexc")
SCENE = "materials/scenes/forest.json"
VARIANTS = 9  # rock, tiles, rock_normal in main and depth; rock and tiles in shadow; rock in weights


def files(folder, stamps=True):
    """Every file under `folder` (temporaries too, and the stamps, whose hash covers the output folder's path, when
    `stamps`), by path, with its bytes."""
    found = {}
    for parent, _, names in os.walk(folder):
        for name in names:
            if not stamps and name.endswith(".hexc-stamp"):
                continue
            path = os.path.join(parent, name)
            found[os.path.relpath(path, folder)] = open(path, "rb").read()
    return found


@pytest.fixture(scope="module")
def context():
    return hexc.Context("")


def test_scene_build_reports_progress_and_writes_the_command_lines_files(context, tmp_path):
    calls = []
    built = context.build(SCENE, tmp_path / "py", progress=lambda *call: calls.append(call))
    assert [done for done, _, _ in calls] == list(range(1, VARIANTS + 1))
    assert {total for _, total, _ in calls} == {VARIANTS}
    assert {name for _, _, name in calls} == {"rock.main", "tiles.main", "rock_normal.main", "rock.depth", "tiles.depth",
                                              "rock_normal.depth", "rock.shadow", "tiles.shadow", "rock.weights"}
    assert "9 compiled, 0 up to date" in built.log
    run = subprocess.run([HEXC, SCENE, "-o", str(tmp_path / "cli"), "--no-cache"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert files(tmp_path / "py", stamps=False) == files(tmp_path / "cli", stamps=False)
    # Up to date: nothing compiled, so no progress call.
    calls.clear()
    assert "0 compiled, 9 up to date" in context.build(SCENE, tmp_path / "py", progress=lambda *call: calls.append(call)).log
    assert calls == []


class Stop(Exception):
    pass


@pytest.mark.parametrize("first", [True, False], ids=["new folder", "earlier build"])
def test_an_exception_in_the_callback_stops_the_build_with_nothing_written(context, tmp_path, first):
    out = tmp_path / "out"
    if not first:
        context.build(SCENE, out, targets="hlsl")
    before = files(out) if out.exists() else None
    calls = []

    def progress(done, total, name):
        calls.append(done)
        if done == 3:
            raise Stop("stop after %s" % name)

    with pytest.raises(Stop, match="stop after"):
        context.build(SCENE, out, progress=progress, force=True, jobs=2)
    # Compiles under way when it raised finish; no call after the one that raised.
    assert calls == [1, 2, 3]
    assert (files(out) if out.exists() else None) == before  # untouched: no output, stamp or temporary
    # Negative control: the same build whose callback returns writes its files (every target's).
    context.build(SCENE, out, progress=lambda *call: None, force=True)
    written = files(out)
    assert "forest.scene.json" in written and written != before


def test_build_errors(context, tmp_path):
    with pytest.raises(hexc.CompileError) as raised:
        context.build("materials/invalid/kind_misspelled.json", tmp_path)
    assert raised.value.diagnostics[0].code.startswith("HX1") and raised.value.diagnostics[0].line > 0
    assert os.listdir(tmp_path) == []
    with pytest.raises(hexc.CompileError, match="--variant rock.nowhere"):  # as the command line's exit code 1
        context.build(SCENE, tmp_path, variants=["rock.nowhere"])
    with pytest.raises(ValueError, match="--jobs"):
        context.build(SCENE, tmp_path, jobs=-1)
    with pytest.raises(OSError, match="not a folder"):
        context.build("materials/rock.json", "materials/rock.json")
