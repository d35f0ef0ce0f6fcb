#!/usr/bin/env bash
# The Bazel test: installs hexc from BUILD into a fresh prefix (or takes the one in $HEXC_INSTALLED_PREFIX,
# tests/package/prefix.sh), builds tests/bazel/workspace (the rules
# hexc_outputs and hexc_material, loaded from the installed share/hexc/bazel/) in Bazel's linux-sandbox: a plain
# material with its vertex stage, a histogram one, a packing one, a MaterialX document and a scene. Checks that
# each target's files are exactly, and byte for byte, those the command line writes (an output Bazel was not told
# of would be missing), then which actions each edit runs, then that a material whose texture is not declared
# fails to build (outside a sandbox hexc would find the file and succeed):
#   tests/bazel/run.sh BUILD
# Exits 77 (ctest's SKIP_RETURN_CODE) when bazel is not installed (Debian: bazel-bootstrap).
set -euo pipefail
cd "$(dirname "$0")/../.."
command -v bazel > /dev/null || { echo "bazel: not installed (Debian package bazel-bootstrap); skipped"; exit 77; }
build=$(realpath "$1")
work=$build/bazel
[ ! -e "$work" ] || chmod -R u+w "$work"  # Bazel leaves its outputs read-only
rm -rf "$work" && mkdir -p "$work"
prefix=$(tests/package/prefix.sh "$build" "$work/prefix")

ws=$work/workspace
source tests/bazel/common.sh
workspace "$ws" "$prefix"
trap 'in_bazel "$ws" "$work/root" shutdown' EXIT
fail() { echo "bazel: $*" >&2; exit 1; }
bazel_build() { build_all "$ws" "$work/root" "$work/exec.json" > "$work/log" 2>&1; }
# Builds and checks which targets' hexc actions ran: expect NAME... (none for a no-op); every build is clean, but
# for the lines that match $allow.
expect() {
  bazel_build || { cat "$work/log"; fail "$step: the build failed"; }
  ! grep -E "WARNING|ERROR|warning\[|error\[" "$work/log" | grep -v "${allow:-^$}" ||  # Bazel's, hexc's
    fail "$step: the build printed the lines above"
  got=$(python3 tests/bazel/hexc_actions.py "$work/exec.json" ran)
  [ "$got" = "$*" ] || { cat "$work/log"; fail "$step: expected hexc to run for [$*], it ran for [$got]"; }
  echo "ok: $step: [$got]"
}
# The files of a target: those hexc writes into DIR for the same material and options, each identical.
same_as_cli() {  # TARGET MATERIAL OPTION...
  local target=$1 material=$2 cli=$work/cli/$1
  shift 2
  (cd "$ws" && "$prefix/bin/hexc" "$material" -o "$cli" -q --no-cache "$@") || fail "the command line failed for $material"
  for f in "$cli"/*; do cmp "$f" "$ws/bazel-bin/${f##*/}" || fail "$target: bazel-bin/${f##*/} differs from the command line's"; done
  listed=$(sed -n "s/^$target: //p" "$work/files")
  [ "$listed" = "$(ls "$cli" | sort | xargs)" ] || fail "$target's files [$listed] are not the command line's [$(ls "$cli" | xargs)]"
}

step="first build" expect crate gravel rock slate yard
# Each target's files, as Bazel knows them: "<target>: <file> ...".
in_bazel "$ws" "$work/root" cquery --nosandbox_debug --output=starlark \
  --starlark:expr='target.label.name + ": " + " ".join(sorted([f.basename for f in target.files.to_list()]))' //... \
  > "$work/files" 2> "$work/log" || { cat "$work/log"; fail "cquery failed"; }
same_as_cli rock materials/rock.json --vertex
same_as_cli gravel materials/gravel.json --targets spirv,hlsl
same_as_cli crate materials/crate.json
same_as_cli slate materials/slate.mtlx
same_as_cli yard materials/yard.json --targets spirv
echo "ok: every target's files are the command line's, byte for byte, tables, packed texture, vertex stages and scene included"
step="no-op build" expect

# New pixels of gravel's albedo: gravel and the scene that uses it run; the shaders keep their bytes, the tables not.
shader=$(sha256sum "$ws/bazel-bin/gravel.frag.spv") table=$(sha256sum "$ws/bazel-bin/gravel.albedo.lut.pfm")
cp materials/textures/tiles_albedo.png "$ws/materials/textures/gravel_albedo.png"
step="gravel_albedo.png's pixels edited" expect gravel yard
[ "$(sha256sum "$ws/bazel-bin/gravel.frag.spv")" = "$shader" ] || fail "new pixels changed gravel's shader"
[ "$(sha256sum "$ws/bazel-bin/gravel.albedo.lut.pfm")" != "$table" ] || fail "gravel's table was not derived again"

chmod u+w "$ws/bazel-bin/crate.albedo.packed.png" && rm "$ws/bazel-bin/crate.albedo.packed.png"
step="deleted crate.albedo.packed.png" expect crate
[ -s "$ws/bazel-bin/crate.albedo.packed.png" ] || fail "crate.albedo.packed.png was not rebuilt"

# A texture of another size, and a removed slot: hexc_outputs lists again and the outputs follow.
# A texture of another size than the one it packs with: crate no longer packs, which hexc says, and its packed
# texture leaves the declared outputs (hexc_outputs lists again, as crate_roughness.png is in its srcs); back to
# the size, it packs again and builds clean.
tests/consumer/png.py "$ws/materials/textures/crate_roughness.png" 97 61 1
allow="warning\[HX124\]: slot \`roughness\` is not packed: its texture is 97x61" step="crate_roughness.png resized" expect crate yard
grep -q "warning\[HX124\]" "$work/log" || fail "no warning that crate's roughness is not packed"
grep -q "crate.albedo.packed.png" "$work/root/"*/external/hexc_outputs/outputs.bzl && fail "crate.albedo.packed.png is still declared"
cp materials/textures/rock_height.png "$ws/materials/textures/crate_roughness.png"
step="crate_roughness.png back to 256x256" expect crate yard
[ -s "$ws/bazel-bin/crate.albedo.packed.png" ] || fail "crate packs no more"
sed -i '/"roughness"/d; s/\(gravel_albedo.png" }\),/\1/' "$ws/materials/gravel.json"
sed -i 's/\("texture": "textures\/gravel_albedo.png" }\),/\1/' "$ws/materials/gravel.json"
step="gravel's roughness slot removed" expect gravel yard
grep -q "gravel.roughness" "$work/root/"*/external/hexc_outputs/outputs.bzl && fail "gravel.roughness's tables are still declared"
step="second build after the edits" expect

# A rule whose options differ from those hexc_outputs listed with: hexc writes a file the rule does not declare,
# which Bazel would drop without a word; the rule fails instead, naming both lists.
cp "$ws/BUILD" "$work/BUILD"
sed -i 's/targets = \["spirv", "hlsl"\],/targets = ["spirv", "hlsl", "glsl"],/' "$ws/BUILD"
! bazel_build || { cat "$work/log"; fail "gravel with a glsl target its outs do not list built"; }
grep -q "hexc_material: hexc wrote \[.*gravel.frag.glsl.*\] but the rule declares" "$work/log" || { cat "$work/log"; fail "no word of gravel.frag.glsl"; }
echo "ok: an output the rule does not declare fails the build: $(grep -o 'hexc_material: hexc wrote.\{0,60\}' "$work/log")..."
cp "$work/BUILD" "$ws/BUILD"

# rock_normal.png stays in the workspace, only undeclared: the sandbox must hide it from the action.
sed -i '/rock_normal.png/d' "$ws/BUILD"
[ -f "$ws/materials/textures/rock_normal.png" ] || fail "rock_normal.png is missing from the workspace"
! bazel_build || { cat "$work/log"; fail "the build with an undeclared texture succeeded"; }
grep -q "texture file not found: materials/textures/rock_normal.png" "$work/log" || { cat "$work/log"; fail "the build failed for another reason"; }
echo "ok: an undeclared texture fails the build: $(grep -o 'error\[HX.*' "$work/log")"
