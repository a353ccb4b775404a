"""The default database's people: the shipped ANSUR II survey, the synthetic
people with strength experiments, and the shipped target and virtual
population made from them (db/people/default.py's docstring says what each is).

Separate from db/people/default.py, which every path opening the default database
imports (`sass query`, `sass person`: sass_tui/startup.py): the readers of
the shipped files and the virtual population's maker (numpy, the prediction
model) are imported at this module's top, reached once a database is built
(db/people/default.py's fill_default).
"""

from __future__ import annotations

import sqlite3
from pathlib import Path

from sass_tui.db.engine.schema import DatabaseError
from sass_tui.db.people.ansur import DEFAULT_LABEL, store_ansur
from sass_tui.db.people.flatfile import FlatFiles, read_flat_files
from sass_tui.db.people.people_store import store_people
from sass_tui.db.populations.virtual import store_shipped_in
from sass_tui.db.progress import Progress
from sass_tui.db.query.scope import DEMONSTRATION_SOURCE, virtual_source
from sass_tui.model import datasets

ANSUR_FILES = ("ANSUR_II_MALE_Public.csv.gz", "ANSUR_II_FEMALE_Public.csv.gz")


def shipped_ansur_files() -> list[Path]:
    return [datasets.directory() / "ansur2" / name for name in ANSUR_FILES]


def store_default_people(
    conn: sqlite3.Connection, progress: Progress | None = None
) -> dict[str, int]:
    """Store the shipped people, and the shipped target and virtual population
    `nhanes-2017-2020` made from them (db/populations/virtual.py's store_shipped_in),
    inside the caller's transaction.  Returns the people stored per source."""
    # source `synthetic`: db/people/default.py's SYNTHETIC_LABEL
    synthetic = read_flat_files(FlatFiles.in_directory(datasets.directory() / "db"))
    synthetic.source = [DEMONSTRATION_SOURCE] * len(synthetic)
    store_people(conn, synthetic, replace=False)
    files = shipped_ansur_files()
    missing = [str(f) for f in files if not f.is_file()]
    if missing:
        raise DatabaseError(f"the shipped ANSUR II files are missing: {', '.join(missing)}")
    # Making the shipped target and virtual people takes about as long as
    # reading the survey (benchmarks/virtual.py): each gets half the bar.
    halves = _Halves(progress)
    counts = store_ansur(conn, files, label=DEFAULT_LABEL, progress=halves.first)
    virtual = store_shipped_in(conn, progress=halves.second)
    return {
        DEMONSTRATION_SOURCE: len(synthetic),
        DEFAULT_LABEL: sum(counts.values()),
        virtual_source(datasets.NHANES_NAME): virtual,
    }


class _Halves:
    """One progress bar for two steps: `first(done, total)` fills its first
    half, `second(done, total)` its second, in the first's units (each a Progress)."""

    def __init__(self, progress: Progress | None) -> None:
        self.progress = progress
        self.half = 0  # the first step's total, once it has reported

    def first(self, done: int, total: int) -> None:
        self.half = total
        if self.progress is not None:
            self.progress(done, 2 * total)

    def second(self, done: int, total: int) -> None:
        half = self.half or total
        if self.progress is not None:
            self.progress(half + done * half // total, 2 * half)
