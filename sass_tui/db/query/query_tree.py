"""The query language's one meaning: a typed expression tree (immutable nodes), and the SQL of
each engine compiled from it.

`db/query/query.py` parses a query once (lark) into this tree: comparisons of a
stored column with a value already converted to the stored unit, joined by
AND and OR.  Every engine compiles the same tree to its own SQL (`to_sql`):
SQLite (the file of one engineer), PostgreSQL (a lab's shared database) and
DuckDB (db/columns.py, counts over millions of people).  Nothing parses the
generated SQL back.

Null semantics are SQL's in every dialect: a comparison with a missing value
is unknown, which a WHERE reads as false; `!=` on free text keeps people
without a value (`source != ansur2` finds the people of every other source,
including those with none), as the SQLite compiler always did.

NOT is not a node: `negation` pushes it down to the comparisons (De Morgan's
laws, which hold in SQL's three-valued logic) and turns each operator into
its opposite (`NOT stature > 180` is `stature <= 180`).  On a value that is
there that is exactly SQL's NOT; on a missing value both are unknown, so
nobody without a stature is in either answer, as SQL's `NOT (...)` would
have it.  Free text's `NOT branch = 'Combat Arms'` is `branch != 'Combat
Arms'`, so it keeps the people without a branch as `!=` does.  Every
engine's SQL, the real-people scope (db/query/scope.py) and the DuckDB copy then
read NOT without knowing it.  BETWEEN is the pair `>=` and `<=` (SQL's own
definition of `x BETWEEN a AND b`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any, Literal

Dialect = Literal["sqlite", "postgresql", "duckdb"]
DIALECTS: tuple[Dialect, ...] = ("sqlite", "postgresql", "duckdb")
PERSON_TABLE = "person"
# The comparison operators of the tree: the grammar's spellings (<>, ≤, ≥, ≠) are mapped here.
OPERATORS = ("<", ">", "<=", ">=", "=", "!=")
# Each operator's opposite: `NOT x op v` holds exactly when `x OPPOSITE[op] v` does.
OPPOSITE = {"<": ">=", ">=": "<", ">": "<=", "<=": ">", "=": "!=", "!=": "="}


class _Node:
    """An immutable node compared by type and fields: what a frozen dataclass
    gives, without importing dataclasses (and inspect) on `sass query`'s path
    (tests/test_layers.py)."""

    __slots__: tuple[str, ...] = ()

    def _values(self) -> tuple[Any, ...]:
        return tuple(getattr(self, name) for name in self.__slots__)

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"{type(self).__name__} is immutable")

    def __eq__(self, other: object) -> bool:
        return (
            isinstance(other, _Node)
            and type(other) is type(self)
            and self._values() == other._values()
        )

    def __hash__(self) -> int:
        return hash((type(self).__name__, self._values()))

    def __repr__(self) -> str:
        fields = ", ".join(f"{n}={getattr(self, n)!r}" for n in self.__slots__)
        return f"{type(self).__name__}({fields})"


class Comparison(_Node):
    """`table.column op value`, the value in the column's stored unit.

    `field` is the field as the user named it, lower case and dotted
    (`source`, `measure.sittingheight`, `girth.right_upper_arm.z`); `nocase`
    marks free text compared without regard to case (only = and !=)."""

    __slots__ = ("field", "table", "column", "op", "value", "nocase")
    field: str
    table: str
    column: str
    op: str
    value: float | str
    nocase: bool

    def __init__(
        self, field: str, table: str, column: str, op: str, value: float | str, nocase: bool = False
    ) -> None:
        for name, item in zip(self.__slots__, (field, table, column, op, value, nocase)):
            object.__setattr__(self, name, item)

    def comparisons(self) -> Iterator[Comparison]:
        yield self


class _Terms(_Node):
    """A node joining its terms (And, Or): one class body for both, told apart by type."""

    __slots__ = ("terms",)
    terms: tuple[Expr, ...]

    def __init__(self, terms: tuple[Expr, ...]) -> None:
        object.__setattr__(self, "terms", tuple(terms))

    def comparisons(self) -> Iterator[Comparison]:
        for term in self.terms:
            yield from term.comparisons()


class And(_Terms):
    """Every term holds."""


class Or(_Terms):
    """Some term holds."""


Expr = Comparison | And | Or


def negation(expr: Expr) -> Expr:
    """NOT `expr`, as comparisons joined by AND and OR (see the module's docstring)."""
    if isinstance(expr, Comparison):
        return Comparison(
            expr.field, expr.table, expr.column, OPPOSITE[expr.op], expr.value, expr.nocase
        )
    negated = tuple(negation(term) for term in expr.terms)
    return Or(negated) if isinstance(expr, And) else And(negated)


def names_field(expr: Expr, name: str) -> bool:
    """Whether the query compares the field `name` anywhere (e.g. `source`:
    a scope that applies unless the user named the field)."""
    return any(c.field == name for c in expr.comparisons())


def tables(expr: Expr) -> tuple[str, ...]:
    """The tables other than person the query reads, in the order first named."""
    seen: dict[str, None] = {}
    for c in expr.comparisons():
        if c.table != PERSON_TABLE:
            seen.setdefault(c.table, None)
    return tuple(seen)


def columns(expr: Expr) -> tuple[tuple[str, str], ...]:
    """The (table, column) pairs the query reads, in the order first named."""
    return tuple(dict.fromkeys((c.table, c.column) for c in expr.comparisons()))


def aliases(expr: Expr) -> dict[str, str]:
    """table -> the alias the SQL joins it under (person is `p`)."""
    return {PERSON_TABLE: "p"} | {table: f"t{i}" for i, table in enumerate(tables(expr))}


def placeholder(dialect: Dialect) -> str:
    return "%s" if dialect == "postgresql" else "?"


def to_sql(
    expr: Expr,
    dialect: Dialect,
    alias_of: dict[str, str] | None = None,
    column_sql: Callable[[Comparison], str] | None = None,
) -> tuple[str, list[object]]:
    """The WHERE condition of `expr` in `dialect` and its parameters (the
    user's values travel only as parameters).  `alias_of` maps each table
    to the name the FROM clause gives it (default: `aliases(expr)`);
    `column_sql` names a compared column otherwise (the DuckDB copy's one
    wide table, db/query/accelerator.py)."""
    names = aliases(expr) if alias_of is None and column_sql is None else alias_of or {}
    mark = placeholder(dialect)
    if isinstance(expr, Comparison):
        column = (
            column_sql(expr) if column_sql is not None else f"{names[expr.table]}.{expr.column}"
        )
        if expr.nocase:
            if dialect == "sqlite":
                equal = f"{column} = {mark} COLLATE NOCASE"
                differ = f"{column} != {mark} COLLATE NOCASE"
            else:
                # SQLite's NOCASE folds ASCII letters only; lower() is the other engines' fold.
                equal = f"lower({column}) = lower({mark})"
                differ = f"lower({column}) != lower({mark})"
            if expr.op == "=":
                return equal, [expr.value]
            return f"({column} IS NULL OR {differ})", [expr.value]
        return f"{column} {expr.op} {mark}", [expr.value]
    joiner = " AND " if isinstance(expr, And) else " OR "
    parts = [to_sql(term, dialect, names, column_sql) for term in expr.terms]
    return "(" + joiner.join(sql for sql, _ in parts) + ")", [p for _, ps in parts for p in ps]


def from_clause(expr: Expr, alias_of: dict[str, str] | None = None) -> str:
    """`person p` and a LEFT JOIN on id_num for every other table the query reads
    (one row per person in each: the query tables of db/engine/schema.py)."""
    names = aliases(expr) if alias_of is None else alias_of
    joins = "".join(
        f" LEFT JOIN {table} {names[table]} ON {names[table]}.id_num = p.id_num"
        for table in names
        if table != PERSON_TABLE
    )
    return f"{PERSON_TABLE} p{joins}"
