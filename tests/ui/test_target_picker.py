"""The target picker (ui/query/target_picker.py) on the query screen and the Fit
Test screen, by key presses: the weighted share shown is the database's own
weighted count and weighted fit test, and the screens say they are weighted."""

from __future__ import annotations

import numpy as np
import pytest
from _screen import settle

from sass_tui.cli import main
from sass_tui.db.engine.schema import connect
from sass_tui.db.populations.fit import fit_test
from sass_tui.db.populations.fit_table import format_table
from sass_tui.db.populations.targets import SHIPPED, load_target, weighted_count
from sass_tui.ui.query.fit_screen import FitScreen
from sass_tui.ui.query.query_screen import QueryScreen
from sass_tui.ui.query.target_picker import NO_TARGET, TargetPicker

SIZE = (120, 40)
QUERY = "stature <= 160 cm"


@pytest.fixture
def targeted_db(db, tmp_path):
    """The shipped database with one target: shorter, heavier women."""
    rng = np.random.default_rng(5)
    stature = rng.normal(160.5, 6.8, 400)
    mass = np.exp(np.log(74) + 0.19 * rng.standard_normal(400))
    sample = tmp_path / "civilian.csv"
    sample.write_text(
        "stature,mass\n" + "".join(f"{s:.2f},{m:.2f}\n" for s, m in zip(stature, mass)),
        encoding="utf-8",
    )
    argv = ["target", "civ", "--db", str(db), "--gender", "female", "--sample", str(sample)]
    assert main(argv) == 0
    return db


@pytest.mark.slow
def test_the_query_screen_and_fit_test_weighted_to_a_target(app_at, drive, targeted_db):
    with connect(targeted_db) as conn:
        weights = load_target(conn, "civ")
        counted = weighted_count(conn, QUERY, weights)
        expected = format_table(fit_test(conn, QUERY, target=weights))

    async def scenario():
        async with app_at(SIZE, db=targeted_db) as (app, pilot):
            await pilot.press("d")
            await settle(pilot)
            screen = app.screen
            assert isinstance(screen, QueryScreen)
            await pilot.press("t")
            await pilot.pause()
            assert isinstance(app.screen, TargetPicker)
            assert app.screen.names == ["civ", *SHIPPED]
            await pilot.press("down", "enter")
            await pilot.pause()
            assert app.screen is screen and screen.target == "civ"
            screen.start_query(QUERY)
            await settle(pilot)
            said = screen.message_line.history[-1][1]
            assert f"({counted.percent:.1f} %)" in said and "Weighted to target civ" in said
            await pilot.press("f", "enter")
            await settle(pilot)
            fit = app.screen
            assert isinstance(fit, FitScreen)
            assert "weighted to target civ" in str(fit.query_one("#fit-title").render())
            assert str(fit.query_one("#fit-table").render()).strip() == expected.strip()
            # the picker on the Fit Test screen: no target, the test unweighted again
            await pilot.press("t")
            await pilot.pause()
            assert isinstance(app.screen, TargetPicker)
            assert app.screen.query_one("#target-menu").get_option_at_index(0).prompt == NO_TARGET
            await pilot.press("up", "enter")
            await settle(pilot)
            assert app.screen is fit and fit.target is None
            assert "weighted" not in str(fit.query_one("#fit-title").render())
            assert "target" not in str(fit.query_one("#fit-table").render())

    drive(scenario())


@pytest.mark.slow
def test_with_no_target_made_the_shipped_ones_are_offered(app_at, drive, db):
    """The shipped target and virtual population (made on first use) are
    offered before anybody made a target; the virtual one is labelled."""

    async def scenario():
        async with app_at(SIZE, db=db) as (app, pilot):
            await pilot.press("d")
            await settle(pilot)
            await pilot.press("t")
            await pilot.pause()
            assert isinstance(app.screen, TargetPicker)
            assert app.screen.names == list(SHIPPED)
            menu = app.screen.query_one("#target-menu")
            assert str(menu.get_option_at_index(2).prompt) == (
                "virtual:nhanes-2017-2020 (VIRTUAL people)"
            )
            await pilot.press("escape")

    drive(scenario())


@pytest.mark.slow
def test_make_population_weighted_to_a_target(app_at, drive, targeted_db, tmp_path):
    """Make Population with a target: the spreadsheet's stature percentiles are the
    weighted empirical percentiles of the target's people (computed here from the
    stored weights and the people's statures)."""
    from sass_tui.model.names import GIRTH
    from sass_tui.model.population.targets import weighted_percentile

    with connect(targeted_db) as conn:
        weights = load_target(conn, "civ")
        stature = dict(conn.execute("SELECT id_num, stature FROM person"))
    expected = weighted_percentile(
        [stature[int(i)] for i in weights.ids], weights.weights, [5, 50, 95]
    )
    out = tmp_path / "civ.dat"

    async def scenario():
        async with app_at(SIZE, db=targeted_db) as (app, pilot):
            await pilot.press("d")
            await settle(pilot)
            app.screen.start_query("gender = female")
            await settle(pilot)
            await pilot.press("t", "down", "enter")
            await pilot.press("a", "m")
            await pilot.press(*str(out), "enter")
            await settle(pilot)
            figure = app.session.population
            assert figure.gender == "female"
            stats = figure.global_stats.stats("female")[0, 0]
            np.testing.assert_allclose(stats, expected, atol=1e-9)
            assert "weighted to target civ" in figure.groups[GIRTH].source.title
            assert figure.stature == pytest.approx(expected[1])

    drive(scenario())
