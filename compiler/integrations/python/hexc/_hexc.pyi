# The extension under the hexc package (module.cpp): the C API's calls, with plain values. Use `import hexc`.
from typing import Any, Callable, Optional

import numpy
import numpy.typing

version: str
api_version: int
# The C API's statuses (hexc/hexc.h).
OK: int
INVALID_INPUT: int
BAD_ARGUMENT: int
NO_VULKAN: int
CANCELLED: int

Diagnostics = list[tuple[str, bool, str, int, int, str, str, str]]

class Context:
    def __init__(self, cache_dir: Optional[str]) -> None: ...
    # (ok, [(name, bytes)], [(code, error, file, line, column, path, message, fix)], formatted diagnostics)
    def compile(self, source: str, in_memory: bool, name: str, base_dir: str,
                options: list[tuple[str, str]]) -> tuple[bool, list[tuple[str, bytes]],
                                                         list[tuple[str, bool, str, int, int, str, str, str]], str]: ...
    # (status, (height, width, 4) float32 image or None, diagnostics, text) of `hexc render|preview ARGS`.
    def picture(self, preview: bool, args: list[str]) -> tuple[int, Optional[numpy.typing.NDArray[numpy.float32]], Diagnostics, str]: ...
    # (status, diagnostics, text) of `hexc ARGS`; what `progress` raises stops the build and is raised.
    def build(self, args: list[str], progress: Optional[Callable[[int, int, str], Any]]) -> tuple[int, Diagnostics, str]: ...
    def cache_stats(self) -> tuple[int, int]: ...
