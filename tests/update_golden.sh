#!/usr/bin/env bash
# Regenerates every golden folder tests/golden/<name>/ (hexc run with the arguments in its args file) through the
# golden test itself, so they are written exactly as it compares them. Run after an intended change to codegen, the
# library, templates or backends, then review the diff like any other change. BUILD: the build folder (default build).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build}
cmake --build "$build" --target hexc hexc-tests
HEXC_UPDATE_GOLDEN=1 "$build/tests/hexc-tests" --gtest_filter='Features/Golden.*' --gtest_brief=1
echo "golden outputs regenerated in tests/golden/"
