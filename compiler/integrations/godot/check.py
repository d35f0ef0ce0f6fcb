#!/usr/bin/env python3
"""The Godot 3 engine test (CTest label `engine`), in one Godot run (Debian's godot3, GLES3 on llvmpipe, under
xvfb-run) of the project in project/, every frame with a red marker Godot draws over the screen's top-left corner:

- the matrix: the Godot 3 package of every material under materials/ (engine_check.matrix_materials) compiled by
  Godot itself (drawn once; a SHADER ERROR fails), but the ones the docs say a package refuses (hexc must refuse them);
- drawn against hexc's fp64 reference (engine_check.drawn_materials: rock, tiles, the mixed, layered and probe
  materials; and the golden histogram material, its Gaussian textures and tables the package's OpenEXR files), each
  function of the package shown unshaded on a mesh with Godot's uv convention ((0, 0) at the top-left, the package
  built without --uv-bottom-left, as docs/conventions.md says), within the bound derived in engine_check.py; the
  layered material weighed by the vertex colour (engine_check.layered_material(weights="vertex")) on a mesh whose
  corners carry engine_check.VERTEX_COLORS, which its functions read from Godot's COLOR; the probe's bumps lit by a
  Godot light on Godot's own QuadMesh, from the right and from the top: 15 of 15 lit from the light's side, for a
  green-up and a DirectX map;
- negative controls, which must fail: the package built for the other uv origin, a mesh mirrored in u, the normal
  map of the other green convention, the albedo decoded twice, a NaN value; the layered material with two layers'
  textures exchanged and with a splat channel swapped; the histogram slot's own texture bound in place of its
  Gaussian texture; the vertex-weighed one with the mesh's red and green vertex colour channels exchanged.

The frame is read back as Godot's docs say (get_data() then flip_y), and every image must show the marker at its
top-left.
    check.py HEXC WORKDIR"""
import functools
import json
import shutil
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import engine_check as ec  # noqa: E402

ROOT = Path(__file__).resolve().parents[3]
SIZE = 256
# Godot 3 renders 3D into a half-float buffer (rendering/quality/depth/hdr, on by default) before its sRGB output:
# 11 bits of mantissa, so a value is kept within 2^-11 of itself.
HDR_BUFFER = 2 ** -11
TOP = [0, 1, 0.5]  # towards a light at the top of the screen
LIGHTS = {"right": [1, 0, 0.5], "top": TOP}
HISTOGRAM = ec.histogram_material(ROOT)


@functools.lru_cache(maxsize=None)  # a package is written once, for the matrix and the checks that draw it
def package(hexc, material, work, bottom_left=False):
    out = work / (Path(material).stem + ("_bl" if bottom_left else ""))
    run = subprocess.run([hexc, str(material), "--engine", "godot3", "-q", "--no-cache", "-o", str(out)] +
                         (["--uv-bottom-left"] if bottom_left else []), capture_output=True, text=True)
    return (out / "godot3") if run.returncode == 0 else run.stderr


def textures(pkg, swap=None):
    """uniform -> the file Godot loads and whether it is sRGB (engine_check.package_textures)."""
    return {u: {"path": str(path), "srgb": srgb} for u, (path, srgb) in ec.package_textures(pkg, swap).items()}


def value_shader(pkg, function, nan=False):
    """The package's shader, unshaded, showing `function`'s value at the mesh's uv and vertex colour, where it takes
    one (the manifest's parameters, as the package's fragment passes COLOR) (times NaN if `nan`)."""
    shader = next(pkg.glob("*.shader")).read_text()
    head = shader[:shader.index("void fragment()")].replace("shader_type spatial;", "shader_type spatial;\nrender_mode unshaded;", 1)
    args = "UV, COLOR" if function["parameters"] == "vec2 uv, vec4 color" else "UV"
    show = {"vec4": "{}.rgb", "float": "vec3({})", "vec3": "{} * 0.5 + 0.5"}[function["returns"]].format(f"{function['name']}({args})")
    if nan:
        show = f"({show}) * intBitsToFloat(2143289344)"  # 0x7fc00000, a quiet NaN
    path = pkg.parent / "views" / (function["name"] + ("_nan" if nan else "") + ".shader")  # beside the package, not in it
    path.parent.mkdir(exist_ok=True)
    path.write_text(head + "void fragment() {\n    ALBEDO = " + show + ";\n}\n")
    return str(path)


def render(project, jobs):
    """Godot's run of the jobs, and each job's shader errors (Godot prints them after the job's HEXC-JOB line)."""
    (project / "job.json").write_text(json.dumps({"jobs": jobs}))
    run = subprocess.run(["xvfb-run", "-a", "godot3", "--path", str(project)], capture_output=True, text=True, timeout=600)
    errors, job = [[] for _ in jobs], None
    for line in run.stderr.splitlines():
        if line.startswith("HEXC-JOB "):
            job = int(line.split()[1])
        elif job is not None and ("SHADER ERROR" in line or "HEXC-ERROR" in line):
            errors[job].append(line)
    missing = [j["out"] for j in jobs if "out" in j and not Path(j["out"]).exists()]
    if missing or job != len(jobs) - 1:
        sys.exit("FAIL Godot did not render every job:\n" + "\n".join(missing + run.stderr.splitlines()[-20:]))
    return errors


class Jobs:
    """The jobs of the Godot run and, for each, what is checked of its image once Godot has run."""

    def __init__(self, work):
        self.work, self.jobs, self.checks = work, [], []

    def add(self, shader, textures, check, name=None, **options):
        job = {"shader": shader, "textures": textures, **options}
        if name:
            job["out"] = str(self.work / f"{name}.png")
        self.jobs.append(job)
        self.checks.append(check)


def vertex_weighed(hexc, jobs, work):
    """The layered material weighed by the vertex colour: each role on a mesh with engine_check.VERTEX_COLORS; and the
    albedo with the colours' red and green exchanged, which must fail."""
    material = ec.layered_material(work / "layered", weights="vertex")
    pkg = package(hexc, material, work)
    rect = ec.rect_for(ec.manifest(pkg), SIZE)
    functions = [f for f in ec.manifest(pkg)["functions"] if f["returns"] != "vec2"]
    for f in functions:
        jobs.add(value_shader(pkg, f), textures(pkg), value_check(hexc, material, pkg, f, rect), f"{material.stem}_{f['name']}", uv=rect,
                 colors=ec.VERTEX_COLORS)
    albedo = next(f for f in functions if f["role"] == "albedo")
    jobs.add(value_shader(pkg, albedo), textures(pkg),
             value_check(hexc, material, pkg, albedo, rect, "a vertex colour channel swapped: the mesh's red and green exchanged"),
             f"control_{len(jobs.jobs)}", uv=rect, colors=ec.VERTEX_COLORS_SWAPPED)


def value_check(hexc, material, pkg, f, rect, control=None):
    view = {"package": pkg, "origin": "top-left", "size": SIZE, "rect": rect, "relative": HDR_BUFFER, "encode": ec.srgb}
    return lambda out, errors: ec.value_verdict(hexc, material, f, out, view, control, errors)


def lit_check(what, side, control=False):
    return lambda out, errors: ec.lit_verdict(out, what, side, control, errors)


def compile_check(material):
    def check(out, errors):
        return ec.row(f"matrix: {Path(material).name} compiled by Godot 3", "; ".join(errors) or "no shader error", not errors)
    return check


def draw(hexc, jobs, work):
    """The drawn materials' value views and the probe lit, as the docs say a user builds them."""
    for material in ec.drawn_materials(ROOT, work) + [HISTOGRAM]:
        pkg = package(hexc, material, work)
        rect = ec.rect_for(ec.manifest(pkg), SIZE)
        for f in ec.manifest(pkg)["functions"]:
            if f["returns"] != "vec2":  # the derivative: its normal function is checked
                jobs.add(value_shader(pkg, f), textures(pkg), value_check(hexc, material, pkg, f, rect),
                         f"{Path(material).stem}_{f['name']}", uv=rect)
    for convention in ("gl", "dx"):
        material = ec.probe_material(work / "probe", convention, albedo=False)
        pkg = package(hexc, material, work)
        for side, light in LIGHTS.items():
            jobs.add(str(next(pkg.glob("*.shader"))), textures(pkg),
                     lit_check(f"probe bumps ({convention} map) on Godot's QuadMesh", side), f"{material.stem}_{side}", light=light)
    for material in (ROOT / "materials" / "rock.json", work / "layered" / "layered.json", work / "probe" / "probe_gl.json",
                     ROOT / "materials" / "terrain" / "terrain.json"):
        pkg = package(hexc, material, work)  # docs/engines.md's screenshots: lit by Godot, not checked
        jobs.add(str(next(pkg.glob("*.shader"))), textures(pkg), lambda out, errors: False, f"{material.stem}_lit",
                 light=[0.4, 0.4, 0.8])


def controls(hexc, jobs, work):
    """Wrong variants a user could make, each of which the checks must fail."""
    probe, bumps = work / "probe" / "probe_gl.json", work / "probe" / "probe_gl_bumps.json"
    pkg, bl = package(hexc, probe, work), package(hexc, probe, work, bottom_left=True)
    albedo = next(f for f in ec.manifest(pkg)["functions"] if f.get("slot") == "albedo")
    rect = ec.rect_for(ec.manifest(pkg), SIZE)
    mirrored = [rect[2], rect[1], rect[0], rect[3]]
    decoded = ec.srgb_decoded_copy(work / "probe" / "probe_albedo.png", work / "probe" / "probe_albedo_decoded.png")
    for what, shader, tex, uv in (
            ("v flipped: the package built with --uv-bottom-left", value_shader(bl, albedo), textures(bl), rect),
            ("u mirrored: a mesh whose u runs right to left", value_shader(pkg, albedo), textures(pkg), mirrored),
            ("sRGB decoded twice: a linearised copy of the albedo bound as sRGB", value_shader(pkg, albedo),
             textures(pkg, {"albedo": decoded}), rect),
            ("a NaN value: the albedo function times NaN", value_shader(pkg, albedo, nan=True), textures(pkg), rect)):
        jobs.add(shader, tex, value_check(hexc, probe, pkg, albedo, rect, what), f"control_{len(jobs.jobs)}", uv=uv)
    layered = work / "layered" / "layered.json"
    lpkg = package(hexc, layered, work)
    role = next(f for f in ec.manifest(lpkg)["functions"] if f.get("role") == "albedo")
    lrect = ec.rect_for(ec.manifest(lpkg), SIZE)
    for what, swap in ec.layered_controls(layered.parent).items():
        jobs.add(value_shader(lpkg, role), textures(lpkg, swap), value_check(hexc, layered, lpkg, role, lrect, what),
                 f"control_{len(jobs.jobs)}", uv=lrect)
    hpkg = package(hexc, HISTOGRAM, work)
    halbedo = next(f for f in ec.manifest(hpkg)["functions"] if f.get("slot") == "albedo")
    hrect = ec.rect_for(ec.manifest(hpkg), SIZE)
    jobs.add(value_shader(hpkg, halbedo), textures(hpkg, {"albedo": ROOT / "materials" / "textures" / "rock_albedo.png"}),
             value_check(hexc, HISTOGRAM, hpkg, halbedo, hrect, "the histogram slot's own texture bound in place of its Gaussian texture"),
             f"control_{len(jobs.jobs)}", uv=hrect)
    bumps_bl, bumps_pkg = package(hexc, bumps, work, bottom_left=True), package(hexc, bumps, work)
    jobs.add(str(next(bumps_bl.glob("*.shader"))), textures(bumps_bl),
             lit_check("v flipped: the bumps package built with --uv-bottom-left", "top", True), "control_bumps_v", light=TOP)
    jobs.add(str(next(bumps_pkg.glob("*.shader"))), textures(bumps_pkg, {"normal": work / "probe" / "probe_normal_dx.png"}),
             lit_check("green inverted: the DirectX map bound to the green-up slot", "top", True), "control_bumps_green", light=TOP)


def matrix(hexc, jobs, work):
    """Every material's package, compiled by Godot (drawn for a frame); the refused ones refused by hexc."""
    failed = 0
    for material in ec.matrix_materials(ROOT):
        pkg = package(hexc, material, work)
        if ec.refused(material, "godot3"):
            failed += ec.row(f"matrix: {material.name} skipped", "refused by hexc, as the docs say: " + ec.refused(material, "godot3"),
                             isinstance(pkg, str))
        elif isinstance(pkg, str):
            failed += ec.row(f"matrix: {material.name}", "hexc refused it: " + pkg.strip(), False)
        else:
            jobs.add(str(next(pkg.glob("*.shader"))), textures(pkg), compile_check(material))
    return failed


def main(argv):
    hexc, work = argv[1], Path(argv[2])
    shutil.rmtree(work, ignore_errors=True)
    project = work / "project"
    shutil.copytree(Path(__file__).parent / "project", project)
    start, jobs = time.monotonic(), Jobs(work)
    print("| check | figure | result |\n|---|---|---|")
    failed = matrix(hexc, jobs, work)
    draw(hexc, jobs, work)
    vertex_weighed(hexc, jobs, work)
    controls(hexc, jobs, work)
    errors = render(project, jobs.jobs)
    for job, check, job_errors in zip(jobs.jobs, jobs.checks, errors):
        failed += check(Path(job.get("out", "")), job_errors)
    print(f"Godot 3: {len(jobs.jobs)} jobs in one run and their checks in {time.monotonic() - start:.1f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
