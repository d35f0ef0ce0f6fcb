#!/usr/bin/env bash
# Regenerates tests/golden/<material>/ from the example materials with the built hexc.
# Run after an intended change to codegen or templates, then review the diff like any other change.
set -euo pipefail
cd "$(dirname "$0")/.."
hexc=${HEXC:-build/hexc}
for m in rock tiles rock_normal; do
  rm -rf "tests/golden/$m"
  "$hexc" -q "materials/$m.json" -o "tests/golden/$m"
  rm -f "tests/golden/$m/.$m.hexc-stamp"  # the incremental-build stamp is not an output
done
echo "golden outputs regenerated in tests/golden/"
