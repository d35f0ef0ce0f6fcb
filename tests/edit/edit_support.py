"""What the tests of `hexc edit` share: a server on a free port, raw HTTP requests to it, headless Chromium on its page.

The browser is Debian's chromium, driven by Debian's chromium-driver through python3-selenium (.ci/setup-test installs the
three; Debian builds the driver from the same Chromium release). Without them a browser test exits 77, which CTest counts
as skipped, unless HEXC_REQUIRE_BROWSER=1 (as .ci/test sets it), when it fails.
"""
import http.client
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import unittest

# Generous: the suite runs beside other tests on a loaded two-core machine, where Chromium starts in seconds and
# SwiftShader draws a frame of the page in well under one.
TIMEOUT = 120

# The flags of compiler/edit/capture.cpp (headlessChromiumFlags), which hexc edit --capture starts Chromium with.
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync", "--hide-scrollbars"]


class Server:
    """`hexc edit MATERIAL --port 0`: the address it prints, requests to it, and its end."""

    def __init__(self, hexc, material, *extra):
        self.process = subprocess.Popen([hexc, "edit", str(material), "--port", "0", *extra], stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, text=True)
        line = self.process.stdout.readline()
        match = re.search(r"open (http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]+))", line)
        if not match:
            self.process.kill()
            raise RuntimeError("hexc edit printed no address: %r %s" % (line, self.process.stderr.read()))
        self.url, self.port, self.token = match.group(1), int(match.group(2)), match.group(3)

    def request(self, method, path, body=None, headers=None, host=None, token=True):
        """(status, headers, body bytes) of one request; `token` False sends none, a string sends that one."""
        connection = http.client.HTTPConnection("127.0.0.1", self.port, timeout=TIMEOUT)
        if token is not False:
            path += ("&" if "?" in path else "?") + "token=" + (self.token if token is True else token)
        connection.putrequest(method, path, skip_host=True, skip_accept_encoding=True)
        connection.putheader("Host", host or "127.0.0.1:%d" % self.port)
        data = body if isinstance(body, bytes) or body is None else json.dumps(body).encode()
        if data is not None:
            connection.putheader("Content-Length", str(len(data)))
        for k, v in (headers or {}).items():
            connection.putheader(k, v)
        connection.endheaders(data)
        response = connection.getresponse()
        out = (response.status, dict(response.getheaders()), response.read())
        connection.close()
        return out

    def cpu_seconds(self):
        """The server's processor time so far (user and system, all threads): a bound on work, which a loaded machine
        does not stretch as it does wall time."""
        fields = open("/proc/%d/stat" % self.process.pid).read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")

    def memory_mib(self, field):
        """The server's resident memory now (`VmRSS`) or at its peak so far (`VmHWM`), in MiB, from /proc."""
        for line in open("/proc/%d/status" % self.process.pid):
            if line.startswith(field + ":"):
                return int(line.split()[1]) / 1024
        raise AssertionError("no %s in /proc/%d/status" % (field, self.process.pid))

    def json(self, method, path, body=None):
        status, _, data = self.request(method, path, body)
        return status, json.loads(data)

    def stop(self):
        self.process.terminate()
        try:
            self.process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        self.process.stdout.close()
        self.process.stderr.close()


def rock_copy(prefix):
    """A temporary folder holding materials/rock.json and its textures: (folder, material path, material bytes)."""
    folder = tempfile.mkdtemp(prefix=prefix)
    shutil.copytree("materials/textures", os.path.join(folder, "textures"))
    material = os.path.join(folder, "rock.json")
    shutil.copy("materials/rock.json", material)
    with open(material, "rb") as f:
        return folder, material, f.read()


# The window of a test that looks at the page's layout (tests/edit/authoring_test.py): a laptop's.
WINDOW = "1280,800"
# The window of a test that reads its views back at sizes of its own (readFloat: the aspect is the read-back's, not the
# canvas's), never the canvas: the page still draws the canvas at every change of view, on the processor
# (SwiftShader), and this one's canvas is 220 x 181 pixels against 860 x 565, a seventh of the work (a 4-layer terrain's
# view: 0.09 s of processor time against 0.44 s).
SMALL_WINDOW = "640,480"


def browser_or_skip(flags=CHROMIUM_FLAGS, window=WINDOW):
    """Selenium's Chrome on Debian's chromium and chromedriver with `flags` and a window of `window` ("W,H"), a fresh
    profile; exits 77 (skip) without them."""
    missing = [p for p in ("/usr/bin/chromium", "/usr/bin/chromedriver") if not os.path.exists(p)]
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        missing.append("python3-selenium")
    if missing:
        print("no %s (Debian: apt-get install chromium chromium-driver python3-selenium)" % ", ".join(missing))
        sys.exit(1 if os.environ.get("HEXC_REQUIRE_BROWSER") == "1" else 77)
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    profile = tempfile.mkdtemp(prefix="hexc-edit-test-")
    for flag in flags + ["--user-data-dir=" + profile, "--window-size=" + window]:
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    driver.set_script_timeout(TIMEOUT)
    driver.set_page_load_timeout(TIMEOUT)
    driver.hexc_profile = profile
    return driver


def quit_browser(driver):
    driver.quit()
    shutil.rmtree(driver.hexc_profile, ignore_errors=True)


def run_with_browser(module, *sharing, window=WINDOW):
    """A browser test's main: `module`'s HEXC from the command line, and its DRIVER (and that of the modules in `sharing`,
    whose functions it calls) one Chromium, with a window of `window`, for all of its tests; exits with their result."""
    module.HEXC = os.path.abspath(sys.argv.pop(1))
    module.DRIVER = browser_or_skip(window=window)
    for m in sharing:
        m.HEXC, m.DRIVER = module.HEXC, module.DRIVER
    try:
        result = unittest.main(module=module, verbosity=2, exit=False).result
    finally:
        quit_browser(module.DRIVER)
    sys.exit(0 if result.wasSuccessful() else 1)


def wait_for(condition, what, timeout=TIMEOUT):
    """Polls `condition` until it returns something true; fails naming `what` after `timeout` seconds."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        value = condition()
        if value:
            return value
        time.sleep(0.1)
    raise AssertionError("timed out after %d s waiting for %s" % (timeout, what))


def page_state(driver):
    return driver.execute_script("const h = window.hexcEdit; return h && {status: h.status, compiles: h.compiles, frames: h.frames, "
                                 "pending: h.pending, liveEdits: h.liveEdits, shown: h.shown, programs: h.programs};")


def wait_idle(driver, compiles=0, what="the page to be drawn"):
    """Waits until the page has compiled at least `compiles` times, has no compile pending and drew a frame after."""
    def idle():
        s = page_state(driver)
        return s if s and s["status"] != "loading" and s["pending"] == 0 and s["compiles"] >= compiles and s["frames"] > 0 else None
    state = wait_for(idle, what)
    frames = state["frames"]
    wait_for(lambda: page_state(driver)["frames"] > frames or driver.execute_script("return !window.hexcEdit.drawPending();"), "a frame")
    return page_state(driver)


def read_pfm(path):
    """(width, height, rows top first of [r, g, b] floats) of a PFM file as hexc writes it (bottom row first)."""
    with open(path, "rb") as f:
        data = f.read()
    header = data.split(b"\n", 3)
    width, height = map(int, header[1].split())
    scale = float(header[2])
    count = width * height * 3
    values = struct.unpack(("<" if scale < 0 else ">") + "%df" % count, header[3][:count * 4])
    rows = [[values[(height - 1 - y) * width * 3 + x * 3:(height - 1 - y) * width * 3 + x * 3 + 3] for x in range(width)] for y in range(height)]
    return width, height, rows
