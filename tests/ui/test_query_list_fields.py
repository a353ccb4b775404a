"""The query list shows the measurements a query compared as columns, sorts
by any field `sass query --fields` lists, shows a source whole, and finds a
person by any part of a name; the measurement menu's filter puts the names
that begin with what was typed first."""

from __future__ import annotations

import csv

import pytest
from _screen import message, open_query_screen, paste, settle, slash_query

from sass_tui.db.query.query import compile_query
from sass_tui.ui.query.query_builder import MEASUREMENTS_MENU, TYPE_A_SOURCE, QueryBuilder
from sass_tui.ui.query.query_list import ListSheet
from sass_tui.ui.query.query_people import SortError, sort_column
from sass_tui.ui.query.query_popup import QueryPopup, filtered_labels

QUERY = "gender = female AND measure.poplitealheight > 440 mm"
SIZE = (100, 37)


def popliteal_heights_in_the_csv(ansur_dir) -> list[float]:
    """Straight from ANSUR II's CSV (mm): the women's popliteal heights over
    440 mm, in cm as the database stores them."""
    with open(ansur_dir / "ANSUR_II_FEMALE_Public.csv", encoding="latin-1") as file:
        heights = (float(r["poplitealheight"]) for r in csv.DictReader(file))
        return [height / 10 for height in heights if height > 440]


def test_sort_by_the_measurement_just_queried(drive, app_at, ansur_dir):
    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await slash_query(pilot, QUERY)
            expected = sorted(popliteal_heights_in_the_csv(ansur_dir), reverse=True)
            sheet = app.screen.query_one(ListSheet)
            # The measurement is a column of the list, after the source.
            header = str(sheet.render()).splitlines()[0]
            assert "poplitealheight cm" in header, header
            await pilot.press("o")
            await paste(pilot, "-measure.poplitealheight")
            await pilot.press("enter")
            await settle(pilot)
            assert "sorted by measure.poplitealheight, largest first" in message(app)
            shown = [row["measure.poplitealheight"] for row in sheet.rows]
            assert shown == pytest.approx(expected[: len(shown)])
            assert "poplitealheight ▼" in str(sheet.render()).splitlines()[0]
            # The measurement's name alone sorts by it too, smallest first.
            await pilot.press("o")
            await paste(pilot, "poplitealheight")
            await pilot.press("enter")
            await settle(pilot)
            assert sheet.rows[0]["measure.poplitealheight"] == pytest.approx(min(expected))

    drive(scenario())


def test_a_source_is_shown_whole_and_a_name_found_by_any_word(drive, app_at):
    async def scenario():
        async with app_at((80, 24), db=True) as (app, pilot):
            await slash_query(pilot, "source = 'virtual:nhanes-2017-2020'")
            sheet = app.screen.query_one(ListSheet)
            text = str(sheet.render())
            assert "virtual:nhanes-2017-2020" in text, text
            # The number that ends a name ("virtual nhanes-2017-2020 F 4216").
            number = sheet.rows[-1]["name"].split()[-1]
            await pilot.press("j")
            await paste(pilot, number)
            await pilot.press("enter")
            await settle(pilot)
            assert sheet.highlighted["name"].split()[-1] == number, message(app)

    drive(scenario())


def test_a_sort_that_names_nothing_says_what_it_takes():
    assert sort_column("measure.poplitealheight") == ("measure.poplitealheight", False)
    assert sort_column("-girth.neck.x") == ("girth.neck.x", True)
    assert sort_column("stat") == ("stature", False)
    with pytest.raises(SortError, match="sass query --fields"):
        sort_column("measure.nosuchthing")


def test_the_filter_puts_the_names_that_begin_so_first():
    labels = filtered_labels(MEASUREMENTS_MENU, "poplit")
    assert labels[0].startswith("poplitealheight"), labels
    assert any(label.startswith("buttockpopliteallength") for label in labels)
    assert filtered_labels(MEASUREMENTS_MENU, "zzz") == []


def test_the_builders_source_is_picked_from_the_databases(drive, app_at):
    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await open_query_screen(pilot)
            await pilot.press("d", "b")
            await settle(pilot)
            popup = app.screen.query_one(QueryPopup)
            for label in ("Global Information", "Source"):
                await pilot.press(*["down"] * popup.labels.index(label), "enter")
                await pilot.pause()
            assert popup.labels[:3] == ["ansur2", "synthetic", "virtual:nhanes-2017-2020"]
            assert TYPE_A_SOURCE in popup.labels
            await pilot.press("down", "down", "enter")
            await pilot.pause()
            assert app.screen.builder.text == "source = 'virtual:nhanes-2017-2020'"
            assert popup.menu_key == "conjunction"

    drive(scenario())


def test_a_source_with_a_quote_is_quoted_the_other_way():
    builder = QueryBuilder(sources=("O'Brien survey",))
    for label in ("Global Information", "Source", "O'Brien survey"):
        builder.choose(label)
    assert builder.text == 'source = "O\'Brien survey"'
    compile_query(builder.text)  # the query language takes it


def test_the_query_line_offers_the_last_query_selected_and_keeps_a_failed_one(drive, app_at):
    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await slash_query(pilot, "stature > 190 cm")
            await pilot.press("slash")
            answer = app.screen.query_one("#answer")
            assert answer.value == "stature > 190 cm"
            assert answer.selected_text == "stature > 190 cm"
            # Typing replaces it: the error is in the text typed, which stays.
            await pilot.press(*"mass > 9x0 kg", "enter")
            await pilot.pause()
            assert app.screen.message_line.prompting
            assert answer.value == "mass > 9x0 kg"
            assert message(app).startswith("Not run:"), message(app)
            assert "at the cursor" in message(app)
            assert answer.cursor_position == "mass > 9x0 kg".index("x")
            # Fixed where the cursor is, it runs.
            await pilot.press("delete", "enter")
            await settle(pilot)
            assert "people found" in message(app), message(app)
            assert app.screen.lists.last_query == "mass > 90 kg"

    drive(scenario())
