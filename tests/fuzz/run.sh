#!/usr/bin/env bash
# Runs each libFuzzer target (or those named) for SECONDS (default 60) from a build configured with clang and -DHEXC_FUZZ=ON:
#   tests/fuzz/run.sh build-asan 60      (300 or more for a longer run: docs/verification.md)
#   tests/fuzz/run.sh build-asan 60 mtlx texture
# Seeds: the example, invalid and scene materials (parse, compile), the MaterialX documents (mtlx), the built-in
# templates (template), one byte per container (texture: KTX2, DDS, EXR), the example terrain and two layers reading KTX2
# arrays (layers), plus the corpus each target grew in earlier runs
# (BUILD/fuzz-corpus/TARGET). A crash stops the run with the
# input saved as BUILD/fuzz-artifacts/TARGET/crash-*; add it to tests/fuzz/regressions/TARGET/ once fixed.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:?usage: tests/fuzz/run.sh BUILD_DIR [SECONDS [TARGET...]]}
seconds=${2:-60}
targets=("${@:3}")
[ ${#targets[@]} -gt 0 ] || targets=(parse mtlx compile template texture json_text layers)
# A KTX2 array of two 2x2 RGBA8 layers of vkFormat $1 (octal: 045 UNORM, 053 sRGB): the magic, the header (typeSize 1,
# 2x2, depth 0, 2 layers, 1 face, 1 level, no supercompression), 32 bytes of unused offsets, level 0 at byte 104,
# 32 bytes long; its texels.
ktx2_array() {
  printf '\253KTX 20\273\r\n\032\n\'"$1"'\0\0\0\001\0\0\0\002\0\0\0\002\0\0\0\0\0\0\0\002\0\0\0\001\0\0\0\001\0\0\0\0\0\0\0'
  head -c 32 /dev/zero
  printf '\150\0\0\0\0\0\0\0\040\0\0\0\0\0\0\0\040\0\0\0\0\0\0\0'
  printf '%032d' "$2"
}
for target in "${targets[@]}"; do
  corpus=$build/fuzz-corpus/$target seeds=$build/fuzz-seeds/$target artifacts=$build/fuzz-artifacts/$target
  mkdir -p "$corpus" "$seeds" "$artifacts"
  if [ "$target" = template ]; then
    cp templates/builtin/*.glsl "$seeds"/
  elif [ "$target" = mtlx ]; then
    cp materials/mtlx/*.mtlx materials/mtlx/invalid/*.mtlx "$seeds"/
  elif [ "$target" = json_text ]; then
    for m in materials/*.json; do { cat "$m"; printf '\000'; cat "$m"; } > "$seeds/$(basename "$m")"; done  # a file, NUL, its edit
  elif [ "$target" = texture ]; then
    printf '\000' > "$seeds/ktx2" && printf '\001' > "$seeds/dds"  # the container's magic is added by the target
    { printf '\000'; ktx2_array 045 0 | tail -c +13; } > "$seeds/ktx2_array"  # the target adds the magic: 0 picks KTX2
    printf '\002' > "$seeds/exr"
  elif [ "$target" = layers ]; then
    { cat materials/terrain/terrain.json; printf '\000'; } > "$seeds/terrain"  # the example's own textures
    # Two layers whose roles read KTX2 arrays f0 (sRGB albedo), f1 (normal), f2 (height in alpha), weighed by a splat
    # map f3: a 2x2 RGBA TGA, top row first. Files separated as the target splits them.
    layer() {
      printf '{"name":"%s","slots":[{"name":"albedo","kind":"color","texture":"f0","layer":%d},' "$1" "$2"
      printf '{"name":"normal","kind":"normal","texture":"f1","layer":%d},' "$2"
      printf '{"name":"height","kind":"scalar","channel":"a","texture":"f2","layer":%d}]}' "$2"
    }
    { printf '{"name":"arrays","layers":[%s,%s],' "$(layer grass 0)" "$(layer sand 1)"
      printf '"layer_blend":{"splat":["f3"],"mode":"height","height":"height","width":0.2}}\000'
      ktx2_array 053 1; printf '@@HEXC@@'; ktx2_array 045 2; printf '@@HEXC@@'; ktx2_array 045 3; printf '@@HEXC@@'
      printf '\0\0\002\0\0\0\0\0\0\0\0\0\002\0\002\0\040\050'
      printf '\377\0\0\0\0\377\0\0\200\200\0\0\0\0\377\0'; } > "$seeds/arrays"
  else
    cp materials/*.json materials/invalid/*.json materials/scenes/*.json "$seeds"/
  fi
  echo "fuzz_$target: ${seconds} s"
  # -rss_limit_mb: hexc's inputs are capped; a run that needs more is a finding. -timeout: one input, seconds.
  log=$build/fuzz-$target.log
  dict=tests/fuzz/material.dict max_len=16384 len_control=100
  # MaterialX documents need room to be slow: quadratic locating showed only past tens of KB. libFuzzer's length
  # control would take longer than a run to let inputs grow that far (6 KB after 300 s): off for mtlx.
  [ "$target" = mtlx ] && dict=tests/fuzz/mtlx.dict max_len=65536 len_control=0
  [ "$target" = layers ] && dict=tests/fuzz/layers.dict
  if ! "$build/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -dict="$dict" -max_len="$max_len" -len_control="$len_control" \
      -rss_limit_mb=4096 -timeout=30 -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus" "$seeds" > "$log" 2>&1; then
    tail -n 60 "$log"
    echo "fuzz_$target failed: the input is in $artifacts/" >&2
    exit 1
  fi
  grep -E '^stat::(number_of_executed_units|peak_rss_mb)' "$log" | sed "s/^/fuzz_$target /"  # named: targets may run side by side
done
