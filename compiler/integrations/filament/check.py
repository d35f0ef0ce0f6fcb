#!/usr/bin/env python3
"""The Filament engine test (CTest label `engine`): hexc writes the Filament package of each material given and of
engine_check.py's mixed material (non-square textures, a DirectX normal map, packed slots), at both uv origins;
Filament's own compiler compiles each .mat (matc -a opengl -p desktop) and its material file declares every texture
the manifest says the functions read (matinfo). Rendering it headless is not done here yet (docs/engines.md).
    check.py HEXC WORKDIR MATERIAL.json ..."""
import shutil
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import engine_check as ec  # noqa: E402

ORIGINS = {"top-left": [], "bottom-left": ["--uv-bottom-left"]}


def main(argv):
    hexc, work, materials = argv[1], Path(argv[2]), argv[3:]
    shutil.rmtree(work, ignore_errors=True)
    materials = materials + [ec.mixed_material(work / "mixed")]
    start, failed = time.monotonic(), 0
    for material in materials:
        for origin, flags in ORIGINS.items():
            out = work / Path(material).stem / origin
            subprocess.run([hexc, str(material), "--engine", "filament", "-q", "--no-cache", "-o", str(out), *flags], check=True)
            pkg = out / "filament"
            mat = next(pkg.glob("*.mat"))
            filamat = mat.with_suffix(".filamat")
            run = subprocess.run(["matc", "-a", "opengl", "-p", "desktop", "-o", str(filamat), str(mat)], capture_output=True, text=True)
            info = subprocess.run(["matinfo", str(filamat)], capture_output=True, text=True).stdout if run.returncode == 0 else ""
            wanted = [w["uniform"] for w in ec.manifest(pkg)["targets"]["glsl"]["textures"].values()]
            missing = [u for u in wanted if f"{u} " not in info]
            ok = run.returncode == 0 and not missing
            failed += not ok
            print(f"{'ok  ' if ok else 'FAIL'} {mat.name} ({origin}): matc exit {run.returncode}"
                  f"{'' if not missing else ', parameters missing: ' + ', '.join(missing)}")
            if run.returncode != 0:
                print(run.stdout[-3000:] + run.stderr[-3000:])
    print(f"Filament: {2 * len(materials)} materials compiled by matc in {time.monotonic() - start:.1f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
