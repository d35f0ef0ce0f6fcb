#!/usr/bin/env python3
"""The docs are tests: every fenced block of README.md and docs/*.md run or checked as a reader would use it.

    tests/docs/docs_test.py BUILD [DOC.md ...]     (from the source root; default: README.md and docs/*.md)

hexc is installed from BUILD into a fresh prefix (`cmake --install`), or is the one installed in
$HEXC_INSTALLED_PREFIX (CI: /usr, the Debian package; tests/package/prefix.sh), whose bin/ is first on PATH, as the
docs' `hexc` is. Each document runs in a fresh folder of its own holding what a reader's checkout has that the docs use
(`materials/`, `tests/material/`), with HOME a fresh folder too (no shader cache, no Bazel server from before), in
which `~/Pictures/bricks.png` is the reader's own texture quick-start.md asks for (a copy of an example texture).
The one thing changed in what the docs say: `/opt/hexc`, the install prefix they use, is that prefix.
blocks.py says how each block is classified from its info string. A block that fails is reported with its document,
line and why; the test fails on it, and on a block it cannot classify. Before the docs, a fixture
(tests/docs/fixture.md) with a failing command, a stale listing, a stale excerpt, a wrong file, a `hexc edit` whose
page shows an error and an unclassified block must be reported on exactly those blocks: the negative control.
Exits 77 (skipped) without Chromium or Bazel, unless HEXC_REQUIRE_BROWSER=1.
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blocks as md  # noqa: E402
import runner  # noqa: E402

FIXTURE = "tests/docs/fixture.md"
# The fixture's blocks the negative control must report, by line, and those it must pass.
FIXTURE_FAILS = {"tests/docs/fixture.md:%d" % n for n in (13, 19, 30, 36, 42, 48)}


def readme_checks(ctx, docs_blocks):
    """The README's first two commands are not re-run (the second is CI; the first would configure CI's build folder
    again): their parts must exist, .ci/run must run the second, and the first's hexc command runs with the
    installed hexc. Returns failures."""
    failures = []
    found = [b for b in docs_blocks if b.doc == "README.md" and b.body.startswith(".ci/setup")]
    if len(found) != 1:
        return ["README.md: no block starting with `.ci/setup` (the README's first and second commands)"]
    block = found[0]
    first, second = block.body.split("\n")[:2]
    parts = first.split(" && ")
    where = block.where()
    if not block.not_run:
        failures.append("%s: must carry a `*Not run in CI: ...*` line (the docs test does not build CI's folder)" % where)
    if parts[0] != ".ci/setup" or not os.access(".ci/setup", os.X_OK):
        failures.append("%s: `%s` is not the executable .ci/setup" % (where, parts[0]))
    cmake_text = open("CMakeLists.txt").read()
    if len(parts) < 2 or not parts[1].startswith("cmake -S . -B build "):
        failures.append("%s: the first command's second part is not `cmake -S . -B build ...`" % where)
    for option in re.findall(r"-D(\w+)=", parts[1] if len(parts) > 1 else ""):
        if not re.search(r"option\(%s\b" % option, cmake_text) and option not in ("CMAKE_BUILD_TYPE",):
            failures.append("%s: -D%s is no option of CMakeLists.txt" % (where, option))
    last = parts[-1]
    if not last.startswith("build/hexc "):
        failures.append("%s: the first command does not end with `build/hexc ...`" % where)
    else:
        ran = ctx.run_shell(block, "hexc " + last[len("build/hexc "):], ctx.folder_for("README.md"))
        failures += ran or listing_check(docs_blocks, ctx.folder_for("README.md"))
    ci_run = open(".ci/run").read()
    if second != ".ci/test" or not re.search(r'^exec "\$\(dirname "\$0"\)/test"$', ci_run, re.M):
        failures.append("%s: .ci/run does not exec the README's second command `%s`" % (where, second))
    return failures


def listing_check(docs_blocks, folder):
    """The README's listing of what its first command writes (`out/<file>  what it is`) names exactly the files written
    (not the hidden stamp)."""
    found = [b for b in docs_blocks if b.doc == "README.md" and b.kind == "text" and b.body.startswith("out/")]
    if len(found) != 1:
        return ["README.md: no ```text block listing out/, what its first command writes"]
    listed = sorted(line.split()[0] for line in found[0].body.split("\n") if line.strip())
    written = sorted("out/" + f for f in os.listdir(os.path.join(folder, "out")) if not f.startswith("."))
    if listed != written:
        return ["%s lists %s, the first command wrote %s" % (found[0].where(), listed, written)]
    print("ok: %s lists exactly the files `hexc materials/rock.json -o out/` writes" % found[0].where())
    return []


def policy_check(ctx, docs_blocks):
    """The package sets the policies it needs: build-integration.md's CMake project, its cmake_minimum_required line
    taken out, still configures (CMake then warns of the missing line, not of hexc's package)."""
    found = [b for b in docs_blocks if b.kind == "file" and b.attrs["file"].endswith("CMakeLists.txt") and "find_package(hexc" in b.body]
    if not found:
        return ["no ```cmake file=.../CMakeLists.txt block with find_package(hexc) in the docs"]
    block = found[0]
    src = os.path.join(ctx.work, "no_minimum_required")
    shutil.copytree(os.path.join(ctx.folder_for(block.doc), os.path.dirname(block.attrs["file"])), src,
                    ignore=shutil.ignore_patterns("build"))
    body = "\n".join(l for l in block.body.split("\n") if not l.startswith("cmake_minimum_required"))
    with open(os.path.join(src, "CMakeLists.txt"), "w") as f:
        f.write(body + "\n")
    r = subprocess.run(["cmake", "-S", src, "-B", os.path.join(src, "build"), "-DCMAKE_PREFIX_PATH=" + ctx.prefix],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=ctx.env)
    if r.returncode != 0 or "CMake Error" in r.stdout:
        return ["%s without its cmake_minimum_required line does not configure:\n%s" % (block.where(), runner.tail(r.stdout))]
    print("ok: %s configures without its cmake_minimum_required line too" % block.where())
    return []


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    started = time.monotonic()
    build = os.path.abspath(sys.argv[1])
    docs = sys.argv[2:] or ["README.md"] + sorted(glob.glob("docs/*.md"))
    missing = runner.missing_tools()
    if missing:
        print("docs test: no %s" % ", ".join(missing))
        sys.exit(1 if os.environ.get("HEXC_REQUIRE_BROWSER") == "1" else 77)
    ctx = runner.Context(build, os.path.join(build, "docs_test"))
    try:
        # The negative control: the fixture's broken blocks are reported, its good ones pass.
        fixture = md.parse(FIXTURE, open(FIXTURE).read())
        fixture_failures = ctx.run_doc(FIXTURE, fixture, quiet=True)
        reported = {f.split(" ")[0] for f in fixture_failures}
        if reported != FIXTURE_FAILS:
            print("FAIL: the negative control (%s) reported %s, expected %s:" % (FIXTURE, sorted(reported), sorted(FIXTURE_FAILS)))
            print("\n".join(fixture_failures))
            return 1
        print("ok: negative control: %s reports its failing command, stale listing, stale excerpt, wrong file, erring "
              "edit page and unclassified block (%d of %d blocks), and passes the rest" % (FIXTURE, len(reported), len(fixture)))

        all_blocks, failures = [], []
        for doc in docs:
            doc_started = time.monotonic()
            blocks = md.parse(doc, open(doc).read())
            all_blocks += blocks
            doc_failures = ctx.run_doc(doc, blocks)
            failures += doc_failures
            print("%s: %d blocks, %d failed (%.0f s)" % (doc, len(blocks), len(doc_failures), time.monotonic() - doc_started))
        if not sys.argv[2:]:
            failures += readme_checks(ctx, all_blocks) + policy_check(ctx, all_blocks)
    finally:
        ctx.close()

    counts = {k: sum(1 for b in all_blocks if b.kind == k and not b.not_run) for k in md.KINDS}
    marked = [b for b in all_blocks if b.not_run]
    print("\n%d blocks: %d run (%d sh, %d console), %d files written, %d shown whole from the repository, %d excerpts "
          "(%d checked against their file), %d text, %d not run (marked):" %
          (len(all_blocks), counts["run"] + counts["console"], counts["run"], counts["console"], counts["file"], counts["shows"],
           counts["excerpt"], sum(1 for b in all_blocks if b.kind == "excerpt" and "of" in b.attrs and not b.not_run),
           counts["text"], len(marked)))
    for b in marked:
        print("  %s: %s" % (b.where(), b.not_run))
    print("time: %.0f s" % (time.monotonic() - started))
    if failures:
        print("\n%d FAILED:" % len(failures))
        for f in failures:
            print("FAIL: " + f)
        return 1
    print("all blocks ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
