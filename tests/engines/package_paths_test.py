#!/usr/bin/python3
"""Every engine package's manifest names only files that are there: each path it names (every `file`, each slot's
`texture`, the `source` paths) resolves from the package's folder to an existing file, for every engine package of
every example material, built as docs/engines.md says (`hexc M --engine ... -o out/`). An engine that refuses a
material (HX300, as docs/engines.md says: triplanar, the web engines' float tables) writes no package for it; every
engine's package of a layered example (the terrain) is written and checked.

Negative control: a package whose manifest names its functions' source as the functions output (`.functions.glsl`,
not in the package) and a texture relative to the material, not to the package, must be found wrong.

  package_paths_test.py HEXC WORK_DIR MATERIAL...
"""
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path



def engine_names(hexc):
    """Every engine of hexc's table, as `hexc --help` lists --engine's choices: an engine added is checked here too."""
    text = subprocess.run([hexc, "--help"], capture_output=True, text=True, check=True).stdout
    return re.search(r"--engines TEXT:\{([^}]*)\}", text).group(1).split(",")


def named_paths(manifest):
    """(where, path) for every file a manifest names: each `file` anywhere, each slot's `texture`, the `source` paths."""
    out = []

    def walk(value, where):
        if isinstance(value, dict):
            for key, item in value.items():
                if key == "file" and isinstance(item, str):
                    out.append((f"{where}/file", item))
                elif key != "source":
                    walk(item, f"{where}/{key}")
        elif isinstance(value, list):
            for i, item in enumerate(value):
                walk(item, f"{where}/{i}")

    walk(manifest, "")
    out += [(f"/slots/{i}/texture", s["texture"]) for i, s in enumerate(manifest["slots"])]
    source = manifest.get("source", {})
    out += [(f"/source/{key}", source[key]) for key in ("material", "template", "layout") if key in source]
    out += [(f"/source/textures/{slot}", path) for slot, path in source.get("textures", {}).items()]
    return out


def problems_of(package):
    """What the package's manifest names that its folder does not resolve to a file."""
    manifests = list(package.glob("*.manifest.json"))
    if len(manifests) != 1:
        return [f"{package}: {len(manifests)} manifests, expected 1"]
    manifest = json.loads(manifests[0].read_text())
    return [f"{manifests[0]}: {where} names {path!r}, which is not a file from the package's folder"
            for where, path in named_paths(manifest) if not (package / path).is_file()]


def build(hexc, material, engines, out):
    """The packages' folders, or None when hexc refuses the material for one of the engines as docs/engines.md says
    (HX300)."""
    run = subprocess.run([hexc, str(material), "--engine", ",".join(engines), "-q", "--no-cache", "-o", str(out)],
                         capture_output=True, text=True)
    if run.returncode == 1 and "error[HX300]" in run.stderr:
        return None
    if run.returncode != 0:
        sys.exit(f"FAIL {material} --engine {','.join(engines)}: exit {run.returncode}\n{run.stderr[-2000:]}")
    return [out / engine for engine in engines]


def packages(hexc, engines, material, out):
    """Every package hexc writes for the material (all engines at once, else engine by engine), and the count refused."""
    every = build(hexc, material, engines, out)
    if every is not None:
        return every, 0
    each = [build(hexc, material, [engine], out / engine) for engine in engines]
    return [p[0] for p in each if p is not None], sum(p is None for p in each)


def negative_control(package, work):
    """The check must fail on a manifest as hexc wrote it before: its functions' file and textures as the material's."""
    wrong = work / "negative" / package.name
    shutil.copytree(package, wrong)
    manifest_file = next(wrong.glob("*.manifest.json"))
    manifest = json.loads(manifest_file.read_text())
    for entry in manifest["targets"].values():
        entry["file"] = manifest["material"] + ".functions.glsl"
    manifest["slots"][0]["texture"] = "textures/rock_albedo.png"
    manifest_file.write_text(json.dumps(manifest))
    found = problems_of(wrong)
    if len(found) < 2:
        sys.exit("FAIL negative control: a manifest naming files outside its package passed:\n" + "\n".join(found))


def main():
    hexc, work, materials = sys.argv[1], Path(sys.argv[2]), [Path(m) for m in sys.argv[3:]]
    shutil.rmtree(work, ignore_errors=True)
    checked, refused, problems, engines = 0, 0, [], engine_names(hexc)
    for material in materials:
        built, no = packages(hexc, engines, material, work / material.name)  # rock.json and rock.mtlx apart
        checked, refused = checked + len(built), refused + no
        layered = material.suffix == ".json" and "layers" in json.loads(material.read_text())
        # Every engine's package carries a layered material (docs/engines.md#layered-materials): written, not refused.
        problems += [f"{material}: the {e} package, which carries layers, was refused" for e in engines
                     if layered and e not in [p.name for p in built]]
        for package in built:
            problems += problems_of(package)
    negative_control(work / "rock.json" / "godot3", work)
    for problem in problems:
        print(problem)
    print(f"{checked} packages checked ({len(engines)} engines), {refused} refused (HX300), {len(problems)} paths that do not resolve")
    sys.exit(1 if problems or checked == 0 else 0)


if __name__ == "__main__":
    main()
