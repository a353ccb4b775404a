"""Fit Test on the query screen: the last query as design limits
over ANSUR II, driven by key presses; the shares on screen are fit_test's and
a direct count over the survey's CSV files."""

from __future__ import annotations

import pytest
from _screen import settle
from test_query_measurements import csv_rows
from test_query_screen import choose

from sass_tui.db.engine.schema import connect
from sass_tui.db.populations.design import design, format_design
from sass_tui.db.populations.fit import fit_test
from sass_tui.db.populations.fit_table import format_table
from sass_tui.ui.query.fit_screen import FitScreen
from sass_tui.ui.query.query_screen import QueryScreen

SIZE = (120, 40)
LIMITS = "measure.sittingheight < 95 cm AND stature > 160"  # as the menus build it


@pytest.mark.slow
def test_fit_test_of_the_query_over_ansur2(drive, app_at, db):
    fit = {"male": 0, "female": 0}
    people = {"male": 0, "female": 0}
    for row in csv_rows():
        gender = row["gender"].lower()
        people[gender] += 1
        fit[gender] += float(row["sittingheight"]) < 950 and float(row["stature"]) > 1600
    with connect(db) as conn:
        expected = fit_test(conn, LIMITS)
    for gender in ("male", "female"):
        assert expected.genders[gender].fit == fit[gender]
        assert expected.genders[gender].n == people[gender]

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await pilot.press("d")
            await settle(pilot)
            await pilot.press("d", "b")
            await choose(pilot, "Measurements")
            await pilot.press(*"sittingh", "enter")
            await choose(pilot, "Less Than (<)")
            await pilot.press(*"95", "enter")
            await choose(pilot, "And")
            await choose(pilot, "Global Information")
            await choose(pilot, "Stature (cm)")
            await choose(pilot, "Greater Than (>)")
            await pilot.press(*"160", "enter")
            await choose(pilot, "Done")
            await settle(pilot)
            await pilot.press("f", "enter")
            await settle(pilot)
            assert isinstance(app.screen, FitScreen)
            shown = str(app.screen.query_one("#fit-table").render())
            assert shown.strip() == format_table(expected).strip()
            for gender in ("male", "female"):
                line = next(x for x in shown.splitlines() if x.startswith(gender))
                assert line.split()[1:3] == [str(people[gender]), str(fit[gender])]
                share = 100 * fit[gender] / people[gender]
                assert f"{share:.1f} %" in line
            await pilot.press("escape")
            await pilot.pause()
            assert isinstance(app.screen, QueryScreen)

    drive(scenario())


async def open_fit_screen(pilot) -> None:
    """The query screen, LIMITS run as the query, then Fit Test over ANSUR II."""
    await pilot.press("d")
    await settle(pilot)
    pilot.app.screen.start_query(LIMITS)
    await settle(pilot)
    await pilot.press("f", "enter")
    await settle(pilot)


@pytest.mark.slow
def test_fit_screen_snapshot(snap_compare, new_app, db):
    assert snap_compare(new_app(db=True), run_before=open_fit_screen, terminal_size=(80, 24))


def _direct_counts(edges, values) -> list[int]:
    """People per bin by plain comparison: edges[k] <= v < edges[k+1], the last
    bin also holding its right edge."""
    last = len(edges) - 2
    return [
        sum(1 for v in values if lo <= v < hi or (k == last and v == hi))
        for k, (lo, hi) in enumerate(zip(edges, edges[1:]))
    ]


@pytest.mark.slow
def test_fit_screen_histogram_counts_the_population_and_draws_the_limits(drive, app_at, db):
    """The bars plotted are a direct count over the survey's CSV (mm -> cm);
    `l` moves to the next limited measurement."""
    survey = {
        "male": {"sittingheight": [], "stature": []},
        "female": {"sittingheight": [], "stature": []},
    }
    for row in csv_rows():
        for name in ("sittingheight", "stature"):
            survey[row["gender"].lower()][name].append(float(row[name]) / 10)

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await open_fit_screen(pilot)
            screen = app.screen
            assert isinstance(screen, FitScreen)
            for name, limit in (("sittingheight", 95.0), ("stature", 160.0)):
                hist = screen.histograms[screen.shown]
                assert hist.field.removeprefix("measure.") == name
                assert [line.value for line in hist.lines] == [limit]
                assert hist.edges[0] <= limit <= hist.edges[-1]  # the line is on the plot
                centers, counts = screen.plotted
                edges = [float(e) for e in hist.edges]
                assert centers == [(a + b) / 2 for a, b in zip(edges, edges[1:])]
                for gender in ("male", "female"):
                    assert counts[gender] == _direct_counts(edges, survey[gender][name])
                    assert sum(counts[gender]) == len(survey[gender][name])
                title = str(screen.query_one("#fit-plot-title").render())
                assert f"{name} (cm) of source = ansur2, red: {name} " in title
                await pilot.press("l")
                await pilot.pause()
            assert screen.shown == 0  # two limited measurements: back to the first

    drive(scenario())


def test_fit_screen_histogram_snapshot(snap_compare, new_app, db):
    assert snap_compare(new_app(db=True), run_before=open_fit_screen, terminal_size=(100, 30))


@pytest.mark.slow
def test_the_fit_screen_says_when_it_is_done_and_f1_lists_its_keys(drive, app_at, db):
    """A SassScreen like the others: its message line says the test is done
    and which keys apply; F1 lists them; Escape closes the help, then returns."""
    from sass_tui.ui.palette import HelpScreen

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await open_fit_screen(pilot)
            screen = app.screen
            assert isinstance(screen, FitScreen)
            said = str(screen.message_line.query_one("#message").render())
            assert said.startswith("Fit test done:") and "l the next limit" in said
            await pilot.press("f1")
            await pilot.pause()
            assert isinstance(app.screen, HelpScreen)
            names = {command.name for command in app.screen.commands}
            assert {"Back to the query", "Next limit", "Help"} <= names
            await pilot.press("escape")
            await pilot.pause()
            assert app.screen is screen
            await pilot.press("escape")
            await settle(pilot)
            assert isinstance(app.screen, QueryScreen)

    drive(scenario())


@pytest.mark.slow
def test_design_limits_typed_on_the_fit_screen_are_solved_as_sass_design(drive, app_at, db):
    """`e`, limits with ? and a share, Enter: the screen shows what sass design
    answers for them over the same people (and its fit test)."""
    limits = "stature <= ? AND measure.hipbreadthsitting <= ?"
    with connect(db) as conn:
        expected = design(conn, limits, 90.0, "source = ansur2")

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await open_fit_screen(pilot)
            screen = app.screen
            await pilot.press("e")
            await pilot.pause()
            assert app.focused is screen.query_one("#fit-limits")
            screen.query_one("#fit-limits").value = limits
            screen.query_one("#fit-accommodate").value = "90"
            await pilot.press("enter")
            await settle(pilot)
            shown = str(screen.query_one("#fit-table").render())
            assert shown.startswith(format_design(expected).strip().splitlines()[0])
            for text in expected.texts:
                assert text in shown
            assert "Accommodated (checked with sass fit): 90." in shown
            assert screen.limits == limits

    drive(scenario())
