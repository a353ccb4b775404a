"""What `sass db init` replaces, said before it asks, and the stored targets
it keeps.  Replacing a database stores the default people again (the shipped
ANSUR II and synthetic people) and deletes everyone else; a target population
(db/populations/targets.py) weighs people by id, so it can be kept when every person it
weighs is stored again: an ANSUR II person is found again by its source key
(the survey's subject id), a synthetic person by its id (the flat files'
numbering).  A target weighing anyone imported is deleted with them.  Either
engine, through db/engine/dialect.py.  The column copy of a SQLite file replaced
(db/query/accelerator.py) is dropped: no later history can use it."""

from __future__ import annotations

import shutil
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from sass_tui.db.engine.dialect import dialect_of, mark_of
from sass_tui.db.people.ansur import DEFAULT_LABEL
from sass_tui.db.people.default import SYNTHETIC_LABEL
from sass_tui.db.populations.targets import (
    Target,
    TargetWeights,
    list_targets,
    store_target,
    target_exists,
)
from sass_tui.db.query import copy_file
from sass_tui.db.query.copy_file import LOCK, cache_folder
from sass_tui.db.query.scope import virtual_source
from sass_tui.model.datasets import NHANES_NAME
from sass_tui.model.text import printable

# The people `sass db init` stores again: the virtual ones made anew from
# the shipped NHANES sample (db/populations/virtual.py's store_shipped_in).
DEFAULT_SOURCES = (DEFAULT_LABEL, SYNTHETIC_LABEL, virtual_source(NHANES_NAME))
# The targets `sass db init` makes anew: the shipped target and the virtual
# population's weights (db/populations/targets.py's SHIPPED).
MADE_ANEW = (NHANES_NAME, virtual_source(NHANES_NAME))


@dataclass(frozen=True)
class HeldTarget:
    """A stored target and who it weighs: per weighted person (source, source
    key, id, weight)."""

    target: Target
    people: Sequence[tuple[str | None, str | None, int, float]]

    def imported(self) -> dict[str, int]:
        """People of the target from sources `sass db init` does not store again."""
        out: dict[str, int] = {}
        for source, _key, _id, _weight in self.people:
            if source not in DEFAULT_SOURCES:
                label = "deleted people" if source is None else str(source)
                out[label] = out.get(label, 0) + 1
        return out

    @property
    def keepable(self) -> bool:
        return not self.imported()


@dataclass(frozen=True)
class Held:
    """What a database holds that `sass db init` replaces."""

    people: dict[str, int]  # source -> people, most first
    targets: list[HeldTarget]

    @property
    def count(self) -> int:
        return sum(self.people.values())

    def lines(self) -> list[str]:
        """One line per source and per target: what replacing does to it."""
        out = []
        for source, n in self.people.items():
            fate = (
                "stored again from the shipped data"
                if source in DEFAULT_SOURCES
                else "deleted (import them again afterwards)"
            )
            out.append(f"{n:,} {'person' if n == 1 else 'people'} from {printable(source)}: {fate}")
        for held in self.targets:
            out.append(f"target {printable(held.target.name)}: {target_fate(held)}")
        return out


def target_fate(held: HeldTarget) -> str:
    if held.target.name in MADE_ANEW:
        return "made anew from the shipped data"
    if held.keepable:
        return f"kept (its {len(held.people):,} people are stored again)"
    return f"deleted ({_lacking(held)})"


def _lacking(held: HeldTarget) -> str:
    imported = ", ".join(f"{n:,} from {printable(s)}" for s, n in held.imported().items())
    return f"it weighs people the default data lacks: {imported}"


def what_init_replaces(conn: Any) -> Held:
    """The people per source and the stored targets of a database (nothing
    of either in a database without the tables)."""
    if not _has_table(conn, "person"):
        return Held({}, [])
    people = {
        str(source): int(n)
        for source, n in conn.execute(
            "SELECT source, count(*) FROM person GROUP BY source ORDER BY count(*) DESC, source"
        )
    }
    if not _has_table(conn, "target"):
        return Held(people, [])
    m = mark_of(conn)
    targets = [
        HeldTarget(
            target,
            [
                (source, key, int(id_num), float(weight))
                for source, key, id_num, weight in conn.execute(
                    "SELECT p.source, p.source_key, w.id_num, w.weight FROM target_weight w "
                    f"LEFT JOIN person p ON p.id_num = w.id_num WHERE w.target = {m} "
                    "ORDER BY w.id_num",
                    (target.name,),
                )
            ],
        )
        for target in list_targets(conn)
    ]
    return Held(people, targets)


def keep_targets(conn: Any, held: Held) -> list[str]:
    """After `sass db init` stored the default people: store again each
    target of `held` whose people are all back, under their new ids; one line
    per target saying what became of it.  A target of that name the
    initialisation made itself (a shipped target) is the new one."""
    if not held.targets:
        return []
    keys = {
        str(key): int(id_num)
        for key, id_num in conn.execute(
            "SELECT source_key, id_num FROM person WHERE source_key IS NOT NULL"
        )
    }
    synthetic = {
        int(id_num)
        for (id_num,) in conn.execute(
            f"SELECT id_num FROM person WHERE source = {mark_of(conn)}", (SYNTHETIC_LABEL,)
        )
    }
    said = []
    for one in held.targets:
        name = printable(one.target.name)
        if target_exists(conn, one.target.name):
            said.append(f"target {name}: made anew by sass db init")
            continue
        if not one.keepable:
            said.append(f"deleted target {name}: {_lacking(one)}")
            continue
        ids = [
            keys.get(str(key)) if key is not None else (id_num if id_num in synthetic else None)
            for _source, key, id_num, _weight in one.people
        ]
        if any(i is None for i in ids):
            said.append(f"deleted target {name}: some of its people are not stored again")
            continue
        order = np.argsort(np.array(ids, dtype=np.int64))
        weights = TargetWeights(
            one.target,
            np.array(ids, dtype=np.int64)[order],
            np.array([w for *_rest, w in one.people], dtype=float)[order],
        )
        store_target(conn, weights, replace=False)
        said.append(f"kept target {name} ({len(ids):,} people, stored again)")
    return said


def _has_table(conn: Any, name: str) -> bool:
    if dialect_of(conn) == "sqlite":
        sql = "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?"
    else:
        sql = (
            "SELECT 1 FROM information_schema.tables "
            "WHERE table_name = %s AND table_schema = current_schema()"
        )
    return conn.execute(sql, (name,)).fetchone() is not None


def forget_column_copy(path: Path) -> None:
    """Drop the copy of the database at `path`, in memory and on disk (after
    `db init`: no later history can use it; errors ignored)."""
    with LOCK:
        held = copy_file.OPEN_COPIES.pop(path, None)
        if held is not None:
            held.close()
    shutil.rmtree(cache_folder(path), ignore_errors=True)
