"""Long work shows progress and Escape cancels it, driven by key
presses: Input DB of a generated file shows done/total on the bar; Escape
rolls the import back (row counts and integrity_check unchanged); a cancelled
Make Population writes no file and loads nothing."""

from __future__ import annotations

import threading

import pytest
from _screen import message, paste, settle
from big_flat_files import write_big_flat_files
from test_query_population import query_young_women
from test_query_screen import open_query_screen
from textual import events

from sass_tui.db.engine.schema import connect, row_counts
from sass_tui.ui.progress import Work, WorkBar

SIZE = (120, 40)


def _state(path):
    with connect(path) as conn:
        return row_counts(conn), conn.execute("PRAGMA integrity_check").fetchone()[0]


class HeldWork:
    """Holds the worker at its first progress report until the test lets go:
    the test sees the bar mid-way and presses Escape there, without timing."""

    def __init__(self, monkeypatch, what: str) -> None:
        self.reached = threading.Event()
        self.gate = threading.Event()
        self.reports: list[tuple[int, int]] = []
        original = Work.report

        def report(work: Work, done: int, total: int) -> None:
            if work.what == what:
                self.reports.append((done, total))
            original(work, done, total)
            if work.what == what and done and not self.reached.is_set():
                self.reached.set()
                self.gate.wait(60)  # a guard against a hung test, not a timing

        monkeypatch.setattr(Work, "report", report)
        # Every report reaches the bar: at MAX_UPDATES a second, a report made
        # within 1/20 s of the one before is left out, and the one the worker
        # is held at could be that one (the bar never showing it).
        monkeypatch.setattr("sass_tui.ui.progress.MAX_UPDATES", 10**9)

    async def until_shown(self, pilot, bar: WorkBar) -> None:
        for _ in range(500):  # a bound on turns of the event loop, not a time
            await pilot.pause()
            if self.reached.is_set() and bar.done:
                return
        self.gate.set()
        raise AssertionError(f"the bar never showed progress: {self.reports}")


async def _answer(pilot, text) -> None:
    pilot.app.screen.query_one("#answer").post_message(events.Paste(str(text)))
    await pilot.pause()
    await pilot.press("enter")


def test_input_db_shows_lines_done_of_total_and_escape_rolls_it_back(
    drive, app_at, db, tmp_path, monkeypatch
):
    files = write_big_flat_files(tmp_path / "big", people=1500)
    before = _state(db)
    held = HeldWork(monkeypatch, "Input DB")

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            bar = screen.query_one(WorkBar)
            assert not bar.display or bar.text == ""
            await pilot.press("i")
            for path in (files.person, files.girth, files.joint_limits, files.center_of_mass):
                await _answer(pilot, path)
            await pilot.press("escape")  # no strength files: the import starts
            await held.until_shown(pilot, bar)
            lines = 1500 * 26
            assert bar.text == f"Input DB 500/{lines:,}"
            assert bar.display
            assert str(bar.query_one("#work-count").render()) == f"500/{lines:,}"
            await pilot.press("escape")  # cancel
            assert "Cancelling Input DB" in message(app)
            held.gate.set()
            await settle(pilot)
            assert message(app) == "Input DB cancelled; the database is unchanged."
            assert bar.text == "" and not bar.has_class("-busy")
            assert not screen.running

    drive(scenario())
    assert _state(db) == before


def test_input_db_bar_runs_to_the_total(drive, app_at, db, tmp_path, monkeypatch):
    files = write_big_flat_files(tmp_path / "big", people=600)
    seen: list[tuple[int, int]] = []
    original = WorkBar.show

    def show(bar, event) -> None:
        original(bar, event)
        seen.append((bar.done, bar.total))

    monkeypatch.setattr(WorkBar, "show", show)

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await open_query_screen(pilot)
            await pilot.press("i")
            for path in (files.person, files.girth, files.joint_limits, files.center_of_mass):
                await _answer(pilot, path)
            await pilot.press("escape")
            await settle(pilot)
            assert message(app) == "Loaded 600 people into the database."

    drive(scenario())
    assert seen and seen[-1] == (600 * 26, 600 * 26)
    assert [d for d, _t in seen] == sorted(d for d, _t in seen)


@pytest.mark.slow
def test_make_population_cancelled_writes_and_loads_nothing(
    drive, app_at, db, tmp_path, monkeypatch
):
    target = tmp_path / "young.dat"
    held = HeldWork(monkeypatch, "Make Population")

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await query_young_women(pilot)
            screen = app.screen
            await pilot.press("a", "m")
            loaded = {g: fig.source for g, fig in app.session.population.groups.items()}
            await paste(pilot, str(target))
            await pilot.press("enter")
            bar = screen.query_one(WorkBar)
            await held.until_shown(pilot, bar)
            assert bar.text.startswith("Make Population ")
            done, total = held.reports[-1]
            assert bar.text == f"Make Population {done:,}/{total:,}"
            await pilot.press("escape")
            held.gate.set()
            await settle(pilot)
            assert message(app) == "Make Population cancelled: nothing written or loaded."
            after = {g: fig.source for g, fig in app.session.population.groups.items()}
            assert after == loaded

    drive(scenario())
    assert not target.exists()
    assert not (tmp_path / "young-cmass.dat").exists()


@pytest.mark.slow
def test_a_query_shows_people_searched_and_escape_keeps_the_lists(drive, app_at, db, monkeypatch):
    monkeypatch.setattr("sass_tui.ui.query.query_screen.QUERY_BAR_AFTER", 0.0)  # show it at once
    monkeypatch.setattr("sass_tui.ui.progress.MAX_UPDATES", 10**9)  # and every report
    held = HeldWork(monkeypatch, "Query")
    with connect(db) as conn:
        (people,) = conn.execute("SELECT count(*) FROM person").fetchone()

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            screen.lists.run_chunk = 5000  # two ranges of the people
            screen.start_query("gender = male")
            bar = screen.query_one(WorkBar)
            await held.until_shown(pilot, bar)
            done, total = held.reports[-1]
            assert total == people and 0 < done < people  # the first of two id ranges
            assert bar.text == f"Query {done:,}/{people:,}"
            await pilot.press("escape")
            held.gate.set()
            await settle(pilot)
            assert message(app) == "Query cancelled; the lists are as they were."
            assert screen.lists.last_query is None
            assert screen.lists.count("query") == 0
            screen.start_query("gender = male")  # and the next query runs
            await settle(pilot)
            assert "people found" in message(app)

    drive(scenario())


def test_reports_are_thinned_to_the_screen_but_the_last_always_comes():
    class Target:
        def __init__(self) -> None:
            self.posted: list[tuple[int, int]] = []

        def post_message(self, message) -> bool:
            self.posted.append((message.done, message.total))
            return True

    target = Target()
    work = Work(target, "test")  # type: ignore[arg-type]
    for done in range(1, 10_001):
        work.report(done, 10_000)  # far faster than 20 a second
    assert target.posted[0] == (1, 10_000) and target.posted[-1] == (10_000, 10_000)
    assert len(target.posted) < 100


@pytest.mark.slow
def test_a_family_shows_its_steps_and_escape_cancels_it(drive, app_at, db, monkeypatch):
    from textual.widgets import DataTable

    from sass_tui.ui.query.family_screen import FamilyScreen

    monkeypatch.setattr("sass_tui.ui.progress.MAX_UPDATES", 10**9)
    held = HeldWork(monkeypatch, "Family")

    async def scenario():
        async with app_at((100, 37), db=True) as (app, pilot):
            await pilot.press("y", "enter", *"stature,mass", "enter", *"90", "enter")
            screen = app.screen
            assert isinstance(screen, FamilyScreen)
            bar = screen.query_one(WorkBar)
            await held.until_shown(pilot, bar)
            assert bar.text == "Family 1/3"
            await pilot.press("escape")  # cancels, stays on the screen
            held.gate.set()
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert app.screen is screen
            assert str(screen.query_one("#message").render()) == (
                "Family cancelled: nothing built or written."
            )
            assert screen.family is None and screen.query_one(DataTable).row_count == 0
            await pilot.press("escape")  # nothing running: back
            assert app.screen is not screen

    drive(scenario())


def test_the_fit_test_shows_its_steps_and_escape_cancels_it(drive, app_at, db, monkeypatch):
    from sass_tui.ui.query.fit_screen import FitScreen
    from sass_tui.ui.query.query_screen import QueryScreen

    monkeypatch.setattr("sass_tui.ui.progress.MAX_UPDATES", 10**9)
    held = HeldWork(monkeypatch, "Fit Test")

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            screen.start_query("stature < 190 cm")
            await settle(pilot)
            await pilot.press("f", "enter")
            fit = app.screen
            assert isinstance(fit, FitScreen)
            await held.until_shown(pilot, fit.query_one(WorkBar))
            assert fit.query_one(WorkBar).text == "Fit Test 1/3"
            work = fit.work
            await pilot.press("escape")
            assert work is not None and work.cancel.is_set()
            held.gate.set()
            await settle(pilot)
            assert isinstance(app.screen, QueryScreen)

    drive(scenario())


def test_escape_during_the_first_build_of_the_default_database_leaves_no_file(
    drive, app_at, tmp_path, monkeypatch
):
    """Cancelled at its first report: rolled back and the file removed, so the
    next start builds it again instead of opening an empty database."""
    path = tmp_path / "data" / "sass.db"
    monkeypatch.setenv("SASS_DB", str(path))
    held = HeldWork(monkeypatch, "Building the database")

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.press("d")
            screen = app.screen
            bar = screen.query_one(WorkBar)
            await held.until_shown(pilot, bar)
            done, total = held.reports[-1]
            assert bar.text == f"Building the database {done:,}/{total:,}"
            await pilot.press("escape")
            held.gate.set()
            await settle(pilot)
            assert "cancelled" in message(app)
            assert screen.lists is None

    drive(scenario())
    assert not path.exists()
