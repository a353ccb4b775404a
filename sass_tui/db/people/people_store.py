"""Storing people in bulk: the batch of arrays an importer makes
(PeopleBatch), written into the relations and the query tables of
db/engine/schema.py inside the caller's transaction, and people deleted with all
their data.

Separate from db/engine/schema.py, which every path that opens a database imports
(`sass query`, `sass query --count`: sass_tui/startup.py), so that numpy is
imported at this module's top: only the importers (db/people/ansur.py,
db/people/flatfile.py, db/populations/virtual.py, the default database's db/people/default_people.py)
import it.
"""

from __future__ import annotations

import sqlite3
from collections.abc import Iterable, Sequence
from functools import lru_cache
from typing import Any

import numpy as np

from sass_tui.db.engine.schema import (
    CENTER_OF_MASS_NAMES,
    GIRTH_NAMES,
    JOINT_LIMIT_NAMES,
    PERSON_ATTRIBUTES,
    PERSON_TABLES,
    QUERY_TABLES,
    STRENGTH_PARAMETERS,
    SqlRow,
    strength_summary,
)
from sass_tui.model.measures import MEASURES
from sass_tui.model.names import FIG_PREFIX, MASS_FRACTIONS
from sass_tui.model.vocabulary import MOTION_NAMES

_MASS_FRACTION = dict(MASS_FRACTIONS)


@lru_cache(maxsize=1)
def girth_mass_fractions() -> np.ndarray:
    """Appendix K fraction of each girth row (0 for eyes, NaN for eye location).
    A function: computed once, when first stored."""
    return np.array(
        [
            _MASS_FRACTION.get(f"{FIG_PREFIX[name]}mass", 0.0) if name != "eye_location" else np.nan
            for name in GIRTH_NAMES
        ]
    )


class PeopleBatch:
    """People to store, every group as arrays in the model's row order (NaN = no value).

    Strength experiments are lists of tuples whose first element is the
    person's index in the batch, the rest the relation's fields after id_num
    (canonical units).  A plain class, not a dataclass (dataclasses imports
    inspect, docs/performance.md): the importers that make batches need not
    pay for it.
    """

    def __init__(
        self,
        *,
        id_num: np.ndarray,  # int64
        name: list[str],
        gender: list[str],
        stature: np.ndarray,
        mass: np.ndarray,
        handedness: list[str | None],
        age: np.ndarray,
        source: list[str],
        source_key: list[str | None],
        girth: np.ndarray | None = None,  # (n, 25, 4): x, y, z, mass
        joint_limits: np.ndarray | None = None,  # (n, 40, 3)
        center_of_mass: np.ndarray | None = None,  # (n, 21, 3)
        extra_girth: list[SqlRow] | None = None,  # (i, seg, x, y, z, mass)
        strength_par: list[SqlRow] | None = None,  # (i, exp, side, type, speed, fatigue, training)
        shoulder: list[SqlRow] | None = None,  # (i, exp, ax, ay, az, elbow, axis, p, n)
        elbow: list[SqlRow] | None = None,  # (i, exp, elbow, sx, sy, sz, wx, wy, wz, p, n)
        wrist: list[SqlRow] | None = None,  # (i, exp, wx, wy, wz, elbow, axis, p, n)
        # Survey attributes (PERSON_ATTRIBUTES), each a list of n values or None (no value).
        attributes: dict[str, list[object]] | None = None,
        measures: np.ndarray | None = None,  # (n, len(MEASURES)), canonical units
    ) -> None:
        self.id_num = id_num
        self.name = name
        self.gender = gender
        self.stature = stature
        self.mass = mass
        self.handedness = handedness
        self.age = age
        self.source = source
        self.source_key = source_key
        self.girth = girth
        self.joint_limits = joint_limits
        self.center_of_mass = center_of_mass
        self.extra_girth: list[SqlRow] = [] if extra_girth is None else extra_girth
        self.strength_par: list[SqlRow] = [] if strength_par is None else strength_par
        self.shoulder: list[SqlRow] = [] if shoulder is None else shoulder
        self.elbow: list[SqlRow] = [] if elbow is None else elbow
        self.wrist: list[SqlRow] = [] if wrist is None else wrist
        self.attributes: dict[str, list[object]] = {} if attributes is None else attributes
        self.measures = measures

    def __len__(self) -> int:
        return len(self.id_num)


def _nullable(array: np.ndarray) -> list[Any]:
    """Array -> nested lists with None for NaN (vectorised: object array)."""
    out = array.astype(object)
    out[np.isnan(array)] = None
    rows: list[Any] = out.tolist()
    return rows


def _long_rows(ids: list[int], names: Sequence[str], values: np.ndarray) -> Iterable[SqlRow]:
    """(id, row name, v...) for every row that has at least one value, in the
    order of the tables' key (id_num, seg_name): appended at the B-tree's end."""
    by_name = np.argsort(np.asarray(names))
    values = values[:, by_name]
    present = ~np.all(np.isnan(values), axis=2)
    person, row = np.nonzero(present)
    id_array = np.asarray(ids, dtype=np.int64)
    name_array = np.asarray(names, dtype=object)[by_name]
    return zip(
        id_array[person].tolist(),
        name_array[row].tolist(),
        *[_nullable(values[person, row, k]) for k in range(values.shape[2])],
    )


def delete_people(conn: sqlite3.Connection, ids: Sequence[int]) -> None:
    """Delete these people with all their data (inside the caller's transaction)."""
    _delete_people(conn, ids)


def _delete_people(conn: sqlite3.Connection, ids: Sequence[int]) -> None:
    conn.execute("CREATE TEMP TABLE IF NOT EXISTS _gone (id_num INTEGER PRIMARY KEY)")
    conn.execute("DELETE FROM _gone")
    conn.executemany("INSERT OR IGNORE INTO _gone VALUES (?)", ((int(i),) for i in ids))
    for table in PERSON_TABLES + ("person",):
        conn.execute(f"DELETE FROM {table} WHERE id_num IN (SELECT id_num FROM _gone)")


def store_people(conn: sqlite3.Connection, batch: PeopleBatch, *, replace: bool = True) -> None:
    """Insert a batch (inside the caller's transaction).  With replace, people
    whose id_num is already stored are deleted first, with all their data."""
    ids = [int(i) for i in batch.id_num]
    if replace:
        _delete_people(conn, ids)
    _store_people(conn, ids, batch)


def _store_people(conn: sqlite3.Connection, ids: list[int], batch: PeopleBatch) -> None:
    no_value = [None] * len(ids)
    conn.executemany(
        f"INSERT INTO person VALUES ({', '.join(['?'] * (9 + len(PERSON_ATTRIBUTES)))})",
        zip(
            ids,
            batch.name,
            batch.gender,
            _nullable(batch.stature),
            _nullable(batch.mass),
            batch.handedness,
            _nullable(batch.age),
            batch.source,
            batch.source_key,
            *[batch.attributes.get(name, no_value) for name in PERSON_ATTRIBUTES],
        ),
    )
    if batch.measures is not None:
        conn.executemany(
            f"INSERT INTO measure VALUES ({', '.join(['?'] * (1 + len(MEASURES)))})",
            ((i, *row) for i, row in zip(ids, _nullable(batch.measures))),
        )
        packed = np.ascontiguousarray(batch.measures, dtype="<f8")
        conn.executemany(
            "INSERT OR REPLACE INTO measure_packed VALUES (?, ?)",
            ((i, packed[k].tobytes()) for k, i in enumerate(ids)),
        )
    for table, names, values, width in (
        ("girth", GIRTH_NAMES, batch.girth, 4),
        ("joint_limits", JOINT_LIMIT_NAMES, batch.joint_limits, 3),
        ("center_of_mass", CENTER_OF_MASS_NAMES, batch.center_of_mass, 3),
    ):
        if values is None:
            continue
        marks = ", ".join(["?"] * (width + 2))
        conn.executemany(f"INSERT INTO {table} VALUES ({marks})", _long_rows(ids, names, values))
        id_array = np.asarray(ids, dtype=np.int64)
        for k, name in enumerate(names):
            cells = values[:, k, :3]
            present = np.flatnonzero(~np.all(np.isnan(cells), axis=1))
            # zip's tuples, column by column: no Python frame per row
            conn.executemany(
                f"INSERT INTO {QUERY_TABLES[table][name]} VALUES (?, ?, ?, ?)",
                zip(id_array[present].tolist(), *_nullable(cells[present].T)),
            )
    if batch.extra_girth:
        conn.executemany(
            "INSERT INTO girth VALUES (?, ?, ?, ?, ?, ?)",
            ((ids[i], *rest) for i, *rest in batch.extra_girth),
        )
    _store_strength(conn, ids, batch)


def _store_strength(conn: sqlite3.Connection, ids: list[int], batch: PeopleBatch) -> None:
    if not batch.strength_par:
        return
    conn.executemany(
        "INSERT INTO strength_par VALUES (?, ?, ?, ?, ?, ?, ?, 'deg', 'N-m', 'deg/s')",
        ((ids[i], *rest) for i, *rest in batch.strength_par),
    )
    conn.executemany(
        "INSERT INTO shoulder_strgh VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
        ((ids[i], *rest) for i, *rest in batch.shoulder),
    )
    conn.executemany(
        "INSERT INTO elbow_strgh VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
        ((ids[i], *rest) for i, *rest in batch.elbow),
    )
    conn.executemany(
        "INSERT INTO wrist_strgh VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
        ((ids[i], *rest) for i, *rest in batch.wrist),
    )
    summary = strength_summary(batch.strength_par, batch.shoulder, batch.elbow, batch.wrist, ids)
    width = len(STRENGTH_PARAMETERS)
    conn.executemany(
        f"INSERT INTO strength_q VALUES ({', '.join(['?'] * (width + 1))})",
        (row[: width + 1] for row in summary),
    )
    for k, motion in enumerate(MOTION_NAMES):
        conn.executemany(
            f"INSERT INTO {QUERY_TABLES['strength'][motion]} VALUES (?, ?)",
            ((row[0], row[width + 1 + k]) for row in summary if row[width + 1 + k] is not None),
        )
