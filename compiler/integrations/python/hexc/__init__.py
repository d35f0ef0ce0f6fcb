"""hexc, the hex-tiling material compiler, in process (docs/python.md).

    import hexc
    result = hexc.compile("materials/rock.json", targets=["hlsl", "spirv"])
    result.files["rock.frag.hlsl"]   # str; SPIR-V and other binary files are bytes
    result.manifest                  # dict
    try:
        hexc.compile({"name": "x"})
    except hexc.CompileError as e:
        for d in e.diagnostics: print(d.code, d.line, d.column, d.path, d.message)

Compiles release the interpreter lock: threads compile at once, sharing a context's shader cache.
"""
from __future__ import annotations

import json
import os
import threading
from dataclasses import dataclass
from typing import Any, Iterable, Mapping, Optional, Union

from . import _hexc

__all__ = ["compile", "material_text", "Context", "Result", "Diagnostic", "CompileError", "__version__", "API_VERSION"]
__version__: str = _hexc.version
API_VERSION: int = _hexc.api_version

# Files a compile writes whose bytes are not text: SPIR-V, derived textures and tables.
_BINARY = (".spv", ".png", ".pfm", ".ktx2", ".exr")


@dataclass(frozen=True)
class Diagnostic:
    """A problem hexc found, located as the command line prints it (`str()` gives that line)."""
    code: str        # "HX104" (docs/cli.md, "Diagnostic codes")
    error: bool      # False: a warning
    file: str
    line: int        # 1-based; 0 when unknown
    column: int
    path: str        # JSON pointer, "/slots/0/kind"; "" when not about a value
    message: str
    fix: str         # what was probably meant; "" when hexc has no guess

    def __str__(self) -> str:
        where = self.file + (":%d:%d" % (self.line, self.column) if self.line else "")
        text = "%s: %s[%s]: %s%s" % (where, "error" if self.error else "warning", self.code,
                                     self.path + ": " if self.path else "", self.message)
        return text + (" (%s)" % self.fix if self.fix else "")


class CompileError(Exception):
    """A material hexc cannot compile; `diagnostics` holds every problem (warnings too), `str()` them as printed."""

    def __init__(self, diagnostics: list[Diagnostic], text: str):
        super().__init__(text.rstrip("\n"))
        self.diagnostics = diagnostics


@dataclass(frozen=True)
class Result:
    """What a compile writes: every file by name, the manifests parsed, and the warnings."""
    files: dict[str, Union[str, bytes]]
    manifests: dict[str, Any]  # each "*.manifest.json" file, parsed
    diagnostics: list[Diagnostic]

    @property
    def manifest(self) -> Optional[dict]:
        """The material's manifest (a compile to targets writes one; a compile to engines one per package)."""
        top = [name for name in self.manifests if "/" not in name]
        return self.manifests[top[0]] if len(top) == 1 else None


def material_text(material: Mapping[str, Any]) -> str:
    """The JSON text a material given as a dict is compiled from: diagnostics' lines and columns count in it. Python's
    json module writes it, so a non-finite float becomes `NaN` or `Infinity`, which hexc reports as JSON does not
    allow them."""
    return json.dumps(material, indent=2, ensure_ascii=False) + "\n"


def _names(value: Union[str, Iterable[str]]) -> str:
    return value if isinstance(value, str) else ",".join(value)


def _options(targets, engines, uv_origin, hlsl_sm, glsl_version, entry, bake, debug, vertex, specialise):
    options = []
    for key, value in (("targets", targets), ("engines", engines)):
        if value is not None:
            options.append((key, _names(value)))
    for key, value in (("uv-origin", uv_origin), ("hlsl-sm", hlsl_sm), ("glsl-version", glsl_version), ("entry", entry)):
        if value is not None:
            options.append((key, str(value)))
    for key, value in (("bake", bake), ("debug", debug), ("vertex", vertex), ("no-specialise", not specialise)):
        options.append((key, "1" if value else "0"))
    return options


def _result(ok: bool, outputs, diagnostics, text: str) -> Result:
    found = [Diagnostic(*d) for d in diagnostics]
    if not ok:
        raise CompileError(found, text)
    files: dict[str, Union[str, bytes]] = {}
    for name, data in outputs:
        files[name] = data if name.endswith(_BINARY) else data.decode("utf-8")
    manifests = {name: json.loads(data) for name, data in files.items() if name.endswith(".manifest.json")}
    return Result(files, manifests, found)


class Context:
    """A shader cache shared by the compiles made through it, as one run of the command line shares one. `cache_dir`
    None: the command line's default folder ($XDG_CACHE_HOME/hexc, else ~/.cache/hexc); "": memory only."""

    def __init__(self, cache_dir: Optional[Union[str, os.PathLike]] = None):
        self._context = _hexc.Context(None if cache_dir is None else os.fspath(cache_dir))

    def compile(self, material: Union[str, os.PathLike, Mapping[str, Any]], *,
                targets: Optional[Union[str, Iterable[str]]] = None, engines: Optional[Union[str, Iterable[str]]] = None,
                uv_origin: Optional[str] = None, hlsl_sm: Optional[Union[int, str]] = None,
                glsl_version: Optional[Union[int, str]] = None, entry: Optional[str] = None, bake: bool = False,
                debug: bool = False, vertex: bool = False, specialise: bool = True,
                base_dir: Optional[Union[str, os.PathLike]] = None, name: Optional[str] = None) -> Result:
        """Compiles `material`: a path to a material file, its JSON text, or a dict. Text and dicts read their textures
        from `base_dir` (default: the working folder) and are called `name` in diagnostics (default: "material.json").
        Options are the command line's (docs/cli.md); a wrong one raises ValueError, a wrong material CompileError."""
        options = _options(targets, engines, uv_origin, hlsl_sm, glsl_version, entry, bake, debug, vertex, specialise)
        if isinstance(material, Mapping):
            source, in_memory = material_text(material), True
        elif isinstance(material, str) and material.lstrip().startswith("{"):
            source, in_memory = material, True
        else:
            source, in_memory = os.fspath(material), False
        base = "" if base_dir is None else os.fspath(base_dir)
        return _result(*self._context.compile(source, in_memory, name or "material.json", base, options))

    def cache_stats(self) -> tuple[int, int]:
        """(hits, misses): shader code taken from the cache and compiled, over the context's life."""
        return self._context.cache_stats()


_default: Optional[Context] = None
_default_lock = threading.Lock()


def compile(material: Union[str, os.PathLike, Mapping[str, Any]], **options: Any) -> Result:
    """Context.compile through one context per process, with the command line's default cache folder."""
    global _default
    with _default_lock:
        if _default is None:
            _default = Context()
    return _default.compile(material, **options)
