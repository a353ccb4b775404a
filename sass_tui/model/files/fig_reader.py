"""The .fig reader (model/files/figfile.py writes them): a lark grammar, built
once.  Nothing of sass reads a .fig file back (the tests do, and a user's
script may), so lark, imported at this module's top, is off every start-up
path (sass_tui/startup.py's NEVER)."""

from __future__ import annotations

import math
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, cast

from lark import Lark
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken

from sass_tui.model.files.figfile import FigFile, FigParseError
from sass_tui.model.files.paths import LARGEST_TEXT_FILE, regular_file
from sass_tui.model.text import quoted

if TYPE_CHECKING:
    from lark import Token, Tree

_GRAMMAR = r"""
start: statement*
?statement: assignment | figure
assignment: NAME "=" NUMBER UNIT? ";"
figure: "figure" "[" STRING "]" "(" STRING ")" ";"
NAME: /(?!figure\b)[A-Za-z_][A-Za-z0-9_]*/
UNIT: /[A-Za-z_]+/
NUMBER: /[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?/
STRING: /"[^"\n]*"/
COMMENT: /\/\*(.|\n)*?\*\//
%import common.WS
%ignore WS
%ignore COMMENT
"""


@lru_cache(maxsize=1)
def _parser() -> Lark:
    return Lark(_GRAMMAR, parser="lalr", propagate_positions=True)


def parse_fig(text: str, name: str = "<text>") -> FigFile:
    try:
        tree = _parser().parse(text)
    except UnexpectedToken as exc:
        found = "end of file" if exc.token.type == "$END" else quoted(str(exc.token))
        expected = ", ".join(sorted(_describe(t) for t in exc.expected))
        raise FigParseError(
            f"{name}:{exc.line}:{exc.column}: found {found}; expected {expected}"
        ) from None
    except UnexpectedCharacters as exc:
        raise FigParseError(
            f"{name}:{exc.line}:{exc.column}: unexpected character {exc.char!r}"
        ) from None
    except UnexpectedEOF:
        raise FigParseError(f"{name}: the file ends in the middle of a statement") from None
    except UnexpectedInput as exc:  # pragma: no cover - other lark errors
        raise FigParseError(f"{name}:{exc.line}:{exc.column}: {exc}") from None
    fig = FigFile()
    # The grammar makes every statement a Tree and every leaf under one a Token.
    for node in cast("list[Tree[Token]]", tree.children):
        if node.data == "assignment":
            var, number, *unit = cast("list[Token]", node.children)
            if str(var) in fig.variables:
                raise FigParseError(f"{name}:{var.line}:{var.column}: {var} assigned twice")
            value = float(number)
            if not math.isfinite(value):
                raise FigParseError(
                    f"{name}:{number.line}:{number.column}: {var} = {number}: too large a number"
                )
            fig.variables[str(var)] = (value, str(unit[0]) if unit else "")
        else:
            body, archive = (str(s)[1:-1] for s in node.children)
            fig.body, fig.archive = body, archive
    if not fig.archive:
        raise FigParseError(f'{name}: no closing line figure ["body.fig"] ("skinny.a");')
    return fig


def read_fig(path: str | Path) -> FigFile:
    # a FIFO or a device would never end; a huge file is refused unread
    path = regular_file(path, largest=LARGEST_TEXT_FILE, kind="a .fig file")
    # utf-8-sig: a .fig edited in a Windows editor starts with a byte-order mark
    return parse_fig(path.read_text(encoding="utf-8-sig"), str(path))


def _describe(terminal: str) -> str:
    return {
        "NAME": "a variable name",
        "NUMBER": "a number",
        "UNIT": "a unit",
        "SEMICOLON": "';'",
        "EQUAL": "'='",
        "STRING": "a quoted file name",
        "FIGURE": "'figure'",
        "LSQB": "'['",
        "RSQB": "']'",
        "LPAR": "'('",
        "RPAR": "')'",
    }.get(terminal, terminal)
