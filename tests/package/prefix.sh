#!/usr/bin/env bash
# The hexc the consumer, Bazel and docs tests use, by its install prefix, printed: the one installed in
# $HEXC_INSTALLED_PREFIX when it is set (CI: /usr, where the Debian package installed it), else BUILD installed into
# DIR, a fresh prefix (`cmake --install --strip`: no root needed; stripped as the package is, so that both are the same
# files and the Bazel remote cache test's two machines share its actions). An installed hexc must be BUILD's own (the
# same `hexc --version`, build identity included), so that a package left from another build is not what gets tested.
#   tests/package/prefix.sh BUILD DIR
set -euo pipefail
build=$(realpath "$1") dir=$2
if [ -z "${HEXC_INSTALLED_PREFIX:-}" ]; then
  cmake --install "$build" --prefix "$dir" --strip > /dev/null
  echo "$dir"
  exit 0
fi
prefix=$HEXC_INSTALLED_PREFIX
[ -x "$prefix/bin/hexc" ] || { echo "HEXC_INSTALLED_PREFIX=$prefix: no $prefix/bin/hexc" >&2; exit 1; }
if [ "$("$prefix/bin/hexc" --version)" != "$("$build/hexc" --version)" ]; then
  echo "HEXC_INSTALLED_PREFIX=$prefix: $prefix/bin/hexc is not $build/hexc ($("$prefix/bin/hexc" --version | head -1)," \
    "not $("$build/hexc" --version | head -1)): install the package made from $build" >&2
  exit 1
fi
echo "$prefix"
