#!/usr/bin/python3
"""Compiles every example and checks each manifest hexc writes against docs/manifest.schema.json.

    manifest_check.py SCHEMA HEXC LAYOUT WORKDIR INPUT...

Each INPUT (a material, MaterialX document or scene), and two materials written here with a packed texture and a
histogram slot, is compiled by HEXC into its own folder under WORKDIR, under
each option set below (the default layout, the engine's LAYOUT file, SPIR-V combined samplers, MSL argument
buffers with --vertex and --manifest-paths), and every *.manifest.json written must validate. So that the check can fail, one manifest is then broken in the ways an engine would trip over
(a template resource without its descriptor type, a slot setting left out) and must be rejected.
Prints one line per manifest and a closing "N passed, M failed"; exits 1 if any expectation fails.
Run it with the Debian interpreter (/usr/bin/python3), which has python3-jsonschema.
"""
import copy
import json
import shutil
import subprocess
import sys
from pathlib import Path

import jsonschema


def derived_examples(work, textures):
    """Materials whose manifests list the textures hexc derives (no example has them): packed and histogram."""
    def slot(name, kind, texture, **extra):
        return {"name": name, "kind": kind, "texture": str((textures / texture).resolve()), **extra}
    materials = {
        "packed": {"name": "packed", "pack": True,
                   "slots": [slot("albedo", "color", "rock_albedo.png"), slot("roughness", "scalar", "rock_roughness.png")]},
        "histogram": {"name": "histogram", "template": "unlit",
                      "slots": [slot("albedo", "color", "rock_albedo.png", hextiling={"blend": "histogram"})]},
    }
    files = []
    for name, material in materials.items():
        files.append(str(work / f"{name}.json"))
        Path(files[-1]).write_text(json.dumps(material))
    return files


def main(argv):
    if len(argv) < 6:
        sys.exit(__doc__)
    schema = json.loads(Path(argv[1]).read_text())
    hexc, layout, work, inputs = argv[2], argv[3], Path(argv[4]), argv[5:]
    option_sets = {
        "default": [],
        "engine_layout": ["--layout", layout, "--hlsl-sm", "51"],
        "combined": ["--combined", "1"],
        "argument_buffers": ["--msl-argument-buffers", "1", "--vertex", "--manifest-paths"],
        "functions": ["--functions", "--uv-bottom-left"],
    }
    validator = jsonschema.Draft202012Validator(schema)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    inputs += derived_examples(work, Path(layout).parent.parent / "textures")
    passed = failed = 0
    manifests = []
    for name, options in option_sets.items():
        for source in inputs:
            out = work / name / Path(source).name
            run = subprocess.run([hexc, source, "-o", str(out), "--no-cache", "-q", *options], capture_output=True, text=True)
            if run.returncode != 0 and name == "functions" and "projected triplanar" in run.stderr:
                continue  # the functions output refuses triplanar materials, as documented
            if run.returncode != 0:
                print(f"FAIL {source} ({name}): hexc exited {run.returncode}: {run.stderr.strip()}")
                failed += 1
                continue
            manifests += sorted(out.glob("*.manifest.json"))
    for path in manifests:
        errors = sorted(validator.iter_errors(json.loads(path.read_text())), key=lambda e: list(e.absolute_path))
        if errors:
            failed += 1
            for e in errors[:5]:
                print(f"FAIL {path}: /{'/'.join(map(str, e.absolute_path))}: {e.message[:300]}")
        else:
            passed += 1
            print(f"ok   {path}")
    # The schema must reject what an engine could not build layouts from.
    engine = next((p for p in manifests if p.name == "engine_rock.manifest.json"), None)
    if engine is None:
        print("FAIL no engine_rock manifest among the inputs")
        failed += 1
    else:
        good = json.loads(engine.read_text())
        for what, path in [("a template resource without its descriptor type", ["targets", "spirv", "template_resources", 0, "vulkan", "descriptor_type"]),
                           ("push constants without their size", ["targets", "spirv", "template_resources", 2, "size"]),
                           ("a slot without its lod", ["slots", 0, "hextiling", "lod"])]:
            bad = copy.deepcopy(good)
            parent = bad
            for key in path[:-1]:
                parent = parent[key]
            del parent[path[-1]]
            if validator.is_valid(bad):
                print(f"FAIL the schema accepts {what}")
                failed += 1
            else:
                passed += 1
                print(f"ok   rejected: {what}")
    print(f"{passed} passed, {failed} failed")
    return 1 if failed or not passed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
