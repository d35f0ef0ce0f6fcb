#!/usr/bin/env bash
# The Bazel test: installs hexc from BUILD into a fresh prefix, builds tests/bazel/workspace (the rule
# hexc_material, loaded from the installed share/hexc/bazel/) in Bazel's linux-sandbox, checks the outputs are
# byte-identical to the command line's, then checks that a material whose texture is not declared fails to build
# (outside a sandbox hexc would find the file and succeed):
#   tests/bazel/run.sh BUILD
# Exits 77 (ctest's SKIP_RETURN_CODE) when bazel is not installed (Debian: bazel-bootstrap).
set -euo pipefail
cd "$(dirname "$0")/../.."
command -v bazel > /dev/null || { echo "bazel: not installed (Debian package bazel-bootstrap); skipped"; exit 77; }
build=$(realpath "$1")
work=$build/bazel
[ ! -e "$work" ] || chmod -R u+w "$work"  # Bazel leaves its outputs read-only
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > /dev/null

ws=$work/workspace
cp -r tests/bazel/workspace "$ws"
sed -i "s|/opt/hexc|$work/prefix|" "$ws/WORKSPACE"
mkdir -p "$ws/materials/textures"
cp materials/rock.json "$ws/materials/"
cp materials/textures/rock_{albedo,normal,roughness}.png "$ws/materials/textures/"

fail() { echo "bazel: $*" >&2; exit 1; }
# --batch: no server outlives the test. Only Debian's system bazelrc (its install base) applies, not a user's.
# linux-sandbox explicitly: a sandbox that cannot start fails the build instead of falling back to none.
bazel_build() {
  (cd "$ws" && bazel --batch --nohome_rc --noworkspace_rc --output_user_root="$work/root" \
    build --spawn_strategy=linux-sandbox --nosandbox_debug //:rock) > "$work/log" 2>&1
}

(cd "$ws" && "$work/prefix/bin/hexc" materials/rock.json -o "$work/cli" -q --vertex) || fail "the command line failed"
bazel_build || { cat "$work/log"; fail "the sandboxed build failed"; }
for f in rock.manifest.json rock.{frag,vert}.{spv,hlsl,glsl,metal}; do
  cmp "$ws/bazel-bin/$f" "$work/cli/$f" || fail "bazel-bin/$f differs from the command line's"
done
echo "ok: sandboxed build, outputs identical to the command line's"

# rock_normal.png stays in the workspace, only undeclared: the sandbox must hide it from the action.
sed -i '/rock_normal.png/d' "$ws/BUILD"
[ -f "$ws/materials/textures/rock_normal.png" ] || fail "rock_normal.png is missing from the workspace"
! bazel_build || { cat "$work/log"; fail "the build with an undeclared texture succeeded"; }
grep -q "texture file not found: materials/textures/rock_normal.png" "$work/log" || { cat "$work/log"; fail "the build failed for another reason"; }
echo "ok: an undeclared texture fails the build: $(grep -o 'error\[HX.*' "$work/log")"
