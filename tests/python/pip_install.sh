#!/bin/sh
# `pip install --no-build-isolation --no-index .` of the source tree into a fresh virtual environment (Debian's numpy,
# setuptools and pybind11 through --system-site-packages), reusing the build folder BUILD (setup.py's HEXC_BUILD_DIR),
# then the installed package, not the tree's or the build folder's, compiles rock.json to the command line's files.
#   pip_install.sh SOURCE BUILD WORK   (CTest python_pip)
set -eu
source=$1 build=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
start=$(date +%s)
HEXC_BUILD_DIR="$build" "$work/venv/bin/pip" install --quiet --no-build-isolation --no-index "$source"
echo "pip install: $(($(date +%s) - start)) s"
cd "$work"
"$build/hexc" "$source/materials/rock.json" -o cli --no-cache -q
venv/bin/python - "$source/materials/rock.json" <<'PY'
import os, sys
import hexc
here = os.path.realpath("venv")
assert os.path.realpath(hexc.__file__).startswith(here), "hexc imported from %s, not the environment" % hexc.__file__
files = hexc.Context("").compile(sys.argv[1]).files
cli = {name: open(os.path.join("cli", name), "rb").read() for name in os.listdir("cli") if not name.startswith(".")}
assert {n: d if isinstance(d, bytes) else d.encode() for n, d in files.items()} == cli, sorted(files)
print("installed hexc %s compiles rock.json to the command line's %d files" % (hexc.__version__, len(cli)))
PY
