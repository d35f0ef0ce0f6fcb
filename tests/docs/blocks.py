"""The fenced code blocks of a Markdown file and what each one is, from its info string (CONTRIBUTING.md, "The docs are tests").

    ```sh                      shell commands, run in order (a `hexc edit` line starts the server and checks its page)
    ```console [vary=A,B]      `$ ` lines are commands; the lines after each, what it prints (stdout and stderr), compared
                               exactly; an upper-case word named in `vary` stands for text that differs between runs (a
                               port, a token), the same text wherever it appears in the block
    ```LANG file=PATH          a file the reader saves as PATH (relative to the folder the docs' commands run in)
    ```LANG shows=PATH         a file of the repository, shown whole: it must be byte for byte PATH
    ```LANG excerpt [of=PATH] [vary=A,B]
                               a part of a file or of what hexc writes, `...` standing for what is left out; with `of`,
                               PATH (after the blocks before it ran) must hold it, token for token (`vary` as above)
    ```text                    neither a command, its output nor a file: a synopsis, a table of measured figures

A block that cannot run here has a visible paragraph right above it (a blank line between is allowed):
`*Not run in CI: <reason>.*`; it is listed with its reason and not run. Any other block is an error.
"""
import re
from dataclasses import dataclass, field

MARKER = re.compile(r"^\*Not run in CI: (.+)\*$")
FENCE = re.compile(r"^(\s*)(`{3,}|~{3,})(.*)$")
KINDS = ("run", "console", "file", "shows", "excerpt", "text")


@dataclass
class Block:
    doc: str
    line: int  # of the opening fence, 1-based
    info: str
    body: str
    kind: str = ""  # one of KINDS, or "" when it cannot be classified
    attrs: dict = field(default_factory=dict)
    not_run: str = ""  # the marker's reason
    problem: str = ""  # why it cannot be classified

    def where(self):
        return "%s:%d (```%s)" % (self.doc, self.line, self.info)


def classify(block):
    words = block.info.split()
    lang = words[0] if words else ""
    attrs = {}
    for w in words[1:]:
        key, _, value = w.partition("=")
        attrs[key] = value
    block.attrs = attrs
    if "file" in attrs:
        block.kind = "file"
    elif "shows" in attrs:
        block.kind = "shows"
    elif "excerpt" in attrs and set(attrs) <= {"excerpt", "of", "vary"}:
        block.kind = "excerpt"
    elif lang in ("sh", "bash") and not attrs:
        block.kind = "run"
    elif lang == "console" and set(attrs) <= {"vary"}:
        block.kind = "console"
    elif lang == "text" and not attrs:
        block.kind = "text"
    if not block.kind:
        block.problem = ("no info string" if not words else "info string `%s` names no kind" % block.info) + \
            " (sh, console, LANG file=PATH, LANG shows=PATH, LANG excerpt, text; or a `*Not run in CI: reason.*` line above)"
        if block.not_run:
            block.problem = ""  # marked: listed with its reason, never run
    return block


def parse(path, text):
    """Every fenced block of `text` (the file `path`), classified."""
    lines = text.split("\n")
    blocks = []
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        indent, fence, info = m.groups()
        close = re.compile(r"^\s*" + re.escape(fence[0]) + "{%d,}\\s*$" % len(fence))
        j = i + 1
        while j < len(lines) and not close.match(lines[j]):
            j += 1
        body = "\n".join(l[len(indent):] if l.startswith(indent) else l for l in lines[i + 1:j])
        above = i - 1
        while above >= 0 and not lines[above].strip():
            above -= 1
        start = above
        while start > 0 and lines[start - 1].strip() and not FENCE.match(lines[start - 1]):
            start -= 1
        paragraph = " ".join(l.strip() for l in lines[start:above + 1])
        marker = MARKER.match(paragraph) if above >= 0 and i - above <= 2 else None
        block = Block(path, i + 1, info.strip(), body, not_run=marker.group(1) if marker else "")
        blocks.append(classify(block))
        i = j + 1
    return blocks


TOKEN = re.compile(r'"(?:\\.|[^"\\])*"|\.\.\.|-?\d+(?:\.\d+)?(?:[eE][+-]?\d+)?|\w+|\S')


def excerpt_matches(excerpt, text, vary=()):
    """Whether `text` holds `excerpt` token for token (spacing and line breaks aside), `...` standing for any tokens and
    each `vary` word for the same text wherever it appears."""
    seen = set()
    pattern = "".join(r"(?:[^\x00]*\x00)*?" if t == "..." else vary_pattern(t, vary, seen, r"[^\x00\s\"]+?") + "\x00"
                      for t in TOKEN.findall(excerpt))
    return re.search(pattern, "".join(t + "\x00" for t in TOKEN.findall(text))) is not None


def vary_pattern(expected, vary, seen, any_text=r"\S+?"):
    """A regular expression for `expected`, in which each `vary` word stands for `any_text`, the same wherever it
    appears (`seen` holds the words bound before)."""
    names = [v for v in vary if v]
    if not names:
        return re.escape(expected)
    parts = []
    for piece in re.split("(" + "|".join(re.escape(n) for n in names) + ")", expected):
        if piece in names:
            parts.append("(?P=%s)" % piece if piece in seen else "(?P<%s>%s)" % (piece, any_text))
            seen.add(piece)
        else:
            parts.append(re.escape(piece))
    return "".join(parts)


def output_pattern(expected, vary):
    """A console block's expected output as a regular expression (vary_pattern)."""
    return re.compile(vary_pattern(expected, vary, set()))


def console_steps(body):
    """[(command, expected output)] of a console block."""
    steps = []
    for line in body.split("\n"):
        if line.startswith("$ "):
            steps.append([line[2:], []])
        elif steps:
            steps[-1][1].append(line)
        else:
            raise ValueError("a console block starts with `$ COMMAND`, not %r" % line)
    return [(c, "\n".join(out).rstrip()) for c, out in steps]
