"""Runs the blocks of a document (blocks.py) in a fresh folder against an installed hexc; docs_test.py drives it."""
import difflib
import http.client
import importlib.util
import os
import re
import select
import shutil
import signal
import subprocess
import sys
import time

import blocks as md

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "edit"))
import edit_support  # noqa: E402

# What a reader's checkout holds that the docs' commands use, copied into each document's folder.
CHECKOUT = ["materials", "tests/material"]
# The install prefix the docs name; the test's own prefix stands for it.
DOCS_PREFIX = "/opt/hexc"
# A block's commands on a loaded two-core machine: Bazel's first build (a JVM, its install base) is the longest.
BLOCK_TIMEOUT = 600
PAGE_TIMEOUT = edit_support.TIMEOUT


def missing_tools():
    have_selenium = importlib.util.find_spec("selenium") is not None
    missing = [p for p in ("/usr/bin/chromium", "/usr/bin/chromedriver") if not os.path.exists(p)]
    if not os.path.isdir("tests/node/node_modules/naga-wasm"):
        missing.append("tests/node's npm packages (npm ci --prefix tests/node)")
    return missing + ([] if have_selenium else ["python3-selenium"]) + ([] if shutil.which("bazel") else ["bazel"])


def tail(text, lines=25):
    return "\n".join("    | " + l for l in text.rstrip().split("\n")[-lines:])


class Context:
    def __init__(self, build, work):
        self.source = os.getcwd()
        self.work = work
        if os.path.exists(work):
            subprocess.run(["chmod", "-R", "u+w", work])  # Bazel leaves its outputs read-only
            shutil.rmtree(work)
        os.makedirs(work)
        # BUILD installed into a fresh prefix, or the hexc in $HEXC_INSTALLED_PREFIX (CI: the Debian package's /usr).
        self.prefix = subprocess.run(["tests/package/prefix.sh", build, os.path.join(work, "prefix")], check=True,
                                     stdout=subprocess.PIPE, text=True).stdout.strip()
        home = os.path.join(work, "home")
        os.makedirs(os.path.join(home, "Pictures"))
        shutil.copy("materials/textures/tiles_albedo.png", os.path.join(home, "Pictures", "bricks.png"))
        self.env = dict(os.environ, HOME=home, PATH=os.path.join(self.prefix, "bin") + os.pathsep + os.environ["PATH"])
        for variable in ("XDG_CACHE_HOME", "CMAKE_PREFIX_PATH", "hexc_DIR", "MAKEFLAGS", "HEXC_INSTALLED_PREFIX"):
            self.env.pop(variable, None)
        # The npm package the wgsl target needs, where a reader who set it up as docs/cli.md ("WGSL") says has it.
        self.env["HEXC_NODE_PATH"] = os.path.abspath("tests/node/node_modules")
        self.driver = None
        self.folders = {}

    def folder_for(self, doc):
        """The document's fresh folder, a reader's checkout of what the docs use."""
        if doc not in self.folders:
            folder = os.path.join(self.work, "docs", re.sub(r"[^\w.-]", "_", doc))
            for path in CHECKOUT:
                shutil.copytree(path, os.path.join(folder, path))
            self.folders[doc] = folder
        return self.folders[doc]

    def close(self):
        for folder in self.folders.values():
            for ws in glob_workspaces(folder):
                subprocess.run(["bazel", "shutdown"], cwd=ws, env=self.env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                               timeout=120)
        if self.driver:
            edit_support.quit_browser(self.driver)

    def run_doc(self, doc, blocks, quiet=False):
        """Runs or checks each block in order; returns a failure per failed block, "doc:line (```info): why"."""
        folder = self.folder_for(doc)
        failures = []
        for block in blocks:
            if block.problem:
                failures.append("%s: cannot classify: %s" % (block.where(), block.problem))
                continue
            if block.not_run:
                continue
            started = time.monotonic()
            try:
                why = getattr(self, "block_" + block.kind)(block, folder)
            except Exception as e:  # a block that breaks the runner is that block's failure
                why = ["%s: %s" % (type(e).__name__, e)]
            if why:
                failures += ["%s: %s" % (block.where(), w) for w in why]
            if not quiet:
                print("%s %s (%.1f s)" % ("FAIL" if why else "ok  ", block.where(), time.monotonic() - started))
        return failures

    # ---- the kinds of block

    def block_run(self, block, folder):
        """A shell block: its lines in order, in bash with -e; a `hexc edit` line starts the server and checks its page."""
        script = []
        for line in block.body.split("\n") + [None]:
            if line is not None and not starts_server(line):
                script.append(line)
                continue
            failures = self.run_shell(block, "\n".join(script), folder) if "".join(script).strip() else []
            if not failures and line is not None:
                failures = self.check_edit(line.split("#")[0].strip(), None, [], folder)
            if failures:
                return failures
            script = []
        return []

    def block_console(self, block, folder):
        failures = []
        vary = block.attrs.get("vary", "").split(",")
        for command, expected in md.console_steps(block.body):
            if starts_server(command):
                first, _, rest = expected.partition("\n")
                failures += self.check_edit(command, first, vary, folder)
                if rest:
                    failures.append("`%s`: only its first printed line can be compared" % command)
                continue
            r = subprocess.run(["bash", "-o", "pipefail", "-c", self.for_here(command)], cwd=folder, env=self.env,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=BLOCK_TIMEOUT)
            actual = "\n".join(l.rstrip() for l in r.stdout.rstrip().split("\n"))
            if not md.output_pattern(expected, vary).fullmatch(actual):
                diff = difflib.unified_diff(expected.split("\n"), actual.split("\n"), "the doc", "what it printed", lineterm="", n=1)
                failures.append("`%s` (exit %d) prints other than the doc shows:\n%s" % (command, r.returncode, tail("\n".join(diff), 40)))
        return failures

    def block_file(self, block, folder):
        path = os.path.join(folder, block.attrs["file"])
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(self.for_here(block.body) + "\n")
        return []

    def block_shows(self, block, folder):
        path = block.attrs["shows"]
        here = os.path.join(folder, path)
        text = open(here if os.path.exists(here) else path).read()
        if text.rstrip("\n") != block.body.rstrip("\n"):
            diff = difflib.unified_diff(block.body.rstrip("\n").split("\n"), text.rstrip("\n").split("\n"), "the doc", path,
                                        lineterm="", n=1)
            return ["the block is not %s:\n%s" % (path, tail("\n".join(diff), 40))]
        return []

    def block_excerpt(self, block, folder):
        if "of" not in block.attrs:
            return []
        path = os.path.join(folder, block.attrs["of"])
        if not os.path.exists(path):
            return ["%s, which it is an excerpt of, does not exist (does a block before write it?)" % block.attrs["of"]]
        vary = block.attrs.get("vary", "").split(",")
        if not md.excerpt_matches(block.body, open(path).read(), vary):
            return ["%s does not hold this excerpt (token for token, `...` for what is left out): %s" %
                    (block.attrs["of"], first_mismatch(block.body, open(path).read(), vary))]
        return []

    def block_text(self, block, folder):
        return []

    # ---- running commands

    def for_here(self, text):
        return text.replace(DOCS_PREFIX, self.prefix)

    def run_shell(self, block, script, folder):
        r = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", self.for_here(script)], cwd=folder, env=self.env,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=BLOCK_TIMEOUT)
        if r.returncode != 0:
            return ["exit %d from\n%s\n  which printed:\n%s" % (r.returncode, tail(script, 10), tail(r.stdout))]
        return []

    def check_edit(self, command, expected, vary, folder):
        """Starts `hexc edit ...` as written, compares the line it prints, loads its page (HTTP, then headless Chromium)
        and checks it is drawn without an error; then stops it as a reader does, with Ctrl-C."""
        process = subprocess.Popen(["bash", "-c", "exec " + command], cwd=folder, env=self.env, stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE, text=True, start_new_session=True)
        failures = []
        try:
            ready, _, _ = select.select([process.stdout], [], [], PAGE_TIMEOUT)
            line = process.stdout.readline().rstrip("\n") if ready else ""
            if expected is not None and not md.output_pattern(expected, vary).fullmatch(line):
                failures.append("`%s` printed %r, the doc shows %r" % (command, line, expected))
            match = re.search(r"open (http://127\.0\.0\.1:(\d+)/\?token=\S+)", line)
            if not match:
                return failures + ["`%s` printed no address: %r" % (command, line)]
            failures += self.check_page(command, match.group(1), int(match.group(2)))
        finally:
            process.send_signal(signal.SIGINT)
            try:
                code = process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                process.kill()
                code = process.wait()
                failures.append("`%s` did not stop on Ctrl-C (SIGINT) within 30 s" % command)
            stderr = process.stderr.read()
            process.stdout.close()
            process.stderr.close()
        if failures and stderr.strip():
            failures[-1] += "\n  hexc edit printed on stderr:\n" + tail(stderr)
        if code not in (0, -signal.SIGINT, 130) and not failures:
            failures.append("`%s` exited %d on Ctrl-C:\n%s" % (command, code, tail(stderr)))
        return failures

    def check_page(self, command, url, port):
        connection = http.client.HTTPConnection("127.0.0.1", port, timeout=PAGE_TIMEOUT)
        connection.request("GET", url[url.index("/", len("http://")):])
        response = connection.getresponse()
        body = response.read()
        connection.close()
        if response.status != 200 or b"<html" not in body.lower():
            return ["`%s`: GET of its address answered %d, %d bytes" % (command, response.status, len(body))]
        if not self.driver:
            self.driver = edit_support.browser_or_skip()
        self.driver.get(url)

        def settled():
            s = edit_support.page_state(self.driver)
            return s if s and (s["status"] == "error" or (s["status"] != "loading" and s["pending"] == 0 and s["frames"] > 0)) else None
        state = edit_support.wait_for(settled, "the page of `%s` to be drawn" % command, PAGE_TIMEOUT)
        shown = self.driver.execute_script("const d = document.getElementById('diagnostics'); "
                                           "return d && !d.hidden ? [d.className, d.textContent] : null;")
        if state["status"] == "error" or (shown and shown[0] == "error"):
            return ["`%s`: its page shows an error (status %s):\n%s" % (command, state["status"], tail(shown[1] if shown else ""))]
        if shown:
            print("  note: the page of `%s` shows %s:\n%s" % (command, shown[0], tail(shown[1])))
        return []


def starts_server(command):
    """Whether a command line is `hexc edit` serving until Ctrl-C (with --capture it draws one image and exits)."""
    return command.strip().startswith("hexc edit ") and "--capture" not in command


def glob_workspaces(folder):
    found = []
    for root, dirs, files in os.walk(folder):
        dirs[:] = [d for d in dirs if not d.startswith("bazel-") and d != "materials"]
        if "WORKSPACE" in files:
            found.append(root)
    return found


def first_mismatch(excerpt, text, vary):
    """Where the excerpt's tokens stop matching the file's from its first token on: what a reader should look at."""
    tokens = md.TOKEN.findall(excerpt)
    for n in range(len(tokens), 0, -1):
        prefix = "".join(t + " " for t in tokens[:n])
        if md.excerpt_matches(prefix, text, vary):
            return "it holds the excerpt up to `%s`, not from `%s` on" % (" ".join(tokens[max(0, n - 6):n]),
                                                                           " ".join(tokens[n:n + 8]))
    return "not even its first token `%s`" % (tokens[0] if tokens else "")
