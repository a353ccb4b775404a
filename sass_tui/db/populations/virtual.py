"""Virtual populations in the database: make, store, and the shipped one
(the method: sass_tui/model/population/virtual.py, docs/target-populations.md).

A virtual population NAME is one virtual person per sample row with a
gender, a stature and a mass: the row's own stature, mass, age and gender,
and its own hip (as buttock circumference) and waist circumference where the
sample measured them (MEASURED), the other ANSUR II measures predicted from
those and the age (clamped to the soldiers' 17-58) by sass's regression
fitted on the real people of that gender (model/population/prediction.py)
plus a residual drawn from its bounded heteroscedastic scatter (seed SEED:
the same database gives the same people), and the girth relation derived
from the measures as ANSUR II people's is (db/people/ansur.py's derived_girth).
A person with a known value beyond the real people's range is flagged:
the target's summary lists them (`outside_range`), `within_range` leaves
them out of a weighted answer.

They are stored as people, as ANSUR II people are (the person, measure and
girth tables), under the source `virtual:NAME` (db/query/scope.py: out of every
real answer, reached by `--virtual NAME`, the query term
`source = "virtual:NAME"`), and their survey weights, mean 1, as the
target `virtual:NAME` (db/populations/targets.py's tables; `Target.is_virtual`), so
that everything that takes a target's weights takes theirs.

No Textual, no printing.
"""

from __future__ import annotations

import datetime as _dt
import sqlite3
from dataclasses import dataclass, replace

import numpy as np
import numpy.typing as npt

from sass_tui.db.engine import staging
from sass_tui.db.engine.dialect import dialect_of, mark_of, writing
from sass_tui.db.engine.schema import PERSON_TABLES, SQLITE_ONLY_TABLES
from sass_tui.db.people.ansur import derived_girth
from sass_tui.db.people.people_store import PeopleBatch, delete_people, store_people
from sass_tui.db.people.values import load_values
from sass_tui.db.populations.targets import (
    BOTH,
    WEIGHTED_BY,
    Target,
    TargetWeights,
    UnknownTargetError,
    check_name,
    insert_target,
    make_target,
    target_exists,
)
from sass_tui.db.progress import Progress
from sass_tui.db.query.scope import virtual_query, virtual_source
from sass_tui.model.datasets import NHANES, NHANES_NAME, NHANES_WEIGHT, shipped_text
from sass_tui.model.files.sample_file import read_sample
from sass_tui.model.measures import MEASURES
from sass_tui.model.population.prediction import Predictor
from sass_tui.model.population.target_sample import Sample
from sass_tui.model.population.targets import TargetError, kish_effective_n
from sass_tui.model.population.virtual import VirtualPeople, draw_virtual, fitted_range
from sass_tui.model.vocabulary import GENDERS

SEED = 20172020
PREDICTED_FROM = ("stature", "mass")
# What a civilian survey measured as ANSUR II does, kept and predicted from
# when the sample has the column (model/files/sample_file.py's NHANES_COLUMNS).
MEASURED = ("measure.buttockcircumference", "measure.waistcircumference")
# Predicted from too, clamped to the fitted people's range (ANSUR II: 17-58).
HELD = ("age",)
# The fields the regression predicts: ANSUR II's measures, stature and mass
# as the person table holds them (model/population/prediction.py's ALIASES).
FIELDS = (
    "stature",
    "mass",
    *(f"measure.{m}" for m in MEASURES if m not in ("stature", "weightkg")),
)
# What the regression is fitted on: those and the held fields.
FITTED = (*FIELDS, *HELD)
# Whom the regression learns from: every real person (db/query/scope.py), each gender its own.
TRAINING = "gender = male OR gender = female"


@dataclass(frozen=True)
class VirtualPopulation:
    people: PeopleBatch  # ids 0: given when stored
    weights: npt.NDArray[np.float64]  # mean 1, the batch's order
    target: Target  # the target `virtual:NAME` that carries the weights
    beyond: dict[str, int]  # per gender: people beyond the range the regression was fitted on
    outside: npt.NDArray[np.bool_]  # per person, the batch's order: beyond that range


def virtual_name(name: str) -> str:
    """The target name under which a virtual population's weights are stored."""
    return virtual_source(name)


def make_virtual(
    conn: sqlite3.Connection, name: str, sample: Sample, sample_name: str, gender: str = BOTH
) -> VirtualPopulation:
    """The virtual population NAME of `sample` (its stature and mass rows; a
    row's gender from the sample's gender column, else `gender`).  Nothing stored."""
    check_name(name)
    if tuple(sample.fields[:2]) != PREDICTED_FROM:
        raise TargetError(
            "a virtual population is predicted from stature and mass: --by stature,mass"
        )
    if sample.genders is None:
        if gender == BOTH:
            raise TargetError(
                f"{sample_name}: no gender column; a virtual population of both genders "
                "needs each row's gender",
                where=sample_name,
            )
        sample = replace(sample, genders=(gender,) * len(sample.matrix))
    values = load_values(conn, FITTED, TRAINING)
    predictor = Predictor.fit(values, FITTED)
    rng = np.random.default_rng(SEED)
    parts: list[tuple[str, Sample, VirtualPeople]] = []
    beyond: dict[str, int] = {}
    fitted: dict[str, dict[str, object]] = {}
    for gender in GENDERS:
        rows = sample.of_gender(gender)
        if len(rows.matrix) == 0:
            continue
        model = predictor.model(gender)
        names, known = _known(rows, model.index())
        drawn = draw_virtual(model, names, known, rng, held=HELD)
        beyond[gender] = drawn.beyond
        fitted[gender] = {
            "people": drawn.fitted_on,
            **{field: list(fitted_range(model, field)) for field in names},
        }
        parts.append((gender, rows, drawn))
    if not parts:
        raise TargetError(f"{sample_name}: no row with a gender, a stature and a mass")
    people = _batch(name, parts)
    raw = np.concatenate([rows.row_weights for _, rows, _ in parts])
    outside = np.concatenate([drawn.outside for _, _, drawn in parts])
    weights = raw * len(raw) / raw.sum()
    label = virtual_name(name)
    target = Target(
        name=label,
        gender=BOTH,
        population=virtual_query(name),
        fields=PREDICTED_FROM,
        sample=sample_name,
        sample_rows=len(raw),
        people=len(raw),
        effective_n=kish_effective_n(weights),
        summary={
            "virtual": {
                "beyond": beyond,
                "fitted_on": fitted,
                "predicted_from": [*PREDICTED_FROM, *sample.optional_fields, *HELD],
                "kept": list(sample.optional_fields),
                "held": list(HELD),
                # the batch's offsets (source_key virtual:NAME:OFFSET) beyond the range
                "outside_range": [int(k) for k in np.flatnonzero(outside)],
                "seed": SEED,
            },
            WEIGHTED_BY: sample.weighted_by,
        },
        created=_dt.datetime.now(_dt.UTC).isoformat(timespec="seconds"),
        weighted_by=sample.weighted_by,
    )
    return VirtualPopulation(people, weights, target, beyond, outside)


def _known(rows: Sample, index: dict[str, int]) -> tuple[tuple[str, ...], npt.NDArray[np.float64]]:
    """The names and values (NaN: not measured) a gender's rows are predicted
    from: stature and mass, the MEASURED fields the sample has and the model
    knows, and the age when the sample has one."""
    names: list[str] = list(PREDICTED_FROM)
    columns = [rows.matrix[:, :2]]
    for j, field in enumerate(rows.optional_fields):
        if field in MEASURED and field in index and rows.optional is not None:
            names.append(field)
            columns.append(rows.optional[:, j : j + 1])
    if rows.ages is not None and "age" in index:
        names.append("age")
        columns.append(rows.ages[:, None])
    return tuple(names), np.hstack(columns)


def _batch(name: str, parts: list[tuple[str, Sample, VirtualPeople]]) -> PeopleBatch:
    measures = np.concatenate([_measures(drawn.fields, drawn.values) for _, _, drawn in parts])
    n = len(measures)
    genders = [g for g, rows, _ in parts for _ in range(len(rows.matrix))]
    ages = np.concatenate(
        [
            rows.ages if rows.ages is not None else np.full(len(rows.matrix), np.nan)
            for _, rows, _ in parts
        ]
    )
    keys = [f"{k}" for k in range(n)]
    source = virtual_source(name)
    return PeopleBatch(
        id_num=np.zeros(n, dtype=np.int64),
        name=[f"virtual {name} {g[0].upper()} {i + 1}" for i, g in enumerate(genders)],
        gender=genders,
        stature=measures[:, MEASURES.index("stature")].copy(),
        mass=measures[:, MEASURES.index("weightkg")].copy(),
        handedness=[None] * n,
        age=ages,
        source=[source] * n,
        source_key=[f"{source}:{key}" for key in keys],
        girth=derived_girth(measures),
        measures=measures,
    )


def _measures(fields: tuple[str, ...], values: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """The drawn fields as the 93 ANSUR II measures (MEASURES order; NaN: not predicted)."""
    column = {"stature": "stature", "mass": "weightkg"}
    out = np.full((len(values), len(MEASURES)), np.nan)
    for j, field in enumerate(fields):
        if field in HELD:
            continue  # the row's own, stored as the person's
        name = column.get(field, field.removeprefix("measure."))
        out[:, MEASURES.index(name)] = values[:, j]
    return out


def store_virtual_in(conn: sqlite3.Connection, population: VirtualPopulation) -> None:
    """Store a virtual population in the caller's transaction (a SQLite
    connection: the database itself, or PostgreSQL's staging file), replacing
    the people and weights of one of the same name."""
    source = virtual_source(population.target.name.removeprefix(virtual_name("")))
    gone = [r[0] for r in conn.execute("SELECT id_num FROM person WHERE source = ?", (source,))]
    if gone:
        delete_people(conn, gone)
    people = population.people
    first = (conn.execute("SELECT max(id_num) FROM person").fetchone()[0] or 0) + 1
    people.id_num[:] = np.arange(first, first + len(people), dtype=np.int64)
    store_people(conn, people, replace=False)
    insert_target(conn, TargetWeights(population.target, people.id_num, population.weights))


def store_virtual(conn: sqlite3.Connection, population: VirtualPopulation) -> None:
    """Store a virtual population in its own transaction, on either engine
    (db/engine/staging.py's store_people decides how: on PostgreSQL through a
    staging file, copied in one transaction)."""

    def load(into: sqlite3.Connection) -> None:
        with writing(into):
            store_virtual_in(into, population)

    staging.store_people(conn, load)


def shipped_sample() -> Sample:
    """The shipped NHANES 2017-March 2020 adults with a stature and a mass,
    each with its gender, age and examination weight."""
    return read_sample(
        shipped_text(NHANES),
        PREDICTED_FROM,
        NHANES_NAME,
        weight=NHANES_WEIGHT,
        need_gender=True,
        optional=MEASURED,
    )


def make_shipped(conn: sqlite3.Connection) -> tuple[TargetWeights, VirtualPopulation]:
    """The shipped target and virtual population `nhanes-2017-2020` (both
    genders, adults 20+), nothing stored: the real people weighted to
    NHANES's examination weights within their range (`within_range`: the
    heaviest NHANES women lie beyond every ANSUR II woman; `outside_share`
    says how much), and one virtual person per NHANES adult."""
    sample = shipped_sample()
    _target, weights, _weightings = make_target(
        conn, NHANES_NAME, BOTH, sample, NHANES_NAME, within_range=True
    )
    return weights, make_virtual(conn, NHANES_NAME, sample, NHANES_NAME)


def store_shipped_in(conn: sqlite3.Connection, progress: Progress | None = None) -> int:
    """Make and store the shipped target and virtual population in the
    caller's transaction, on a SQLite connection holding the default people
    (`sass db init`: the database itself, or PostgreSQL's staging file, whose
    targets are copied with its people).  `progress(done, 2)` after each
    half.  Returns how many virtual people."""
    weights, population = make_shipped(conn)
    if progress is not None:
        progress(1, 2)
    insert_target(conn, weights)
    store_virtual_in(conn, population)
    if progress is not None:
        progress(2, 2)
    return len(population.weights)


def store_target_and_virtual(
    conn: sqlite3.Connection, weights: TargetWeights, population: VirtualPopulation
) -> None:
    """A target's real people's weights and the virtual population made from
    the same sample in one transaction, on either engine: a kill or a full
    disk between the two stores neither (they were two, and a target was
    left without its people).  On PostgreSQL the staged people's copy
    (db/engine/postgres.py's import_staged) nests in this transaction."""
    with writing(conn):
        insert_target(conn, weights)
        if dialect_of(conn) == "sqlite":
            store_virtual_in(conn, population)
        else:
            store_virtual(conn, population)


def drop_virtual(conn: sqlite3.Connection, name: str) -> int:
    """Delete the virtual population NAME (or `virtual:NAME`): its weights and
    its people (every table of theirs, on either engine).  Returns how many people."""
    name = name.removeprefix(virtual_name(""))
    source, label = virtual_source(name), virtual_name(name)
    m = mark_of(conn)
    tables = [
        t for t in PERSON_TABLES if dialect_of(conn) == "sqlite" or t not in SQLITE_ONLY_TABLES
    ]
    with writing(conn):
        if not target_exists(conn, label):
            raise UnknownTargetError(f"no virtual population named {name!r}", where=name)
        (people,) = conn.execute(
            f"SELECT count(*) FROM person WHERE source = {m}", (source,)
        ).fetchone()
        for table in (*tables, "person"):
            conn.execute(
                f"DELETE FROM {table} WHERE id_num IN "
                f"(SELECT id_num FROM person WHERE source = {m})",
                (source,),
            )
        conn.execute(f"DELETE FROM target_weight WHERE target = {m}", (label,))
        conn.execute(f"DELETE FROM target WHERE name = {m}", (label,))
    return int(people)
