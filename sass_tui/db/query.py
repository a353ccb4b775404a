"""The query language (spec §4) compiled to parameterised SQL.

    gender = male AND girth.right_upper_arm.z > 28 cm AND strength.elbow_flexion.max > 20 ft-lb

AND binds tighter than OR; parentheses group.  Values with a unit are
converted to the stored unit; the SQL holds only `?` placeholders, never the
user's text.  Errors name the offending token and its column.

For the UI: `Query.count()` and `Query.page(offset, limit)` (or
`page_after(last_id, limit)`) never load more than one page of people.
"""

from __future__ import annotations

import math
import re
import sqlite3
from dataclasses import dataclass
from functools import lru_cache

from lark import Lark, Token, Transformer, v_args
from lark.exceptions import (
    UnexpectedCharacters,
    UnexpectedEOF,
    UnexpectedInput,
    UnexpectedToken,
    VisitError,
)

from sass_tui.db.schema import (
    CENTER_OF_MASS_NAMES,
    GIRTH_NAMES,
    JOINT_LIMIT_NAMES,
    QUERY_TABLES,
)
from sass_tui.model.errors import SassError
from sass_tui.model.strength import MOTION_NAMES
from sass_tui.model.units import DISPLAY, LARGEST_NUMBER, UnitError, convert, unit_name
from sass_tui.model.vocabulary import GENDERS, STRENGTH_TYPES
from sass_tui.model.vocabulary import PERSON_HANDEDNESS as HANDEDNESS

GRAMMAR = r"""
?start: or_expr
?or_expr: and_expr (_OR and_expr)*
?and_expr: atom (_AND atom)*
?atom: "(" or_expr ")"
     | comparison
comparison: field OP value
field: NAME ("." NAME)*
value: NUMBER UNIT?   -> number
     | NAME           -> word
_OR.3: /or\b/i
_AND.3: /and\b/i
OP: "<=" | ">=" | "!=" | "<>" | "<" | ">" | "=" | "≤" | "≥" | "≠"
NAME.2: /[A-Za-z_][A-Za-z0-9_]*/
NUMBER: /[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?/
UNIT: /(ft|lbf?|N|n)[-·*]?(lbf?|lbs|m|ft)\b|deg\/s|rad\/s|°\/s|[A-Za-z°"]+/
%import common.WS
%ignore WS
"""

_OPERATORS = {
    "<": "<",
    ">": ">",
    "<=": "<=",
    ">=": ">=",
    "=": "=",
    "!=": "!=",
    "<>": "!=",
    "≤": "<=",
    "≥": ">=",
    "≠": "!=",
}

# field -> (table alias, column, stored unit or None, allowed words or None)
_GLOBAL_FIELDS = {
    "gender": ("p", "gender", None, GENDERS),
    "mass": ("p", "mass", "kg", None),
    "stature": ("p", "stature", "cm", None),
    "age": ("p", "age", "", None),
    "handedness": ("p", "handedness", None, HANDEDNESS),
    "strength_type": ("s", "strength_type", None, STRENGTH_TYPES),
    "motion_speed": ("s", "motion_speed", "deg/s", None),
    "training_level": ("s", "training_level", "", None),
    "fatigue_level": ("s", "fatigue_level", "", None),
}
# group word -> (query-table group, rows, stored unit, what a row is called)
_GROUPS = {
    "girth": ("girth", GIRTH_NAMES, "cm", "segment"),
    "joint_limit": ("joint_limits", JOINT_LIMIT_NAMES, "deg", "joint limit"),
    "center_of_mass": ("center_of_mass", CENTER_OF_MASS_NAMES, "cm", "segment"),
    "strength": ("strength", MOTION_NAMES, "N_m", "motion"),
}


class QueryError(ValueError, SassError):
    """A query that cannot be run; `column` is 1-based in the query text."""

    def __init__(self, message: str, text: str = "", column: int | None = None):
        self.column = column
        self.text = text
        where = f"column {column}: " if column else ""
        super().__init__(f"{where}{message}")

    def pointer(self) -> str:
        """The query with a caret under the offending column."""
        if not self.column:
            return self.text
        return f"{self.text}\n{' ' * (self.column - 1)}^"


@lru_cache(maxsize=1)
def parser() -> Lark:
    return Lark(GRAMMAR, parser="lalr", propagate_positions=True, maybe_placeholders=False)


@dataclass(frozen=True)
class CompiledQuery:
    text: str
    where: str
    params: tuple
    tables: tuple[tuple[str, str], ...]  # (alias, table) joined to person p

    def from_clause(self) -> str:
        joins = "".join(
            f" LEFT JOIN {table} {alias} ON {alias}.id_num = p.id_num"
            for alias, table in self.tables
        )
        return f"person p{joins}"


class _Compiler(Transformer):
    def __init__(self, text: str):
        super().__init__()
        self.text = text
        self.tables: dict[str, str] = {}  # table -> alias
        self._field_token: Token | None = None

    def _alias(self, table: str) -> str:
        if table not in self.tables and len(self.tables) >= MAX_JOINED_TABLES:
            self._fail(
                f"the query uses more than {MAX_JOINED_TABLES} different segments, joints "
                "and motions; split it",
                self._field_token,
            )
        return self.tables.setdefault(table, f"t{len(self.tables)}")

    def _fail(self, message: str, token) -> None:
        raise QueryError(message, self.text, getattr(token, "column", None))

    def or_expr(self, items):
        return (
            "(" + " OR ".join(sql for sql, _ in items) + ")",
            [p for _, ps in items for p in ps],
        )

    def and_expr(self, items):
        return (
            "(" + " AND ".join(sql for sql, _ in items) + ")",
            [p for _, ps in items for p in ps],
        )

    def field(self, names):
        self._field_token = names[0]  # for _alias's error: the field being resolved
        return list(names)

    @v_args(inline=True)
    def number(self, value, unit=None):
        return ("number", value, unit)

    @v_args(inline=True)
    def word(self, value):
        return ("word", value, None)

    @v_args(inline=True)
    def comparison(self, names, op, value):
        alias, column, unit, words = self._resolve(names)
        sql_op = _OPERATORS[str(op)]
        kind, token, unit_token = value
        if words is not None:
            if kind != "word" or token.lower() not in words:
                self._fail(
                    f"{'.'.join(names)} is one of {', '.join(words)}, not {str(token)!r}", token
                )
            if sql_op not in ("=", "!="):
                self._fail(f"{'.'.join(names)} can only be compared with = or !=", op)
            return (f"{alias}.{column} {sql_op} ?", [token.lower()])
        if kind != "number":
            self._fail(f"{'.'.join(names)} needs a number, not {str(token)!r}", token)
        number = float(token)
        if not math.isfinite(number) or abs(number) > LARGEST_NUMBER:
            self._fail(f"{str(token)!r} is not a usable number", token)
        if unit_token is not None:
            if not unit:
                self._fail(
                    f"{'.'.join(names)} takes no unit, found {str(unit_token)!r}", unit_token
                )
            try:
                number = convert(number, unit_name(str(unit_token)), unit)
            except UnitError as exc:
                self._fail(f"{exc}", unit_token)
        return (f"{alias}.{column} {sql_op} ?", [number])

    def _resolve(self, names: list[Token]):
        head = names[0].lower()
        if len(names) == 1 and head in _GLOBAL_FIELDS:
            alias, column, unit, words = _GLOBAL_FIELDS[head]
            if alias != "p":
                alias = self._alias("strength_q")
            return alias, column, unit, words
        if head not in _GROUPS:
            self._fail(
                f"unknown field {str(names[0])!r}; expected one of "
                f"{', '.join(_GLOBAL_FIELDS)} or girth.SEGMENT.x|y|z, "
                "joint_limit.JOINT.x|y|z, center_of_mass.SEGMENT.x|y|z, strength.MOTION.max",
                names[0],
            )
        group, rows, unit, what = _GROUPS[head]
        if len(names) != 3:
            shape = (
                "strength.MOTION.max"
                if head == "strength"
                else f"{head}.{what.upper().replace(' ', '_')}.x|y|z"
            )
            self._fail(f"expected {shape}", names[0])
        row, axis = names[1].lower(), names[2].lower()
        if row not in rows:
            self._fail(
                f"unknown {what} {str(names[1])!r}; expected one of {', '.join(rows)}", names[1]
            )
        expected_axes = ("max",) if head == "strength" else ("x", "y", "z")
        if axis not in expected_axes:
            self._fail(
                f"expected {' or '.join(expected_axes)} after {head}.{row}, found "
                f"{str(names[2])!r}",
                names[2],
            )
        return self._alias(QUERY_TABLES[group][row]), axis, unit, None


# Bounds on a query's shape, checked before parsing: deeper nesting would
# exhaust Python's recursion in the tree walk, and more comparisons SQLite's
# expression tree (its limit is 1000 levels; "a OR b OR ..." nests one a term).
MAX_NESTING = 50
MAX_COMPARISONS = 200
MAX_LENGTH = 20_000
MAX_JOINED_TABLES = 63  # SQLite joins at most 64 tables: person and 63 more
_COMPARISON_OPERATOR = re.compile(r"<=|>=|!=|<>|[<>=≤≥≠]")


def _check_size(text: str) -> None:
    """Refuse a query too long, too deeply nested or with too many comparisons."""
    if len(text) > MAX_LENGTH:
        raise QueryError(
            f"the query is {len(text)} characters long; at most {MAX_LENGTH} are allowed",
            text[:80],
            None,
        )
    depth = 0
    for column, char in enumerate(text, start=1):
        if char == "(":
            depth += 1
            if depth > MAX_NESTING:
                raise QueryError(f"parentheses nested more than {MAX_NESTING} deep", text, column)
        elif char == ")":
            depth -= 1
    for count, match in enumerate(_COMPARISON_OPERATOR.finditer(text), start=1):
        if count > MAX_COMPARISONS:
            raise QueryError(
                f"more than {MAX_COMPARISONS} comparisons in one query; "
                "split it or use a range (e.g. stature > 170 cm AND stature < 180 cm)",
                text,
                match.start() + 1,
            )


def compile_query(text: str) -> CompiledQuery:
    """Parse and check a query; raises QueryError pointing at the bad token."""
    if not text.strip():
        raise QueryError(
            "the query is empty; expected e.g. gender = male AND stature > 180 cm", text, 1
        )
    _check_size(text)
    try:
        tree = parser().parse(text)
    except UnexpectedCharacters as exc:
        raise QueryError(
            f"unexpected character {text[exc.pos_in_stream]!r}", text, exc.column
        ) from None
    except UnexpectedEOF:
        raise QueryError("the query ends too early", text, len(text) + 1) from None
    except UnexpectedToken as exc:
        token = exc.token
        if token.type == "$END":
            raise QueryError(
                "the query ends too early; expected " + _expected(exc.expected), text, len(text) + 1
            ) from None
        raise QueryError(
            f"unexpected {str(token)!r}; expected " + _expected(exc.expected), text, token.column
        ) from None
    except UnexpectedInput as exc:  # pragma: no cover - other lark errors
        raise QueryError(str(exc), text, getattr(exc, "column", None)) from None
    compiler = _Compiler(text)
    try:
        where, params = compiler.transform(tree)
    except VisitError as exc:
        if isinstance(exc.orig_exc, QueryError):
            raise exc.orig_exc from None
        raise
    return CompiledQuery(
        text,
        where,
        tuple(params),
        tuple((alias, table) for table, alias in compiler.tables.items()),
    )


_TOKEN_WORDS = {
    "_AND": "AND",
    "_OR": "OR",
    "OP": "a comparison (< > <= >= = !=)",
    "NAME": "a name",
    "NUMBER": "a number",
    "UNIT": "a unit",
    "LPAR": "(",
    "RPAR": ")",
    "DOT": ".",
    "$END": "the end",
}


def _expected(expected) -> str:
    return ", ".join(sorted({_TOKEN_WORDS.get(e, e) for e in expected}))


# --- running --------------------------------------------------------------

PERSON_FIELDS = ("id", "name", "gender", "mass", "stature", "handedness", "age", "source")
LIST_FIELDS = PERSON_FIELDS + ("strength_type", "motion_speed", "training_level", "fatigue_level")
_SELECT = (
    "p.id_num, p.name, p.gender, p.mass, p.stature, p.handedness, p.age, p.source, "
    "sq.strength_type, sq.motion_speed, sq.training_level, sq.fatigue_level"
)


@dataclass
class Query:
    """A compiled query bound to a connection: count it, fetch it a page at a time."""

    conn: sqlite3.Connection
    compiled: CompiledQuery

    def count(self) -> int:
        sql = f"SELECT count(*) FROM {self.compiled.from_clause()} WHERE {self.compiled.where}"
        return self.conn.execute(sql, self.compiled.params).fetchone()[0]

    def _rows(self, extra: str, params: tuple) -> list[dict]:
        sql = (
            f"SELECT {_SELECT} FROM {self.compiled.from_clause()} "
            f"LEFT JOIN strength_q sq ON sq.id_num = p.id_num "
            f"WHERE {self.compiled.where}{extra}"
        )
        return [
            dict(zip(LIST_FIELDS, row))
            for row in self.conn.execute(sql, self.compiled.params + params)
        ]

    def page(self, offset: int = 0, limit: int = 25) -> list[dict]:
        """People offset .. offset+limit-1 in id order (the query list's page)."""
        return self._rows(" ORDER BY p.id_num LIMIT ? OFFSET ?", (int(limit), int(offset)))

    def page_after(self, last_id: int | None, limit: int = 25) -> list[dict]:
        """The next page after person `last_id` (keyset paging: cost independent of depth)."""
        if last_id is None:
            return self.page(0, limit)
        return self._rows(" AND p.id_num > ? ORDER BY p.id_num LIMIT ?", (int(last_id), int(limit)))

    def ids(self) -> list[int]:
        sql = f"SELECT p.id_num FROM {self.compiled.from_clause()} WHERE {self.compiled.where}"
        return [r[0] for r in self.conn.execute(sql, self.compiled.params)]

    def iter_all(self, page_size: int = 1000):
        last = None
        while True:
            rows = self.page_after(last, page_size)
            if not rows:
                return
            yield from rows
            last = rows[-1]["id"]


def run_query(conn: sqlite3.Connection, text: str) -> Query:
    return Query(conn, compile_query(text))


def unit_display(unit: str) -> str:
    return DISPLAY.get(unit, unit)
