"""The manikin family screen, driven by keys: its table equals
`load_family`, and `w` writes the files `sass family` writes."""

from __future__ import annotations

import json
import threading

import pytest
from _screen import paste, settle, wait_until
from textual.widgets import DataTable

from sass_tui.db.people.default import open_database
from sass_tui.db.people.values import load_values
from sass_tui.db.populations.family import load_family
from sass_tui.model.files.family_files import write_family
from sass_tui.model.files.fig_reader import read_fig
from sass_tui.ui.query import family_screen
from sass_tui.ui.query.family_screen import FamilyBuilt, FamilyScreen


def _said(app) -> str:
    return app.screen.message_line.history[-1][1]


@pytest.mark.slow
def test_the_family_table_equals_load_family(db, drive, app_at, tmp_path, monkeypatch):
    threads: list[str] = []

    def write_family_noting_the_thread(*args):
        threads.append(
            "main" if threading.current_thread() is threading.main_thread() else "worker"
        )
        return write_family(*args)

    monkeypatch.setattr(family_screen, "write_family", write_family_noting_the_thread)
    conn = open_database(db)
    try:
        expected = load_family(conn, "male", ["stature", "mass"], 0.9)
    finally:
        conn.close()

    async def scenario():
        async with app_at((100, 37), db=True) as (app, pilot):
            await pilot.press("y")
            assert isinstance(app.screen, FamilyScreen)
            await pilot.press("enter")  # gender: male
            await pilot.press(*"stature,mass", "enter")
            await pilot.press(*"90", "enter")
            await settle(pilot)
            table = app.screen.query_one(DataTable)
            assert table.row_count == len(expected.manikins)
            for index, manikin in enumerate(expected.manikins):
                row = table.get_row_at(index)
                assert row[0] == manikin.name
                assert row[1:3] == [f"{manikin.values[f]:.1f}" for f in expected.measures]
                assert manikin.nearest.name in row[3]
            await pilot.press("w")
            await paste(pilot, str(tmp_path / "fam"))
            await pilot.press("enter")
            await wait_until(pilot, lambda: _said(app).startswith("Wrote "), lambda: _said(app))
            # written by a worker (half a second for 13 manikins): the loop went on
            assert threads == ["worker"], threads
            written = json.loads((tmp_path / "fam" / "family.json").read_text())
            assert len(written["manikins"]) == len(expected.manikins)
            assert read_fig(tmp_path / "fam" / f"male_{expected.manikins[0].name}.fig")
            await pilot.press("escape")
            assert not isinstance(app.screen, FamilyScreen)

    drive(scenario())


def test_a_wrong_measure_is_said(db, drive, app_at):
    async def scenario():
        async with app_at((100, 37), db=True) as (app, pilot):
            await pilot.press("y", "enter", *"stature,nosuch", "enter")
            kind, text = app.screen.message_line.history[-1]
            assert kind == "error" and "nosuch" in text

    drive(scenario())


@pytest.mark.slow
def test_w_writes_the_family_it_offered_even_if_another_arrives_meanwhile(
    db, drive, app_at, tmp_path
):
    """`w` offers the family shown; a family built meanwhile (a worker started
    by `b` finishing while the directory is asked) does not take its place."""
    conn = open_database(db)
    try:
        female = load_family(conn, "female", ["stature", "mass"], 0.9)
        people = load_values(conn, ["stature", "mass"], "gender = female").matrix
    finally:
        conn.close()

    async def scenario():
        async with app_at((100, 37), db=True) as (app, pilot):
            await pilot.press("y", "enter", *"stature,mass", "enter", *"90", "enter")
            await settle(pilot)
            await pilot.press("w")
            assert "[family_male]" in str(app.screen.query_one("#message").render())
            app.screen.post_message(FamilyBuilt(female, list(people[:, 0]), list(people[:, 1])))
            await pilot.pause()
            await paste(pilot, str(tmp_path / "fam"))
            await pilot.press("enter")
            await wait_until(pilot, lambda: _said(app).startswith("Wrote "), lambda: _said(app))
            names = sorted(p.name for p in (tmp_path / "fam").glob("*.fig"))
            assert names and all(name.startswith("male_") for name in names), names

    drive(scenario())


@pytest.mark.slow
def test_family_screen_snapshot(db, snap_compare, new_app):
    async def run_before(pilot):
        await pilot.press("y", "enter", *"stature,mass", "enter", *"90", "enter")
        await settle(pilot)

    assert snap_compare(new_app(db=True), run_before=run_before, terminal_size=(100, 37))
