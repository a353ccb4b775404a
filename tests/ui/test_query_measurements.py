"""On the query screen: the searchable Measurements menu, the new
Global Information attributes (text values put in quotes), and the list's
source column; driven by key presses, counts checked against the CSV."""

from __future__ import annotations

import csv

import pytest
from _paths import ANSUR
from _screen import message, settle
from test_query_screen import choose, popup_labels, summary

from sass_tui.ui.query.query_popup import MenuSearch, QueryPopup
from sass_tui.ui.query.query_screen import ListSheet

SIZE = (120, 40)


def csv_rows():
    for name in ("ANSUR_II_MALE_Public.csv", "ANSUR_II_FEMALE_Public.csv"):
        path = ANSUR / name
        if not path.exists():
            pytest.skip("the ANSUR II CSV files of ../shared are not here")
        with path.open(newline="", encoding="latin-1") as handle:
            for row in csv.DictReader(handle):
                yield {key.lower(): value for key, value in row.items()}


@pytest.mark.slow
def test_measurement_menu_filters_and_builds_a_query_with_quoted_text(drive, app_at, db):
    # Independent count: sitting height is in mm in the survey, 95 cm = 950 mm.
    expected = sum(
        1
        for row in csv_rows()
        if float(row["sittingheight"]) > 950 and row["branch"].lower() == "combat arms"
    )

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await pilot.press("d")
            await settle(pilot)
            await pilot.press("d", "b")
            await choose(pilot, "Measurements")
            popup = app.screen.query_one(QueryPopup)
            assert popup.border_title == "Measurements"
            assert len(popup_labels(app)) == 93 + 1  # and Previous Menu
            assert isinstance(app.focused, MenuSearch)
            await pilot.press(*"sittingh")
            assert popup_labels(app) == ["sittingheight (cm)", "Previous Menu"]
            await pilot.press("enter")
            await choose(pilot, "Greater Than (>)")
            await pilot.press(*"95", "enter")
            await choose(pilot, "And")
            await choose(pilot, "Global Information")
            await choose(pilot, "Branch")
            await choose(pilot, "Equal (=)")
            await pilot.press(*"Combat Arms", "enter")
            assert "measure.sittingheight > 95 cm AND branch = 'Combat Arms'" in message(app)
            await choose(pilot, "Done")
            await settle(pilot)
            assert f"{expected:,} people found" in message(app)
            assert "measure.sittingheight > 95 cm AND branch = 'Combat Arms'" in summary(app)
            rendered = str(app.screen.query_one(ListSheet).render())
            header = rendered.splitlines()[0]
            assert "Source" in header
            assert rendered.count("ANSUR II") >= min(expected, 5)

    drive(scenario())


@pytest.mark.slow
def test_escape_in_the_measurement_menu_is_previous_menu(drive, app_at, db):
    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await pilot.press("d")
            await settle(pilot)
            await pilot.press("d", "b")
            await choose(pilot, "Measurements")
            await pilot.press(*"zzz")
            assert popup_labels(app) == ["Previous Menu"]
            await pilot.press("escape")
            await pilot.pause()
            assert app.screen.query_one(QueryPopup).border_title == "Query Menu"

    drive(scenario())
