# The extension under the hexc package (module.cpp): the C API's calls, with plain values. Use `import hexc`.
from typing import Optional

version: str
api_version: int

class Context:
    def __init__(self, cache_dir: Optional[str]) -> None: ...
    # (ok, [(name, bytes)], [(code, error, file, line, column, path, message, fix)], formatted diagnostics)
    def compile(self, source: str, in_memory: bool, name: str, base_dir: str,
                options: list[tuple[str, str]]) -> tuple[bool, list[tuple[str, bytes]],
                                                         list[tuple[str, bool, str, int, int, str, str, str]], str]: ...
    def cache_stats(self) -> tuple[int, int]: ...
