"""Predict on the spreadsheet, driven by keys."""

from __future__ import annotations

import numpy as np
import pytest
from _screen import wait_until

from sass_tui.db.people.default import open_database
from sass_tui.db.populations.predict import open_predictor
from sass_tui.model.files.fig_reader import read_fig
from sass_tui.model.names import CENTER_OF_MASS, GIRTH
from sass_tui.model.population.prediction import split_known

KNOWN = "stature=180 cm, mass=85 kg"


@pytest.fixture
def expected(db):
    conn = open_database(db)
    try:
        predictor = open_predictor(conn)
        known = predictor.parse_known("male", split_known(KNOWN))
        return predictor.predict("male", known)
    finally:
        conn.close()


async def _wait_prompt(app, pilot):
    await wait_until(
        pilot,
        lambda: app.message_line.prompting,
        lambda: f"no prompt: {app.message_line.history[-1]}",
    )


async def _predict(app, pilot, text=KNOWN):
    await pilot.press("k")
    await _wait_prompt(app, pilot)
    await pilot.press(*text)
    await pilot.press("enter")
    await pilot.pause()


@pytest.mark.slow
def test_predict_by_keys_shows_the_predicted_figure(
    db, drive, app_at, expected, tmp_path, monkeypatch
):
    monkeypatch.chdir(tmp_path)

    async def scenario():
        async with app_at((80, 40), db=True) as (app, pilot):
            population = app.session.population
            before = population.groups[GIRTH].values.copy()
            await _predict(app, pilot)
            figure = app.figure
            assert figure is not population
            assert figure.person == "predicted from stature 180 cm, mass 85 kg"
            for group in (GIRTH, CENTER_OF_MASS):
                predicted = expected.group_values(group)
                shown = figure.groups[group].values
                have = ~np.isnan(predicted)
                np.testing.assert_allclose(shown[have], predicted[have])
            assert "predicted from stature 180 cm, mass 85 kg" in app.message_line.history[-1][1]
            # The interval of the cell under the cursor (girth row 0, x).
            await pilot.press("a")
            row = figure.groups[GIRTH].rows[0].name
            estimate = expected.values[f"girth.{row}.x"]
            said = app.message_line.history[-1][1]
            assert f"{estimate.low:.1f} – {estimate.high:.1f} cm" in said, said
            # Create Figure writes the predicted figure.
            await pilot.press("f")
            await pilot.press(*"pred.fig", "enter")
            await pilot.press("n", "enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            fig = read_fig(tmp_path / "pred.fig")
            assert fig is not None
            text = (tmp_path / "pred.fig").read_text()
            assert "predicted from stature 180 cm" in text
            # Disp. Pop. returns to the population, unchanged.
            await pilot.press("o")
            assert app.figure is population
            np.testing.assert_array_equal(population.groups[GIRTH].values, before)
            await pilot.press("a")  # no prediction shown: the key does nothing

    drive(scenario())


@pytest.mark.parametrize(
    ("typed", "said"),
    [
        ("statur=180", "did you mean"),
        ("stature=85 kg", "stature=85 kg"),
        ("stature=900 cm", "stature"),
        ("stature", "expected NAME=VALUE"),
        ("stature=180 cm, stature=170 cm", "stature is already known (stature=180 cm)"),
    ],
)
@pytest.mark.slow
def test_predict_errors_on_the_message_line(db, drive, app_at, typed, said):
    async def scenario():
        async with app_at((80, 40), db=True) as (app, pilot):
            population = app.session.population
            await _predict(app, pilot, typed)
            kind, text = app.message_line.history[-1]
            assert kind == "error" and said in text, text
            assert app.figure is population

    drive(scenario())


@pytest.mark.slow
def test_names_complete_as_typed(db, drive, app_at):
    async def scenario():
        async with app_at((80, 40), db=True) as (app, pilot):
            await pilot.press("k")
            await _wait_prompt(app, pilot)
            await pilot.press(*"stature=180 cm, ma")
            answer = app.message_line.answer
            # The suggester answers in a worker of its own.
            await wait_until(
                pilot, lambda: answer._suggestion.startswith("stature=180 cm, ma"), "no suggestion"
            )
            assert answer._suggestion == "stature=180 cm, mass"
            await pilot.press("right")  # accepts the suggestion
            assert answer.value == "stature=180 cm, mass"

    drive(scenario())


@pytest.mark.slow
def test_predicted_figure_snapshot(db, snap_compare, new_app):
    """80x24: the label in the population slot, the Interval command, a cell's interval."""

    async def run_before(pilot):
        await _predict(pilot.app, pilot)
        await pilot.press("down", "a")

    assert snap_compare(new_app(db=True), run_before=run_before, terminal_size=(80, 24))


@pytest.mark.slow
def test_a_gender_without_people_is_said(db, drive, app_at):
    async def scenario():
        async with app_at((80, 40), db=True) as (app, pilot):
            await pilot.press("k")
            await _wait_prompt(app, pilot)
            await pilot.press("escape")
            # The database's women gone from the model: as a database of men only.
            del app.spreadsheet._predictor.models["female"]
            app.session.set_gender("female")
            await pilot.press("k")
            await pilot.pause()
            kind, text = app.message_line.history[-1]
            assert kind == "error" and "no female people" in text, text
            assert not app.message_line.prompting

    drive(scenario())
