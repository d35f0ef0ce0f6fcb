#!/usr/bin/env bash
# The Debian package, installed from BUILD (`apt-get install ./BUILD/hexc_<version>-1_amd64.deb`, .ci/test's stage
# "Debian package: build, install"): what `dpkg -L hexc` lists, Debian policy's parts (tests/package/policy.py: the
# control fields, the copyright file, changelog.Debian.gz, stripped files, Depends), and hexc, `import hexc` and
# docs/c-api.md's C program used from /usr as a reader does, in a fresh folder with an empty environment (no build
# tree on PATH or anywhere in it), and libhexc.a without wasm2c's runtime names. Negative controls: a listing without
# any one required file is refused, each policy check refuses a wrong variant (BUILD's hexc is the unstripped one),
# wabt's libwasm-rt-impl.a has wasm2c's runtime names, `import hexc` without the site folders (python3 -S) fails, so
# the module comes from dist-packages, and tests/package/prefix.sh refuses a hexc of another build.
#   tests/package/installed.sh BUILD
set -euo pipefail
cd "$(dirname "$0")/../.."
build=$(realpath "$1")
version=$(sed -n 's/^project(hexc VERSION \([0-9.]*\) .*/\1/p' CMakeLists.txt)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "package: $*" >&2; exit 1; }
# A command as a reader runs it: Debian's PATH only, HOME a fresh folder, nothing else.
clean() { env -i PATH=/usr/bin:/bin HOME="$work/home" "$@"; }
mkdir -p "$work/home" "$work/reader"
cp -r materials "$work/reader/"

# What the package must hold, as patterns of `dpkg -L hexc`'s lines; prints those a listing (stdin) lacks.
required=(
  /usr/bin/hexc
  /usr/share/man/man1/hexc.1.gz
  '/usr/lib/(.*/)?cmake/hexc/hexcConfig.cmake' '/usr/lib/(.*/)?cmake/hexc/hexcMaterials.cmake'
  '/usr/lib/(.*/)?libhexc.a' /usr/include/hexc/hexc.h /usr/include/hexc/compiler.h
  /usr/lib/python3/dist-packages/hexc/__init__.py '/usr/lib/python3/dist-packages/hexc/_hexc.cpython-.*.so'
  /usr/share/hexc/bazel/hexc.bzl /usr/share/hexc/material.schema.json
  /usr/share/doc/hexc/README.md /usr/share/doc/hexc/docs/build-integration.md
  /usr/share/doc/hexc/copyright /usr/share/doc/hexc/changelog.Debian.gz
)
lacks() {
  local listing
  listing=$(cat)
  for pattern in "${required[@]}"; do grep -qxE "$pattern" <<< "$listing" || echo "$pattern"; done
}
listing=$(dpkg -L hexc) || fail "hexc is not installed"
missing=$(lacks <<< "$listing")
[ -z "$missing" ] || fail "dpkg -L hexc lacks: $missing"
for pattern in "${required[@]}"; do  # the negative control: each file taken out is missed
  [ "$(grep -vxE "$pattern" <<< "$listing" | lacks)" = "$pattern" ] || fail "a listing without $pattern passes"
done
echo "ok: dpkg -L hexc lists its ${#required[@]} required files; a listing without any one of them is refused"

python3 tests/package/policy.py / <(dpkg -s hexc) --controls "$build" <<< "$listing" || fail "Debian policy (above)"

# libhexc.a's wasm2c runtime (naga's) is under names of its own: a program that links libhexc.a and a wasm2c runtime
# of its own would otherwise define wasm_rt_* twice. Negative control: wabt's runtime, libwasm-rt-impl.a, is found out.
wasm_rt() { nm -g --defined-only "$1" 2> /dev/null | grep -E ' [[:alpha:]] wasm_rt_' || true; }
library=$(grep -xE '/usr/lib/(.*/)?libhexc.a' <<< "$listing")
[ -z "$(wasm_rt "$library")" ] || fail "$library defines wasm2c's runtime names: $(wasm_rt "$library" | head -3 | xargs)"
wabt=$(dpkg -L wabt 2> /dev/null | grep '/libwasm-rt-impl\.a$') || fail "no libwasm-rt-impl.a (Debian's wabt) to check the check"
[ -n "$(wasm_rt "$wabt")" ] || fail "the check finds no wasm_rt_* name in $wabt"
echo "ok: $library defines no wasm_rt_* name (the check finds $(wasm_rt "$wabt" | wc -l) in $wabt)"

# hexc from /usr/bin, this build's and the project's version.
[ "$(clean sh -c 'command -v hexc')" = /usr/bin/hexc ] || fail "hexc is not /usr/bin/hexc on Debian's PATH"
[ "$(clean hexc --version)" = "$("$build/hexc" --version)" ] || fail "/usr/bin/hexc is not $build/hexc"
[[ $(clean hexc --version | head -1) == "hexc $version "* ]] || fail "hexc --version does not say $version"
(cd "$work/reader" && clean hexc materials/rock.json -o out/ -q) || fail "hexc materials/rock.json -o out/ failed"
for f in rock.frag.spv rock.frag.hlsl rock.frag.glsl rock.frag.metal rock.manifest.json; do
  [ -s "$work/reader/out/$f" ] || fail "hexc materials/rock.json -o out/ did not write $f"
done
echo "ok: $(clean hexc --version | head -1) from /usr/bin compiles materials/rock.json"

# import hexc with Debian's Python, from dist-packages: nothing on PYTHONPATH, not found in the folder.
(cd "$work/reader" && ! clean python3 -S -c "import hexc" 2> /dev/null) || fail "import hexc works without site folders"
got=$(cd "$work/reader" && clean python3 -c "import hexc
print(hexc.__file__, hexc.__version__, ' '.join(sorted(hexc.compile('materials/rock.json').files)))") ||
  fail "python3 -c 'import hexc; ...' failed"
read -r file module_version files <<< "$got"
[ "$file" = /usr/lib/python3/dist-packages/hexc/__init__.py ] || fail "import hexc found $file"
[ "$module_version" = "$version" ] || fail "hexc.__version__ is $module_version, not $version"
[[ " $files " == *" rock.frag.spv "* ]] || fail "hexc.compile('materials/rock.json') gave [$files]"
echo "ok: import hexc from $file (version $module_version; python3 -S does not find it), compiles rock: $files"

# docs/c-api.md's program, with the CMakeLists.txt its comment gives, found in /usr without CMAKE_PREFIX_PATH.
c=$work/c_example
mkdir -p "$c"
sed -n '/^```c file=hexc_example.c$/,/^```$/p' docs/c-api.md | sed '1d;$d' > "$c/hexc_example.c"
sed -n '/beside it:$/,/^ \* then:/s/^ \*   //p' "$c/hexc_example.c" > "$c/CMakeLists.txt"
grep -q "find_package(hexc" "$c/CMakeLists.txt" || fail "no CMakeLists.txt in docs/c-api.md's program"
clean cmake -S "$c" -B "$c/build" > "$work/log" 2>&1 || { cat "$work/log"; fail "configuring docs/c-api.md's program failed"; }
found=$(sed -n 's/^hexc_DIR:PATH=//p' "$c/build/CMakeCache.txt")
[[ $found == /usr/lib/* ]] || fail "CMake found hexc in $found"
clean cmake --build "$c/build" > "$work/log" 2>&1 || { cat "$work/log"; fail "building docs/c-api.md's program failed"; }
mkdir -p "$work/reader/c_out"
(cd "$work/reader" && clean "$c/build/hexc_example" materials/rock.json c_out > /dev/null) || fail "hexc_example failed"
cmp "$work/reader/c_out/rock.frag.spv" "$work/reader/out/rock.frag.spv" || fail "the C API's rock.frag.spv is not hexc's"
echo "ok: docs/c-api.md's C program builds against $found and writes hexc's rock.frag.spv"

# The tests that then use this package (HEXC_INSTALLED_PREFIX=/usr) take it as this build's, and would refuse
# another build's hexc: a stand-in printing another build identity is refused.
[ "$(HEXC_INSTALLED_PREFIX=/usr tests/package/prefix.sh "$build" "$work/unused")" = /usr ] || fail "prefix.sh refuses /usr"
mkdir -p "$work/other/bin"
printf '#!/bin/sh\necho "hexc %s (build 0000000000000000)"\n' "$version" > "$work/other/bin/hexc"
chmod +x "$work/other/bin/hexc"
! HEXC_INSTALLED_PREFIX=$work/other tests/package/prefix.sh "$build" "$work/unused" 2> /dev/null ||
  fail "prefix.sh takes another build's hexc"
echo "ok: tests/package/prefix.sh takes /usr as this build's hexc and refuses another build's"
