"""How long `hexc edit`'s page takes from an edit to the frame that shows it, in headless Chromium on the machine's
software renderer (SwiftShader): a slider (a uniform, no compile) and a structural change (compiled again by the
server). Prints the figures with their spread and the machine's load; measures, never fails on a number.

Usage: edit_latency.py HEXC [REPETITIONS]   (from the source root; docs/edit.md has the figures)

Each time is taken in the page, from the control's event (performance.now() as the edit starts) to the end of the
frame drawn after it (a one-pixel readPixels after drawing waits for the renderer). A structural change includes
the page's 120 ms wait for more edits before it asks the server to compile, the server's four compiles (the page's
programs: hex-tiled, plain, weights, the slot's values), WebGL linking them (ANGLE translates them) and the first frame
that draws them (SwiftShader compiles shaders for the CPU when they are first drawn); it is split into those parts. The cost line's compile of the
shipped shader runs after the frame, as does the next edit (each edit waits for the previous one's frame only).
"""
import json
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "edit"))
from edit_support import Server, browser_or_skip, quit_browser, wait_idle  # noqa: E402

# Sets a control, then resolves with the milliseconds from the edit to the end of the first frame drawn after the
# page has no compile pending.
MEASURE = """
const [pointer, kind, event, value, structural, done] = arguments;
const h = window.hexcEdit, frames = h.frames, compiles = h.compiles;
const e = document.querySelector(`[data-pointer="${pointer}"] ${kind}`);
e.value = value;
e.dispatchEvent(new Event(event));
const poll = () => {
  if (h.frames > frames && h.pending === 0 && (!structural || h.compiles > compiles) && h.lastFrame > h.editAt) {
    const t = h.timing;  // a structural edit's parts: the server's answer, WebGL's compile and link, the frame
    done(structural ? [h.lastFrame - h.editAt, t.answered - t.sent, t.linked - t.answered, h.lastFrame - t.textures] : [h.lastFrame - h.editAt]);
  } else requestAnimationFrame(poll);
};
poll();
"""


def summary(name, times):
    q = statistics.quantiles(times, n=4) if len(times) >= 4 else [min(times), statistics.median(times), max(times)]
    return "%-46s n=%-3d median %7.1f ms  IQR %7.1f-%7.1f ms  min %7.1f  max %7.1f" % (name, len(times), statistics.median(times), q[0], q[2],
                                                                                      min(times), max(times))


def main():
    hexc, repetitions = os.path.abspath(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 15
    folder = tempfile.mkdtemp(prefix="hexc-edit-bench-")
    shutil.copytree("materials/textures", os.path.join(folder, "textures"))
    material = os.path.join(folder, "rock.json")
    shutil.copy("materials/rock.json", material)
    load_before = open("/proc/loadavg").read().split()[:3]
    driver = browser_or_skip()
    server = Server(hexc, material)
    try:
        driver.set_window_size(1280, 800)
        driver.get(server.url)
        wait_idle(driver, 1)
        renderer = driver.execute_script("const gl = document.createElement('canvas').getContext('webgl2');"
                                         "const i = gl.getExtension('WEBGL_debug_renderer_info');"
                                         "return i ? gl.getParameter(i.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);")
        canvas = driver.execute_script("const c = document.getElementById('canvas'); return [c.width, c.height];")
        slider = [driver.execute_async_script(MEASURE, "/hextiling/falloff", "input[type=range]", "input", str(0.55 + 0.3 * (i % 2)), False)
                  for i in range(repetitions * 2)]
        # rotationsteps is a whole number fixed in the code: each new value is a shader the server has not compiled.
        fresh = [driver.execute_async_script(MEASURE, "/hextiling/rotationsteps", "input[type=number]", "change", str(i + 2), True)
                 for i in range(repetitions)]
        # The mask toggled between two values: after the first of each, the page's programs come from the shader cache
        # and only the shipped shader (the cost line) is compiled.
        cached = [driver.execute_async_script(MEASURE, "/hextiling/mask", "select", "change", json.dumps(["checker", "hex"][i % 2]), True)
                  for i in range(repetitions + 2)][2:]
    finally:
        server.stop()
        quit_browser(driver)
        shutil.rmtree(folder, ignore_errors=True)
    load_after = open("/proc/loadavg").read().split()[:3]
    chromium = subprocess.run(["/usr/bin/chromium", "--version"], capture_output=True, text=True).stdout.strip()
    print("hexc edit latency, materials/rock.json on the ground plane split view, canvas %dx%d" % tuple(canvas))
    print("machine: %s, %d cores; %s; %s" % (platform.machine(), os.cpu_count(), chromium, renderer))
    print("load average (1, 5, 15 min): before %s, after %s" % (" ".join(load_before), " ".join(load_after)))
    print(summary("slider (falloff, a uniform)", [t[0] for t in slider]))
    for name, runs in (("structural, new shader (rotationsteps)", fresh), ("structural, cached programs (mask)", cached)):
        print(summary(name, [t[0] for t in runs]))
        for i, part in ((1, "  of which the server's compile and answer"), (2, "  of which WebGL's link (ANGLE)"),
                        (3, "  of which the first frame (SwiftShader's JIT)")):
            print(summary(part, [t[i] for t in runs]))


if __name__ == "__main__":
    main()
