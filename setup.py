"""`pip install --no-build-isolation .` from hexc's source tree (docs/python.md): CMake builds the extension hexc._hexc
(compiler/integrations/python) and setuptools installs it with the package's Python files.

The CMake build folder is HEXC_BUILD_DIR when set (one configured already: only what changed is built), else
build/pip under the tree, configured on the first install and reused by the next. setuptools' own files go beside it.
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
PACKAGE = "compiler/integrations/python/hexc"
VERSION = re.search(r"project\(hexc VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)
BUILD = pathlib.Path(os.environ.get("HEXC_BUILD_DIR") or ROOT / "build" / "pip").resolve()
BUILD.mkdir(parents=True, exist_ok=True)  # setuptools writes its metadata there before the extension is built


class CMakeBuild(build_ext):
    """Builds the extension with CMake instead of compiling sources itself."""

    def build_extension(self, ext):
        if not (BUILD / "CMakeCache.txt").exists():
            configure = ["cmake", "-S", str(ROOT), "-B", str(BUILD), "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF",
                         "-DHEXC_BENCH=OFF", "-DHEXC_PYTHON3=" + sys.executable]
            configure += ["-G", "Ninja"] if shutil.which("ninja") else []
            if shutil.which("ccache"):
                configure += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
            subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(BUILD), "--target", "hexc_python", "--parallel"], check=True)
        built = BUILD / "python" / "hexc" / ("_hexc" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.exists():
            found = sorted(p.name for p in built.parent.glob("_hexc*"))
            raise RuntimeError("%s has no %s for this Python (%s), but %s: configure it with -DHEXC_PYTHON3=%s"
                               % (BUILD, built.name, sys.version.split()[0], found or "nothing", sys.executable))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    name="hexc",
    version=VERSION,
    description="hexc, the hex-tiling material compiler, in process",
    python_requires=">=3.9",
    install_requires=["numpy"],
    packages=["hexc"],
    package_dir={"hexc": PACKAGE},
    package_data={"hexc": ["*.pyi", "py.typed"]},
    ext_modules=[Extension("hexc._hexc", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(BUILD / "setuptools")}, "egg_info": {"egg_base": str(BUILD)}},
    zip_safe=False,
)
