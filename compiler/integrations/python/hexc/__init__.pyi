# Type stubs of the hexc package (docs/python.md).
import os
from typing import Any, Iterable, Mapping, Optional, Union

__version__: str
API_VERSION: int

Material = Union[str, os.PathLike[str], Mapping[str, Any]]
Names = Union[str, Iterable[str]]

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

def material_text(material: Mapping[str, Any]) -> str: ...

class Context:
    def __init__(self, cache_dir: Optional[Union[str, os.PathLike[str]]] = None) -> None: ...
    def compile(self, material: Material, *, targets: Optional[Names] = None, engines: Optional[Names] = None,
                uv_origin: Optional[str] = None, hlsl_sm: Optional[Union[int, str]] = None,
                glsl_version: Optional[Union[int, str]] = None, entry: Optional[str] = None, bake: bool = False,
                debug: bool = False, vertex: bool = False, specialise: bool = True,
                base_dir: Optional[Union[str, os.PathLike[str]]] = None, name: Optional[str] = None) -> Result: ...
    def cache_stats(self) -> tuple[int, int]: ...

def compile(material: Material, *, targets: Optional[Names] = None, engines: Optional[Names] = None,
            uv_origin: Optional[str] = None, hlsl_sm: Optional[Union[int, str]] = None,
            glsl_version: Optional[Union[int, str]] = None, entry: Optional[str] = None, bake: bool = False,
            debug: bool = False, vertex: bool = False, specialise: bool = True,
            base_dir: Optional[Union[str, os.PathLike[str]]] = None, name: Optional[str] = None) -> Result: ...
