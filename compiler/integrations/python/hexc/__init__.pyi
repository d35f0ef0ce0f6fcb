# Type stubs of the hexc package (docs/python.md).
import os
from typing import Any, Callable, Iterable, Mapping, Optional, Union

import numpy
import numpy.typing

__version__: str
API_VERSION: int

Material = Union[str, os.PathLike[str], Mapping[str, Any]]
Names = Union[str, Iterable[str]]
Path = Union[str, os.PathLike[str]]
# (height, width, 4) float32 RGBA, row 0 at the top.
Image = numpy.typing.NDArray[numpy.float32]
Progress = Callable[[int, int, str], Any]

class Diagnostic:
    code: str
    error: bool
    file: str
    line: int
    column: int
    path: str
    message: str
    fix: str
    def __init__(self, code: str, error: bool, file: str, line: int, column: int, path: str, message: str,
                 fix: str) -> None: ...

class CompileError(Exception):
    diagnostics: list[Diagnostic]
    def __init__(self, diagnostics: list[Diagnostic], text: str) -> None: ...

class Result:
    files: dict[str, Union[str, bytes]]
    manifests: dict[str, Any]
    diagnostics: list[Diagnostic]
    @property
    def manifest(self) -> Optional[dict[str, Any]]: ...

class Build:
    diagnostics: list[Diagnostic]
    log: str

def material_text(material: Mapping[str, Any]) -> str: ...

class Context:
    def __init__(self, cache_dir: Optional[Union[str, os.PathLike[str]]] = None) -> None: ...
    def compile(self, material: Material, *, targets: Optional[Names] = None, engines: Optional[Names] = None,
                uv_origin: Optional[str] = None, hlsl_sm: Optional[Union[int, str]] = None,
                glsl_version: Optional[Union[int, str]] = None, entry: Optional[str] = None, bake: bool = False,
                debug: bool = False, vertex: bool = False, specialise: bool = True,
                base_dir: Optional[Union[str, os.PathLike[str]]] = None, name: Optional[str] = None) -> Result: ...
    def render(self, material: Path, *, output: str = "shaded", slot: Optional[str] = None,
               size: tuple[int, int] = (512, 512), uv_rect: tuple[float, float, float, float] = (0.0, 0.0, 1.0, 1.0),
               reference: bool = False, target: str = "spirv", encoding: str = "linear", template: Optional[Path] = None,
               layout: Optional[Path] = None) -> Image: ...
    def preview(self, material: Path, *, cell: int = 256, encoding: str = "srgb", template: Optional[Path] = None,
                layout: Optional[Path] = None) -> Image: ...
    def build(self, inputs: Union[Path, Iterable[Path]], out_dir: Path, *, progress: Optional[Progress] = None,
              variants: Iterable[str] = (), force: bool = False, jobs: int = 0, targets: Optional[Names] = None,
              engines: Optional[Names] = None, uv_origin: Optional[str] = None, hlsl_sm: Optional[Union[int, str]] = None,
              glsl_version: Optional[Union[int, str]] = None, entry: Optional[str] = None, bake: bool = False,
              debug: bool = False, vertex: bool = False, specialise: bool = True) -> Build: ...
    def cache_stats(self) -> tuple[int, int]: ...

def compile(material: Material, *, targets: Optional[Names] = None, engines: Optional[Names] = None,
            uv_origin: Optional[str] = None, hlsl_sm: Optional[Union[int, str]] = None,
            glsl_version: Optional[Union[int, str]] = None, entry: Optional[str] = None, bake: bool = False,
            debug: bool = False, vertex: bool = False, specialise: bool = True,
            base_dir: Optional[Union[str, os.PathLike[str]]] = None, name: Optional[str] = None) -> Result: ...

def render(material: Path, *, output: str = "shaded", slot: Optional[str] = None, size: tuple[int, int] = (512, 512),
           uv_rect: tuple[float, float, float, float] = (0.0, 0.0, 1.0, 1.0), reference: bool = False,
           target: str = "spirv", encoding: str = "linear", template: Optional[Path] = None,
           layout: Optional[Path] = None) -> Image: ...
def preview(material: Path, *, cell: int = 256, encoding: str = "srgb", template: Optional[Path] = None,
            layout: Optional[Path] = None) -> Image: ...
def build(inputs: Union[Path, Iterable[Path]], out_dir: Path, *, progress: Optional[Progress] = None,
          variants: Iterable[str] = (), force: bool = False, jobs: int = 0, targets: Optional[Names] = None,
          engines: Optional[Names] = None, uv_origin: Optional[str] = None, hlsl_sm: Optional[Union[int, str]] = None,
          glsl_version: Optional[Union[int, str]] = None, entry: Optional[str] = None, bake: bool = False,
          debug: bool = False, vertex: bool = False, specialise: bool = True) -> Build: ...
