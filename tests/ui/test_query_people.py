"""The query screen's people: a query typed whole (`/`), every value of a
person (Enter, also right after an arrow in the same read), sort by any
column (`o`), jump to an id or a name (`j`), the message log (`L`) with
long messages whole at 80 columns; snapshots of the person view and the log."""

from __future__ import annotations

import csv

import pytest
from _screen import message, open_query_screen, paste, settle, slash_query, wait_until
from hypothesis import given
from hypothesis import strategies as st
from textual import events

from sass_tui.db.query.lists import SORT_COLUMNS
from sass_tui.db.query.query import field_column
from sass_tui.ui.message_log import MessageLog
from sass_tui.ui.query.person_screen import PersonScreen
from sass_tui.ui.query.query_list import ListSheet
from sass_tui.ui.query.query_people import SortError, sort_column

TALL = "gender = female AND stature > 175 cm"
SIZE = (100, 37)
NARROW = (80, 24)


def tall_women_in_the_csv(ansur_dir) -> list[float]:
    """Straight from ANSUR II's CSV: statures (mm) of the women over 175 cm."""
    with open(ansur_dir / "ANSUR_II_FEMALE_Public.csv", encoding="latin-1") as file:
        return [float(r["stature"]) for r in csv.DictReader(file) if float(r["stature"]) > 1750]


def rows(app) -> list[dict]:
    return app.screen.query_one(ListSheet).rows


@pytest.mark.slow
def test_slash_runs_a_typed_query(drive, app_at, ansur_dir):
    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await slash_query(pilot, TALL)
            expected = len(tall_women_in_the_csv(ansur_dir))
            assert expected == 67  # the tall women
            assert message(app).startswith(f"Query execution is complete. {expected} people")
            # `/` again offers the last query to edit.
            await pilot.press("slash")
            assert app.screen.query_one("#answer").value == TALL

    drive(scenario())


@pytest.mark.slow
def test_down_enter_in_one_read_shows_every_value_of_the_next_person(drive, app_at, db):
    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await slash_query(pilot, TALL)
            second = rows(app)[1]
            app.post_message(events.Key("down", None))
            app.post_message(events.Key("enter", "\r"))
            await wait_until(pilot, lambda: isinstance(app.screen, PersonScreen), "no person view")
            screen = app.screen
            assert screen.record["id"] == second["id"]
            text = str(screen.query_one("#person-text").render())
            assert text.startswith(f"{second['name']} (id {second['id']})")
            # Every measure the database holds for the person, with its unit.
            for name, value in screen.record["measures"].items():
                assert f"{name:<32} {value:>8.2f}" in text
            assert "girth (cm):" in text and "unmeasured:" in text
            await pilot.press("escape")
            assert not isinstance(app.screen, PersonScreen)

    drive(scenario())


@pytest.mark.slow
def test_sort_by_stature_largest_first_and_back(drive, app_at, ansur_dir):
    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await slash_query(pilot, TALL)
            await pilot.press("o")
            await paste(pilot, "-stature")
            await pilot.press("enter")
            await settle(pilot)
            tallest = max(tall_women_in_the_csv(ansur_dir)) / 10
            assert rows(app)[0]["stature"] == pytest.approx(tallest)
            statures = [r["stature"] for r in rows(app)]
            assert statures == sorted(statures, reverse=True)
            assert message(app) == "Query List sorted by Stature cm, largest first."
            assert "Stature ▼" in str(app.screen.query_one(ListSheet).render())
            await pilot.press("o", "enter")  # empty: the list's own order
            await settle(pilot)
            ids = [r["id"] for r in rows(app)]
            assert ids == sorted(ids)
            await pilot.press("o")
            await paste(pilot, "colour")
            await pilot.press("enter")
            assert "'colour' names no column" in message(app)

    drive(scenario())


@pytest.mark.slow
def test_jump_to_a_name_on_a_later_page(drive, app_at, db):
    async def scenario():
        async with app_at(NARROW, db=True) as (app, pilot):
            await slash_query(pilot, TALL)
            sheet = app.screen.query_one(ListSheet)
            assert sheet.total > sheet.page_size  # the person is on a later page
            lists = app.screen.lists
            last = lists.page("query", sheet.total - 1, 1)[0]
            await pilot.press("j")
            await paste(pilot, last["name"].lower())
            await pilot.press("enter")
            await settle(pilot)
            assert sheet.highlighted["id"] == last["id"]
            assert message(app) == f"{last['name']}: number {sheet.total} of the query list."
            await pilot.press("j")
            await paste(pilot, "nobody")
            await pilot.press("enter")
            assert message(app) == "Nobody in the query list is 'nobody'."

    drive(scenario())


def test_sort_words():
    assert sort_column("stature") == ("stature", False)
    assert sort_column(" -Mass ") == ("mass", True)
    assert sort_column("speed") == ("motion_speed", False)
    assert sort_column("") is None
    with pytest.raises(SortError, match="more than one column"):
        sort_column("s")


LONG = (
    "A long message, longer than the eighty columns of the message line: it is "
    "cut there, and the message log shows it whole, wrapped onto the lines it needs."
)


@pytest.mark.slow
def test_message_log_on_the_query_screen_shows_long_messages_whole(drive, app_at, db):
    async def scenario():
        async with app_at(NARROW, db=True) as (app, pilot):
            await open_query_screen(pilot)
            app.screen.say(LONG)
            await pilot.press("L")
            await pilot.pause()
            assert isinstance(app.screen, MessageLog)
            log = app.screen.query_one("#log-text")
            assert log.size.width < len(LONG)  # wrapped, not cut
            assert LONG in str(log.render())

    drive(scenario())


@pytest.mark.slow
def test_person_view_snapshot(snap_compare, new_app, db):
    async def run_before(pilot):
        await open_query_screen(pilot)
        pilot.app.screen.start_query(TALL)
        await settle(pilot)
        await pilot.press("enter")
        await wait_until(pilot, lambda: isinstance(pilot.app.screen, PersonScreen), "no view")

    assert snap_compare(new_app(db=True), run_before=run_before, terminal_size=NARROW)


@pytest.mark.slow
def test_message_log_on_the_query_screen_snapshot(snap_compare, new_app, db):
    async def run_before(pilot):
        await open_query_screen(pilot)
        pilot.app.screen.message_line.history.clear()  # it names the test's own database file
        pilot.app.screen.say(LONG)
        await pilot.press("L")
        await pilot.pause()

    assert snap_compare(new_app(db=True), run_before=run_before, terminal_size=NARROW)


@given(st.text(max_size=20))
def test_any_sort_text_is_a_column_the_lists_sort_by_or_a_sort_error(text):
    try:
        sort = sort_column(text)
    except SortError as exc:
        assert "\n" not in str(exc) and "sort by one of" in str(exc)
        return
    # a column of the list, or a field `sass query --fields` lists (its column is found)
    assert sort is None or isinstance(sort[1], bool)
    assert sort is None or sort[0] in SORT_COLUMNS or field_column(sort[0])
