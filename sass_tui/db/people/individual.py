"""Fetch one person with every group, ready for the anthropometric spreadsheet
(report §12.4, Disp. Indv.): arrays in the model's row order, canonical units
(cm, deg, kg, N-m), NaN where the database has no value."""

from __future__ import annotations

import sqlite3
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from sass_tui.db.engine.dialect import dialect_of
from sass_tui.db.engine.schema import (
    CENTER_OF_MASS_NAMES,
    ELBOW_MOTIONS,
    GIRTH_NAMES,
    JOINT_LIMIT_NAMES,
    PERSON_ATTRIBUTES,
    QUERY_TABLES,
    SHOULDER_MOTIONS,
    STRENGTH_Q_COLUMNS,
    WRIST_MOTIONS,
    DatabaseError,
    strength_summary,
)
from sass_tui.db.query.query_tree import placeholder
from sass_tui.db.query.scope import DEMONSTRATION_SOURCE, VIRTUAL_PREFIX
from sass_tui.model.body.landmarks import LANDMARK_MEASURES
from sass_tui.model.measures import MEASURES
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GROUPS, JOINT_LIMITS
from sass_tui.model.vocabulary import EXPERIMENT_PARAMETERS

if TYPE_CHECKING:
    from sass_tui.db.engine.database import Database
    from sass_tui.model.body.figure import Figure


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
    # as strength_q: type, speed, training, fatigue, <motion>_max (N-m)
    strength: dict[str, str | float | None]
    experiments: list[dict[str, Any]] = field(default_factory=list)  # strength_par rows
    shoulder: list[dict[str, Any]] = field(default_factory=list)
    elbow: list[dict[str, Any]] = field(default_factory=list)
    wrist: list[dict[str, Any]] = field(default_factory=list)
    # the measurements that place the person's landmarks (LANDMARK_MEASURES, cm)
    landmarks: dict[str, float] = field(default_factory=dict)


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
    """Nine reads by key, one per relation, in one read transaction (the
    caller's if it has one open).  The strength summary (first experiment's
    parameters, each motion's maximum) is computed from the experiments read
    here, by the function that fills the query tables at storage, instead of
    fifteen more reads of strength_q and the q_strength_* tables: each of
    those is a B-tree of its own whose pages for a random person are rarely
    in cache (docs/performance.md, "Database at scale").

    One transaction: the person is one snapshot (no write can commit between
    two of the reads), and SQLite takes its shared lock, looks for a hot
    journal and reads the file's change counter once instead of once per
    read (32 fcntl and 25 stat calls a fetch before): a third less CPU."""
    if conn.in_transaction:
        return _fetch_individual(conn, int(id_num))
    if dialect_of(conn) == "postgresql":  # one snapshot for the reads, as SQLite's one transaction
        with conn.transaction():  # type: ignore[attr-defined]
            conn.execute("SET TRANSACTION ISOLATION LEVEL REPEATABLE READ")
            return _fetch_individual(conn, int(id_num))
    conn.execute("BEGIN")
    try:
        return _fetch_individual(conn, int(id_num))
    finally:
        if conn.in_transaction:
            conn.execute("COMMIT")


def _fetch_individual(conn: sqlite3.Connection, id_num: int) -> Individual:
    m = placeholder(dialect_of(conn))
    person = conn.execute(
        "SELECT id_num, name, gender, stature, mass, handedness, age, source "
        f"FROM person WHERE id_num = {m}",
        (id_num,),
    ).fetchone()
    if person is None:
        raise DatabaseError(f"no person with id {id_num}")
    girth = conn.execute(
        f"SELECT seg_name, thickness, width, length, mass FROM girth WHERE id_num = {m}", (id_num,)
    ).fetchall()
    joint_limits = conn.execute(
        f"SELECT seg_name, jlimit_x, jlimit_y, jlimit_z FROM joint_limits WHERE id_num = {m}",
        (id_num,),
    ).fetchall()
    cmass = conn.execute(
        f"SELECT seg_name, cmass_x, cmass_y, cmass_z FROM center_of_mass WHERE id_num = {m}",
        (id_num,),
    ).fetchall()
    experiments = _dicts(
        conn.execute(f"SELECT * FROM strength_par WHERE id_num = {m} ORDER BY exp_num", (id_num,))
    )
    shoulder = _dicts(
        conn.execute(
            f"SELECT * FROM shoulder_strgh WHERE id_num = {m} ORDER BY exp_num, axis", (id_num,)
        )
    )
    elbow = _dicts(
        conn.execute(f"SELECT * FROM elbow_strgh WHERE id_num = {m} ORDER BY exp_num", (id_num,))
    )
    wrist = _dicts(
        conn.execute(
            f"SELECT * FROM wrist_strgh WHERE id_num = {m} ORDER BY exp_num, axis", (id_num,)
        )
    )
    measured = conn.execute(
        f"SELECT {', '.join(LANDMARK_MEASURES)} FROM measure WHERE id_num = {m}", (id_num,)
    ).fetchone()
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
        landmarks={
            name: float(value)
            for name, value in zip(LANDMARK_MEASURES, measured or ())
            if value is not None
        },
    )


# --- a whole person for `sass person` (the headless Disp. Indv.) ---------------------

_AXES = ("x", "y", "z")


def find_person(conn: sqlite3.Connection, key: str) -> int:
    """The id of the person `key` names: a database id, or a name (any case)."""
    text = " ".join(key.split())  # spacing as typed does not matter
    m = placeholder(dialect_of(conn))
    same_name = (
        f"name = {m} COLLATE NOCASE"
        if dialect_of(conn) == "sqlite"
        else f"lower(name) = lower({m})"
    )
    if text.isascii() and text.isdigit() and int(text) < 2**63:  # SQLite's INTEGER
        row = conn.execute(f"SELECT id_num FROM person WHERE id_num = {m}", (int(text),)).fetchone()
        if row is not None:
            return int(row[0])
    found = [
        int(r[0])
        for r in conn.execute(
            f"SELECT id_num FROM person WHERE {same_name} ORDER BY id_num", (text,)
        )
    ]
    if len(found) == 1:
        return found[0]
    if found:
        raise DatabaseError(
            f"{len(found)} people are named {key!r} (ids {', '.join(map(str, found[:10]))}); "
            "give the id"
        )
    raise DatabaseError(f"no person with id or name {key!r}")


def person_record(conn: sqlite3.Connection, id_num: int) -> dict[str, object]:
    """Everything stored about one person, by query-language names, canonical
    units (cm, kg, deg, N-m): `values` (group rows and survey attributes),
    `measures` (ANSUR II measurements) and `unmeasured` (names with no value)."""
    person = fetch_individual(conn, id_num)
    m = placeholder(dialect_of(conn))
    values: dict[str, object] = {}
    unmeasured: list[str] = []
    for word, group, names in (
        ("girth", GIRTH, GIRTH_NAMES),
        ("joint_limit", JOINT_LIMITS, JOINT_LIMIT_NAMES),
        ("center_of_mass", CENTER_OF_MASS, CENTER_OF_MASS_NAMES),
    ):
        cells = person.groups[group]
        for r, row in enumerate(names):
            for a, axis in enumerate(_AXES):
                name = f"{word}.{row}.{axis}"
                value = float(cells[r, a])
                if value == value:
                    values[name] = value
                else:
                    unmeasured.append(name)
    for table_name, motion in zip(QUERY_TABLES["strength"].values(), QUERY_TABLES["strength"]):
        row = conn.execute(f"SELECT max FROM {table_name} WHERE id_num = {m}", (id_num,)).fetchone()
        name = f"strength.{motion}.max"
        if row is not None and row[0] is not None:
            values[name] = float(row[0])
        else:
            unmeasured.append(name)
    attributes = conn.execute(
        f"SELECT handedness, {', '.join(PERSON_ATTRIBUTES)} FROM person WHERE id_num = {m}",
        (id_num,),
    ).fetchone()
    for name, value in zip(("handedness", *PERSON_ATTRIBUTES), attributes):
        if value is not None:
            values[name] = value
    measured = conn.execute(
        f"SELECT {', '.join(MEASURES)} FROM measure WHERE id_num = {m}", (id_num,)
    ).fetchone()
    measures: dict[str, float] = {}
    for k, name in enumerate(MEASURES):
        stored = None if measured is None else measured[k]
        if stored is None:
            unmeasured.append(f"measure.{name}")
        else:
            measures[name] = float(stored)

    def number(value: float) -> float | None:
        return None if value != value else value

    return {
        "id": person.id_num,
        "name": person.name,
        "gender": person.gender,
        "mass": number(person.mass),
        "stature": number(person.stature),
        "age": number(person.age),
        "source": person.source,
        "values": values,
        "measures": measures,
        "unmeasured": unmeasured,
    }


# (side, motion, 7 angles in JOINT_AXES order in deg, strength N-m,
#  (strength_type, motion_speed, training_level, fatigue_level))
StrengthMeasurement = tuple[str, str, tuple[float, ...], float, tuple[str, float, float, float]]


def person_records(database: Database, keys: Sequence[str]) -> list[dict[str, object]]:
    """Everything stored about the people `keys` name (an id or a name), in
    order (person_record), read under the database's lock: `sass person`."""
    with database.connection() as conn:
        return [person_record(conn, find_person(conn, key)) for key in keys]


def strength_measurements(person: Individual) -> list[StrengthMeasurement]:
    """The person's own strength experiments, one entry per motion measured
    (pstrgh is the axis's positive motion, nstrgh its negative one; the
    motions of schema.SHOULDER_MOTIONS, ELBOW_MOTIONS, WRIST_MOTIONS).  Angles
    an experiment does not record (the wrist in a shoulder experiment, the
    shoulder in a wrist one) are taken as neutral, 0 deg."""
    experiments = {e["exp_num"]: e for e in person.experiments}

    def angle(value: object) -> float:
        return 0.0 if value is None else float(value)  # type: ignore[arg-type]

    out: list[StrengthMeasurement] = []

    def add(row: dict[str, object], motions: tuple[str, str], angles: tuple[float, ...]) -> None:
        experiment = experiments.get(row["exp_num"])
        if experiment is None:
            return
        conditions = (
            str(experiment["strgh_type"]),
            angle(experiment["speed"]),
            angle(experiment["training"]),
            angle(experiment["fatigue"]),
        )
        for motion, value in zip(motions, (row["pstrgh"], row["nstrgh"])):
            if value is not None:
                out.append(
                    (str(experiment["side_of_limb"]), motion, angles, angle(value), conditions)
                )

    for row in person.shoulder:
        shoulder = (row["shoulder_ang_x"], row["shoulder_ang_y"], row["shoulder_ang_z"])
        add(
            row,
            SHOULDER_MOTIONS[row["axis"]],
            (*map(angle, shoulder), angle(row["elbow_ang"]), 0.0, 0.0, 0.0),
        )
    for row in person.elbow:
        names = (
            "shoulder_ang_x",
            "shoulder_ang_y",
            "shoulder_ang_z",
            "elbow_ang",
            "wrist_ang_x",
            "wrist_ang_y",
            "wrist_ang_z",
        )
        add(row, ELBOW_MOTIONS, tuple(angle(row[n]) for n in names))
    for row in person.wrist:
        wrist = (row["wrist_ang_x"], row["wrist_ang_y"], row["wrist_ang_z"])
        add(
            row,
            WRIST_MOTIONS[row["axis"]],
            (0.0, 0.0, 0.0, angle(row["elbow_ang"]), *map(angle, wrist)),
        )
    return out


def person_figure(person: Individual, population: Figure) -> Figure:
    """The person's figure (report §12.4, Disp. Indv.): their own values,
    percentiles against `population`, unmeasured cells from the population
    (the figure says which); `population` is left as it was."""
    # The figure's name is its title (and its file's name): a demonstration
    # person is never taken for a real one (db/query/scope.py).
    synthetic = person.source.lower() == DEMONSTRATION_SOURCE
    virtual = person.source.lower().startswith(VIRTUAL_PREFIX)
    label = (
        " (synthetic)" if synthetic else " (VIRTUAL: predicted, not measured)" if virtual else ""
    )
    return population.for_person(
        f"{person.name}{label}",
        person.gender,
        {g: person.groups[g] for g in GROUPS},
        mass=person.mass,
        stature=person.stature,
        landmarks=person.landmarks,
        handedness=person.handedness if person.handedness in ("right", "left") else None,
        **{k: person.strength.get(k) for k in EXPERIMENT_PARAMETERS},
    )
