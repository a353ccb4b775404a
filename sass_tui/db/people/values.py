"""Values of many people at once, as a matrix: what prediction, fit tests,
manikin families and populations compute with.

    values = load_values(conn, ["stature", "measure.sittingheight"], "gender = female")
    values.matrix[:, 1]          # sitting heights of every woman, cm (NaN = not measured)

Fields are query-language names (`stature`, `mass`, `age`,
`measure.sittingheight`, `girth.right_upper_arm.z`, `center_of_mass.head.x`,
`strength.elbow_flexion.max`, ...); values are in canonical units (cm, kg,
deg, N-m, years).  `where` is a query in the query language; `ids` (a
selected list) keeps only those people (both may be given).  People come in
id order.  No Textual import here.
"""

from __future__ import annotations

import sqlite3
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from sass_tui.db.engine.dialect import dialect_of, ids_in
from sass_tui.db.query.query import (
    MEASURE_TABLE,
    TEXT,
    ParsedQuery,
    QueryError,
    _FieldError,
    compile_query,
    resolve_field,
)
from sass_tui.db.query.query_tree import PERSON_TABLE, to_sql
from sass_tui.db.query.scope import real_only
from sass_tui.model.measures import MEASURES

MEASURE_INDEX = {name: j for j, name in enumerate(MEASURES)}


@dataclass(frozen=True)
class Values:
    ids: np.ndarray  # int64, (n,)
    names: tuple[str, ...]
    genders: tuple[str, ...]
    fields: tuple[str, ...]
    units: tuple[str, ...]  # canonical unit of each field ('' if none)
    matrix: np.ndarray  # float64, (n, len(fields)); NaN = not measured

    def __len__(self) -> int:
        return len(self.ids)

    def only(self, ids: np.ndarray) -> Values:
        """These values of the people among `ids` alone (their order kept)."""
        keep = np.isin(self.ids, ids)
        return Values(
            ids=self.ids[keep],
            names=tuple(n for n, k in zip(self.names, keep) if k),
            genders=tuple(g for g, k in zip(self.genders, keep) if k),
            fields=self.fields,
            units=self.units,
            matrix=self.matrix[keep],
        )

    def column(self, field: str) -> np.ndarray:
        return self.matrix[:, self.fields.index(field)]


def numeric_field(field: str) -> tuple[str, str, str]:
    """A numeric field's (table, column, unit); QueryError for unknown or text fields."""
    try:
        table, column, unit, words = resolve_field(field.split("."))
    except _FieldError as exc:
        raise QueryError(f"field {field!r}: {exc}", field) from None
    if words is not None or words is TEXT:
        raise QueryError(f"field {field!r} holds words, not numbers", field)
    return table, column, unit or ""


def load_values(
    conn: sqlite3.Connection,
    fields: Sequence[str],
    where: str | ParsedQuery | None = None,
    *,
    ids: Sequence[int] | None = None,
) -> Values:
    """Every selected person's values of `fields` (see the module's docstring)."""
    resolved = [numeric_field(f) for f in fields]
    dialect = dialect_of(conn)
    blank = where is None or (isinstance(where, str) and not where.strip())
    compiled = None if where is None or blank else compile_query(where)
    aliases: dict[str, str] = {}
    joins = []
    columns = []
    measure_slots: list[tuple[int, int]] = []  # (field index, MEASURES index)
    # SQLite reads the measures from measure_packed (one row of doubles per
    # person, kept by triggers); PostgreSQL has no such copy and selects them
    # from the measure table like any other column.
    packed = dialect == "sqlite"
    for k, (table, column, _unit) in enumerate(resolved):
        if table == MEASURE_TABLE and packed:
            measure_slots.append((k, MEASURE_INDEX[column]))
            continue
        if table == "person":
            columns.append(f"p.{column}")
            continue
        if table not in aliases:
            aliases[table] = f"v{len(aliases)}"
            joins.append(
                f" LEFT JOIN {table} {aliases[table]} ON {aliases[table]}.id_num = p.id_num"
            )
        columns.append(f"{aliases[table]}.{column}")
    other = [
        k for k, (table, _c, _u) in enumerate(resolved) if not (table == MEASURE_TABLE and packed)
    ]
    select = ["p.id_num", "p.name", "p.gender"] + columns
    if measure_slots:
        joins.append(" LEFT JOIN measure_packed vp ON vp.id_num = p.id_num")
        select += ["vp.id_num IS NOT NULL", "vp.data"]
    conditions: list[str] = []
    params: tuple[object, ...] = ()
    if compiled is not None:
        from_clause = compiled.from_clause() + "".join(joins)
        condition, params = compiled.sql(dialect)
        conditions.append(condition)
    else:
        from_clause = "person p" + "".join(joins)
        if (
            ids is None
        ):  # everyone: every real person (db/query/scope.py), e.g. what predict learns from
            scope, scope_params = to_sql(real_only(None), dialect, {PERSON_TABLE: "p"})
            conditions.append(scope)
            params = (*params, *scope_params)
    if ids is not None:
        condition, listed = ids_in(conn, "p.id_num", ids)
        conditions.append(condition)
        params = (*params, listed)
    where_sql = f" WHERE {' AND '.join(f'({c})' for c in conditions)}" if conditions else ""
    sql = f"SELECT {', '.join(select)} FROM {from_clause}{where_sql} ORDER BY p.id_num"
    rows = conn.execute(sql, params).fetchall()
    n = len(rows)
    matrix = np.full((n, len(fields)), np.nan)
    if not n:
        return Values(
            ids=np.empty(0, dtype=np.int64),
            names=(),
            genders=(),
            fields=tuple(fields),
            units=tuple(unit for _t, _c, unit in resolved),
            matrix=matrix,
        )
    ids, names, genders, *data = zip(*rows)
    if other:
        matrix[:, other] = np.array(data[: len(other)], dtype=float).T
    if measure_slots:
        _fill_measures(conn, matrix, measure_slots, ids, data[len(other)], data[len(other) + 1])
    return Values(
        ids=np.array(ids, dtype=np.int64),
        names=tuple(names),
        genders=tuple(genders),
        fields=tuple(fields),
        units=tuple(unit for _t, _c, unit in resolved),
        matrix=matrix,
    )


def _fill_measures(
    conn: sqlite3.Connection,
    matrix: np.ndarray,
    slots: list[tuple[int, int]],
    ids: Sequence[int],
    measured: Sequence[int],
    blobs: Sequence[bytes | None],
) -> None:
    """Measures from the packed rows; a stale row (NULL) from the measure table."""
    width = len(MEASURES) * 8
    have = np.array([b is not None for b in blobs])
    targets = [k for k, _j in slots]
    sources = [j for _k, j in slots]
    if have.any():
        packed = np.frombuffer(b"".join(b for b in blobs if b is not None), dtype="<f8")
        packed = packed.reshape(-1, width // 8)
        rows = np.flatnonzero(have)
        matrix[np.ix_(rows, np.array(targets, dtype=np.intp))] = packed[:, sources]
    stale = [k for k in range(len(ids)) if measured[k] and blobs[k] is None]
    columns = ", ".join(MEASURES[j] for j in sources)
    for start in range(0, len(stale), 500):
        part = stale[start : start + 500]
        where = {int(ids[k]): k for k in part}
        marks = ", ".join("?" * len(part))
        for id_num, *values in conn.execute(
            f"SELECT id_num, {columns} FROM measure WHERE id_num IN ({marks})", list(where)
        ):
            matrix[where[id_num], targets] = np.array(values, dtype=float)
