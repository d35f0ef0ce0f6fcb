"""hexc's Unity and Unreal packages compiled with glslang's HLSL front end (docs/engines.md#unity, #unreal).

usage: hlsl_test.py HEXC unity|unreal GLSLANGVALIDATOR

Neither engine runs here, so each package is compiled as the engine would compile it, against stub declarations of
the engine's shader library (tests/engines/stubs/, from the engines' documented declarations):

- Unity: every Shader Graph Custom Function entry point (`hexc_<slot>_float`, with the ports the file's header lists)
  called from a fragment shader as Shader Graph's generated code calls it (`UnityTexture2D` ports, `UnityTexture2DArray`
  for a Texture 2D Array port); the URP shader's HLSLPROGRAM block, vertex and fragment stage.
- Unreal: every Custom node the `.ush` header lists, as the function Unreal generates for it (its inputs as parameters,
  a Texture Object input as `Texture2D X, SamplerState XSampler`, `Texture2DArray X, ...` for a texture array's), called
  from a fragment shader.

For every example under materials/ (a triplanar one must be refused with HX300, as docs/engines.md says; the terrain,
layered, with its roles as texture arrays), the engine tests' mixed material (packed slots, 300 x 170 textures, a DirectX-convention normal map) and their
layered one (its roles as texture arrays, and as a texture per slot with `"arrays": "off"`): rock and mixed at both uv
origins, the others at one, alternately. Then a package with a mistyped function must be refused by the same compile.
"""
import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "compiler" / "integrations"))
from engine_check import layered_material, mixed_material  # noqa: E402

STUBS = ROOT / "tests" / "engines" / "stubs"
TYPES = {"1": "float", "2": "float2", "3": "float3", "4": "float4"}
SWIZZLE = {"1": ".x", "2": ".xy", "3": ".xyz", "4": ""}


def compile_hlsl(glslang, path, stage, entry, stubs):
    """glslang's HLSL front end on `path`: (ok, output)."""
    r = subprocess.run([glslang, "-D", "-V", "-S", stage, "-e", entry, f"-I{stubs}", str(path), "-o", os.devnull],
                       capture_output=True, text=True)
    return r.returncode == 0, r.stdout + r.stderr


def header_lines(text):
    """The package's header comment lines that describe its nodes (after the line ending in 'in order.' or 'code.')."""
    return [line[5:] for line in text.splitlines() if line.startswith("//   ")]


def unity_consumer(hlsl_name, hlsl_text):
    """A fragment shader calling every Custom Function entry point as Shader Graph's generated code does (a Color port
    given the vertex colour, as a Vertex Color node gives it)."""
    node = re.compile(r"^(\w+): UV \(Vector 2\)(, Color \(Vector 4\))?((?:, \w+ \(Texture 2D(?: Array)?\))*) -> Out \(Vector (\d)\)$")
    textures, arrays, calls = [], set(), []
    for line in header_lines(hlsl_text):
        m = node.match(line)
        assert m, f"unexpected node line: {line}"
        ports = re.findall(r", (\w+) \(Texture 2D( Array)?\)", m.group(3))
        textures += [t for t, _ in ports if t not in textures]
        arrays |= {t for t, array in ports if array}
        args = "".join(f", UnityBuildTexture2DArrayStruct({t})" if array else f", UnityBuildTexture2DStructNoScale({t})"
                       for t, array in ports)
        color = ", color" if m.group(2) else ""
        calls.append(f"    {{ {TYPES[m.group(4)]} Out; {m.group(1)}_float(uv{color}{args}, Out); sum{SWIZZLE[m.group(4)]} += Out; }}")
    assert calls, "no Custom Function node listed"
    return "\n".join([
        '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"',
        '#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Texture.hlsl"',
        f'#include "{hlsl_name}"',
        *[f"TEXTURE2D_ARRAY({t});\nSAMPLER(sampler{t});" if t in arrays else
          f"TEXTURE2D({t});\nSAMPLER(sampler{t});\nfloat4 {t}_TexelSize;" for t in textures],
        "float4 main(float2 uv : TEXCOORD0, float4 color : COLOR) : SV_Target",
        "{",
        "    float4 sum = 0.0;",
        *calls,
        "    return sum;",
        "}", ""])


def unreal_consumer(ush_name, ush_text):
    """A fragment shader calling every Custom node of the header as the function Unreal generates for it (a Color
    input given the vertex colour, as a VertexColor node gives it)."""
    node = re.compile(r"^(.+) <- CMOT Float (\d) \(UV(, Color)?((?:, \w+(?: \(Texture2DArray\))?)*)\): (.*)$")
    textures, types, functions, calls = [], {}, [], []
    for i, line in enumerate(header_lines(ush_text)):
        m = node.match(line)
        assert m, f"unexpected node line: {line}"
        found = re.findall(r", (\w+)( \(Texture2DArray\))?", m.group(4))  # a Texture Object input of a texture array
        inputs = [t for t, _ in found]
        types |= {t: "Texture2DArray" if array else "Texture2D" for t, array in found}
        textures += [t for t in inputs if t not in textures]
        params = (", MaterialFloat4 Color" if m.group(3) else "") + "".join(f", {types[t]} {t}, SamplerState {t}Sampler" for t in inputs)
        functions.append(f"MaterialFloat{'' if m.group(2) == '1' else m.group(2)} CustomExpression{i}(FMaterialPixelParameters Parameters, MaterialFloat2 UV{params})\n"
                         f"{{\n    {m.group(5)}\n}}\n")
        args = (", Parameters.VertexColor" if m.group(3) else "") + "".join(f", {t}, {t}Sampler" for t in inputs)
        calls.append(f"    sum{SWIZZLE[m.group(2)]} += CustomExpression{i}(Parameters, Parameters.TexCoords[0]{args});")
    assert calls, "no Custom node listed"
    return "\n".join([
        '#include "/Engine/Private/Common.ush"',
        f'#include "{ush_name}"',
        *[f"{types[t]} {t};\nSamplerState {t}Sampler;" for t in textures],
        *functions,
        "float4 main(float2 uv : TEXCOORD0) : SV_Target",
        "{",
        "    FMaterialPixelParameters Parameters = (FMaterialPixelParameters)0;",
        "    Parameters.TexCoords[0] = uv;",
        "    float4 sum = 0.0;",
        *calls,
        "    return sum;",
        "}", ""])


def urp_program(shader_text):
    """The URP shader's HLSLPROGRAM block."""
    m = re.search(r"HLSLPROGRAM\n(.*?)\n\s*ENDHLSL", shader_text, re.S)
    assert m, "no HLSLPROGRAM block"
    return m.group(1)


def check(glslang, source, path, stage, entry, stubs, failures, what):
    path.write_text(source)
    ok, output = compile_hlsl(glslang, path, stage, entry, stubs)
    if not ok:
        failures.append(f"{what}: {output.strip()[:2000]}")
    return ok, output


# What the docs say these packages refuse (docs/engines.md), by the key that makes a material so: compiled, it must
# be refused with HX300, and is listed as left out.
REFUSED = {"projection": "triplanar, no functions output: HX300, docs/engines.md"}


def refused_why(material):
    """Why the docs say the packages refuse `material`, or None."""
    if material.suffix != ".json":
        return None
    doc = json.loads(material.read_text())
    settings = [doc, doc.get("hextiling", {})] + [s.get("hextiling", {}) for s in doc.get("slots", [])]
    return next((why for key, why in REFUSED.items() for where in settings if key in where), None)


def check_package(hexc, engine, glslang, material, out, bottom_left, failures):
    """Writes the package and compiles it (a material the docs say is refused must be refused with HX300)."""
    args = [hexc, str(material), "--engine", engine, "-o", str(out)] + (["--uv-bottom-left"] if bottom_left else [])
    r = subprocess.run(args, capture_output=True, text=True)
    if refused_why(material):
        if r.returncode == 0 or "error[HX300]" not in r.stderr:
            failures.append(f"{' '.join(args)}: expected HX300 ({refused_why(material)}), got exit {r.returncode}: {r.stderr}")
        return
    if r.returncode != 0:
        failures.append(f"{' '.join(args)}: {r.stderr}")
        return
    folder = out / engine
    name = next(folder.glob("*.manifest.json")).name.removesuffix(".manifest.json")  # the material's name, not its file's
    what = f"{name} {engine} {'bottom-left' if bottom_left else 'top-left'}"
    stubs = STUBS / engine
    manifest = json.loads((folder / f"{name}.manifest.json").read_text())
    slots = {f.get("slot") for f in manifest["functions"]}  # which of the inputs below the package must fill
    if engine == "unity":
        hlsl = (folder / f"{name}.hexc.hlsl").read_text()
        check(glslang, unity_consumer(f"{name}.hexc.hlsl", hlsl), folder / "shadergraph.hlsl", "frag", "main", stubs, failures,
              f"{what}: Shader Graph Custom Function nodes")
        program = urp_program((folder / f"{name}.shader").read_text())
        for stage, entry in (("vert", "vert"), ("frag", "frag")):
            check(glslang, program, folder / f"urp_{stage}.hlsl", stage, entry, stubs, failures, f"{what}: URP shader, {stage}")
        for slot, expected in (("albedo", "surface.albedo = (hexc_albedo(uv, "), ("normal", "surface.normalTS = hexc_normal_normal(uv, "),
                               ("roughness", "surface.smoothness = 1.0 - hexc_roughness(uv, ")):
            if slot in slots and expected not in program:
                failures.append(f"{what}: the URP shader lacks `{expected}`")
    else:
        ush = (folder / f"{name}.ush").read_text()
        check(glslang, unreal_consumer(f"{name}.ush", ush), folder / "custom.hlsl", "frag", "main", stubs, failures,
              f"{what}: Custom nodes")
        for slot, pin in (("albedo", "Base Color <- CMOT Float 4"), ("normal", "Normal <- CMOT Float 3"),
                          ("roughness", "Roughness <- CMOT Float 1")):
            if slot in slots and f"//   {pin}" not in ush:
                failures.append(f"{what}: no Custom node for `{pin}`")
        if "normal" in slots and "* float3(1.0, -1.0, 1.0);" not in ush:
            failures.append(f"{what}: the Normal node does not turn hexc's normal to Unreal's green-down convention")


def check_refused(engine, glslang, folder, failures):
    """A package with a mistyped function (one definition renamed) must not compile."""
    stubs = STUBS / engine
    if engine == "unity":
        source_file, consumer = folder / "rock.hexc.hlsl", unity_consumer
    else:
        source_file, consumer = folder / "rock.ush", unreal_consumer
    text = source_file.read_text()
    broken = re.sub(r"^(float4 )hexc_albedo\(", r"\1hexc_albedoo(", text, count=1, flags=re.M)
    assert broken != text, "no definition of hexc_albedo to mistype"
    bad = folder / f"broken{source_file.suffix}"
    bad.write_text(broken)
    bad_path = folder / "broken_consumer.hlsl"
    bad_path.write_text(consumer(bad.name, broken))
    ok, output = compile_hlsl(glslang, bad_path, "frag", "main", stubs)
    if ok or "hexc_albedo" not in output:
        failures.append(f"{engine}: a package whose hexc_albedo is misnamed compiled (or failed elsewhere): {output[:500]}")


def main():
    hexc, engine, glslang = sys.argv[1:4]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        # Every example under materials/ (tiles.json: rotation 0; preview_surface: a plain-tiled slot read with implicit
        # levels), the mixed material (packed, non-square, a DirectX normal map), histogram (its tables read at an
        # explicit level).
        examples = sorted([*ROOT.glob("materials/*.json"), *ROOT.glob("materials/terrain/*.json"), *ROOT.glob("materials/mtlx/*.mtlx")])
        examples = [m for m in examples if m.suffix == ".mtlx" or {"slots", "layers"} & json.loads(m.read_text()).keys()]
        mixed = mixed_material(tmp / "mixed")
        layered = [layered_material(tmp / "layered"), layered_material(tmp / "layered", arrays=False)]  # arrays, and not
        materials = examples + [mixed, *layered, ROOT / "tests" / "golden" / "materials" / "histogram.json"]
        both = {ROOT / "materials" / "rock.json", mixed}  # rock and mixed at both uv origins, the rest alternately
        packages = [(m, bl) for i, m in enumerate(materials) for bl in ((False, True) if m in both else (i % 2 == 1,))]
        for material, bottom_left in packages:
            out = tmp / f"{material.stem}_{'bl' if bottom_left else 'tl'}"
            check_package(hexc, engine, glslang, material, out, bottom_left, failures)
        check_refused(engine, glslang, tmp / "rock_tl" / engine, failures)
        left_out = [f"{m.relative_to(ROOT)} ({refused_why(m)})" for m in materials if refused_why(m)]
        compiled = [(m, bl) for m, bl in packages if not refused_why(m)]
    print(f"{engine}: left out as the docs say (refused with HX300, checked): {', '.join(left_out) or 'none'}")
    return report(failures, f"{engine}: {len(compiled)} packages of {len({m for m, _ in compiled})} materials compiled with glslang's HLSL front end")


def report(failures, summary):
    """Prints each failure and the summary with their count; the exit code."""
    for f in failures:
        print("FAIL", f)
    print(f"{summary}, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
