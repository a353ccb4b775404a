"""Generate sass_tui/db/query/_query_parser.py, the query language's parser, with
lark's stand-alone generator (LALR, positions kept) from
sass_tui/db/query/query_grammar.py.  Run after changing the grammar:

    python scripts/make_query_parser.py

The generated module is then edited (`LEAN_EDITS`) so that importing it does
not import what parsing never uses: logging (lark's logger, silenced at
CRITICAL), dataclasses and inspect (one frozen record and a class decorator),
pickle, zlib and base64 (lark's grammar cache).  Those load when the code
that needs them first runs; `sass query` starts some 10 ms sooner
(docs/performance.md, "Start-up ratios").  Each edit must match exactly once,
so a new lark version that moves the code fails here instead of silently.
"""

from __future__ import annotations

import hashlib
import subprocess
import sys
import tempfile
from pathlib import Path

from sass_tui.db.query.query_grammar import GRAMMAR

OUT = Path(__file__).resolve().parents[1] / "sass_tui" / "db" / "query" / "_query_parser.py"


def grammar_digest() -> str:
    return hashlib.sha256(GRAMMAR.encode("utf-8")).hexdigest()


# Defined at the top of the generated module: what the edits below call.
_LEAN_PRELUDE = '''
class _LazyLogger:
    """lark's logger ("lark", level CRITICAL), made when first used."""

    def __getattr__(self, name):
        import logging

        real = logging.getLogger("lark")
        if not real.handlers:
            real.addHandler(logging.StreamHandler())
            real.setLevel(logging.CRITICAL)
        return getattr(real, name)


def _lazy(module):
    """`module`, imported when first used."""
    return __import__(module)


def _frozen_record(*fields):
    """What @dataclass(frozen=True) makes of a class with `fields`, without
    importing dataclasses: __init__ (then __post_init__), __eq__, __hash__,
    __repr__, and no assignment."""

    def decorate(cls):
        def __init__(self, *args):
            for name, value in zip(fields, args, strict=True):
                object.__setattr__(self, name, value)
            self.__post_init__()

        def __setattr__(self, name, value):
            raise AttributeError(f"cannot assign to field {name!r}")

        def _values(self):
            return tuple(getattr(self, name) for name in fields)

        def __eq__(self, other):
            if other.__class__ is not self.__class__:
                return NotImplemented
            return _values(self) == _values(other)

        def __repr__(self):
            inner = ", ".join(f"{name}={getattr(self, name)!r}" for name in fields)
            return f"{cls.__qualname__}({inner})"

        cls.__init__ = __init__
        cls.__setattr__ = __setattr__
        cls.__delattr__ = __setattr__
        cls.__eq__ = __eq__
        cls.__hash__ = lambda self: hash(_values(self))
        cls.__repr__ = __repr__
        return cls

    return decorate
'''

# (what lark's stand-alone module says, what the lean module says instead)
LEAN_EDITS = (
    ("import logging\n", ""),
    ("from dataclasses import dataclass\n", ""),
    (
        'logger: logging.Logger = logging.getLogger("lark")\n'
        "logger.addHandler(logging.StreamHandler())\n",
        "logger = _LazyLogger()\n",
    ),
    ("logger.setLevel(logging.CRITICAL)\n", ""),
    (
        "@dataclass(frozen=True)\nclass TextSlice(",
        '@_frozen_record("text", "start", "end")\nclass TextSlice(',
    ),
    ("from inspect import getmembers, getmro\n", ""),
    (
        "    def _apply_v_args(cls, visit_wrapper):\n",
        "    def _apply_v_args(cls, visit_wrapper):\n"
        "        from inspect import getmembers, getmro\n",
    ),
    ("import pickle, zlib, base64\n", ""),
)


def lean(source: str) -> str:
    """`source` with LEAN_EDITS made (each exactly once), every use of pickle
    through _lazy, and _LEAN_PRELUDE after the first import."""
    for old, new in LEAN_EDITS:
        if source.count(old) != 1:
            raise SystemExit(f"lark's stand-alone module changed: {old!r} is not there once")
        source = source.replace(old, new)
    for name in ("logging.", "dataclass", "zlib.", "base64.", "getmro("):
        if name in source and not (name == "getmro(" and source.count(name) == 1):
            raise SystemExit(f"lark's stand-alone module uses {name!r} somewhere new")
    source = source.replace("pickle.", "_lazy('pickle').")
    first_class = "class LarkError(Exception):\n"
    if first_class not in source:
        raise SystemExit(f"lark's stand-alone module changed: no {first_class!r}")
    return source.replace(first_class, _LEAN_PRELUDE.lstrip() + "\n\n" + first_class, 1)


def generate() -> str:
    import lark

    with tempfile.TemporaryDirectory() as tmp:
        source = Path(tmp) / "query.lark"
        source.write_text(GRAMMAR, encoding="utf-8")
        done = subprocess.run(
            [sys.executable, "-m", "lark.tools.standalone", "--propagate_positions", str(source)],
            capture_output=True,
            text=True,
            check=True,
        )
    header = (
        "# Generated by scripts/make_query_parser.py from sass_tui/db/query/query_grammar.py\n"
        f"# with lark {lark.__version__}'s stand-alone generator; do not edit.\n"
        "# ruff: noqa\n"
        "# mypy: ignore-errors\n"
        # Annotations as strings: lark's are ~300 typing subscriptions at import.
        "from __future__ import annotations\n"
        f'GRAMMAR_SHA256 = "{grammar_digest()}"\n'
    )
    return header + lean(done.stdout)


def main() -> int:
    from sass_tui.model.files.atomic import write_text_atomic

    write_text_atomic(OUT, generate())
    print(f"wrote {OUT}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
