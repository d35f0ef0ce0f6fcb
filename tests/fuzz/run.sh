#!/usr/bin/env bash
# Runs each libFuzzer target (or those named) for SECONDS (default 60) from a build configured with clang and -DHEXC_FUZZ=ON:
#   tests/fuzz/run.sh build-asan 60      (300 or more for a longer run: docs/verification.md)
#   tests/fuzz/run.sh build-asan 60 mtlx texture
# Seeds: the example, invalid and scene materials (parse, compile), the MaterialX documents (mtlx), the built-in
# templates (template) and one byte per container (texture: KTX2, DDS, EXR), plus the corpus each target grew in earlier runs
# (BUILD/fuzz-corpus/TARGET). A crash stops the run with the
# input saved as BUILD/fuzz-artifacts/TARGET/crash-*; add it to tests/fuzz/regressions/TARGET/ once fixed.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:?usage: tests/fuzz/run.sh BUILD_DIR [SECONDS [TARGET...]]}
seconds=${2:-60}
targets=("${@:3}")
[ ${#targets[@]} -gt 0 ] || targets=(parse mtlx compile template texture json_text)
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
    # A KTX2 array of two 2x2 RGBA8 layers: the header after the magic (vkFormat 37, typeSize 1, 2x2, depth 0, 2 layers,
    # 1 face, 1 level, no supercompression), 32 bytes of unused offsets, level 0 at byte 104, 32 bytes long; its texels.
    { printf '\000\045\0\0\0\001\0\0\0\002\0\0\0\002\0\0\0\0\0\0\0\002\0\0\0\001\0\0\0\001\0\0\0\0\0\0\0'
      head -c 32 /dev/zero
      printf '\150\0\0\0\0\0\0\0\040\0\0\0\0\0\0\0\040\0\0\0\0\0\0\0'
      printf '%032d' 0; } > "$seeds/ktx2_array"
    printf '\002' > "$seeds/exr"
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
  if ! "$build/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -dict="$dict" -max_len="$max_len" -len_control="$len_control" \
      -rss_limit_mb=4096 -timeout=30 -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus" "$seeds" > "$log" 2>&1; then
    tail -n 60 "$log"
    echo "fuzz_$target failed: the input is in $artifacts/" >&2
    exit 1
  fi
  grep -E '^stat::(number_of_executed_units|peak_rss_mb)' "$log" | sed "s/^/fuzz_$target /"  # named: targets may run side by side
done
