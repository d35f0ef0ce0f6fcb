"""hexc, the hex-tiling material compiler, in process (docs/python.md).

    import hexc
    result = hexc.compile("materials/rock.json", targets=["hlsl", "spirv"])
    result.files["rock.frag.hlsl"]   # str; SPIR-V and other binary files are bytes
    result.manifest                  # dict
    try:
        hexc.compile({"name": "x"})
    except hexc.CompileError as e:
        for d in e.diagnostics: print(d.code, d.line, d.column, d.path, d.message)
    hexc.render("materials/rock.json", output="albedo", size=(64, 64), reference=True)   # numpy (64, 64, 4) float32
    hexc.preview("materials/rock.json", cell=64)                                         # the preview sheet
    hexc.build(["materials/rock.json"], "out", progress=lambda done, total, name: print(done, total, name))

Compiles, renders and builds release the interpreter lock: threads compile at once, sharing a context's shader cache.
"""
from __future__ import annotations

import json
import os
import threading
from dataclasses import dataclass
from typing import Any, Callable, Iterable, Mapping, Optional, Union

from . import _hexc

__all__ = ["compile", "render", "preview", "build", "material_text", "Context", "Result", "Build", "Diagnostic", "CompileError",
           "__version__", "API_VERSION"]
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


@dataclass(frozen=True)
class Build:
    """What a build reported: its warnings, and everything the command line would have printed (the summary)."""
    diagnostics: list[Diagnostic]
    log: str


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


def _raise(status: int, diagnostics: list[Diagnostic], text: str):
    """The exception of a render's, preview's or build's status, as the command line's exit code tells them apart."""
    if status == _hexc.INVALID_INPUT:
        raise CompileError(diagnostics, text)
    if status == _hexc.BAD_ARGUMENT:
        raise ValueError(text.rstrip("\n"))
    if status == _hexc.NO_VULKAN:
        raise RuntimeError(text.rstrip("\n"))
    raise OSError(text.rstrip("\n"))  # an output could not be written


def _compile_arguments(targets, engines, uv_origin, hlsl_sm, glsl_version, entry, bake, debug, vertex, specialise):
    """The command line's arguments of the compile options (Context.compile's)."""
    arguments = []
    for key, value in _options(targets, engines, uv_origin, hlsl_sm, glsl_version, entry, bake, debug, vertex, specialise):
        if key == "uv-origin":
            arguments += ["--uv-bottom-left"] if value == "bottom-left" else [] if value == "top-left" else ["--uv-origin", value]
        elif key in ("bake", "debug", "vertex", "no-specialise"):
            arguments += ["--" + key] if value == "1" else []
        else:
            arguments += ["--" + key, value]
    return arguments


def _show_arguments(template, encoding, layout):
    arguments = [] if template is None else ["--template", os.fspath(template)]
    arguments += [] if encoding is None else ["--encoding", encoding]
    return arguments + ([] if layout is None else ["--layout", os.fspath(layout)])


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

    def render(self, material: Union[str, os.PathLike], *, output: str = "shaded", slot: Optional[str] = None,
               size: tuple[int, int] = (512, 512), uv_rect: tuple[float, float, float, float] = (0.0, 0.0, 1.0, 1.0),
               reference: bool = False, target: str = "spirv", encoding: str = "linear",
               template: Optional[Union[str, os.PathLike]] = None, layout: Optional[Union[str, os.PathLike]] = None):
        """`hexc render` (docs/cli.md) of the material file `material`, returned instead of written: a numpy array of
        shape (height, width, 4), float32 RGBA, row 0 the top row (v = V0), as `-o IMAGE.pfm` holds it. `output`:
        shaded, albedo, normal, derivative or weights; `size`: (width, height) in pixels; `uv_rect`: (U0, V0, U1, V1);
        `reference`: the fp64 CPU reference (no Vulkan needed), else lavapipe runs the `target` shader. `encoding`
        "linear" (the default) gives the values the shader returns, "srgb" what an sRGB swapchain shows (the sRGB
        transfer function on RGB, alpha linear). Raises CompileError for a bad material, ValueError for a bad option,
        RuntimeError without a Vulkan device."""
        arguments = [os.fspath(material), "--output", output, "--size", "%dx%d" % tuple(size),
                     "--uv-rect", ",".join(repr(float(x)) for x in uv_rect), "--target", target]
        arguments += (["--slot", slot] if slot else []) + (["--reference"] if reference else [])
        return self._picture(False, arguments + _show_arguments(template, encoding, layout))

    def preview(self, material: Union[str, os.PathLike], *, cell: int = 256, encoding: str = "srgb",
                template: Optional[Union[str, os.PathLike]] = None, layout: Optional[Union[str, os.PathLike]] = None):
        """`hexc preview`'s labelled sheet of the material file `material` (plain tiling, the falloff and histogram
        blends, the weights; magnified and minified), rendered on lavapipe: a numpy array of shape
        (2 * (cell + 28), 4 * cell, 4), float32 RGBA, row 0 the top row. sRGB-encoded for display by default
        (`encoding="linear"`: the shader's values), as matplotlib's imshow expects. Raises as render does."""
        arguments = [os.fspath(material), "--cell", str(int(cell))]
        return self._picture(True, arguments + _show_arguments(template, encoding, layout))

    def _picture(self, preview: bool, arguments: list[str]):
        status, image, diagnostics, text = self._context.picture(preview, arguments)
        if status != _hexc.OK:
            _raise(status, [Diagnostic(*d) for d in diagnostics], text)
        return image

    def build(self, inputs: Union[str, os.PathLike, Iterable[Union[str, os.PathLike]]], out_dir: Union[str, os.PathLike], *,
              progress: Optional[Callable[[int, int, str], Any]] = None, variants: Iterable[str] = (), force: bool = False,
              jobs: int = 0, targets: Optional[Union[str, Iterable[str]]] = None,
              engines: Optional[Union[str, Iterable[str]]] = None, uv_origin: Optional[str] = None,
              hlsl_sm: Optional[Union[int, str]] = None, glsl_version: Optional[Union[int, str]] = None,
              entry: Optional[str] = None, bake: bool = False, debug: bool = False, vertex: bool = False,
              specialise: bool = True) -> Build:
        """`hexc INPUTS -o OUT_DIR` (docs/cli.md, docs/scenes.md): material and scene files compiled and written to
        `out_dir` as the command line writes them (atomically, all or nothing, skipping what is up to date), through
        this context's shader cache. `progress(done, total, name)` is called as each material or scene variant is
        compiled (from the build's threads, one call at a time); an exception it raises stops the build before
        anything is written and is raised here. Raises CompileError for bad inputs, ValueError for bad options,
        OSError when an output cannot be written."""
        paths = [inputs] if isinstance(inputs, (str, os.PathLike)) else list(inputs)
        arguments = [os.fspath(p) for p in paths] + ["-o", os.fspath(out_dir)]
        arguments += [a for v in variants for a in ("--variant", v)] + (["--force"] if force else [])
        arguments += ["--jobs", str(jobs)] if jobs else []
        arguments += _compile_arguments(targets, engines, uv_origin, hlsl_sm, glsl_version, entry, bake, debug, vertex,
                                        specialise)
        status, diagnostics, text = self._context.build(arguments, progress)
        found = [Diagnostic(*d) for d in diagnostics]
        if status != _hexc.OK:
            _raise(status, found, text)
        return Build(found, text)

    def cache_stats(self) -> tuple[int, int]:
        """(hits, misses): shader code taken from the cache and compiled, over the context's life."""
        return self._context.cache_stats()


_default: Optional[Context] = None
_default_lock = threading.Lock()


def _default_context() -> Context:
    global _default
    with _default_lock:
        if _default is None:
            _default = Context()
    return _default


def compile(material: Union[str, os.PathLike, Mapping[str, Any]], **options: Any) -> Result:
    """Context.compile through one context per process, with the command line's default cache folder."""
    return _default_context().compile(material, **options)


def render(material: Union[str, os.PathLike], **options: Any):
    """Context.render (a numpy float32 array (height, width, 4), row 0 at the top) through the process's context."""
    return _default_context().render(material, **options)


def preview(material: Union[str, os.PathLike], **options: Any):
    """Context.preview (a numpy float32 array, sRGB by default) through the process's context."""
    return _default_context().preview(material, **options)


def build(inputs: Union[str, os.PathLike, Iterable[Union[str, os.PathLike]]], out_dir: Union[str, os.PathLike],
          **options: Any) -> Build:
    """Context.build (materials and scenes to a folder, with a progress callback) through the process's context."""
    return _default_context().build(inputs, out_dir, **options)
