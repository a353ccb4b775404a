"""Fetch one person with every group, ready for the anthropometric spreadsheet
(report §12.4, Disp. Indv.): arrays in the model's row order, canonical units
(cm, deg, kg, N-m), NaN where the database has no value."""

from __future__ import annotations

import sqlite3
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from sass_tui.db.schema import (
    CENTER_OF_MASS_NAMES,
    GIRTH_NAMES,
    JOINT_LIMIT_NAMES,
    STRENGTH_Q_COLUMNS,
    DatabaseError,
    strength_summary,
)
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS


@dataclass
class Individual:
    id_num: int
    name: str
    gender: str
    stature: float  # cm
    mass: float  # kg
    handedness: str | None
    age: float
    source: str
    groups: dict[str, np.ndarray]  # GIRTH (25, 3), JOINT_LIMITS (40, 3), CENTER_OF_MASS (21, 3)
    segment_masses: dict[str, float]  # girth seg_name -> kg (also the mass-only segments)
    strength: dict[str, object]  # as strength_q: type, speed, training, fatigue, <motion>_max (N-m)
    experiments: list[dict[str, Any]] = field(default_factory=list)  # strength_par rows
    shoulder: list[dict[str, Any]] = field(default_factory=list)
    elbow: list[dict[str, Any]] = field(default_factory=list)
    wrist: list[dict[str, Any]] = field(default_factory=list)


def _fill(rows: Sequence[Sequence[Any]], names: Sequence[str]) -> np.ndarray:
    index = {n: i for i, n in enumerate(names)}
    out = np.full((len(names), 3), np.nan)
    for seg, *values in rows:
        if seg in index:
            out[index[seg]] = [np.nan if v is None else v for v in values[:3]]
    return out


def _batch_row(row: dict[str, Any]) -> tuple[Any, ...]:
    """A relation row as storage's batch tuple: person index 0, then the fields after id_num."""
    return (0, *tuple(row.values())[1:])


def _dicts(cursor: sqlite3.Cursor) -> list[dict[str, Any]]:
    names = [d[0] for d in cursor.description]
    return [dict(zip(names, row)) for row in cursor]


def fetch_individual(conn: sqlite3.Connection, id_num: int) -> Individual:
    """Eight reads by key, one per relation.  The strength summary (first
    experiment's parameters, each motion's maximum) is computed from the
    experiments read here, by the function that fills the query tables at
    storage, instead of fifteen more reads of strength_q and the
    q_strength_* tables: each of those is a B-tree of its own whose pages
    for a random person are rarely in cache (docs/performance.md,
    "Database at scale")."""
    id_num = int(id_num)
    person = conn.execute(
        "SELECT id_num, name, gender, stature, mass, handedness, age, source "
        "FROM person WHERE id_num = ?",
        (id_num,),
    ).fetchone()
    if person is None:
        raise DatabaseError(f"no person with id {id_num}")
    girth = conn.execute(
        "SELECT seg_name, thickness, width, length, mass FROM girth WHERE id_num = ?", (id_num,)
    ).fetchall()
    joint_limits = conn.execute(
        "SELECT seg_name, jlimit_x, jlimit_y, jlimit_z FROM joint_limits WHERE id_num = ?",
        (id_num,),
    ).fetchall()
    cmass = conn.execute(
        "SELECT seg_name, cmass_x, cmass_y, cmass_z FROM center_of_mass WHERE id_num = ?", (id_num,)
    ).fetchall()
    experiments = _dicts(
        conn.execute("SELECT * FROM strength_par WHERE id_num = ? ORDER BY exp_num", (id_num,))
    )
    shoulder = _dicts(
        conn.execute(
            "SELECT * FROM shoulder_strgh WHERE id_num = ? ORDER BY exp_num, axis", (id_num,)
        )
    )
    elbow = _dicts(
        conn.execute("SELECT * FROM elbow_strgh WHERE id_num = ? ORDER BY exp_num", (id_num,))
    )
    wrist = _dicts(
        conn.execute("SELECT * FROM wrist_strgh WHERE id_num = ? ORDER BY exp_num, axis", (id_num,))
    )
    summary = strength_summary(
        [_batch_row(r)[:7] for r in experiments],
        [_batch_row(r) for r in shoulder],
        [_batch_row(r) for r in elbow],
        [_batch_row(r) for r in wrist],
        [id_num],
    )

    def nan(v: float | None) -> float:
        return np.nan if v is None else float(v)

    return Individual(
        id_num=person[0],
        name=person[1],
        gender=person[2],
        stature=nan(person[3]),
        mass=nan(person[4]),
        handedness=person[5],
        age=nan(person[6]),
        source=person[7],
        groups={
            GIRTH: _fill(girth, GIRTH_NAMES),
            JOINT_LIMITS: _fill(joint_limits, JOINT_LIMIT_NAMES),
            CENTER_OF_MASS: _fill(cmass, CENTER_OF_MASS_NAMES),
        },
        segment_masses={seg: row[-1] for seg, *row in girth if row[-1] is not None},
        strength=dict(zip(STRENGTH_Q_COLUMNS, summary[0][1:])) if summary else {},
        experiments=experiments,
        shoulder=shoulder,
        elbow=elbow,
        wrist=wrist,
    )
