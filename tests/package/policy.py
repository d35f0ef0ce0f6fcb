#!/usr/bin/env python3
"""Debian policy's parts of the hexc package (compiler/cmake/debian/package.cmake), checked in a package's files:
the control fields (Section, Priority, Maintainer, a description with a long part, lines under 80 columns), the
copyright file in DEP-5's format, changelog.Debian.gz (gzip -9n: no name, no time, the same bytes from the same text;
its version the package's), the ELF files stripped, the static libraries without debugging sections, neither with a
.comment section (as Debian's dh_strip leaves them, which lintian checks), the ELF programs and modules hardened
(PIE, RELRO, BIND_NOW: lintian's hardening tags), and Depends naming the Debian package of
every shared library an ELF file of the package loads (what dpkg-shlibdeps computes).

    dpkg -L hexc | tests/package/policy.py / <(dpkg -s hexc)                   # the installed package
    dpkg-deb -x X.deb d; dpkg-deb -c X.deb | awk '{print substr($6, 2)}' |
      tests/package/policy.py d <(dpkg-deb -f X.deb)                         # a .deb, unpacked

ROOT is the folder the package's paths (stdin, one a line) are under; CONTROL holds its control fields. Prints each
failure and exits 1, or an "ok" line per check. With --controls BUILD (tests/package/installed.sh) it also runs
each check on a wrong variant of what it was given and fails if a check takes one: the copyright file without its
Format field, a Files paragraph without License, a changelog compressed with a name and time, or for another version,
BUILD's hexc (not stripped) and libhexc.a (with .comment), a program linked lazily without PIE or RELRO, and Depends
without one of its libraries' packages.
"""
import argparse
import gzip
import pathlib
import re
import subprocess
import sys
import tempfile

DEP5 = re.compile(r"https?://www\.debian\.org/doc/packaging-manuals/copyright-format/1\.0/?")


def paragraphs(text):
    """deb822 paragraphs as lists of (field, value lines), or raises ValueError at a line that is neither."""
    result, current = [], []
    for number, line in enumerate(text.split("\n"), 1):
        if not line.strip():
            if current:
                result.append(current)
            current = []
        elif line[0] in " \t":
            if not current:
                raise ValueError(f"line {number}: a continuation line outside a field")
            current[-1][1].append(line[1:])
        elif m := re.match(r"([!-9;-~][!-9;-~]*):(.*)$", line):
            current.append((m[1], [m[2].strip()]))
        else:
            raise ValueError(f"line {number}: not a field: {line!r}")
    return result + [current] if current else result


def fields(paragraph):
    return {name.lower(): lines for name, lines in paragraph}


def check_copyright(text):
    try:
        found = [fields(p) for p in paragraphs(text)]
    except ValueError as e:
        return [f"copyright: {e}"]
    if not found or not DEP5.fullmatch(" ".join(found[0].get("format", [""])).strip()):
        return ["copyright: the first paragraph has no Format field naming DEP-5 1.0"]
    problems = [] if found[0].get("upstream-name", [""])[0] else ["copyright: no Upstream-Name"]
    files = [p for p in found[1:] if "files" in p]
    texts = {p["license"][0] for p in found[1:] if "files" not in p and "license" in p and any(p["license"][1:])}
    if not files:
        problems.append("copyright: no Files paragraph")
    for p in files:
        problems += [f"copyright: Files: {p['files'][0]} has no {f}" for f in ("copyright", "license") if f not in p]
        if "license" in p and not any(p["license"][1:]):  # a short name only: its text in a License paragraph
            names = re.split(r"\s+(?:or|and)\s+|,\s*", p["license"][0])
            problems += [f"copyright: no License paragraph for {n}" for n in names if n and n not in texts]
    return problems


def check_control(control):
    f = {k: "\n".join(v) for k, v in fields(paragraphs(control)[0]).items()}
    problems = [f"control: no {k}" for k in ("section", "priority", "maintainer", "version") if not f.get(k)]
    if not re.fullmatch(r"[^<>]+ <[^@<>\s]+@[^@<>\s]+>", f.get("maintainer", "")):
        problems.append(f"control: Maintainer is not 'Name <address>': {f.get('maintainer')!r}")
    description = f.get("description", "").split("\n")
    if len(description) < 2 or not description[0]:
        problems.append("control: no synopsis and long description")
    problems += [f"control: a description line over 80 columns: {line!r}" for line in description if len(line) >= 80]
    return problems


def check_changelog(data, version):
    try:
        text = gzip.decompress(data)
    except (OSError, EOFError) as e:
        return [f"changelog.Debian.gz does not gunzip: {e}"]
    problems = []
    if data[3] != 0 or data[4:8] != b"\0\0\0\0":  # FLG, MTIME: gzip -n stores no name and no time
        problems.append("changelog.Debian.gz holds a file name or a time (not gzip -n)")
    if subprocess.run(["gzip", "-9n"], input=text, capture_output=True, check=True).stdout != data:
        problems.append("changelog.Debian.gz is not its text compressed by gzip -9n")
    parsed = subprocess.run(["dpkg-parsechangelog", "-l", "-", "-S", "Version"], input=text, capture_output=True)
    if parsed.returncode or parsed.stderr:
        problems.append(f"dpkg-parsechangelog: {parsed.stderr.decode().strip()}")
    elif parsed.stdout.decode().strip() != version:
        problems.append(f"changelog.Debian.gz is for {parsed.stdout.decode().strip()}, the package is {version}")
    return problems


def magic(path):
    with open(path, "rb") as f:
        return f.read(8)


def elf_problems(path):
    """A stripped ELF file, or a static library without debugging sections, and neither with the compiler's .comment
    section, as Debian's dh_strip leaves them; nothing for other files."""
    head = magic(path)
    if not head.startswith(b"\x7fELF") and head != b"!<arch>\n":
        return []
    sections = subprocess.run(["readelf", "-S", "-W", path], capture_output=True, text=True, check=True).stdout
    problems = [f"{path}: has a .comment section"] if " .comment " in sections else []
    if head.startswith(b"\x7fELF"):
        said = subprocess.run(["file", "-b", path], capture_output=True, text=True, check=True).stdout.strip()
        return problems + ([] if said.endswith(", stripped") else [f"{path}: file says {said.rsplit(', ', 1)[-1]!r}"])
    return problems + ([f"{path}: has debugging sections"] if " .debug_" in sections else [])


def hardening_problems(path):
    """An ELF program or shared object as Debian's hardening builds it (lintian's hardening-no-pie, -no-relro and
    -no-bindnow): position-independent, a GNU_RELRO segment, and BIND_NOW; nothing for other files."""
    if not magic(path).startswith(b"\x7fELF"):
        return []
    headers = subprocess.run(["readelf", "-h", "-l", "-d", "-W", path], capture_output=True, text=True, check=True).stdout
    problems = [] if re.search(r"Type:\s+DYN", headers) else [f"{path}: not position-independent"]
    problems += [] if "GNU_RELRO" in headers else [f"{path}: no GNU_RELRO segment"]
    bindnow = re.search(r"\(FLAGS\)\s.*\bBIND_NOW\b", headers) or re.search(r"\(FLAGS_1\)\s.*\bNOW\b", headers)
    return problems + ([] if bindnow else [f"{path}: not linked with -z now (BIND_NOW)"])


def lazy_program(folder):
    """A program linked as Debian's hardening does not: no PIE, no RELRO, lazy binding (a control of the check)."""
    source, program = folder / "lazy.c", folder / "lazy"
    source.write_text("int main(void) { return 0; }\n")
    subprocess.run(["cc", "-no-pie", "-Wl,-z,norelro,-z,lazy", str(source), "-o", str(program)], check=True)
    return program


def needed(path):
    dynamic = subprocess.run(["readelf", "-d", "-W", path], capture_output=True, text=True).stdout
    return re.findall(r"\(NEEDED\)\s+Shared library: \[(.*)\]", dynamic)


def libraries(elves):
    """The Debian packages of the shared libraries the ELF files load, as the dynamic linker finds them."""
    sonames = {soname for e in elves for soname in needed(e)}
    found = subprocess.run(["ldconfig", "-p"], capture_output=True, text=True, check=True).stdout
    names = {}  # /lib is /usr/lib: dpkg knows a file by the name its package gave it, so both are asked
    for m in re.finditer(r"^\s*(\S+) \((.*)\) => (\S+)$", found, re.M):
        if m[1] in sonames and "x86-64" in m[2]:
            names[m[1]] = [m[3], m[3][4:] if m[3].startswith("/usr/") else "/usr" + m[3]]
    asked = [name for both in names.values() for name in both]
    owned = subprocess.run(["dpkg", "-S", *asked], capture_output=True, text=True).stdout if asked else ""
    owners = dict(reversed(line.split(": ", 1)) for line in owned.splitlines() if ": /" in line)
    package = {n: owner.split(":")[0] for n, owner in owners.items()}
    return {next((package[n] for n in names.get(s, []) if n in package), f"(no package has {s})") for s in sonames}


def depends(control):
    value = " ".join(fields(paragraphs(control)[0]).get("depends", [""]))
    return {re.split(r"[\s(:]", d.strip())[0] for d in re.split(r"[,|]", value)}


def check_depends(control, packages):
    return [f"control: Depends does not name {p} (a library hexc loads)" for p in sorted(packages - depends(control))]


def run(root, listing, control):
    doc = root / "usr/share/doc/hexc"
    version = "\n".join(fields(paragraphs(control)[0])["version"])
    files = [root / p.lstrip("/") for p in listing if (root / p.lstrip("/")).is_file()]
    elves = [p for p in files if magic(p).startswith(b"\x7fELF")]
    packages = libraries(elves)
    checks = {
        "control fields": lambda: check_control(control),
        "copyright (DEP-5)": lambda: check_copyright((doc / "copyright").read_text()),
        "changelog.Debian.gz": lambda: check_changelog((doc / "changelog.Debian.gz").read_bytes(), version),
        "stripped": lambda: [q for p in files for q in elf_problems(p)],
        "hardened": lambda: [q for p in files for q in hardening_problems(p)],
        "Depends": lambda: check_depends(control, packages),
    }
    problems = []
    for name, check in checks.items():
        try:
            found = check()
        except FileNotFoundError as e:
            found = [f"{name}: no {e.filename}"]
        problems += found
        if not found:
            print(f"ok: {name}" + (f" ({len(elves)} ELF files)" if name in ("stripped", "hardened", "Depends") else ""))
    return problems, packages


def controls(root, control, build, packages):
    """Each check on a wrong variant of the package's own files: every one must be refused."""
    doc = root / "usr/share/doc/hexc"
    copyright, changelog = (doc / "copyright").read_text(), (doc / "changelog.Debian.gz").read_bytes()
    text = gzip.decompress(changelog)
    version = "\n".join(fields(paragraphs(control)[0])["version"])
    dropped = sorted(packages)[0]  # Depends without it: a package as dpkg-shlibdeps would not make it
    fewer = re.sub(rf"^(Depends:.*?)(, )?\b{re.escape(dropped)}(?=[ ,]|$)( \([^)]*\))?", r"\1", control, flags=re.M)
    wrong = {
        "a copyright file without Format": check_copyright(re.sub(r"^Format: .*\n", "", copyright)),
        "a Files paragraph without License": check_copyright(re.sub(r"\nLicense: none-stated\n.*\n", "\n", copyright)),
        "a changelog with a name and time": check_changelog(gzip.compress(text, 9, mtime=1), version),
        "a changelog for another version": check_changelog(changelog, version + "1"),
        f"{build}/hexc, not stripped": elf_problems(build / "hexc"),
        f"{build}/compiler/src/libhexc.a, with .comment": elf_problems(build / "compiler/src/libhexc.a"),
        f"Depends without {dropped}": check_depends(fewer, packages),
    }
    with tempfile.TemporaryDirectory() as folder:
        wrong["a program without PIE, RELRO and BIND_NOW"] = hardening_problems(lazy_program(pathlib.Path(folder)))
    taken = [name for name, problems in wrong.items() if not problems]
    print(f"controls: {len(wrong) - len(taken)} of {len(wrong)} wrong variants refused")
    return [f"a check takes {name}" for name in taken]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", type=pathlib.Path)
    parser.add_argument("control", type=argparse.FileType())
    parser.add_argument("--controls", type=pathlib.Path, metavar="BUILD")
    args = parser.parse_args()
    control = args.control.read()
    problems, packages = run(args.root, sys.stdin.read().split("\n"), control)
    if args.controls and not problems:
        problems = controls(args.root, control, args.controls, packages)
    for problem in problems:
        print(f"package: {problem}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
