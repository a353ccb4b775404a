"""Target populations in the database: make, store, list, drop, and read
the weights (the method: sass_tui/model/population/targets.py, docs/target-populations.md).

A target's base population is `(<population>) AND gender = <gender>`, by
default the ANSUR II people (`source = ansur2`) of that gender; a target of
both genders (`BOTH`, the shipped `nhanes-2017-2020`) is the population's
people of either, each gender calibrated to the sample's rows of that gender
and carrying that gender's share of the sample's weight.  Its weights
have mean 1 over the base people that have every `--by` value; the others
weigh 0.  A weighted count is therefore in people: the base people a
target's weights stand for.  Tables: `target` and `target_weight` (schema 5,
db/engine/schema.py).  People deleted since a target was made simply drop out of
its sums; people added since carry no weight in it.

No Textual, no printing.
"""

from __future__ import annotations

import datetime as _dt
import json
import sqlite3
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
import numpy.typing as npt

from sass_tui.db.engine.dialect import mark_of, writing
from sass_tui.db.people.values import load_values
from sass_tui.db.query.query import CompiledQuery, ParsedQuery, Query, compile_query, joined, parsed
from sass_tui.db.query.scope import VIRTUAL_PREFIX
from sass_tui.model.datasets import NHANES_NAME
from sass_tui.model.population.target_sample import Sample
from sass_tui.model.population.targets import (
    TargetError,
    Weighting,
    calibrate,
    kish_effective_n,
    weighted_percentile,
)
from sass_tui.model.text import printable
from sass_tui.model.vocabulary import GENDERS

DEFAULT_POPULATION = "source = ansur2"  # the real people (= db.fit.DEFAULT_POPULATION)
MAX_NAME = 64
BOTH = "both"  # a target of both genders
# The shipped target and virtual population (db/populations/shipped.py): made on first use.
SHIPPED = (NHANES_NAME, f"{VIRTUAL_PREFIX}{NHANES_NAME}")
WEIGHTED_BY = "weighted_by"  # the summary's key of the sample's survey weight column


class TargetExistsError(TargetError):
    """A target of that name is stored already (replace it with --force)."""


class UnknownTargetError(TargetError):
    """No target of that name is stored."""


@dataclass(frozen=True)
class Target:
    name: str
    gender: str
    population: str  # the query the base people come from (without the gender)
    fields: tuple[str, ...]
    sample: str  # the sample file's name
    sample_rows: int
    people: int  # base people with every --by value (they carry the weight)
    effective_n: float  # Kish
    # gender -> field -> {"target"|"weighted"|"unweighted": [mean, sd, p5, p50, p95],
    # "outside_share": share}; a target stored before both genders: field -> {...}
    summary: dict[str, Any]
    created: str
    weighted_by: str | None = None  # the sample's survey weight column

    @property
    def genders(self) -> tuple[str, ...]:
        return tuple(GENDERS) if self.gender == BOTH else (self.gender,)

    def outside_share(self, gender: str, field: str) -> float | None:
        """The share of the target's `gender` weight beyond every person's
        `field` (None: the target was not made over `field`, or before sass
        said it)."""
        of_gender = self.summary.get(gender)
        if not isinstance(of_gender, dict):  # the summary of an older sass: one gender's
            of_gender = self.summary if gender == self.gender else {}
        share = of_gender.get(field, {}).get("outside_share")
        return None if share is None else float(share)

    def outside_shares(self, weight_of: Mapping[Any, float]) -> dict[str, float]:
        """Per `--by` field, the share of the target's weight beyond every
        person weighted, over the genders of `weight_of` (gender -> its
        weight among the people asked about), each gender counted by its
        share of that weight; a field some such gender lacks a share of is
        left out (a target made before sass said it; a virtual population)."""
        total = sum(w for w in weight_of.values() if w > 0)
        out: dict[str, float] = {}
        if self.is_virtual or total <= 0:
            return out
        for field in self.fields:
            shares = {g: self.outside_share(g, field) for g, w in weight_of.items() if w > 0}
            if all(share is not None for share in shares.values()):
                out[field] = sum(float(x or 0.0) * weight_of[g] / total for g, x in shares.items())
        return out

    @property
    def base_query(self) -> str:
        return base_query(self.population, self.gender)

    @property
    def percent_effective(self) -> float:
        return 100.0 * self.effective_n / self.people if self.people else 0.0

    @property
    def is_virtual(self) -> bool:
        """A virtual population (db/populations/virtual.py): its people are predicted, not measured."""
        return self.name.startswith(VIRTUAL_PREFIX)

    def words(self) -> str:
        """How a weighted answer names its target, on screen and in files."""
        if self.is_virtual:
            virtual = self.summary.get("virtual", {})
            beyond = sum(virtual.get("beyond", {}).values())
            measured = " and ".join(k.removeprefix("measure.") for k in virtual.get("kept", []))
            kept = f", and its measured {measured} where it has them" if measured else ""
            left_out = virtual.get("left_out")
            where = (
                f"{beyond} beyond the range the prediction was fitted on"
                if left_out is None
                else f"{left_out} beyond the range the prediction was fitted on left out "
                "(--within-range)"
            )
            return (
                f"VIRTUAL people, not measured: {self.name.removeprefix(VIRTUAL_PREFIX)} "
                f"({self.people} virtual people with {self.sample}'s own stature and mass{kept}, "
                f"every other measure predicted from the real people; {where}; "
                f"weighted by {self.weighted_by or 'nothing'}; "
                f"effective n {self.effective_n:.0f})"
            )
        who = "both genders" if self.gender == BOTH else self.gender
        survey = f" with its weights {self.weighted_by}" if self.weighted_by else ""
        return (
            f"target {self.name} ({who}, weighted by {', '.join(self.fields)} "
            f"to {self.sample}{survey}; effective n {self.effective_n:.0f} of {self.people})"
        )

    def to_json(self) -> dict[str, Any]:
        return {
            "name": self.name,
            "gender": self.gender,
            "population": self.population,
            "by": list(self.fields),
            "sample": self.sample,
            "sample_rows": self.sample_rows,
            "people": self.people,
            "effective_n": round(self.effective_n, 2),
            "weighted_by": self.weighted_by,
        }


@dataclass(frozen=True)
class TargetWeights:
    target: Target
    ids: npt.NDArray[np.int64]  # id order
    weights: npt.NDArray[np.float64]

    def of(self, ids: npt.NDArray[np.int64]) -> npt.NDArray[np.float64]:
        """The weight of each of `ids` (0 for people not in the target)."""
        if len(self.ids) == 0:  # every one of its people deleted since
            return np.zeros(len(ids))
        where = np.clip(np.searchsorted(self.ids, ids), 0, len(self.ids) - 1)
        out: npt.NDArray[np.float64] = np.where(self.ids[where] == ids, self.weights[where], 0.0)
        return out

    def percentiles(
        self,
        column: npt.NDArray[np.float64],
        weights: npt.NDArray[np.float64],
        percents: Sequence[float],
    ) -> npt.NDArray[np.float64]:
        """Weighted empirical percentiles of `column` under `weights` (the
        target's, `of` its people): model/population/targets.py's weighted_percentile,
        for db/populations/population.py, which imports neither module unless a target
        is given (`sass population`'s row of sass_tui/startup.py)."""
        return weighted_percentile(column, weights, percents)


def base_query(population: str, gender: str) -> str:
    return f"({population})" if gender == BOTH else f"({population}) AND gender = {gender}"


def check_name(name: str) -> str:
    """A target's name: 1-64 printable characters, no space at either end."""
    if not name or name != name.strip() or len(name) > MAX_NAME or printable(name) != name:
        raise TargetError(
            f"target name {printable(name)!r}: expected 1 to {MAX_NAME} printable characters "
            "without spaces at either end",
            where=printable(name),
        )
    if name.startswith(
        VIRTUAL_PREFIX
    ):  # the virtual population's own name: a target is real people
        raise TargetError(
            f"target name {printable(name)!r}: {VIRTUAL_PREFIX!r} begins the name of a virtual "
            f"population (`sass target NAME --virtual` makes {VIRTUAL_PREFIX}NAME); name the "
            "target without it",
            where=printable(name),
        )
    return name


def make_target(
    conn: sqlite3.Connection,
    name: str,
    gender: str,
    sample: Sample,
    sample_name: str,
    population: str | ParsedQuery = DEFAULT_POPULATION,
    *,
    within_range: bool = False,
) -> tuple[Target, TargetWeights, dict[str, Weighting]]:
    """Compute a target (nothing stored: `store_target` stores it); `gender`
    BOTH calibrates each gender to its own rows of the sample (which must
    say each row's gender)."""
    check_name(name)
    if gender not in (*GENDERS, BOTH):
        raise TargetError(f"gender must be {', '.join(GENDERS)} or {BOTH}, not {gender!r}")
    if gender == BOTH and sample.genders is None:
        raise TargetError(
            f"{sample_name}: no gender column; a target of both genders needs each row's gender",
            where=sample_name,
        )
    chosen = parsed(population)  # once: its errors first, then its people
    genders = tuple(GENDERS) if gender == BOTH else (gender,)
    shares = _gender_shares(sample, genders)
    weightings: dict[str, Weighting] = {}
    parts: list[tuple[npt.NDArray[np.int64], npt.NDArray[np.float64]]] = []
    for g in genders:
        values = load_values(conn, sample.fields, joined(chosen, f"gender = {g}"))
        if len(values) == 0:
            raise TargetError(f"the population {chosen.text!r} has no {g} people")
        rows = sample.of_gender(g) if gender == BOTH else sample
        where = f"{sample_name} ({g} rows)" if gender == BOTH else sample_name
        weighting = calibrate(
            sample.fields,
            values.matrix,
            rows.matrix,
            where=where,
            sample_weights=rows.weights,
            within_range=within_range,
        )
        weightings[g] = weighting
        used = weighting.used
        parts.append((values.ids[used], weighting.weights[used] * shares[g]))
    people = sum(len(ids) for ids, _ in parts)
    # Each gender's weights have mean 1 over its people; scaled by its share of
    # the sample's weight and by people / its people, all have mean 1 together.
    ids = np.concatenate([ids for ids, _ in parts])
    weights = np.concatenate([w * people / len(w) for _, w in parts])
    order = np.argsort(ids, kind="stable")
    summary: dict[str, Any] = {
        g: {
            c.field: {
                "target": c.target.as_list(),
                "weighted": c.weighted.as_list(),
                "unweighted": c.unweighted.as_list(),
                "outside_share": c.outside_share,
            }
            for c in w.checks
        }
        for g, w in weightings.items()
    }
    summary[WEIGHTED_BY] = sample.weighted_by
    target = Target(
        name=name,
        gender=gender,
        population=chosen.text,
        fields=tuple(sample.fields),
        sample=printable(sample_name),  # a file's name may hold ESC: shown by every verb
        sample_rows=sum(w.sample_rows for w in weightings.values()),
        people=people,
        effective_n=kish_effective_n(weights),
        summary=summary,
        created=_dt.datetime.now(_dt.UTC).isoformat(timespec="seconds"),
        weighted_by=sample.weighted_by,
    )
    return target, TargetWeights(target, ids[order], weights[order]), weightings


def _gender_shares(sample: Sample, genders: tuple[str, ...]) -> dict[str, float]:
    """Each gender's share of the sample's weight (1 for a one-gender target)."""
    if len(genders) == 1 or sample.genders is None:
        return {g: 1.0 for g in genders}
    of = np.array(sample.genders, dtype=object)
    w = sample.row_weights
    total = float(w.sum())
    if not total > 0:  # a header alone, or blank lines
        raise TargetError("the sample has no rows; a target of both genders needs both")
    shares = {g: float(w[of == g].sum()) / total for g in genders}
    empty = [g for g, share in shares.items() if share <= 0]
    if empty:
        raise TargetError(f"the sample has no {empty[0]} rows; a target of both genders needs both")
    return shares


def store_target(conn: sqlite3.Connection, weights: TargetWeights, *, replace: bool) -> None:
    """Store a made target; TargetExistsError unless `replace` when its name is taken."""
    target = weights.target
    with writing(conn):
        if target_exists(conn, target.name):
            if not replace:
                raise TargetExistsError(
                    f"a target named {target.name!r} exists; give --force to replace it"
                )
        insert_target(conn, weights)


def insert_target(conn: sqlite3.Connection, weights: TargetWeights) -> None:
    """Store a made target in the caller's transaction, replacing one of its name."""
    target = weights.target
    m = mark_of(conn)
    _delete(conn, target.name)
    conn.execute(
        f"INSERT INTO target VALUES ({', '.join([m] * 10)})",
        (
            target.name,
            target.gender,
            target.population,
            json.dumps(list(target.fields)),
            target.sample,
            target.sample_rows,
            target.people,
            target.effective_n,
            json.dumps(target.summary),
            target.created,
        ),
    )
    conn.executemany(
        f"INSERT INTO target_weight VALUES ({m}, {m}, {m})",
        zip(
            [target.name] * len(weights.ids),
            weights.ids.tolist(),
            weights.weights.tolist(),
        ),
    )


def target_exists(conn: sqlite3.Connection, name: str) -> bool:
    m = mark_of(conn)
    return conn.execute(f"SELECT 1 FROM target WHERE name = {m}", (name,)).fetchone() is not None


def _delete(conn: sqlite3.Connection, name: str) -> None:
    m = mark_of(conn)
    conn.execute(f"DELETE FROM target_weight WHERE target = {m}", (name,))
    conn.execute(f"DELETE FROM target WHERE name = {m}", (name,))


def drop_target(conn: sqlite3.Connection, name: str) -> None:
    with writing(conn):
        if not target_exists(conn, name):
            raise _unknown(conn, name)
        _delete(conn, name)


def list_targets(conn: sqlite3.Connection) -> list[Target]:
    return [_target(row) for row in conn.execute(f"SELECT {_COLUMNS} FROM target ORDER BY name")]


_COLUMNS = (
    "name, gender, population, fields, sample, sample_rows, people, effective_n, summary, created"
)


def _target(row: Sequence[Any]) -> Target:
    name, gender, population, fields, sample, rows, people, effective_n, summary, created = row
    # Every text made printable here, where a target is read: a shared
    # PostgreSQL database or an older file may hold a sample file's name with
    # ESC and BEL, which target --list, stats, task, fit, query --count,
    # population (and its .dat files) and the Stats screen printed raw.
    return Target(
        name=printable(name),
        gender=printable(gender),
        population=printable(population),
        fields=tuple(printable(f) for f in json.loads(fields)),
        sample=printable(sample),
        sample_rows=int(rows),
        people=int(people),
        effective_n=float(effective_n),
        summary=json.loads(summary),
        created=printable(created),
        weighted_by=None if (by := json.loads(summary).get(WEIGHTED_BY)) is None else printable(by),
    )


def _unknown(conn: sqlite3.Connection, name: str) -> UnknownTargetError:
    """No target (or, named `virtual:NAME`, no virtual population) `name`:
    the message names those of its kind, without the prefix the user never typed."""
    virtual = name.startswith(VIRTUAL_PREFIX)
    names = [
        t.name.removeprefix(VIRTUAL_PREFIX) for t in list_targets(conn) if t.is_virtual == virtual
    ]
    kind, make = (
        ("virtual population", "`sass target NAME --virtual`")
        if virtual
        else ("target", "`sass target`")
    )
    known = f"; the {kind}s are {', '.join(names)}" if names else "; none is stored yet"
    shown = printable(name.removeprefix(VIRTUAL_PREFIX))
    return UnknownTargetError(
        f"no {kind} named {shown!r}{known} (make one with {make})", where=shown
    )


def load_target(conn: sqlite3.Connection, name: str) -> TargetWeights:
    """A stored target and the weights of its people still in the database (id order)."""
    m = mark_of(conn)
    row = conn.execute(f"SELECT {_COLUMNS} FROM target WHERE name = {m}", (name,)).fetchone()
    if row is None:
        raise _unknown(conn, name)
    rows = conn.execute(
        "SELECT w.id_num, w.weight FROM target_weight w JOIN person p ON p.id_num = w.id_num "
        f"WHERE w.target = {m} ORDER BY w.id_num",
        (name,),
    ).fetchall()
    ids = np.array([r[0] for r in rows], dtype=np.int64)
    weights = np.array([r[1] for r in rows], dtype=float)
    return TargetWeights(_target(row), ids, weights)


@dataclass(frozen=True)
class WeightedCount:
    target: Target
    count: int  # people the query selects
    in_target: int  # of them, people of the target
    weighted: float  # their weight (people the target's weights stand for)
    total: float  # every target person's weight

    @property
    def percent(self) -> float:
        return 100.0 * self.weighted / self.total if self.total else 0.0


def weighted_count(
    conn: sqlite3.Connection, query: str | CompiledQuery, weights: TargetWeights
) -> WeightedCount:
    """How many people `query` selects, and the share of the target's weight they hold."""
    result = Query(conn, query if isinstance(query, CompiledQuery) else compile_query(query))
    ids = np.array(sorted(result.ids()), dtype=np.int64)
    mine = weights.of(ids)
    return WeightedCount(
        target=weights.target,
        count=len(ids),
        in_target=int((mine > 0).sum()),
        weighted=float(mine.sum()),
        total=float(weights.weights.sum()),
    )


def within_range(conn: sqlite3.Connection, weights: TargetWeights) -> TargetWeights:
    """A virtual population's weights without its people predicted from a
    value beyond the real people's range (the summary's `outside_range`):
    they weigh nothing, and the target's words say how many were left out.
    Refused for a target of real people (whose `sass target --within-range`
    is made so)."""
    target = weights.target
    if not target.is_virtual:
        raise TargetError(
            f"--within-range leaves out VIRTUAL people predicted beyond the real people; "
            f"{target.name} is a target of real people: give --virtual NAME",
            where="--within-range",
        )
    virtual = dict(target.summary.get("virtual", {}))
    outside = {int(k) for k in virtual.get("outside_range", [])}
    prefix = f"{target.name}:"  # virtual:NAME:OFFSET, as _batch keys them
    rows = conn.execute(
        f"SELECT id_num, source_key FROM person WHERE source = {mark_of(conn)}",
        (target.name,),
    ).fetchall()
    gone = np.array(
        sorted(int(i) for i, key in rows if int(str(key).removeprefix(prefix)) in outside),
        dtype=np.int64,
    )
    keep = ~np.isin(weights.ids, gone)
    virtual["left_out"] = int((~keep).sum())
    summary = target.summary | {"virtual": virtual}
    return TargetWeights(replace(target, summary=summary), weights.ids[keep], weights.weights[keep])
