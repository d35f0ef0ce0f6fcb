"""How long `hexc edit`'s page takes from an edit to the frame that shows it, in headless Chromium on the machine's
software renderer (SwiftShader): a slider (a uniform, no compile), a structural change (compiled again by the server),
and a change of the material file on disk (noticed, reloaded, drawn); with the page's own frame time to compare with.
Prints the figures with their spread and the machine's load; measures, never fails on a number.

Usage: edit_latency.py HEXC [HEXC ...] [--repetitions N] [--rounds R] [--smoke]   (from the source root)

With several builds of hexc (before and after a change) the runs interleave: each round measures each build once, so
that a change in the machine's load falls on all of them alike. docs/edit.md has the figures. --smoke (CI): one
round of one repetition, and a failure if the page read pixels back while drawing (a pipeline stall every frame) or a
structural change cost other than one shader compile on the server (none for a shader compiled before); no time is judged.

Each time is taken in the page, from the control's event (performance.now() as the edit starts) to the page's mark of
the frame drawn after it (`hexcEdit.lastFrame`: the animation frame after the draw, when the browser took the frame;
builds before the change read one pixel back after drawing instead). A structural change includes the server's
compiles (the page's programs: one of every view, and plain tiling; builds before it compiled the slot's weights and
values apart), WebGL linking them (ANGLE translates them; nothing for programs the page linked before, in builds that
keep them) and the first frame that draws them (SwiftShader compiles shaders for the CPU when they are first drawn);
it is split into those parts, and the server's answer into its own work (parse and compiles, as it reports them) and
the rest (transfer, the page's parse of the JSON). Builds before the page compiled at once waited 120 ms for more edits first. Three
structural cases: a new shader, one the server has compiled before but the page has not linked, and one the page has
shown before (a setting switched back). The cost line's compile of the shipped shader runs after the frame; the next
edit waits for it. The frame time is the interval between frames while the view is moved every frame.
"""
import argparse
import json
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "edit"))
from edit_support import Server, browser_or_skip, quit_browser, wait_idle  # noqa: E402

# Once the cost line of the edit before is done (its compile would share the machine with this one's), sets a control,
# then resolves with the milliseconds from the edit to the end of the first frame drawn after the page has no compile
# pending.
MEASURE = """
const [pointer, kind, event, value, structural, done] = arguments;
const h = window.hexcEdit;
const edit = () => {
  if (document.getElementById('cost').textContent.startsWith('cost: compiling')) return requestAnimationFrame(edit);
  const frames = h.frames, compiles = h.compiles;
  const e = document.querySelector(`[data-pointer="${pointer}"] ${kind}`);
  e.value = value;
  e.dispatchEvent(new Event(event));
  const poll = () => {
    if (h.frames > frames && h.pending === 0 && (!structural || h.compiles > compiles) && h.lastFrame > h.editAt) {
      // A structural edit's parts: the server's answer, WebGL's compile and link, the frame; the server's own part of
      // its answer and the shaders it compiled (null from builds that do not report them).
      const t = h.timing, s = t.server || { ms: null, compiles: null };
      done(structural ? [h.lastFrame - h.editAt, t.answered - t.sent, t.linked - t.answered, h.lastFrame - t.textures, s.ms, s.compiles]
                      : [h.lastFrame - h.editAt]);
    } else requestAnimationFrame(poll);
  };
  poll();
};
edit();
"""

# The page's own frame time: the view turned a little every frame, the median interval between frames drawn.
FRAMES = """
const [count, done] = arguments;
const h = window.hexcEdit, times = [];
const step = () => {
  times.push(h.lastFrame);
  if (times.length > count) return done(times.slice(1).map((t, i) => t - times[i]));
  const v = h.view(), frames = h.frames;
  h.setView({ camera: { ...v.camera, azimuth: v.camera.azimuth + 0.5 } });
  const wait = () => h.frames > frames ? step() : requestAnimationFrame(wait);
  requestAnimationFrame(wait);
};
step();
"""

# After the file was written (at `since`, ms since the epoch): resolves with the wall-clock milliseconds until the
# reloaded material's frame is drawn.
RELOADED = """
const [compiles, done] = arguments;
const h = window.hexcEdit;
let frames = null;  // the frames drawn when the reload's compile was done: the next one shows it
const poll = () => {
  if (frames === null && h.compiles > compiles && h.pending === 0) frames = h.frames;
  if (frames !== null && h.frames > frames) done(Date.now() - (performance.now() - h.lastFrame));
  else requestAnimationFrame(poll);
};
poll();
"""

# Counts WebGL read-backs from now on (--smoke).
COUNT_READBACKS = """
window.readbacks = 0;
const f = WebGL2RenderingContext.prototype.readPixels;
WebGL2RenderingContext.prototype.readPixels = function (...a) { window.readbacks++; return f.apply(this, a); };
"""


def summary(name, times):
    q = statistics.quantiles(times, n=4) if len(times) >= 4 else [min(times), statistics.median(times), max(times)]
    return "%-46s n=%-3d median %7.1f ms  IQR %7.1f-%7.1f ms  min %7.1f  max %7.1f" % (name, len(times), statistics.median(times), q[0], q[2],
                                                                                      min(times), max(times))


def measure(hexc, repetitions, smoke):
    """One build's figures in a fresh page: lists of times by measure."""
    folder = tempfile.mkdtemp(prefix="hexc-edit-bench-")
    shutil.copytree("materials/textures", os.path.join(folder, "textures"))
    material = os.path.join(folder, "rock.json")
    shutil.copy("materials/rock.json", material)
    driver = browser_or_skip()
    server = Server(hexc, material)
    out = {}
    try:
        driver.set_window_size(1280, 800)
        driver.get(server.url)
        wait_idle(driver, 1)
        driver.execute_script(COUNT_READBACKS)
        out["info"] = driver.execute_script("const gl = document.createElement('canvas').getContext('webgl2');"
                                            "const i = gl.getExtension('WEBGL_debug_renderer_info');"
                                            "const c = document.getElementById('canvas');"
                                            "return [i ? gl.getParameter(i.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER), c.width, c.height];")
        out["frame"] = driver.execute_async_script(FRAMES, max(10, repetitions * 2))
        out["slider"] = [driver.execute_async_script(MEASURE, "/hextiling/falloff", "input[type=range]", "input", str(0.55 + 0.3 * (i % 2)),
                                                     False) for i in range(repetitions * 2)]
        out["readbacks"] = driver.execute_script("return window.readbacks;")
        # rotationsteps is a whole number fixed in the code: each new value is a shader the server has not compiled.
        out["fresh"] = [driver.execute_async_script(MEASURE, "/hextiling/rotationsteps", "input[type=number]", "change", str(i + 2), True)
                        for i in range(repetitions)]
        # rotationsteps again, each value compiled by the server just before (as another page of the session would
        # have): the server's answer is a cache hit, but the page has never linked these programs.
        out["served"] = []
        for i in range(repetitions):
            document = driver.execute_script("return window.hexcEdit.document();")
            document["hextiling"]["rotationsteps"] = 40 + i
            server.request("POST", "/api/compile", {"document": document})
            out["served"].append(driver.execute_async_script(MEASURE, "/hextiling/rotationsteps", "input[type=number]", "change", str(40 + i),
                                                             True))
        # The mask toggled between two values: after the first of each, the server's shader cache holds the programs and
        # the page has linked them before (builds before the page kept its programs linked them again).
        out["cached"] = [driver.execute_async_script(MEASURE, "/hextiling/mask", "select", "change", json.dumps(["checker", "hex"][i % 2]), True)
                         for i in range(repetitions + 2)][2:]
        # The file changed on disk (the page has no edits left unsaved: saved first), from the write to the frame.
        driver.execute_script("document.getElementById('save').click();")
        time.sleep(1)
        out["disk"] = []
        for i in range(repetitions):
            compiles = driver.execute_script("return window.hexcEdit.compiles;")
            with open(material) as f:
                text = json.load(f)
            text["hextiling"]["falloff"] = [0.7, 0.8][i % 2]
            since = time.time() * 1000
            with open(material, "w") as f:
                json.dump(text, f, indent=2)
            out["disk"].append([driver.execute_async_script(RELOADED, compiles) - since])
    finally:
        server.stop()
        quit_browser(driver)
        shutil.rmtree(folder, ignore_errors=True)
    return out


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("hexc", nargs="+")
    parser.add_argument("--repetitions", type=int, default=15)
    parser.add_argument("--rounds", type=int, default=1)
    parser.add_argument("--smoke", action="store_true")
    args = parser.parse_args()
    if args.smoke:
        args.repetitions, args.rounds = 1, 1
    builds = [os.path.abspath(h) for h in args.hexc]
    load_before = open("/proc/loadavg").read().split()[:3]
    runs = {b: [] for b in builds}
    for _ in range(args.rounds):
        for b in builds:
            runs[b].append(measure(b, args.repetitions, args.smoke))
    load_after = open("/proc/loadavg").read().split()[:3]
    chromium = subprocess.run(["/usr/bin/chromium", "--version"], capture_output=True, text=True).stdout.strip()
    renderer, width, height = runs[builds[0]][0]["info"]
    print("hexc edit latency, materials/rock.json on the ground plane split view, canvas %dx%d" % (width, height))
    print("machine: %s, %d cores; %s; %s" % (platform.machine(), os.cpu_count(), chromium, renderer))
    print("load average (1, 5, 15 min): before %s, after %s; %d round(s), interleaved" % (" ".join(load_before), " ".join(load_after), args.rounds))
    failed = False
    for b in builds:
        joined = {k: [t for r in runs[b] for t in r[k]] for k in ("frame", "slider", "fresh", "served", "cached", "disk")}
        readbacks = sum(r["readbacks"] for r in runs[b])
        print("\n%s: %d pixel read-backs over %d slider frames" % (b, readbacks, len(joined["slider"])))
        print(summary("the page's frame (view moved every frame)", joined["frame"]))
        print(summary("slider (falloff, a uniform)", [t[0] for t in joined["slider"]]))
        for name, key, compiles in (("structural, new shader (rotationsteps)", "fresh", 1),
                                    ("structural, server-cached, new to the page", "served", 0),
                                    ("structural, seen before (mask toggled back)", "cached", 0)):
            print(summary(name, [t[0] for t in joined[key]]))
            for i, part in ((1, "  of which the server's compile and answer"), (4, "    of which the server's own work"),
                            (2, "  of which WebGL's link (ANGLE)"), (3, "  of which the first frame (SwiftShader's JIT)")):
                if None not in (times := [t[i] for t in joined[key]]):
                    print(summary(part, times))
            counted = [t[5] for t in joined[key] if t[5] is not None]
            if counted:
                print("  shaders the server compiled per change: %s (expected %d each)" % (" ".join(map(str, counted)), compiles))
                failed = failed or any(c != compiles for c in counted)
        print(summary("file changed on disk, to its frame", [t[0] for t in joined["disk"]]))
        failed = failed or readbacks > 0
    if args.smoke and failed:
        print("the page read pixels back while drawing (every frame waits for the renderer), or a structural change cost more "
              "or fewer shader compiles than expected (one for a new shader, none for one compiled before)")
        sys.exit(1)


if __name__ == "__main__":
    main()
