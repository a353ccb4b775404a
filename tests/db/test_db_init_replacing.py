"""`sass db init` over a database that holds more than the default people:
before asking it lists what replacing deletes (the people per source, the
stored targets), and it keeps each target whose people it stores again (the
ANSUR II women a target weighs, found again by their subject ids), deleting
one that weighs an imported person.  On both engines (tests/db/conftest.py)."""

from __future__ import annotations

import sys
from dataclasses import replace

import numpy as np
import pytest
from test_database_safety import NHANES_ADULTS, _flat, _Terminal
from test_targets import civilian_women, write_sample

from sass_tui.cli import main
from sass_tui.db.engine.database import Database
from sass_tui.db.people.flatfile import import_flat_into
from sass_tui.db.populations.targets import (
    SHIPPED,
    TargetWeights,
    list_targets,
    load_target,
    store_target,
)


def _weights_by_subject(db: str, name: str) -> dict[str, float]:
    opened = Database.open(db)
    try:
        with opened.connection() as conn:
            weights = load_target(conn, name)
            keys = dict(conn.execute("SELECT id_num, source_key FROM person").fetchall())
            return {keys[int(i)]: float(w) for i, w in zip(weights.ids, weights.weights)}
    finally:
        opened.close()


def _holding_an_import_and_two_targets(db: str, tmp_path) -> None:
    sample = write_sample(tmp_path / "civilian.csv", civilian_women(3000))
    assert main(["target", "civ", "--db", db, "--gender", "female", "--sample", str(sample)]) == 0
    opened = Database.open(db)
    try:
        import_flat_into(opened, _flat(tmp_path))
        with opened.connection() as conn:
            (jane,) = conn.execute("SELECT id_num FROM person WHERE name = 'JANE_DOE'").fetchone()
            civ = load_target(conn, "civ").target
            only_jane = TargetWeights(
                replace(civ, name="jane", people=1, effective_n=1.0),
                np.array([jane], dtype=np.int64),
                np.array([1.0]),
            )
            store_target(conn, only_jane, replace=False)
    finally:
        opened.close()


@pytest.mark.slow
def test_db_init_lists_what_it_deletes_and_keeps_the_targets_it_can(
    engine_target, tmp_path, capsys, monkeypatch
):
    db = engine_target
    _holding_an_import_and_two_targets(db, tmp_path)
    civ = _weights_by_subject(db, "civ")
    capsys.readouterr()
    # Without a terminal to ask on: refused, saying what --force would delete.
    assert main(["db", "init", "--db", db]) != 0
    refused = capsys.readouterr().err
    assert f"holds {6269 + NHANES_ADULTS} people" in refused and "--force" in refused
    # The shipped virtual population and targets: made anew, not deleted.
    assert f"{NHANES_ADULTS:,} people from virtual:nhanes-2017-2020: stored again" in refused
    assert "target nhanes-2017-2020: made anew from the shipped data" in refused
    assert "target virtual:nhanes-2017-2020: made anew from the shipped data" in refused
    assert "6,068 people from ansur2: stored again from the shipped data" in refused
    assert "1 person from hand-made test person: deleted (import them again afterwards)" in refused
    assert f"target civ: kept (its {len(civ):,} people are stored again)" in refused
    assert "target jane: deleted (it weighs people the default data lacks: 1 from hand-made" in (
        refused
    )
    # On a terminal: the same lines, then the question; "n" changes nothing.
    err = _Terminal()
    monkeypatch.setattr(sys, "stdin", _Terminal("n\n"))
    monkeypatch.setattr(sys, "stderr", err)
    assert main(["db", "init", "--db", db]) == 1
    asked = err.getvalue()
    assert asked.index("  target jane: deleted") < asked.index("[y/N]")
    assert "200 people from synthetic: stored again" in asked
    monkeypatch.undo()
    assert _weights_by_subject(db, "jane")  # still there
    # --force: replaced; civ kept with the same weights on the same women
    assert main(["db", "init", "--db", db, "--force"]) == 0
    said = capsys.readouterr().out
    assert f"kept target civ ({len(civ):,} people, stored again)" in said
    assert "deleted target jane: it weighs people the default data lacks: 1 from hand" in said
    opened = Database.open(db)
    try:
        with opened.connection() as conn:
            assert [t.name for t in list_targets(conn)] == ["civ", *SHIPPED]
            assert conn.execute("SELECT 1 FROM person WHERE name = 'JANE_DOE'").fetchone() is None
    finally:
        opened.close()
    assert _weights_by_subject(db, "civ") == civ
