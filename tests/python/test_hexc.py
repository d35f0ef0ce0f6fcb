"""The Python module (docs/python.md): rock from a path, a JSON string and a dict to the command line's bytes, engine
packages, bad input with the command line's located diagnostics, threads, and memory over 1,000 compiles. Each check
also runs on a wrong input it must reject. Run from the source root with the built package on PYTHONPATH and HEXC_EXE
naming the built hexc (CTest's python_module does)."""
import ctypes
import json
import os
import re
import subprocess
import threading
import time

import pytest

import hexc

HEXC = os.environ.get("HEXC_EXE", "build/hexc")
ROCK = "materials/rock.json"
# "file:line:col: error[HX107]: /slots/0/kind: message": line and column absent when unknown, the path when the
# problem is not about a value.
LINE = re.compile(r"^(.*?)(?::(\d+):(\d+))?: (error|warning)\[(HX\d+)\]: (/\S*: )?")


def command_line(material, out):
    """What `hexc MATERIAL -o OUT` writes, by name, and the located diagnostics it prints."""
    run = subprocess.run([HEXC, str(material), "-o", str(out), "--no-cache"], capture_output=True, text=True)
    files = {}
    for folder, _, names in os.walk(out):
        for name in names:
            if not name.startswith("."):  # the stamp
                path = os.path.join(folder, name)
                files[os.path.relpath(path, out)] = open(path, "rb").read()
    located = [located_tuple(m) for m in map(LINE.match, run.stderr.splitlines()) if m]
    return run.returncode, files, located


def located_tuple(m):
    return (m.group(1), int(m.group(2) or 0), int(m.group(3) or 0), m.group(5), (m.group(6) or "")[:-2])


def located(diagnostics):
    return [(d.file, d.line, d.column, d.code, d.path) for d in diagnostics]


def as_bytes(files):
    return {name: data if isinstance(data, bytes) else data.encode() for name, data in files.items()}


@pytest.fixture(scope="module")
def context():
    return hexc.Context("")  # memory only: nothing written under the home folder


@pytest.fixture(scope="module")
def rock_cli(tmp_path_factory):
    code, files, _ = command_line(ROCK, tmp_path_factory.mktemp("rock"))
    assert code == 0
    return files


def test_path_compiles_to_the_command_lines_bytes(context, rock_cli):
    result = context.compile(ROCK)
    assert isinstance(result.files["rock.frag.hlsl"], str) and isinstance(result.files["rock.frag.spv"], bytes)
    assert result.files["rock.frag.spv"][:4] == b"\x03\x02\x23\x07"
    assert result.manifest["material"] == "rock" and result.manifests["rock.manifest.json"] is result.manifest
    assert as_bytes(result.files) == rock_cli
    # Negative control: another material's files are not rock's.
    assert as_bytes(context.compile("materials/tiles.json").files) != rock_cli


def test_string_and_dict_compile_as_the_file(context, rock_cli):
    text = open(ROCK).read()
    assert as_bytes(context.compile(text, base_dir="materials", name="rock.json").files) == rock_cli
    material = json.loads(text)
    assert as_bytes(context.compile(material, base_dir="materials", name="rock.json").files) == rock_cli
    # Negative control: the dict is the material, not the file: a changed setting changes the shaders.
    material["hextiling"] = dict(material.get("hextiling", {}), rotation=10)
    assert as_bytes(context.compile(material, base_dir="materials", name="rock.json").files) != rock_cli


def test_targets_engines_and_options(context):
    only = context.compile(ROCK, targets=["hlsl"], hlsl_sm=60)
    assert sorted(only.files) == ["rock.frag.hlsl", "rock.manifest.json"]
    packages = context.compile(ROCK, engines="godot3,threejs")
    assert packages.files and all(n.startswith(("godot3/", "threejs/")) for n in packages.files)
    assert any(n.startswith("godot3/") for n in packages.manifests) and packages.manifest is None
    with pytest.raises(ValueError, match="wgls"):
        context.compile(ROCK, targets="hlsl,wgls")


# Bad input: each as a dict the module writes as JSON text (hexc.material_text) into a folder, where the command line
# reads the same text; the diagnostics must name the same file, lines, columns, codes and JSON paths.
TEXTURE = os.path.abspath("materials/textures/tiles_albedo.png")
BAD = {
    "malformed": {"name": "bad", "template": "unlit", "slots": [{"name": "albedo", "kind": "colour", "texture": TEXTURE}]},
    "not an object": {"name": "bad", "template": "unlit", "slots": {"albedo": TEXTURE}},
    "missing texture": {"name": "bad", "template": "unlit", "slots": [{"name": "albedo", "kind": "color", "texture": "none.png"}]},
    "nan": {"name": "bad", "template": "unlit", "hextiling": {"rotation": float("nan")},
            "slots": [{"name": "albedo", "kind": "color", "texture": TEXTURE}]},
    "infinity": {"name": "bad", "template": "unlit", "hextiling": {"tiling": float("inf")},
                 "slots": [{"name": "albedo", "kind": "color", "texture": TEXTURE}]},
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_input_is_located_as_the_command_line_does(context, tmp_path, case):
    (tmp_path / "material.json").write_text(hexc.material_text(BAD[case]))
    code, files, printed = command_line(tmp_path / "material.json", tmp_path / "out")
    assert code == 1 and not files and printed
    with pytest.raises(hexc.CompileError) as raised:
        context.compile(BAD[case], base_dir=tmp_path)
    diagnostics = raised.value.diagnostics
    assert any(d.line > 0 and d.column > 0 for d in diagnostics if d.error)
    assert located(diagnostics) == printed
    assert str(raised.value) == "\n".join(map(str, diagnostics))
    # Negative control: the next case's diagnostics are not this one's.
    other = BAD[sorted(BAD)[(sorted(BAD).index(case) + 1) % len(BAD)]]
    with pytest.raises(hexc.CompileError) as wrong:
        context.compile(other, base_dir=tmp_path)
    assert located(wrong.value.diagnostics) != printed


def test_missing_file_and_syntax_error(context):
    with pytest.raises(hexc.CompileError) as raised:
        context.compile("materials/no_such_material.json")
    assert raised.value.diagnostics[0].code == "HX100"
    with pytest.raises(hexc.CompileError) as raised:
        context.compile('{"name": "x",}')
    assert [(d.code, d.line, d.column) for d in raised.value.diagnostics] == [("HX101", 1, 13)]


def share_during(work):
    """The share of `work()`'s time in which another Python thread ran its loop, against the loop's rate alone: near 1
    when `work` lets the interpreter lock go (less on a busy machine), near 0 when it holds it (the other thread then
    runs only in the switch intervals, 5 ms each, around it)."""
    count, running = [0], [True]

    def counter():
        while running[0]:
            count[0] += 1

    thread = threading.Thread(target=counter)
    thread.start()
    start, before = time.perf_counter(), count[0]
    time.sleep(0.2)  # the main thread waits without the lock: the loop's own rate
    rate = (count[0] - before) / (time.perf_counter() - start)
    start, before = time.perf_counter(), count[0]
    work()
    share = (count[0] - before) / (rate * (time.perf_counter() - start))
    running[0] = False
    thread.join()
    return share


def test_compiles_release_the_interpreter_lock():
    fresh = hexc.Context("")  # nothing cached: glslang, spirv-opt and SPIRV-Cross run (about 0.1-0.5 s)
    during_compile = share_during(lambda: fresh.compile(ROCK))
    # Negative control: sorted() of a long list runs in C holding the lock for a comparable time.
    numbers = [(i * 7919) % 1_000_003 for i in range(2_000_000)]
    during_sort = share_during(lambda: sorted(numbers))
    print("another thread ran %.2f of a compile's time, %.2f of sorted()'s" % (during_compile, during_sort))
    assert during_sort < 0.1
    assert during_compile > 3 * max(during_sort, 0.05)


def test_threads_compile_at_once_to_the_same_bytes():
    materials = ["materials/rock.json", "materials/tiles.json", "materials/rock_normal.json", "materials/terrain/terrain.json"]
    shared = hexc.Context("")
    expected = {m: as_bytes(hexc.Context("").compile(m).files) for m in materials}
    results, errors = {}, []

    def work(i):
        try:
            for round in range(3):
                m = materials[(i + round) % len(materials)]
                results[(i, round)] = (m, as_bytes(shared.compile(m).files))
        except Exception as e:  # reported below: an exception in a thread does not fail the test by itself
            errors.append(e)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(8)]
    start = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    print("8 threads x 3 compiles: %.2f s, cache (hits, misses) %s" % (time.perf_counter() - start, shared.cache_stats()))
    assert not errors and len(results) == 24
    assert all(files == expected[m] for m, files in results.values())
    # Negative control of the comparison: one material's files are not another's.
    assert expected[materials[0]] != expected[materials[1]]


class _Mallinfo2(ctypes.Structure):
    _fields_ = [(name, ctypes.c_size_t) for name in
                "arena ordblks smblks hblks hblkhd usmblks fsmblks uordblks fordblks keepcost".split()]


_libc = ctypes.CDLL("libc.so.6")
_libc.mallinfo2.restype = _Mallinfo2


def rss_kib():
    """The resident memory once malloc has given back its free pages (malloc_trim): what stays is what is in use, so
    a leak shows at once instead of after it has filled the allocator's free memory."""
    _libc.malloc_trim(0)
    for line in open("/proc/self/status"):
        if line.startswith("VmRSS:"):
            return int(line.split()[1])


def heap_kib():
    """The bytes malloc has handed out and not had back, in KiB, over every arena (glibc's mallinfo2)."""
    m = _libc.mallinfo2()
    return (m.uordblks + m.hblkhd) // 1024


def test_no_leak_over_1000_compiles():
    context = hexc.Context("")
    bad = BAD["malformed"]

    def one(i, kept=None):
        # Compiles that succeed and compiles that raise: both paths must free what they made.
        if i % 4 == 3:
            with pytest.raises(hexc.CompileError):
                context.compile(bad)
        else:
            result = context.compile(ROCK, targets="spirv,hlsl")
            if kept is not None:
                kept.append((result, bytearray(64 << 10)))

    # Warm up until the allocator's arenas, Python's caches and the shader cache hold what a compile needs, then
    # measure the noise: the largest change between batches of 50 compiles once nothing is being built up.
    for i in range(100):
        one(i)
    rss, heap = [], []
    for batch in range(4):
        for i in range(50):
            one(i)
        rss.append(rss_kib())
        heap.append(heap_kib())
    rss_noise = max(abs(a - b) for a, b in zip(rss, rss[1:]))
    heap_noise = max(abs(a - b) for a, b in zip(heap, heap[1:]))
    # Bounds: over 1,000 compiles (20 batches), noise that wanders adds up to at most 20 times a batch's, plus 64 KiB
    # for one container that grows once to its steady capacity after the warm-up (for RSS, 16 pages a page-granular
    # measure can round up). A leak of 64 bytes a compile exceeds the bound on what is handed out when its noise is 0.
    heap_before, rss_before = heap_kib(), rss_kib()
    heap_bound, rss_bound = 20 * heap_noise + 64, 20 * rss_noise + 64
    for i in range(1000):
        one(i)
    heap_growth, rss_growth = heap_kib() - heap_before, rss_kib() - rss_before
    print("1,000 compiles: RSS %d -> %d KiB (+%d, bound %d, noise %d); handed out +%d KiB (bound %d, noise %d)"
          % (rss_before, rss_before + rss_growth, rss_growth, rss_bound, rss_noise, heap_growth, heap_bound, heap_noise))
    assert heap_growth <= heap_bound and rss_growth <= rss_bound
    # Negative control: 250 compiles whose results are kept with 64 KiB each (a binding that never frees a result,
    # 26 MB in all) exceed both bounds. Nothing smaller is kept: 64 KiB is below glibc's threshold for mmap.
    kept = []
    heap_before, rss_before = heap_kib(), rss_kib()
    for i in range(250):
        one(i, kept)
    print("negative control: RSS +%d KiB, handed out +%d KiB" % (rss_kib() - rss_before, heap_kib() - heap_before))
    assert heap_kib() - heap_before > heap_bound and rss_kib() - rss_before > rss_bound
