#!/usr/bin/python3
"""Checks material files against materials/material.schema.json.

    schema_check.py SCHEMA GOOD... [--bad BAD...]

Every GOOD file must be a valid material and every BAD file (after --bad) an invalid one. A directory
argument stands for the *.json files directly in it, except *.schema.json. Prints one line per file and a
closing "N passed, M failed" line; exits 1 if any expectation fails, 2 on usage errors.

Besides the schema, this applies the format rules JSON Schema cannot express, as hexc does
(compiler/src/material/parse_material.cpp):

 1. numbers are finite (Python's json module would otherwise accept NaN, Infinity and 1e999);
 2. slot names are unique within a material;
 3. each height_blend names a slot of the same material,
 4. and that slot is of kind "scalar";

and these rules on each slot's merged settings (the material's hextiling overridden key by key by the
slot's; the schema has the ones it can state exactly, where both keys are in one slot's hextiling):

 5. split_coordinates needs mode "stable";
 6. per-tile transforms (rotationrange, rotationsteps, scalerange, offset, offsetsteps) need mode "stable";
 7. every mask but "hex" needs mode "stable";
 8. taps is 1 or the mask's tap count (2 for "checker", 3 otherwise);
 9. split_coordinates does not work with the "noise" and "noise3" masks,
10. nor with the material's "triplanar" projection;
11. height_blend cannot be combined with taps 1 or "adaptive";
12. taps "adaptive" needs falloff >= 0.5;
13. rotation times the largest |rotationrange| is at most 3600 degrees;

and on layers (docs/material-format.md#layers):

14. every layer has the first layer's roles, of the same kinds;
15. one splat map per four layers;
16. a height blend's `height` names a scalar role;
17. a layer's slot's height_blend names a scalar role, in mode "height" the layers' `height`.

Run it with the Debian interpreter (/usr/bin/python3), which has python3-jsonschema.
"""
import json
import math
import sys
from pathlib import Path

try:
    import jsonschema
except ImportError:
    sys.exit(f"schema_check.py: the jsonschema module is missing for {sys.executable}; "
             "run /usr/bin/python3 with Debian's python3-jsonschema installed")


DRAFT_2020_12 = "https://json-schema.org/draft/2020-12/schema"


class NotFinite(ValueError):
    pass


def _reject_constant(name):
    raise NotFinite(f"{name} is not a JSON number")


def _parse_float(text):
    value = float(text)
    if not math.isfinite(value):
        raise NotFinite(f"{text} is not a finite number")
    return value


def load_json(path):
    """Strict JSON: NaN/Infinity and overflowing numbers are errors, not floats."""
    with open(path, encoding="utf-8") as f:
        return json.load(f, parse_constant=_reject_constant, parse_float=_parse_float)


def pointer(parts):
    """JSON pointer of an error location, e.g. /slots/0/hextiling/falloff."""
    return "/" + "/".join(str(p).replace("~", "~0").replace("/", "~1") for p in parts)


def describe(error):
    """jsonschema's message, made shorter and plainer where it is not."""
    if error.schema is False:
        # The schema forbids keys with `false` in the slot rules that depend on "kind", and for the
        # material-wide keys in a slot's hextiling.
        key = error.absolute_path[-1]
        if key in ("projection", "planesharpness"):
            return f"{key!r} is material-wide: set it in the top-level hextiling, not a slot's"
        return f"{key!r} is not allowed on a slot of this kind"
    message = error.message
    instance = repr(error.instance)
    if len(instance) > 60:  # e.g. a whole slots array
        kind = f"array of {len(error.instance)} items" if isinstance(error.instance, list) else "value"
        message = message.replace(instance, kind)
    return message


def problems(validator, path):
    """Every reason the file is not a valid material, as readable lines; empty when it is valid."""
    try:
        doc = load_json(path)
    except (OSError, UnicodeDecodeError) as e:
        return [f"cannot read: {e}"]
    except (NotFinite, json.JSONDecodeError) as e:
        return [f"not valid JSON: {e}"]

    found = []
    for error in sorted(validator.iter_errors(doc), key=lambda e: list(map(str, e.absolute_path))):
        # For anyOf/oneOf the top-level message is vague; the closest sub-error says what was wrong.
        best = jsonschema.exceptions.best_match([error])
        found.append(f"{pointer(best.absolute_path)}: {describe(best)}")

    slots = doc.get("slots") if isinstance(doc, dict) else None
    if isinstance(slots, list):
        seen = {}
        for i, slot in enumerate(slots):
            name = slot.get("name") if isinstance(slot, dict) else None
            if isinstance(name, str):
                if name in seen:
                    found.append(f"/slots/{i}/name: duplicate slot name {name!r} (first at /slots/{seen[name]})")
                seen.setdefault(name, i)
        found += slot_problems(doc, slots)
    if isinstance(doc, dict) and isinstance(doc.get("layers"), list):
        found += layer_problems(doc)
    return found


def layer_problems(doc):
    """Rules 14-17: every layer has the first layer's roles (names and kinds); one splat map per four layers; a
    height blend's `height` names a scalar role; a layer's slot's height_blend names a scalar role, in mode "height"
    the layers' `height`."""
    found = []
    layers = [l for l in doc["layers"] if isinstance(l, dict) and isinstance(l.get("slots"), list)]
    roles = lambda l: {s.get("name"): s.get("kind") for s in l["slots"] if isinstance(s, dict)}
    first = roles(layers[0]) if layers else {}
    for i, layer in enumerate(layers[1:], 1):
        if roles(layer) != first:
            found.append(f"/layers/{i}/slots: roles {sorted(roles(layer))} differ from the first layer's {sorted(first)}")
    blend = doc.get("layer_blend")
    if isinstance(blend, dict):
        splat = blend.get("splat")
        if isinstance(splat, list) and len(splat) != (len(doc["layers"]) + 3) // 4:
            found.append(f"/layer_blend/splat: {len(doc['layers'])} layers need {(len(doc['layers']) + 3) // 4} splat maps")
        height = blend.get("height")
        if isinstance(height, str) and first.get(height, "none") != "scalar":
            found.append(f"/layer_blend/height: `{height}` is not a scalar role of the layers")
    layer_height = blend.get("height") if isinstance(blend, dict) and blend.get("mode") == "height" else None
    for i, layer in enumerate(doc["layers"]):
        for j, s in enumerate(layer.get("slots", []) if isinstance(layer, dict) else []):
            tiles = s.get("height_blend") if isinstance(s, dict) else None
            name = tiles.get("slot") if isinstance(tiles, dict) else None
            if isinstance(name, str) and (first.get(name, "none") != "scalar" or layer_height not in (None, name)):
                found.append(f"/layers/{i}/slots/{j}/height_blend/slot: `{name}` is not the layers' scalar height role")
    return found


# The built-in hex-tiling defaults that the merged-settings rules read (compiler/include/hexc/material.h).
DEFAULTS = {"mode": "stable", "mask": "hex", "split_coordinates": False, "rotationrange": [-180, 180],
            "rotationsteps": 0, "scalerange": [1, 1], "offset": 1, "offsetsteps": [0, 0]}
MASK_TAPS = {"hex": 3, "checker": 2, "noise": 3, "noise3": 3}


def is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def slot_problems(doc, slots):
    """Rules 3-13 of the docstring, for a document whose slots array is `slots`."""
    found = []
    top = doc.get("hextiling")
    top = top if isinstance(top, dict) else {}
    projection = top.get("projection", "uv")
    kinds = {}  # name -> kind, of the first slot with that name
    for slot in slots:
        if isinstance(slot, dict) and isinstance(slot.get("name"), str):
            kinds.setdefault(slot["name"], slot.get("kind"))

    for i, slot in enumerate(slots):
        if not isinstance(slot, dict):
            continue
        own = slot.get("hextiling")
        at = f"/slots/{i}/hextiling" if "hextiling" in slot else f"/slots/{i}"
        merged = {**DEFAULTS, **top, **(own if isinstance(own, dict) else {})}
        mode, mask, taps = merged["mode"], merged["mask"], merged.get("taps")
        split = merged["split_coordinates"] is True
        if mode == "paper":
            if split:
                found.append(f"{at}: split_coordinates needs mode 'stable'")
            if any(merged[key] != DEFAULTS[key] for key in ("rotationrange", "rotationsteps", "scalerange", "offset", "offsetsteps")):
                found.append(f"{at}: per-tile transforms need mode 'stable'")
            if mask in MASK_TAPS and mask != "hex":
                found.append(f"{at}: mask {mask!r} needs mode 'stable'")
        # Values the schema rejects (taps 4, mask "square") are left to it, not reported twice.
        if mask in MASK_TAPS and taps in (2, 3) and taps != MASK_TAPS[mask]:
            found.append(f"{at}: taps {taps} does not fit mask {mask!r}; expected {MASK_TAPS[mask]} or 1")
        if taps == "adaptive" and is_number(merged.get("falloff", 0.5)) and merged.get("falloff", 0.5) < 0.5:
            found.append(f"{at}: taps 'adaptive' needs falloff >= 0.5")
        rotation, span = merged.get("rotation", 1), merged["rotationrange"]
        if merged.get("enabled", True) is not False and is_number(rotation) and isinstance(span, list) and all(map(is_number, span)) \
                and rotation * max(map(abs, span), default=0) > 3600:
            found.append(f"{at}: rotation times rotationrange reaches more than 3600 degrees")
        if split and mask in ("noise", "noise3"):
            found.append(f"{at}: split_coordinates does not work with mask {mask!r}")
        if split and projection == "triplanar":
            found.append(f"{at}: split_coordinates does not work with the triplanar projection")

        height = slot.get("height_blend")
        if not isinstance(height, dict):
            continue
        if (is_number(taps) and taps == 1) or taps == "adaptive":
            found.append(f"/slots/{i}/height_blend: height_blend cannot be combined with taps {taps}")
        name = height.get("slot")
        if isinstance(name, str):
            if name not in kinds:
                found.append(f"/slots/{i}/height_blend/slot: no slot named {name!r} in this material")
            elif kinds[name] != "scalar":
                found.append(f"/slots/{i}/height_blend/slot: slot {name!r} is of kind {kinds[name]!r}; heights come from a 'scalar' slot")
    return found


def expand(args):
    files = []
    for arg in args:
        p = Path(arg)
        if p.is_dir():
            files += sorted(f for f in p.glob("*.json") if not f.name.endswith(".schema.json"))
        else:
            files.append(p)
    return files


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    schema_path, rest = argv[1], argv[2:]
    if "--bad" in rest:
        i = rest.index("--bad")
        good_args, bad_args = rest[:i], rest[i + 1:]
    else:
        good_args, bad_args = rest, []
    good, bad = expand(good_args), expand(bad_args)
    if not good and not bad:
        print("schema_check.py: no material files given", file=sys.stderr)
        return 2

    try:
        schema = load_json(schema_path)
        if not isinstance(schema, dict) or schema.get("$schema") != DRAFT_2020_12:
            raise ValueError(f'"$schema" is not "{DRAFT_2020_12}" (arguments in the wrong order?)')
        jsonschema.Draft202012Validator.check_schema(schema)
    except Exception as e:  # a broken schema makes every other result meaningless
        print(f"schema_check.py: {schema_path}: not a usable draft 2020-12 schema: {e}", file=sys.stderr)
        return 2
    validator = jsonschema.Draft202012Validator(schema)

    passed = failed = 0
    for path in good:
        found = problems(validator, path)
        if found:
            failed += 1
            print(f"FAIL {path}: expected valid, but:")
            for line in found:
                print(f"       {line}")
        else:
            passed += 1
            print(f"ok   {path}: valid")
    for path in bad:
        found = problems(validator, path)
        if found:
            passed += 1
            print(f"ok   {path}: invalid as expected: {found[0]}" + (f" (+{len(found) - 1} more)" if len(found) > 1 else ""))
        else:
            failed += 1
            print(f"FAIL {path}: expected invalid, but it passes the schema")
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
