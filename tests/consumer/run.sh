#!/usr/bin/env bash
# The consumer test: installs hexc from BUILD into a fresh prefix, builds tests/consumer/project against the
# installed package with GENERATOR, and checks what each edit rebuilds (counted from the rules' "hexc: compiling"
# lines):
#   tests/consumer/run.sh BUILD "Ninja"|"Unix Makefiles"
set -euo pipefail
cd "$(dirname "$0")/../.."
build=$(realpath "$1") generator=$2
work=$build/consumer/${generator// /_}
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > /dev/null

src=$work/src
cp -r tests/consumer/project "$src"
mkdir -p "$src/materials/textures"
cp materials/textures/rock_albedo.png "$src/materials/textures/stone.png"
cp materials/textures/tiles_albedo.png "$src/materials/textures/moss.png"
material() {  # NAME TEXTURE TILING
  printf '{"name": "%s", "template": "unlit", "hextiling": {"tiling": %s},\n "slots": [{"name": "albedo", "kind": "color", "texture": "textures/%s"}]}\n' \
    "$1" "$3" "$2" > "$src/materials/$1.json"
}
material stone stone.png 4
material moss moss.png 3
mtlx() {  # TILING: slate, a MaterialX document (docs/materialx.md)
  cat > "$src/materials/slate.mtlx" <<EOF
<?xml version="1.0"?>
<materialx version="1.39">
  <hextiledimage name="slate_albedo" type="color3">
    <input name="file" type="filename" value="textures/stone.png" colorspace="srgb_texture" />
    <input name="tiling" type="vector2" value="$1" />
  </hextiledimage>
  <standard_surface name="slate_surface" type="surfaceshader">
    <input name="base_color" type="color3" nodename="slate_albedo" />
  </standard_surface>
  <surfacematerial name="slate" type="material" hexc_template="unlit">
    <input name="surfaceshader" type="surfaceshader" nodename="slate_surface" />
  </surfacematerial>
</materialx>
EOF
}
mtlx "2, 2"

fail() { echo "consumer ($generator): $*" >&2; exit 1; }
# Builds and checks which materials hexc compiled: expect NAME... (none for a no-op).
expect() {
  cmake --build "$work/bin" > "$work/log" 2>&1 || { cat "$work/log"; fail "build failed"; }
  got=$(sed -n 's/.*hexc: compiling \([a-z]*\).*/\1/p' "$work/log" | sort | xargs)
  [ "$got" = "$*" ] || { cat "$work/log"; fail "$step: expected hexc to compile [$*], it compiled [$got]"; }
  echo "ok: $step: [$got]"
}

cmake -S "$src" -B "$work/bin" -G "$generator" -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log" || { cat "$work/configure.log"; fail "configure failed"; }
step="first build" expect moss slate stone
for f in moss.manifest.json moss.frag.spv moss.frag.hlsl moss.frag.metal stone.frag.spv slate.frag.spv; do
  [ -s "$work/bin/shaders/$f" ] || fail "first build: shaders/$f missing"
done
[ ! -e "$work/bin/shaders/moss.frag.glsl" ] || fail "TARGETS spirv hlsl msl wrote a .glsl"
step="no-op rebuild" expect

material stone stone.png 5
step="edited stone.json" expect stone

mtlx "3, 3"
step="edited slate.mtlx" expect slate

rm "$work/bin/shaders/moss.frag.hlsl"
step="deleted moss.frag.hlsl" expect moss
[ -s "$work/bin/shaders/moss.frag.hlsl" ] || fail "moss.frag.hlsl was not regenerated"

# Another size: the shaders read a texture's size, so the material that reads it rebuilds, and only that one.
cp materials/textures/rock_height.png "$src/materials/textures/moss.png"
step="moss.png replaced" expect moss

# Touched, not changed: hexc may run once (its stamp says the shaders stand) and must leave the build settled.
touch "$src/materials/textures/moss.png"
cmake --build "$work/bin" > "$work/log" 2>&1 || { cat "$work/log"; fail "build after touching moss.png failed"; }
step="moss.png touched, built again" expect

# A renamed texture: the material names the new file; the old one is gone (no "No rule to make target").
mv "$src/materials/textures/moss.png" "$src/materials/textures/moss2.png"
material moss moss2.png 3
step="moss.png renamed" expect moss
# Ninja settles at once. CMake 3.25's Makefile generator merges each depfile into its own dependency list
# (compiler_depend.make) and keeps the old texture there, so Make re-runs the rule on later builds; hexc then
# finds its stamp up to date and compiles nothing (docs/build-integration.md says so).
if [ "$generator" = Ninja ]; then step="after the rename" expect; fi

"$work/bin/compile_one" "$src/materials/stone.json" > "$work/compiled" || fail "compile_one failed"
grep -qx stone.frag.spv "$work/compiled" || fail "compile_one (hexc::compiler) did not compile stone: $(cat "$work/compiled")"
echo "ok: hexc::compiler links and compiles"
