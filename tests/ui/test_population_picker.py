"""The population picker (P): from the first screen, the sheet becomes the
virtual U.S. civilians' figure in one step, through the database's first
opening; and the picker's choices."""

from __future__ import annotations

from _screen import message, settle, wait_until

from sass_tui.ui.query.population_picker import (
    SURVEY_QUERY,
    PopulationPicker,
    population_choices,
)
from sass_tui.ui.spreadsheet.spreadsheet import SpreadsheetScreen


def test_p_makes_the_sheet_the_virtual_civilians_figure(drive, app_at):
    async def scenario():
        async with app_at((100, 30), db=True) as (app, pilot):
            before = app.figure.stature
            await pilot.press("P")
            await wait_until(
                pilot, lambda: isinstance(app.screen, PopulationPicker), lambda: message(app)
            )
            labels = [choice.label for choice in app.screen.choices]
            assert labels[0].endswith("virtual U.S. civilians"), labels
            await pilot.press("enter")
            await settle(pilot)
            await wait_until(
                pilot, lambda: isinstance(app.screen, SpreadsheetScreen), lambda: message(app)
            )
            assert "written" in message(app) and "and loaded" in message(app), message(app)
            assert "VIRTUAL" in app.figure.groups["girth"].source.title
            assert app.figure.stature != before

    drive(scenario())


def test_the_choices_put_the_virtual_civilians_first():
    choices = population_choices(["nhanes-2017-2020", "virtual:nhanes-2017-2020"], "age > 40")
    assert [c.target for c in choices] == [
        "virtual:nhanes-2017-2020",
        "nhanes-2017-2020",
        None,
        None,
    ]
    assert choices[2].query == SURVEY_QUERY
    assert choices[3].query == "age > 40"
    assert choices[0].file_name() == "virtual-nhanes-2017-2020.dat"
    assert population_choices([], None)[-1].query == SURVEY_QUERY
