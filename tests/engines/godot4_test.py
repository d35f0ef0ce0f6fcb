"""hexc's Godot 4 package checked as far as it can be without Godot 4 (docs/engines.md#godot).

usage: godot4_test.py HEXC GLSLANGVALIDATOR

No Godot 4 runs here (Debian has Godot 3 only), so its shader is checked mechanically: the file must be
`shader_type spatial;`, one `uniform sampler2D NAME : HINTS;` line per texture (`sampler2DArray` for a layered role's
array) with only Godot 4's hints
(source_color, filter_linear_mipmap, repeat_enable; source_color exactly on the sRGB textures the manifest names),
hexc's functions and one `void fragment()`. Then the functions and the fragment body, wrapped as a GLSL 4.50 fragment
shader (each uniform as a plain `uniform sampler2D`, Godot's built-ins UV, COLOR, ALBEDO, NORMAL_MAP, ... as variables), must
compile with glslang: Godot 4's shading language is GLSL-like, and what it shares with GLSL is checked, and so is
one rule of its own that GLSL lacks: a global is a constant with its value (`const uint x = uint(0);`), never a bare
`uint x;` ("Expected initialization of constant", as Godot 3 says). Its other rules beyond GLSL (and rendering) are not
checked: a limit, since no Godot 4 runs here. For every material under materials/ (engine_check.matrix_materials; the
ones the docs say the package refuses must be refused, and are listed), the engine tests' mixed material and their
layered one, its roles as texture arrays and as a texture per slot, at both uv origins.
"""
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "compiler" / "integrations"))
from engine_check import layered_material, matrix_materials, mixed_material, refused  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from hlsl_test import report  # noqa: E402

HINTS = {"source_color", "filter_linear_mipmap", "repeat_enable"}
# Godot 4's spatial fragment built-ins the package reads or writes, as GLSL variables.
BUILTINS = """in vec2 UV_IN;
in vec4 COLOR_IN;
layout(location = 0) out vec4 hexcCheck;
"""
LOCALS = ("    vec2 UV = UV_IN;\n    vec4 COLOR = COLOR_IN;\n    vec3 ALBEDO = vec3(0.0), NORMAL_MAP = vec3(0.5, 0.5, 1.0), EMISSION = vec3(0.0);\n"
          "    float ROUGHNESS = 1.0, METALLIC = 0.0, AO = 1.0;\n")
USE = "    hexcCheck = vec4(ALBEDO + NORMAL_MAP + EMISSION, ROUGHNESS + METALLIC + AO);\n"


def wrap(shader, srgb, problems):
    """The GLSL 4.50 fragment shader of the package's text; `problems` gets what does not have Godot 4's form."""
    lines = shader.splitlines()
    if not lines or lines[0] != "shader_type spatial;":
        problems.append("the first line is not `shader_type spatial;`")
    uniforms, body = [], []
    for line in lines[1:]:
        if line[:1].isalpha() and line.endswith(";") and not line.startswith(("uniform ", "const ")):
            problems.append(f"a global without `const` and its value, which Godot refuses: {line}")
        if line.startswith("uniform "):
            m = re.fullmatch(r"uniform (sampler2D|sampler2DArray) (\w+) : ([\w, ]+);", line)
            hints = set(m.group(3).split(", ")) if m else set()
            if not m or not hints <= HINTS or not {"filter_linear_mipmap", "repeat_enable"} <= hints:
                problems.append(f"not a Godot 4 texture uniform with its sampler hints: {line}")
                continue
            if ("source_color" in hints) != (m.group(2) in srgb):
                problems.append(f"source_color should be on the sRGB textures {sorted(srgb)} only: {line}")
            uniforms.append(f"uniform {m.group(1)} {m.group(2)};")
        else:
            body.append(line)
    text = "\n".join(body)
    start = text.find("void fragment() {")
    if start < 0 or text.count("void fragment()") != 1:
        problems.append("not one `void fragment()`")
        return None
    inputs = text[start + len("void fragment() {"):text.rindex("}")]
    return ("#version 450\n" + "\n".join(f"layout(binding = {i}) {u}" for i, u in enumerate(uniforms)) + "\n" + BUILTINS
            + text[:start] + "void main() {\n" + LOCALS + inputs + USE + "}\n")


def srgb_textures(manifest):
    """The texture uniforms the sampler decodes from sRGB: a slot's own (hexcTex_<slot>; not a slot the shader decodes,
    `"decode": "shader"`), a packed texture holding one, or a layered role's array of them."""
    srgb = {f"hexcTex_{s['name']}" for s in manifest["slots"] if s.get("colorspace") == "srgb" and "decode" not in s}
    for p in manifest.get("packed_textures", []):
        names = {f"hexcTex_{n}" for n in p.get("slots", [])}
        srgb -= names
        if p["colorspace"] == "srgb":
            srgb.add(manifest["targets"]["glsl"]["textures"][p["name"]]["uniform"])
    for a in manifest.get("layers", {}).get("arrays", []):
        if a["array"] and a["colorspace"] == "srgb":
            srgb.add(manifest["targets"]["glsl"]["textures"][a["binding"]["texture"]]["uniform"])
    return srgb


def main():
    hexc, glslang = sys.argv[1:3]
    failures, count = [], 0
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        layered = [layered_material(tmp / "layered"), layered_material(tmp / "layered", arrays=False)]
        for material in matrix_materials(ROOT) + [mixed_material(tmp / "mixed")] + layered:
            for bottom_left in (False, True):
                out = tmp / f"{material.stem}_{int(bottom_left)}"
                args = [hexc, str(material), "--engine", "godot4", "-q", "-o", str(out)] + (["--uv-bottom-left"] if bottom_left else [])
                r = subprocess.run(args, capture_output=True, text=True)
                what = f"{material.name} {'bottom-left' if bottom_left else 'top-left'}"
                if refused(material, "godot4"):
                    print(f"{what}: skipped, refused as the docs say ({refused(material, 'godot4')})")
                    if r.returncode == 0:
                        failures.append(f"{what}: hexc wrote a package the docs say it refuses")
                    continue
                if r.returncode != 0:
                    failures.append(f"{what}: {r.stderr}")
                    continue
                manifest = json.loads(next((out / "godot4").glob("*.manifest.json")).read_text())
                problems = []
                glsl = wrap(next((out / "godot4").glob("*.gdshader")).read_text(), srgb_textures(manifest), problems)
                failures += [f"{what}: {p}" for p in problems]
                if glsl is None:
                    continue
                path = out / "wrapped.frag"
                path.write_text(glsl)
                c = subprocess.run([glslang, "-S", "frag", str(path)], capture_output=True, text=True)
                if c.returncode != 0:
                    failures.append(f"{what}: the wrapped functions and fragment do not compile:\n{c.stdout}{c.stderr}")
                count += 1
    return report(failures, f"godot4: {count} packages wrapped and compiled with glslang (no Godot 4 here: its own compiler not run)")


if __name__ == "__main__":
    sys.exit(main())
