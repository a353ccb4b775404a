"""The query language's grammar (lark, LALR) and its parser, Lark's own,
built once per grammar and kept in the user's cache directory.

Building the LALR tables from GRAMMAR takes lark ~25 ms; loading them back
(`Lark.load`, the same data `Lark(..., cache=...)` keeps) takes ~2 ms.  The
table file is named by a digest of the grammar, the parser's options, lark's
version and Python's, so an edited grammar or another lark builds its own;
it is written atomically (model/atomic.py), and a file that cannot be read
or written only costs the build (docs/performance.md, "The query parser").
"""

from __future__ import annotations

import hashlib
import io
import os
import sys
from functools import lru_cache
from pathlib import Path

import lark
from lark import Lark

from sass_tui.model.atomic import write_bytes_atomic

GRAMMAR = r"""
?start: or_expr
?or_expr: and_expr (_OR and_expr)*
?and_expr: not_expr (_AND not_expr)*
?not_expr: _NOT not_expr -> negation
         | atom
?atom: "(" or_expr ")"
     | comparison
     | between
comparison: field OP value
between: field _BETWEEN value _AND value
field: NAME ("." NAME)*
value: NUMBER (UNIT NUMBER)* UNIT?   -> number
     | NAME                          -> word
     | STRING                        -> quoted
_OR.3: /or\b/i
_AND.3: /and\b/i
_NOT.3: /not\b/i
_BETWEEN.3: /between\b/i
OP: "<=" | ">=" | "!=" | "<>" | "<" | ">" | "=" | "≤" | "≥" | "≠"
NAME.2: /[A-Za-z_][A-Za-z0-9_]*/
STRING: /'[^']*'|"[^"]*"/
NUMBER: /[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?/
UNIT: /(ft|lbf?|N|n)[-·*]?(lbf?|lbs|m|ft)\b|deg\/s|rad\/s|°\/s|[A-Za-z°"]+/
%import common.WS
%ignore WS
"""

# Positions kept for the error columns and the terms' text (db/query.py).
_OPTIONS = {"parser": "lalr", "propagate_positions": True, "maybe_placeholders": False}


def _cache_home() -> Path:
    """$XDG_CACHE_HOME/sass (~/.cache/sass), as db/accelerator.py's column
    copies: platformdirs costs `sass query` 13 ms to import."""
    xdg = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(xdg) / "sass"


def table_file() -> Path:
    """Where the parser's tables for this grammar, lark and Python are kept."""
    key = f"{GRAMMAR}{sorted(_OPTIONS.items())}{lark.__version__}{sys.version_info[:2]}"
    digest = hashlib.sha256(key.encode("utf-8")).hexdigest()[:24]
    return _cache_home() / "parsers" / f"query-{digest}.lark"


@lru_cache(maxsize=1)
def parser() -> Lark:
    """The LALR parser of GRAMMAR: its tables read from the cache file, or
    built and written there for the next process."""
    try:
        path = table_file()
    except RuntimeError:  # no home directory (Path.home) to keep the tables in
        return Lark(GRAMMAR, **_OPTIONS)
    try:
        with open(path, "rb") as tables:
            loaded: Lark = Lark.load(tables)
        return loaded
    except Exception:  # missing, unreadable, or written by another lark: build it
        pass
    built = Lark(GRAMMAR, **_OPTIONS)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        buffer = io.BytesIO()
        built.save(buffer)
        write_bytes_atomic(path, buffer.getvalue())
    except OSError:  # a read-only or full cache: the next process builds again
        pass
    return built
