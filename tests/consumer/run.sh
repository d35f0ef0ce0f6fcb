#!/usr/bin/env bash
# The consumer test: installs hexc from BUILD into a fresh prefix (or takes the one in $HEXC_INSTALLED_PREFIX,
# tests/package/prefix.sh), builds tests/consumer/project (an asset-only
# project, LANGUAGES NONE) against the installed package with GENERATOR, and checks what each edit rebuilds
# (counted from the rules' "hexc: compiling" lines) and that every build is clean; then builds
# tests/consumer/library, which asks for the library component:
#   tests/consumer/run.sh BUILD "Ninja"|"Unix Makefiles"
set -euo pipefail
cd "$(dirname "$0")/../.."
build=$(realpath "$1") generator=$2
work=$build/consumer/${generator// /_}
rm -rf "$work" && mkdir -p "$work"
prefix=$(tests/package/prefix.sh "$build" "$work/prefix")

src=$work/src
cp -r tests/consumer/project "$src"
tex=$src/materials/textures
mkdir -p "$tex"
cp materials/textures/rock_albedo.png "$tex/stone.png"
cp materials/textures/tiles_albedo.png "$tex/moss.png"
cp materials/textures/rock_albedo.png "$tex/gravel.png"
cp materials/textures/rock_roughness.png "$tex/gravel_r.png"
cp materials/textures/tiles_albedo.png "$tex/crate.png"
cp materials/textures/rock_roughness.png "$tex/crate_r.png"
cp materials/textures/tiles_albedo.png "$tex/pebble.png"
slot() { printf '{"name": "%s", "kind": "%s", "texture": "textures/%s"}' "$@"; }
material() {  # NAME TEXTURE TILING: unlit, one colour slot
  printf '{"name": "%s", "template": "unlit", "hextiling": {"tiling": %s},\n "slots": [%s]}\n' "$1" "$3" "$(slot albedo color "$2")" \
    > "$src/materials/$1.json"
}
material stone stone.png 4
material moss moss.png 3
material pebble pebble.png 2
gravel() {  # SLOTS...: histogram blend, each slot's tables written (lit reads albedo and roughness)
  printf '{"name": "gravel", "template": "lit", "hextiling": {"blend": "histogram"}, "slots": [%s]}\n' "$(IFS=,; echo "$*")" \
    > "$src/materials/gravel.json"
}
gravel "$(slot albedo color gravel.png)" "$(slot roughness scalar gravel_r.png)"
printf '{"name": "crate", "template": "lit", "pack": true, "slots": [%s, %s]}\n' "$(slot albedo color crate.png)" \
  "$(slot roughness scalar crate_r.png)" > "$src/materials/crate.json"
printf '{"scene": "yard", "materials": ["stone.json", "moss.json"],\n "passes": [{"name": "main"}, {"name": "depth", "template": "depth", "slots": []}]}\n' \
  > "$src/materials/yard.json"
mtlx() {  # TILING: slate, a MaterialX document (docs/materialx.md)
  cat > "$src/materials/slate.mtlx" <<MTLX
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
MTLX
}
mtlx "2, 2"
fail() { echo "consumer ($generator): $*" >&2; exit 1; }
out=$work/bin
# Builds and checks which files' rules ran hexc: expect NAME... (none for a no-op). Every build is clean: no error
# and no warning, from hexc, CMake (a re-configure) or the build tool.
expect() {
  cmake --build "$out" > "$work/log" 2>&1 || { cat "$work/log"; fail "$step: build failed"; }
  ! grep -i "warning\|error" "$work/log" || fail "$step: the build printed the lines above"
  got=$(sed -n 's/.*hexc: compiling \([a-z]*\).*/\1/p' "$work/log" | sort | xargs)
  [ "$got" = "$*" ] || { cat "$work/log"; fail "$step: expected hexc to run for [$*], it ran for [$got]"; }
  echo "ok: $step: [$got]"
}
# A file's hash, to tell rewritten bytes from refreshed times.
sum() { sha256sum "$out/$1" | cut -d' ' -f1; }

cmake -S "$src" -B "$out" -G "$generator" -DCMAKE_PREFIX_PATH="$prefix" > "$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; fail "configure failed"; }
! grep -i "warning" "$work/configure.log" || fail "the configure step printed warnings"
# The package under test, not another hexc CMake finds (a Debian package's /usr/lib/cmake/hexc).
found_in_prefix() {  # BUILD_FOLDER
  local found
  found=$(realpath "$(sed -n 's/^hexc_DIR:PATH=//p' "$1/CMakeCache.txt")")
  [[ $found == "$(realpath "$prefix")"/* ]] || fail "CMake found hexc in $found, not in $prefix"
}
found_in_prefix "$out"
step="first build" expect crate gravel moss pebble slate stone yard
for f in shaders/{moss.manifest.json,moss.frag.spv,moss.frag.hlsl,moss.frag.metal,stone.frag.spv,slate.frag.spv} \
  shaders/gravel.{albedo,roughness}.{gaussian,lut}.pfm shaders/crate.albedo.packed.png vertex/pebble.{frag,vert}.glsl \
  scene/yard.scene.json scene/{stone,moss}.{main,depth}.frag.spv bundle.txt; do
  [ -s "$out/$f" ] || fail "first build: $f missing"
done
[ ! -e "$out/shaders/moss.frag.glsl" ] || fail "TARGETS spirv hlsl msl wrote a .glsl"
step="no-op rebuild" expect
if [ "$generator" = Ninja ]; then
  grep -q "ninja: no work to do" "$work/log" || { cat "$work/log"; fail "the no-op build did some work"; }
fi

# New pixels, same size: the histogram tables and the packed texture are derived again, the shaders keep their bytes;
# a plain material's rule runs (its texture is newer) but hexc compiles nothing (its stamp is not rewritten).
shaders_before=$(sum shaders/gravel.frag.spv)$(sum shaders/crate.frag.hlsl)
lut_before=$(sum shaders/gravel.albedo.lut.pfm) packed_before=$(sum shaders/crate.albedo.packed.png)
pebble_stamp=$(stat -c %y "$out/vertex/.pebble.hexc-stamp")  # written only when hexc compiles
cp materials/textures/tiles_albedo.png "$tex/gravel.png"
cp materials/textures/rock_height.png "$tex/crate_r.png"
cp materials/textures/rock_albedo.png "$tex/pebble.png"
step="pixels edited" expect crate gravel pebble
[ "$(sum shaders/gravel.frag.spv)$(sum shaders/crate.frag.hlsl)" = "$shaders_before" ] || fail "new pixels changed the shaders"
[ "$(sum shaders/gravel.albedo.lut.pfm)" != "$lut_before" ] || fail "gravel's look-up table was not derived again"
[ "$(sum shaders/crate.albedo.packed.png)" != "$packed_before" ] || fail "crate's packed texture was not derived again"
[ "$(stat -c %y "$out/vertex/.pebble.hexc-stamp")" = "$pebble_stamp" ] || fail "hexc compiled pebble for new pixels"
step="after the pixel edit" expect

material stone stone.png 5
step="edited stone.json (also in the scene)" expect stone yard

mtlx "3, 3"
step="edited slate.mtlx" expect slate

# The outputs the first issue was about: a histogram table and a packed texture, deleted.
rm "$out/shaders/gravel.albedo.lut.pfm" "$out/shaders/crate.albedo.packed.png" "$out/vertex/pebble.vert.glsl"
step="deleted a table, a packed texture and a vertex stage" expect crate gravel pebble
for f in shaders/gravel.albedo.lut.pfm shaders/crate.albedo.packed.png vertex/pebble.vert.glsl; do
  [ -s "$out/$f" ] || fail "$f was not regenerated"
done

# Another size: the shaders read a texture's size, so the files that read it rebuild (moss and the scene), only they.
moss_stamp=$(sum shaders/.moss.hexc-stamp)
tests/consumer/png.py "$tex/moss.png" 97 61 1
step="moss.png resized" expect moss yard
[ "$(sum shaders/.moss.hexc-stamp)" != "$moss_stamp" ] || fail "hexc did not compile moss for its texture's new size"

# A slot removed: its tables go, from the folder and from the declared outputs.
gravel "$(slot albedo color gravel.png)"
step="gravel's roughness slot removed" expect gravel
for f in shaders/gravel.roughness.{gaussian,lut}.pfm; do [ ! -e "$out/$f" ] || fail "stale $f left behind"; done
[ "$(ls "$out/hexc/shaders/" | grep -c '^gravel\.json\.')" = 1 ] || fail "the depfile of gravel's earlier outputs was left behind"
step="after the slot removal" expect

# Touched, not changed: hexc may run once (its stamp says the shaders stand) and must leave the build settled.
touch "$tex/moss.png"
cmake --build "$out" > "$work/log" 2>&1 || { cat "$work/log"; fail "build after touching moss.png failed"; }
step="moss.png touched, built again" expect

# A renamed texture: the material names the new file; the old one is gone (no "No rule to make target").
cp "$tex/moss.png" "$tex/moss2.png"
material moss moss2.png 3
step="moss.png renamed" expect moss yard
# Ninja settles at once. CMake 3.25's Makefile generator merges each depfile into its own dependency list
# (compiler_depend.make) and keeps the old texture there, so Make re-runs the rule on later builds; hexc then
# finds its stamp up to date and compiles nothing (docs/build-integration.md says so).
if [ "$generator" = Ninja ]; then step="after the rename" expect; fi

# A material hexc cannot read: the re-configure stops with hexc's located diagnostic; fixed, the build settles.
good=$(cat "$src/materials/moss.json")
sed -i 's/"kind": "color"/"kind": "colour"/' "$src/materials/moss.json"
! cmake --build "$out" > "$work/log" 2>&1 || { cat "$work/log"; fail "a build with an invalid moss.json succeeded"; }
grep -q 'moss.json:2:.*error\[HX107\]: /slots/0/kind: .*did you mean `color`' "$work/log" || { cat "$work/log"; fail "no located diagnostic"; }
echo "$good" > "$src/materials/moss.json"
step="moss.json broken and fixed" expect moss yard

# The library component, in a project of its own (it needs a C++ compiler), with docs/c-api.md's C program as written.
sed -n '/^```c file=hexc_example.c$/,/^```$/p' docs/c-api.md | sed '1d;$d' > "$work/hexc_example.c"
cmake -S tests/consumer/library -B "$work/library" -G "$generator" -DCMAKE_PREFIX_PATH="$prefix" \
  -DC_EXAMPLE="$work/hexc_example.c" > "$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; fail "configuring the library consumer failed"; }
found_in_prefix "$work/library"
cmake --build "$work/library" > "$work/log" 2>&1 || { cat "$work/log"; fail "building compile_one failed"; }
"$work/library/compile_one" "$src/materials/stone.json" > "$work/compiled" || fail "compile_one failed"
grep -qx stone.frag.spv "$work/compiled" || fail "compile_one (hexc::compiler) did not compile stone: $(cat "$work/compiled")"
echo "ok: hexc::compiler (COMPONENTS library) links and compiles"
mkdir -p "$work/c_out"
"$work/library/hexc_example" "$src/materials/stone.json" "$work/c_out" > "$work/compiled" || fail "hexc_example failed"
for f in stone.frag.hlsl stone.frag.spv stone.manifest.json; do
  [ -s "$work/c_out/$f" ] || fail "docs/c-api.md's program did not write $f: $(cat "$work/compiled")"
done
# The same code as the tool's; the banner's two lines name the targets asked for, which differ.
cmp <(tail -n +3 "$work/c_out/stone.frag.hlsl") <(tail -n +3 "$out/shaders/stone.frag.hlsl") ||
  fail "the C API's stone.frag.hlsl differs from the tool's"
! "$work/library/hexc_example" materials/invalid/kind_misspelled.json "$work/c_out" 2> "$work/printed" || fail "a bad material compiled"
grep -q 'kind_misspelled.json:9:15: error\[HX107\]' "$work/printed" || fail "no located diagnostic from the C API: $(cat "$work/printed")"
echo "ok: docs/c-api.md's C program (hexc/hexc.h) builds as C99 against the package, compiles and reports"
