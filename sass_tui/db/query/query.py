"""The query language (spec §4) compiled to parameterised SQL.

    gender = male AND girth.right_upper_arm.z > 28 cm AND strength.elbow_flexion.max > 20 ft-lb

    measure.sittingheight > 95 cm AND branch = 'Combat Arms' AND source = ansur2

Fields: `gender`, `stature`, `mass`, `age`, `handedness` (alias
`writingpreference`), the survey attributes `component`, `branch`,
`ethnicity` (free text: = or != only, in single or double quotes unless one
word, matched without regard to case), `subjectnumericrace` and `dodrace`
(the survey's codes), `source` (ansur2, synthetic, an import's label),
`measure.<name>` (the 93 ANSUR II measurements, the survey's names lower
case, "did you mean" on a typo), `girth.ROW.x|y|z`, `joint_limit.ROW.x|y|z`,
`center_of_mass.ROW.x|y|z`, `strength.MOTION.max` and the strength
parameters; `field_names()` lists them all with units.

A query that names no `source` term reaches the real people only (the
synthetic demonstration people left out: db/query/scope.py, added in
`compile_query`); `source = synthetic`, or any `source` term, leaves the
choice to the query.

NOT binds tighter than AND, AND tighter than OR; parentheses group.
`field BETWEEN a AND b` is `field >= a AND field <= b`; NOT is pushed down
to the comparisons (db/query/query_tree.py's `negation`).  Values with a unit are
converted to the stored unit, and several numbers each with its unit add up
(`6 ft 2 in`); the SQL holds only `?` placeholders, never the user's text.
Errors name the offending token and its column; an unknown field gets a
"did you mean" (`weight` -> `mass`).  docs/query-language.md is the
language's reference, `sass query --fields` (db/query/query_fields.py) its list of
fields.

A command parses a query once (`parse`: a ParsedQuery) and passes the
parsed query on; `compile_query` and `compile_conjuncts` take it or a text.

For the UI: `Query.count()` and `Query.page(offset, limit)` (or
`page_after(last_id, limit)`) never load more than one page of people.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator
from functools import lru_cache
from typing import Any, NamedTuple, NoReturn, Protocol

from sass_tui.db.engine.schema import (
    CENTER_OF_MASS_NAMES,
    GIRTH_NAMES,
    JOINT_LIMIT_NAMES,
    QUERY_TABLES,
)

# The parser is lark's stand-alone LALR module generated from GRAMMAR
# (db/query/query_grammar.py) by scripts/make_query_parser.py: importing it costs
# less than importing lark and loading its cached tables (docs/performance.md).
from sass_tui.db.query._query_parser import (
    Lark,
    Lark_StandAlone,
    Token,
    Transformer,
    Tree,
    UnexpectedCharacters,
    UnexpectedEOF,
    UnexpectedInput,
    UnexpectedToken,
    VisitError,
    v_args,
)
from sass_tui.db.query.query_limits import MAX_JOINED_TABLES, check_size
from sass_tui.db.query.query_limits import QueryError as QueryError
from sass_tui.db.query.query_tree import (
    PERSON_TABLE,
    And,
    Comparison,
    Dialect,
    Expr,
    Or,
    aliases,
    names_field,
    negation,
    placeholder,
    to_sql,
)
from sass_tui.db.query.scope import demonstration_query, demonstration_tree, real_only
from sass_tui.model.body.human import not_human
from sass_tui.model.measures import MEASURE_UNITS, suggest
from sass_tui.model.units import LARGEST_NUMBER, UnitError, convert, unit_name
from sass_tui.model.vocabulary import GENDERS, MOTION_NAMES, STRENGTH_TYPES
from sass_tui.model.vocabulary import PERSON_HANDEDNESS as HANDEDNESS

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

# Free text compared without regard to case (only = and !=).
TEXT = ("text",)
# field -> (table alias, column, stored unit or None, allowed words, TEXT, or None)
_GLOBAL_FIELDS: dict[str, tuple[str, str, str | None, tuple[str, ...] | None]] = {
    "gender": ("p", "gender", None, GENDERS),
    "mass": ("p", "mass", "kg", None),
    "stature": ("p", "stature", "cm", None),
    "age": ("p", "age", "", None),
    "handedness": ("p", "handedness", None, HANDEDNESS),
    "writingpreference": ("p", "handedness", None, HANDEDNESS),
    "source": ("p", "source", None, TEXT),
    "component": ("p", "component", None, TEXT),
    "branch": ("p", "branch", None, TEXT),
    "ethnicity": ("p", "ethnicity", None, TEXT),
    "subjectnumericrace": ("p", "subjectnumericrace", "", None),
    "dodrace": ("p", "dodrace", "", None),
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
MEASURE_TABLE = "measure"


class Connection(Protocol):
    """What a query runs on: sqlite3's connection, or db/engine/postgres.py's PostgresConnection."""

    def execute(self, sql: str, parameters: Any = ..., /) -> Any: ...


@lru_cache(maxsize=1)
def parser() -> Lark:
    """The LALR parser of GRAMMAR (positions kept for error columns)."""
    standalone: Lark = Lark_StandAlone()
    return standalone


class CompiledQuery(NamedTuple):  # not a dataclass: see model.names.Row
    """A query checked and compiled: its tree (db/query/query_tree.py) and the tree's
    SQLite condition; `sql(dialect)` gives another engine's."""

    text: str
    where: str
    params: tuple[object, ...]
    tables: tuple[tuple[str, str], ...]  # (alias, table) joined to person p
    tree: Expr

    def from_clause(self) -> str:
        joins = "".join(
            f" LEFT JOIN {table} {alias} ON {alias}.id_num = p.id_num"
            for alias, table in self.tables
        )
        return f"person p{joins}"

    def sql(self, dialect: Dialect) -> tuple[str, tuple[object, ...]]:
        """The WHERE condition and its parameters in `dialect`, under the same aliases."""
        alias_of = {"person": "p"} | {table: alias for alias, table in self.tables}
        where, params = to_sql(self.tree, dialect, alias_of)
        return where, tuple(params)

    def names_field(self, name: str) -> bool:
        """Whether the query compares `name` (e.g. `source`) anywhere."""
        return names_field(self.tree, name)


# What the builder makes of a value: (kind, first token, its parts).  A number's
# parts are (number, unit or None) pairs: `6 ft 2 in` is two, `180 cm` one.
_Value = tuple[str, Token, tuple[tuple[Token, "Token | None"], ...]]


class _TreeBuilder(Transformer[Token, Expr]):
    """The lark parse -> the typed tree, every field resolved and every value
    checked and converted to its stored unit (errors point at the token)."""

    def __init__(self, text: str, unknowns: bool = False):
        super().__init__()
        self.text = text
        # `?` is an unknown only where a command solves for it (sass design): its
        # comparison holds NaN, which no SQL is ever made of (design_limits).
        self.unknowns = unknowns
        self.tables: dict[str, None] = {}  # tables named so far, in order
        self._field_token: Token | None = None

    def _count_table(self, table: str) -> None:
        if table not in self.tables and len(self.tables) >= MAX_JOINED_TABLES:
            self._fail(
                f"the query uses more than {MAX_JOINED_TABLES} different segments, joints "
                "and motions; split it",
                self._field_token,
            )
        self.tables.setdefault(table, None)

    def _fail(self, message: str, token: Token | None) -> NoReturn:
        raise QueryError(message, self.text, getattr(token, "column", None))

    def or_expr(self, items: list[Expr]) -> Expr:
        return Or(tuple(items))

    def and_expr(self, items: list[Expr]) -> Expr:
        return And(tuple(items))

    @v_args(inline=True)
    def negation(self, term: Expr) -> Expr:
        return negation(term)

    def field(self, names: list[Token]) -> list[Token]:
        self._field_token = names[0]  # for _count_table's error: the field being resolved
        return list(names)

    def number(self, tokens: list[Token]) -> _Value:
        parts: list[tuple[Token, Token | None]] = []
        for token in tokens:
            if token.type == "NUMBER":
                parts.append((token, None))
            else:
                parts[-1] = (parts[-1][0], token)
        return ("number", tokens[0], tuple(parts))

    @v_args(inline=True)
    def word(self, value: Token) -> _Value:
        return ("word", value, ())

    @v_args(inline=True)
    def quoted(self, value: Token) -> _Value:
        return ("text", value, ())

    @v_args(inline=True)
    def unknown(self, value: Token) -> _Value:
        if not self.unknowns:
            self._fail(
                "? is an unknown for sass design to solve; give a number here, "
                "e.g. stature <= 190 cm",
                value,
            )
        return ("unknown", value, ())

    @v_args(inline=True)
    def comparison(self, names: list[Token], op: Token, value: _Value) -> Comparison:
        return self._comparison(names, _OPERATORS[str(op)], op, value)

    @v_args(inline=True)
    def between(self, names: list[Token], low: _Value, high: _Value) -> Expr:
        """`field BETWEEN low AND high`: `field >= low AND field <= high`, as SQL defines it."""
        for kind, token, _parts in (low, high):
            if kind not in ("number", "unknown"):
                self._fail(
                    f"BETWEEN takes two numbers, not {str(token)!r}; for words write "
                    f"{'.'.join(names)} = ... OR {'.'.join(names)} = ...",
                    token,
                )
        lowest = self._comparison(names, ">=", None, low)
        highest = self._comparison(names, "<=", None, high)
        if isinstance(lowest.value, float) and isinstance(highest.value, float):
            if lowest.value > highest.value:
                self._fail(
                    f"BETWEEN {_value_text(low)} AND {_value_text(high)} selects nobody; "
                    "write the smaller value first",
                    low[1],
                )
        return And((lowest, highest))

    def _comparison(
        self, names: list[Token], sql_op: str, op: Token | None, value: _Value
    ) -> Comparison:
        table, column, unit, words = self._resolve(names)
        field = ".".join(str(n).lower() for n in names)
        kind, token, parts = value
        if kind == "unknown":
            if words is not None or sql_op not in ("<", "<=", ">", ">="):
                self._fail(
                    f"? is solved only as a number limit: {'.'.join(names)} <= ?, >= ?, "
                    "< ?, > ? or BETWEEN ? AND ?",
                    token,
                )
            return Comparison(field, table, column, sql_op, math.nan)
        if words is TEXT:
            if kind not in ("word", "text"):
                self._fail(
                    f"{'.'.join(names)} needs a text value in quotes, e.g. 'Combat Arms', "
                    f"not {_value_text(value)!r}",
                    token,
                )
            if sql_op not in ("=", "!="):
                self._fail(f"{'.'.join(names)} can only be compared with = or !=", op)
            value_text = _unquote(token) if kind == "text" else str(token)
            return Comparison(field, table, column, sql_op, value_text, nocase=True)
        if words is not None:
            if kind == "text":
                # lark's stand-alone generator defines _T three times, so mypy reads this
                # classmethod's cls as a Lark's: the generated module's own typing slip.
                token = Token.new_borrow_pos("NAME", _unquote(token), token)  # type: ignore[misc]
            if kind not in ("word", "text") or token.lower() not in words:
                self._fail(
                    f"{'.'.join(names)} is one of {', '.join(words)}, not {_value_text(value)!r}",
                    token,
                )
            if sql_op not in ("=", "!="):
                self._fail(f"{'.'.join(names)} can only be compared with = or !=", op)
            return Comparison(field, table, column, sql_op, token.lower())
        if kind != "number":
            self._fail(f"{'.'.join(names)} needs a number, not {str(token)!r}", token)
        total = 0.0
        for number_token, unit_token in parts:
            number = float(number_token)
            if not math.isfinite(number) or abs(number) > LARGEST_NUMBER:
                self._fail(f"{str(number_token)!r} is not a usable number", number_token)
            if unit_token is None and len(parts) > 1:
                self._fail(
                    f"each number of {_value_text(value)!r} needs its unit, e.g. 6 ft 2 in",
                    number_token,
                )
            if unit_token is not None:
                if not unit:
                    self._fail(
                        f"{'.'.join(names)} takes no unit, found {str(unit_token)!r}", unit_token
                    )
                try:
                    number = convert(number, unit_name(str(unit_token)), unit)
                except UnitError as exc:
                    self._fail(f"{exc}", unit_token)
            total += number
        return Comparison(field, table, column, sql_op, total)

    def _resolve(self, names: list[Token]) -> FieldInfo:
        try:
            table, column, unit, words = resolve_field([str(n) for n in names])
        except _FieldError as exc:
            self._fail(str(exc), names[min(exc.part, len(names) - 1)])
        if table != "person":
            self._count_table(table)
        return table, column, unit, words


class _FieldError(Exception):
    def __init__(self, message: str, part: int):
        super().__init__(message)
        self.part = part


def _unquote(token: Token | str) -> str:
    return str(token)[1:-1]


def _value_text(value: _Value) -> str:
    """A number with its units as written (`6 ft 2 in`), or the word or quoted text."""
    kind, token, parts = value
    if kind != "number":
        return str(token)
    return " ".join(f"{n} {u}" if u is not None else str(n) for n, u in parts)


FieldInfo = tuple[str, str, "str | None", "tuple[str, ...] | None"]


def resolve_field(names: list[str]) -> FieldInfo:
    """A field's parts (`["measure", "sittingheight"]`) -> (table, column,
    stored unit or None, allowed words / TEXT / None); raises _FieldError."""
    head = names[0].lower()
    if len(names) == 1 and head in _GLOBAL_FIELDS:
        alias, column, unit, words = _GLOBAL_FIELDS[head]
        return ("person" if alias == "p" else "strength_q"), column, unit, words
    if head == "measure":
        if len(names) != 2:
            raise _FieldError("expected measure.NAME, e.g. measure.sittingheight", 0)
        name = names[1].lower()
        if name not in MEASURE_UNITS:
            close = suggest(name)
            hint = (
                f"; did you mean {' or '.join(close)}?"
                if close
                else ("; the names are the ANSUR II survey's, lower case (e.g. sittingheight)")
            )
            raise _FieldError(f"unknown measurement {names[1]!r}{hint}", 1)
        return MEASURE_TABLE, name, MEASURE_UNITS[name], None
    if head not in _GROUPS:
        close = suggest_field(head)
        expected = (
            f"did you mean {' or '.join(close)}? (sass query --fields lists every field)"
            if close
            else f"expected one of {', '.join(_GLOBAL_FIELDS)}, measure.NAME or "
            "girth.SEGMENT.x|y|z, joint_limit.JOINT.x|y|z, center_of_mass.SEGMENT.x|y|z, "
            "strength.MOTION.max"
        )
        raise _FieldError(f"unknown field {names[0]!r}; {expected}", 0)
    group, rows, unit, what = _GROUPS[head]
    if len(names) != 3:
        shape = (
            "strength.MOTION.max"
            if head == "strength"
            else f"{head}.{what.upper().replace(' ', '_')}.x|y|z"
        )
        raise _FieldError(f"expected {shape}", 0)
    row, axis = names[1].lower(), names[2].lower()
    if row not in rows:
        close = suggest(row, names=rows)
        expected = (
            f"did you mean {' or '.join(close)}?" if close else f"expected one of {', '.join(rows)}"
        )
        raise _FieldError(f"unknown {what} {names[1]!r}; {expected}", 1)
    expected_axes = ("max",) if head == "strength" else ("x", "y", "z")
    if axis not in expected_axes:
        raise _FieldError(
            f"expected {' or '.join(expected_axes)} after {head}.{row}, found {names[2]!r}", 2
        )
    return QUERY_TABLES[group][row], axis, unit, None


def field_column(name: str) -> tuple[str, str, str | None]:
    """The table, column and stored unit of the field `name` (any name
    `sass query --fields` lists, e.g. measure.poplitealheight); QueryError
    naming the field when it is none."""
    try:
        table, column, unit, _words = resolve_field(name.strip().split("."))
    except _FieldError as exc:
        raise QueryError(str(exc)) from None
    return table, column, unit


# Words people use for a field under another name.
_FIELD_SYNONYMS = {
    "weight": "mass",
    "bodyweight": "mass",
    "height": "stature",
    "sex": "gender",
    "hand": "handedness",
    "race": "dodrace",
}


def suggest_field(name: str) -> list[str]:
    """Fields a user may have meant by the unknown `name`: its synonym (`weight`
    -> `mass`), names close to it, or the measurement of that name."""
    word = name.lower()
    if word in _FIELD_SYNONYMS:
        return [_FIELD_SYNONYMS[word]]
    if word in MEASURE_UNITS:
        return [f"{MEASURE_TABLE}.{word}"]
    close = suggest(word, names=(*_GLOBAL_FIELDS, MEASURE_TABLE, *_GROUPS))
    return close or [f"{MEASURE_TABLE}.{m}" for m in suggest(word)]


def field_names() -> list[tuple[str, str]]:
    """Every queryable field and its unit ('' none, 'text' free text, else the
    stored unit): for a searchable field menu."""
    out: list[tuple[str, str]] = []
    for name, (_alias, _column, unit, words) in _GLOBAL_FIELDS.items():
        out.append((name, "text" if words is not None else (unit or "")))
    out += [(f"measure.{name}", MEASURE_UNITS[name]) for name in MEASURE_UNITS]
    for head, (_group, rows, unit, _what) in _GROUPS.items():
        axes = ("max",) if head == "strength" else ("x", "y", "z")
        out += [(f"{head}.{row}.{axis}", unit) for row in rows for axis in axes]
    return out


class ParsedQuery(NamedTuple):  # not a dataclass: see model.names.Row
    """A query parsed once: its text, its tree as written (no scope added),
    and the terms its top-level AND joins, each with its text (one term, the
    whole query, when it is not an AND); a command passes it on instead of
    its text (compile_query, compile_conjuncts, names_source)."""

    text: str
    tree: Expr
    terms: tuple[tuple[str, Expr], ...]
    or_column: int | None  # the column of an OR at the top level: no terms to split


def parse(text: str, unknowns: bool = False) -> ParsedQuery:
    """Parse and check a query; raises QueryError pointing at the bad token.
    With `unknowns`, a `?` may stand for a limit's value (`stature <= ?`,
    `BETWEEN ? AND ?`): its comparison's value is NaN (sass design solves it)."""
    if not text.strip():
        raise QueryError(
            "the query is empty; expected e.g. gender = male AND stature > 180 cm", text, 1
        )
    check_size(text)
    try:
        tree = parser().parse(text)
    except UnexpectedCharacters as exc:
        # a list's or another language's separator between two conditions
        joined = "; join conditions with AND or OR" if exc.char in ",;&|" else ""
        raise QueryError(f"unexpected character {exc.char!r}{joined}", text, exc.column) from None
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
    builder = _TreeBuilder(text, unknowns)
    try:
        expr: Expr = builder.transform(tree)
    except VisitError as exc:
        if isinstance(exc.orig_exc, QueryError):
            raise exc.orig_exc from None
        raise
    whole_group = _parenthesised(text, tree.meta.start_pos)
    if tree.data == "and_expr" and not whole_group and isinstance(expr, And):
        # every child of an and_expr is a subtree (a comparison or a group), never a
        # token, and the builder makes one term of each, in order
        children = [t for t in tree.children if isinstance(t, Tree)]
        terms = tuple((_term_text(text, child), term) for child, term in zip(children, expr.terms))
        return ParsedQuery(text, expr, terms, None)
    or_column = _first_or_column(text, tree) if tree.data == "or_expr" and not whole_group else None
    return ParsedQuery(text, expr, ((_term_text(text, tree), expr),), or_column)


def _term_text(text: str, term: Tree[Token]) -> str:
    label = text[term.meta.start_pos : term.meta.end_pos]
    if term.data in ("or_expr", "and_expr"):  # only a parenthesised group is a tree here
        label = f"({label})"
    return " ".join(label.split())


def parse_option(text: str, option: str) -> ParsedQuery:
    """`parse` for the query a command-line option gives: its error names the
    option (`--population: column 3: ...`)."""
    try:
        return parse(text)
    except QueryError as exc:
        error = QueryError(f"{option}: {exc}", exc.text)
        error.column = exc.column
        raise error from None


def parsed(query: str | ParsedQuery) -> ParsedQuery:
    """The query parsed, unless it is already."""
    return query if isinstance(query, ParsedQuery) else parse(query)


def joined(*queries: str | ParsedQuery, text: str | None = None) -> ParsedQuery:
    """The queries joined by AND, the tree `(a) AND (b)` parses to, each
    query parsed once (a population and a target's, a population and a
    gender); `text` says it (default `(a) AND (b)`)."""
    parts = [parsed(q) for q in queries]
    if text is None:
        text = " AND ".join(f"({part.text})" for part in parts)
    terms = tuple((f"({' '.join(part.text.split())})", part.tree) for part in parts)
    return ParsedQuery(text, And(tuple(part.tree for part in parts)), terms, None)


def unlikely_numbers(expr: Expr) -> list[str]:
    """A note for each stature or mass the query compares with a number no
    human has (model/body/human.py): `stature <= 1.9` asks for 1.9 cm and
    answers 0 % without a word; the note says which unit was likely meant."""
    notes = []
    for c in expr.comparisons():
        if c.table != PERSON_TABLE or c.column not in ("stature", "mass"):
            continue
        if isinstance(c.value, str) or not (refused := not_human(c.column, float(c.value))):
            continue
        value = float(c.value)
        if c.column == "stature":
            meant = f"{value:g} m" if 0 < value < 3 else f"{value:g} mm" if value > 300 else ""
        else:
            meant = f"{value:g} g" if value > 500 else ""
        if meant:  # `mass > 0`, a bound no one lies beyond, is no mistake
            notes.append(
                f"note: {c.field} {c.op} {value:g}: {refused}; did you mean `{c.field} {c.op} {meant}`?"
            )
    return notes


def parse_query(text: str) -> Expr:
    """The query's tree as the user wrote it (no scope added); raises QueryError
    pointing at the bad token."""
    return parse(text).tree


def compile_query(query: str | ParsedQuery) -> CompiledQuery:
    """Parse (unless it is parsed) and check a query; raises QueryError pointing
    at the bad token.  A query that names no `source` reaches real people only
    (db/query/scope.py)."""
    once = parsed(query)
    return _compiled(once.text, real_only(once.tree))


def _compiled(text: str, expr: Expr, alias_of: dict[str, str] | None = None) -> CompiledQuery:
    """The tree with its SQLite condition, its tables joined under `alias_of`
    (default: `aliases(expr)`)."""
    alias_of = aliases(expr) if alias_of is None else alias_of
    where, params = to_sql(expr, "sqlite", alias_of)
    joined = tuple((alias, table) for table, alias in alias_of.items() if table != PERSON_TABLE)
    return CompiledQuery(text, where, tuple(params), joined, expr)


def real_people_only(compiled: CompiledQuery) -> CompiledQuery:
    """A query compiled as a part (`compile_conjuncts`) limited to real people
    unless it names a source (db/query/scope.py), under the same aliases."""
    alias_of = {PERSON_TABLE: "p"} | {table: alias for alias, table in compiled.tables}
    return _compiled(compiled.text, real_only(compiled.tree), alias_of)


def names_source(query: str | ParsedQuery) -> bool:
    """Whether the query names a `source` term (then it is not limited to real
    people: db/query/scope.py).  The query must compile."""
    return names_field(parsed(query).tree, "source")


_TOKEN_WORDS = {
    "_AND": "AND",
    "_OR": "OR",
    "_NOT": "NOT",
    "_BETWEEN": "BETWEEN",
    "OP": "a comparison (< > <= >= = !=)",
    "NAME": "a name",
    "NUMBER": "a number",
    "UNIT": "a unit",
    "STRING": "a quoted text",
    "UNKNOWN": "? (an unknown, sass design only)",
    "LPAR": "(",
    "RPAR": ")",
    "DOT": ".",
    "$END": "the end",
}


def _expected(expected: Iterable[str]) -> str:
    return ", ".join(sorted({_TOKEN_WORDS.get(e, e) for e in expected}))


# --- running --------------------------------------------------------------

PERSON_FIELDS = ("id", "name", "gender", "mass", "stature", "handedness", "age", "source")
# The query list's rows: a real person's survey branch, the synthetic people's strength.
LIST_FIELDS = PERSON_FIELDS + (
    "strength_type",
    "motion_speed",
    "training_level",
    "fatigue_level",
    "branch",
)
_PERSON_SELECT = "p.id_num, p.name, p.gender, p.mass, p.stature, p.handedness, p.age, p.source"
_SELECT = (
    f"{_PERSON_SELECT}, sq.strength_type, sq.motion_speed, sq.training_level, sq.fatigue_level, "
    "p.branch"
)


class Query:
    """A compiled query bound to a connection (SQLite's, or a PostgresConnection
    of db/engine/postgres.py): count it, fetch it a page at a time."""

    def __init__(self, conn: Connection, compiled: CompiledQuery) -> None:
        self.conn = conn
        self.compiled = compiled
        self.dialect: Dialect = getattr(conn, "dialect", "sqlite")
        self.where, self.params = compiled.sql(self.dialect)
        self.mark = placeholder(self.dialect)

    def count(self) -> int:
        if self.dialect == "sqlite":
            fast = self._from_copy(ids=False)
            if fast is not None:  # None below ~200k people, or without DuckDB
                return int(fast)
        sql = f"SELECT count(*) FROM {self.compiled.from_clause()} WHERE {self.where}"
        count: int = self.conn.execute(sql, self.params).fetchone()[0]
        return count

    def _from_copy(self, *, ids: bool) -> Any:
        """The count (or the ids) from the column copy of a SQLite file
        (db/query/accelerator.py); None when SQLite must answer."""
        # deferred: db.accelerator — off sass query, sass population, sass predict … (sass_tui/startup.py)
        from sass_tui.db.query import accelerator

        conn: Any = self.conn
        return (
            accelerator.ids(conn, self.compiled) if ids else accelerator.count(conn, self.compiled)
        )

    def _rows(self, extra: str, params: tuple[object, ...]) -> list[dict[str, Any]]:
        sql = (
            f"SELECT {_SELECT} FROM {self.compiled.from_clause()} "
            f"LEFT JOIN strength_q sq ON sq.id_num = p.id_num "
            f"WHERE {self.where}{extra}"
        )
        return [dict(zip(LIST_FIELDS, row)) for row in self.conn.execute(sql, self.params + params)]

    def page(self, offset: int = 0, limit: int = 25) -> list[dict[str, Any]]:
        """People offset .. offset+limit-1 in id order (the query list's page)."""
        mark = self.mark
        return self._rows(
            f" ORDER BY p.id_num LIMIT {mark} OFFSET {mark}", (int(limit), int(offset))
        )

    def page_after(self, last_id: int | None, limit: int = 25) -> list[dict[str, Any]]:
        """The next page after person `last_id` (keyset paging: cost independent of depth)."""
        if last_id is None:
            return self.page(0, limit)
        mark = self.mark
        return self._rows(
            f" AND p.id_num > {mark} ORDER BY p.id_num LIMIT {mark}", (int(last_id), int(limit))
        )

    def ids(self) -> list[int]:
        if self.dialect == "sqlite":
            fast = self._from_copy(ids=True)
            if fast is not None:
                return list(fast)
        sql = (
            f"SELECT p.id_num FROM {self.compiled.from_clause()} WHERE {self.where} "
            "ORDER BY p.id_num"
        )
        return [int(r[0]) for r in self.conn.execute(sql, self.params)]

    def person_rows(self) -> Iterable[tuple[Any, ...]]:
        """Every selected person as a tuple in PERSON_FIELDS order, id order, one
        statement (the command line's listing: no dict per row, no paging)."""
        sql = (
            f"SELECT {_PERSON_SELECT} FROM {self.compiled.from_clause()} "
            f"WHERE {self.where} ORDER BY p.id_num"
        )
        rows: Iterable[tuple[Any, ...]] = self.conn.execute(sql, self.params)
        return rows

    def iter_all(self, page_size: int = 1000) -> Iterator[dict[str, Any]]:
        last = None
        while True:
            rows = self.page_after(last, page_size)
            if not rows:
                return
            yield from rows
            last = rows[-1]["id"]


def demonstration_hint(
    conn: Connection, query: str | CompiledQuery, found: int | None = None
) -> str | None:
    """For a query that found no real person: how many demonstration people it
    would find, and the query that finds them (None: none, or it named a
    source).  `found`: the query's count, if the caller has it already."""
    compiled = query if isinstance(query, CompiledQuery) else compile_query(query)
    if compiled.names_field("source"):
        return None  # it names a source: its answer is what it asked for
    if found is None:
        found = Query(conn, compiled).count()
    if found:
        return None  # it finds real people (e.g. all already selected)
    text = compiled.text
    reach = _compiled(demonstration_query(text), demonstration_tree(compiled.tree))
    reached = Query(conn, reach).count()
    if not reached:
        return None
    carry = (
        " (only they carry strength, joint-limit and center-of-mass values)"
        if any(word in text.lower() for word in ("strength", "joint_limit", "center_of_mass"))
        else ""
    )
    people = "person matches" if reached == 1 else "people match"
    return (
        f"no real person matches; {reached} synthetic demonstration {people}{carry}: {reach.text}"
    )


def run_query(conn: Connection, query: str | ParsedQuery) -> Query:
    return Query(conn, compile_query(query))


def compile_conjuncts(
    query: str | ParsedQuery, first: ParsedQuery | None = None
) -> tuple[CompiledQuery, ...]:
    """The terms a query's top-level AND joins, each compiled on its own;
    with `first`, that query is one more term before them (fit's population
    before its limits: `(population) AND limits`, parsed once each).

    Every term shares one set of joined tables (each term's `tables` is the
    whole set), so the terms can be evaluated side by side in one SELECT.  A
    parenthesised group is one term (`(stature > 160 cm AND stature < 190 cm)`
    is one range), and so is a query wholly in parentheses.  An OR at the top
    level has no terms to split: it is refused, pointing at the OR.
    """
    once = parsed(query)
    if once.or_column is not None:
        raise QueryError(
            "terms joined by OR at the top level cannot be split into separate terms; "
            "join the terms with AND, and put alternatives in parentheses to make them "
            "one term, e.g. (stature < 190 cm OR mass < 100 kg) AND gender = male",
            once.text,
            once.or_column,
        )
    built = list(once.terms)
    if first is not None:
        label = " ".join(first.text.split())
        built.insert(0, (f"({label})" if isinstance(first.tree, And | Or) else label, first.tree))
    # One alias per table over all the terms, so they can share one FROM clause.
    alias_of = aliases(And(tuple(expr for _, expr in built)))
    if len(alias_of) - 1 > MAX_JOINED_TABLES:
        raise QueryError(
            f"the population and the limits use more than {MAX_JOINED_TABLES} different "
            "segments, joints and motions together; split them",
            once.text,
        )
    return tuple(_compiled(label, expr, alias_of) for label, expr in built)


def _parenthesised(text: str, start: int) -> bool:
    """Whether the whole query is one parenthesised group around the tree starting at `start`."""
    prefix = text[:start]
    if not prefix.strip() or prefix.strip(" \t\r\n(") != "":
        return False
    depth = 0
    for position, char in enumerate(text):
        if char == "(":
            depth += 1
        elif char == ")":
            depth -= 1
            if depth == 0:  # the first paren closes here: the group must end the query
                return text[position + 1 :].strip() == ""
    return False


def _first_or_column(text: str, tree: Tree[Token]) -> int | None:
    """Column of the first top-level OR (between the first two terms)."""
    first, second = tree.children[0], tree.children[1]
    if not isinstance(first, Tree) or not isinstance(second, Tree):
        return None
    end = first.meta.end_pos
    start = second.meta.start_pos
    offset = text.lower().find("or", end, start)
    return offset + 1 if offset >= 0 else None
