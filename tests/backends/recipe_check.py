#!/usr/bin/python3
"""Every manifest field docs/bind-a-manifest.md names is one hexc writes, so the recipe cannot drift from the manifest.

    recipe_check.py RECIPE SCHEMA HEXC WORKDIR MANIFEST...

A field is a backquoted path in the recipe whose first name is one of the schema's top-level properties, followed by
`.name`, `.<any>` or `[]` (`slots[].colorspace`, `targets.<target>.textures`). It must resolve in the schema
(`[]`: the array's items; `<...>`: any key; a name: a property, or one the object requires). Below an object the
schema leaves open (per-target fields such as `texture_unit`), it must resolve in one of the MANIFESTs given or in a
manifest HEXC writes here with the options that add fields no example manifest has (`--manifest-paths`, GLSL ES).
Prints each field not found; exits 1 if any is missing or the recipe names none.
"""
import json
import re
import subprocess
import sys
from pathlib import Path


def alternatives(schema, node):
    """The schemas a value under `node` may match: the node itself, and those it refers to or combines."""
    if "$ref" in node:
        node = resolve_ref(schema, node["$ref"])
    out = [node]
    for key in ("allOf", "oneOf", "anyOf"):
        for sub in node.get(key, []):
            out += alternatives(schema, sub)
    return out


def resolve_schema(schema, node, parts):
    """Follows `parts` through the schema: True if found, False if not, or the parts left below an open object."""
    if not parts:
        return True
    part, rest = parts[0], parts[1:]
    found = False
    for alt in alternatives(schema, node):
        properties = alt.get("properties", {})
        if part == "[]":
            step = resolve_schema(schema, alt["items"], rest) if "items" in alt else False
        elif part.startswith("<"):  # any key: the rest must hold under at least one
            extra = alt.get("additionalProperties")
            subs = [extra] if isinstance(extra, dict) else list(properties.values())
            steps = [resolve_schema(schema, sub, rest) for sub in subs]
            step = True if True in steps else next((s for s in steps if s), parts if not subs and is_open(alt) else False)
        elif part in properties:
            step = resolve_schema(schema, properties[part], rest)
        elif part in alt.get("required", []):
            step = True if not rest else parts
        else:
            step = parts if is_open(alt) and alt.get("type") == "object" else False
        if step is True:
            return True
        found = found or step
    return found


def is_open(node):
    """An object whose keys the schema does not list: hexc's manifests say what is in it."""
    return not node.get("properties") and "additionalProperties" not in node


def resolve_ref(schema, ref):
    node = schema
    for key in ref.lstrip("#/").split("/"):
        node = node[key]
    return node


def in_manifest(value, parts):
    """Whether some path through a written manifest matches `parts`."""
    if not parts:
        return True
    part, rest = parts[0], parts[1:]
    if part == "[]":
        return isinstance(value, list) and any(in_manifest(v, rest) for v in value)
    if not isinstance(value, dict):
        return False
    if part.startswith("<"):
        return any(in_manifest(v, rest) for v in value.values())
    return part in value and in_manifest(value[part], rest)


def split(path):
    return [p for p in re.split(r"\.|(\[\])", path) if p]


def main():
    recipe, schema_file, hexc, work = sys.argv[1:5]
    schema = json.loads(Path(schema_file).read_text())
    manifests = [json.loads(Path(m).read_text()) for m in sys.argv[5:]]
    out = Path(work)
    subprocess.run([hexc, "materials/rock.json", "-o", str(out), "--manifest-paths", "--glsl-version", "300es", "--force",
                    "--no-cache", "-q"], check=True)
    manifests.append(json.loads((out / "rock.manifest.json").read_text()))

    top = "|".join(schema["properties"])
    fields = set(re.findall(r"`((?:%s)(?:\[\]|\.<?[a-z_]+>?)+)`" % top, Path(recipe).read_text()))
    missing = []
    for field in sorted(fields):
        found = resolve_schema(schema, schema, split(field))
        if isinstance(found, list):  # below an open object: as hexc writes it
            found = any(in_manifest(m, split(field)) for m in manifests)
        if not found:
            missing.append(field)
    for field in missing:
        print(f"{recipe}: `{field}` is not a manifest field (not in {schema_file}, not in a manifest hexc writes)")
    print(f"{len(fields) - len(missing)} of {len(fields)} fields found")
    return 1 if missing or not fields else 0


if __name__ == "__main__":
    sys.exit(main())
