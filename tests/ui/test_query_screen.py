"""The database query spreadsheet, the pop-up query builder and displaying
individuals (report §12.3-§12.5), driven by key presses and clicks."""

from __future__ import annotations

import numpy as np
import pytest
from _screen import message, settle, wait_until
from textual import events
from textual.widgets import OptionList

from sass_tui.db.engine.schema import connect
from sass_tui.db.people.individual import fetch_individual
from sass_tui.db.query.query import run_query
from sass_tui.model.files.fig_reader import read_fig
from sass_tui.model.names import GIRTH, row_index
from sass_tui.ui.query.query_builder import VALUE_PROMPT, QueryBuilderScreen, QueryPopup
from sass_tui.ui.query.query_screen import (
    BUILD_PROMPT,
    COMPLETE,
    NO_DATA,
    WAIT,
    ListSheet,
    QueryScreen,
    SummaryPanel,
)
from sass_tui.ui.widgets import GlobalPanel, MenuItem

SIZE = (120, 40)
# Only the synthetic demonstration people carry strength: the query names their source.
SAMPLE = (
    "gender = male AND girth.right_upper_arm.z > 28 cm AND strength.elbow_flexion.max > 20 ft-lb"
    " AND source = 'synthetic'"
)


def summary(app) -> str:
    return str(app.screen.query_one(SummaryPanel).render())


def popup_labels(app) -> list[str]:
    options = app.screen.query_one("#popup-options", OptionList)
    return [str(options.get_option_at_index(i).prompt) for i in range(options.option_count)]


def command_slots(app) -> list[str]:
    """Labels of the first two visible buttons of figure 6's second column."""
    column = app.query(".command-column").last()
    return [str(b.label) for b in column.query(MenuItem) if b.display][:2]


async def choose(pilot, label: str) -> None:
    """Pick a pop-up menu item the way a user does: arrow keys, then Enter."""
    popup = pilot.app.screen.query_one(QueryPopup)
    assert popup.display, f"no pop-up menu open to choose {label!r}"
    labels = popup_labels(pilot.app)
    assert label in labels, f"{label!r} not in {popup.border_title}: {labels}"
    await pilot.press(*["down"] * labels.index(label), "enter")


async def type_answer(pilot, text: str) -> None:
    await pilot.press(*text, "enter")


async def open_query_screen(pilot) -> QueryScreen:
    await pilot.press("d")
    await settle(pilot)
    assert isinstance(pilot.app.screen, QueryScreen)
    return pilot.app.screen


async def build_sample_query(pilot, title_log: list[str]) -> None:
    """Figure 13's sequence of pop-up menus."""

    async def step(label):
        title_log.append(pilot.app.screen.query_one(QueryPopup).border_title)
        await choose(pilot, label)

    await step("Global Information")
    await step("Gender")
    await step("Male")
    await step("And")
    await step("Anthropometric Groups")
    await step("Girth")
    await step("Right Upper Arm")
    await step("Z Axis")
    await step("Greater Than (>)")
    assert VALUE_PROMPT in message(pilot.app)
    await type_answer(pilot, "28 cm")
    await step("And")
    await step("Anthropometric Groups")
    await step("Strength")
    await step("Elbow flexion")
    await step("Greater Than (>)")
    await type_answer(pilot, "20 ft-lb")
    await step("And")
    await step("Global Information")
    await step("Source")
    await step("synthetic")  # the database's sources are the Source menu's choices


@pytest.mark.slow
def test_sample_query_through_the_menus_then_display_and_write_a_person(
    drive, app_at, db, tmp_path
):
    with connect(db) as conn:
        expected = run_query(conn, SAMPLE).count()

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await open_query_screen(pilot)
            assert "Query List" in summary(app) and "Exit Query" in str(
                app.screen.query_one("#command-exit_query").label
            )
            await pilot.press("d")
            assert message(app).startswith(BUILD_PROMPT)
            await pilot.click(ListSheet, offset=(20, 6), button=3)  # the right mouse button
            assert app.screen.query_one(QueryPopup).border_title == "Query Menu"
            assert popup_labels(app) == [
                "Global Information",
                "Anthropometric Groups",
                "Measurements",
                "Re_execute",
                "Abort",
            ]
            titles: list[str] = []
            await build_sample_query(pilot, titles)
            assert titles == [
                "Query Menu",
                "Global Information",
                "Gender",
                "Conjunction Menu",
                "Query Menu",
                "Anthropometric Group",
                "Girth Menu",
                "Axis Menu",
                "Relational Operation Menu",
                "Conjunction Menu",
                "Query Menu",
                "Anthropometric Group",
                "Strength Menu",
                "Relational Operation Menu",
                "Conjunction Menu",
                "Query Menu",
                "Global Information",
                "Source",
            ]
            assert app.screen.query_one(QueryPopup).border_title == "Conjunction Menu"
            assert f"Query: {SAMPLE}" in message(app)  # shown live while building
            await choose(pilot, "Done")
            await settle(pilot)
            assert message(app) == f"{COMPLETE} {expected} people found."
            assert SAMPLE in summary(app)
            assert f"Total Data in Query List: {expected}" in summary(app)
            sheet = app.screen.query_one(ListSheet)
            assert len(sheet.rows) == min(25, expected) and sheet.rows[0]["gender"] == "male"
            first_two = [sheet.rows[0]["name"], sheet.rows[1]["name"]]
            await pilot.press("s", "s")  # Select One, twice
            assert f"Total Data in Query List: {expected - 2}" in summary(app)
            assert "Total Data in Selected List: 2" in summary(app)
            await pilot.press("l")  # Display Selected List: Select All etc. are void there
            assert [r["name"] for r in sheet.rows] == first_two
            assert str(app.screen.query_one("#command-select_all").label) == "void"
            # A void command does nothing when clicked; the menu's others do.
            await pilot.click("#command-select_all")
            await pilot.pause()
            assert "Total Data in Selected List: 2" in summary(app)
            await pilot.click("#command-display_list")  # back to the query list
            await pilot.pause()
            assert str(app.screen.query_one("#command-select_all").label) == "Select All"
            await pilot.press("e")  # Exit Query
            assert not isinstance(app.screen, QueryScreen)

            population = app.figure
            assert command_slots(app) == ["Query", "Disp. Indv."]
            await pilot.press("v")  # Disp. Indv.
            # Figure 6's shared slots: "Query or Disp. Pop.", "Disp. Indv. or Disp. More".
            assert command_slots(app) == ["Disp. Pop.", "Disp. More"]
            panel = str(app.query_one(GlobalPanel).render())
            assert first_two[0] in panel and population.population not in panel
            assert f"{first_two[0]} (synthetic)" in panel  # never taken for a real person
            with connect(db) as conn:
                person = fetch_individual(conn, app.query_lists.selected_id(0))
            assert person.name == first_two[0]
            arm = row_index(GIRTH, "right_upper_arm")
            np.testing.assert_allclose(app.figure.groups[GIRTH].values, person.groups[GIRTH])

            out = tmp_path / "person.fig"
            await pilot.press("f")
            assert f"[{first_two[0]}_synthetic.fig]" in message(app)
            app.query_one("#answer").post_message(events.Paste(str(out)))
            await pilot.pause()
            await pilot.press("enter")
            if "Include strength" in message(app):  # when strength data is loaded
                await pilot.press("enter")
            await settle(pilot)
            assert message(app) == f"Wrote {out}."
            fig = read_fig(out)
            assert fig.variables["ruparmz"][0] == pytest.approx(
                person.groups[GIRTH][arm, 2], abs=0.01
            )
            # Export HAnim offers the person's name too, not a percentile figure's.
            await pilot.press("e")
            assert f"HAnim file name [{first_two[0]}_synthetic.x3d]:" in message(app)
            await pilot.press("escape")

            await pilot.press("x")  # Disp. More -> More Menu -> Next
            await pilot.press("down", "down", "down", "enter")
            await pilot.pause()
            assert first_two[1] in str(app.query_one(GlobalPanel).render())
            await pilot.press("d")  # Query's key does nothing while a person is shown
            await pilot.pause()
            assert not isinstance(app.screen, QueryScreen)
            await pilot.press("o")  # Disp. Pop.
            assert app.figure is population and app.figure.person is None
            assert command_slots(app) == ["Query", "Disp. Indv."]
            assert population.population in str(app.query_one(GlobalPanel).render())

    drive(scenario())


@pytest.mark.slow
def test_previous_menu_and_abort(drive, app_at, db):
    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            await pilot.press("d", "b")
            await choose(pilot, "Anthropometric Groups")
            await choose(pilot, "Joint Limit")
            await choose(pilot, popup_labels(app)[0])
            assert screen.builder.text.startswith("joint_limit.")
            await choose(pilot, "Previous Menu")  # erases the joint
            assert screen.builder.text == "joint_limit"
            assert app.screen.query_one(QueryPopup).border_title == "Joint Limit Menu"
            await pilot.press("escape")  # Escape is Previous Menu too
            assert (
                screen.builder.text == ""
                and app.screen.query_one(QueryPopup).border_title == "Anthropometric Group"
            )
            await choose(pilot, "Girth")
            await choose(pilot, "Neck")
            await choose(pilot, "X Axis")
            await choose(pilot, "Less Than (<)")
            await type_answer(pilot, "20")
            assert screen.builder.text == "girth.neck.x < 20"
            await choose(pilot, "Previous Menu")  # erases the value: asked again
            assert VALUE_PROMPT in message(app) and screen.builder.text == "girth.neck.x < "
            await type_answer(pilot, "5")
            await choose(pilot, "Or")
            assert app.screen.query_one(QueryPopup).border_title == "Query Menu"
            assert "Previous Menu" not in popup_labels(app)
            await choose(pilot, "Abort")
            assert not isinstance(app.screen, QueryBuilderScreen) and screen.builder is None
            assert "aborted" in message(app)
            assert "Total Data in Query List: 0" in summary(app)  # nothing was run

            # Re_execute with no previous query says so and keeps the menu open.
            await pilot.press("d", "b")
            await choose(pilot, "Re_execute")
            assert "no previous query" in message(app) and isinstance(
                app.screen, QueryBuilderScreen
            )
            await choose(pilot, "Abort")

    drive(scenario())


@pytest.mark.slow
def test_query_text_edited_before_done_then_re_executed(drive, app_at, db):
    with connect(db) as conn:
        expected = run_query(conn, "gender = female AND stature > 165 cm").count()

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            await pilot.press("d", "b")
            await choose(pilot, "Global Information")
            await choose(pilot, "Gender")
            await choose(pilot, "Male")
            await pilot.press("e")  # edit the query as text on the message line
            answer = app.screen.query_one("#answer")
            assert answer.display and answer.value == "gender = male"
            assert answer.selected_text == "gender = male"  # typing would replace it
            await pilot.press("end", *["backspace"] * 4, *"female AND stature > 165 cm", "enter")
            assert screen.builder.text == "gender = female AND stature > 165 cm"
            assert app.screen.query_one(QueryPopup).border_title == "Conjunction Menu"
            await choose(pilot, "Done")
            await settle(pilot)
            assert message(app) == f"{COMPLETE} {expected} people found."
            await pilot.press("a")  # Select All
            assert f"Total Data in Selected List: {expected}" in summary(app)
            assert "Total Data in Query List: 0" in summary(app)
            # Re_execute: the same query again; the people selected stay selected.
            await pilot.press("d", "b")
            await choose(pilot, "Re_execute")
            await settle(pilot)
            assert message(app) == NO_DATA
            assert f"Total Data in Selected List: {expected}" in summary(app)

    drive(scenario())


@pytest.mark.slow
def test_constraint_that_is_not_a_number(drive, app_at, db):
    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            await pilot.press("d", "b")
            await choose(pilot, "Global Information")
            await choose(pilot, "Stature (cm)")
            await choose(pilot, "Greater Than (>)")
            await type_answer(pilot, "tall")
            assert "'tall' is not a valid constraint" in message(app)
            assert "needs a number" in message(app) and VALUE_PROMPT in message(app)
            assert app.screen.query_one("#answer").display  # still asking
            await type_answer(pilot, "70 kg")  # a mass is not a stature
            assert "'70 kg' is not a valid constraint" in message(app)
            await type_answer(pilot, "70 in")
            assert screen.builder.text == "stature > 70 in"
            assert app.screen.query_one(QueryPopup).border_title == "Conjunction Menu"

    drive(scenario())


def test_paging_delete_and_busy_while_a_query_runs(drive, app_at, db):
    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            screen.start_query("stature > 0")
            assert message(app) == WAIT
            await settle(pilot)
            sheet = screen.query_one(ListSheet)
            total = screen.lists.count("query")
            assert total > 25 and sheet.page_size == 25
            await pilot.press("n")
            assert sheet.first == 25 and sheet.rows[0]["id"] > 25 - 1
            await pilot.press("p", "p")
            assert message(app) == "This is the first page." and sheet.first == 0
            second = sheet.rows[1]["name"]
            await pilot.press("x")  # Delete One: the highlighted (first) person
            assert sheet.rows[0]["name"] == second
            assert f"Total Data in Query List: {total - 1:,}" in summary(app)
            # While the database is busy, list commands answer at once instead of waiting.
            with screen.lists.exclusive():
                await pilot.press("n")
                assert message(app) == WAIT

    drive(scenario())


@pytest.mark.slow
def test_input_db_one_file_at_a_time(drive, app_at, db, tmp_path):
    from sass_tui.model import datasets

    source = datasets.directory() / "db"
    bad = tmp_path / "girth.db"
    bad.write_text("1,BOTTOM_HEAD, 9.80, 7.75, oops, 1.40\n")
    person = tmp_path / "person.db"
    person.write_text("99901,NEW_PERSON,female,160.0,55.0,left,30,test\n")
    girth = tmp_path / "girth-ok.db"
    girth.write_text(
        "\n".join(
            line.replace("1,", "99901,", 1)
            for line in (source / "girth.db").read_text().splitlines()
            if line.startswith("1,")
        )
        + "\n"
    )
    one_person = {name: tmp_path / f"{name}-ok.db" for name in ("jntlmt", "cmass")}
    for name, path in one_person.items():
        path.write_text(
            "\n".join(
                line.replace("1,", "99901,", 1)
                for line in (source / f"{name}.db").read_text().splitlines()
                if line.startswith("1,")
            )
            + "\n"
        )

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)

            async def answer(text):
                app.screen.query_one("#answer").post_message(events.Paste(str(text)))
                await pilot.pause()
                await pilot.press("enter")

            await pilot.press("i")
            assert "Enter File Name for Person" in message(app)
            await pilot.press("enter")  # nothing typed: asked again, saying why
            await pilot.pause()
            assert message(app).startswith(
                "A file name for Person is needed. Enter File Name for Person:"
            )
            await answer(tmp_path / "missing.db")
            await pilot.pause()
            assert message(app).startswith(
                f"{tmp_path / 'missing.db'}: no such file. Enter File Name for Person:"
            )
            await answer(person)
            assert "Girth" in message(app)
            await answer(bad)
            await answer(one_person["jntlmt"])
            await answer(one_person["cmass"])
            assert "Strength Parameter" in message(app)
            await pilot.press("escape")  # no strength files
            await settle(pilot)
            assert "Input DB failed, the database is unchanged" in message(app)
            assert "girth.db:1" in message(app)
            assert (
                screen.lists._conn.execute(
                    "SELECT count(*) FROM person WHERE id_num = 99901"
                ).fetchone()[0]
                == 0
            )

            await pilot.press("i")
            for path in (person, girth, one_person["jntlmt"], one_person["cmass"]):
                await answer(path)
            await pilot.press("escape")
            await settle(pilot)
            assert message(app) == "Loaded 1 people into the database."
            screen.start_query("source = test AND handedness = left AND stature < 161 cm")
            await settle(pilot)
            assert "NEW_PERSON" in [r["name"] for r in screen.query_one(ListSheet).rows]

    drive(scenario())


def test_builder_is_a_modal_screen_that_owns_its_keys(drive, app_at, db):
    """While the pop-up builder is up, its screen has the keys: a query-screen
    command key (l: Display Selected List, n: Next Page) does nothing to the
    query screen below; the builder's result comes back when it closes."""

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            await pilot.press("d", "b")
            assert isinstance(app.screen, QueryBuilderScreen)
            await pilot.press("l", "n")
            assert screen.which == "query" and isinstance(app.screen, QueryBuilderScreen)
            assert app.screen.query_one(QueryPopup).border_title == "Query Menu"
            await pilot.press("escape")  # Abort: the query screen hears the result
            assert app.screen is screen and screen.builder is None
            assert "aborted" in message(app)

    drive(scenario())


def test_enters_in_a_burst_on_abort_close_the_builder_once(drive, app_at, db):
    """Enter typed several times at once on Abort: the builder closes once,
    the query screen stays (the extra Enters used to pop it, then crash);
    they are the query screen's Enters, as typed one by one."""

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            await pilot.press("d", "b")
            await pilot.press(*["down"] * popup_labels(app).index("Abort"))
            for _ in range(3):
                app.post_message(events.Key("enter", "\r"))
            said = screen.message_line.history
            await wait_until(
                pilot,
                lambda: (
                    said[-2:]
                    == [
                        ("info", "Query aborted; nothing was run."),
                        ("info", "The query list is empty."),
                    ]
                ),
                lambda: f"{said[-3:]}",
            )
            await settle(pilot)
            assert app.screen is screen and screen.builder is None
            assert [text for _, text in said].count("Query aborted; nothing was run.") == 1

    drive(scenario())


def test_enters_in_a_burst_in_the_more_menu_choose_once(drive, app_at, db):
    """Enter typed several times at once in the More Menu: one choice (Next),
    the spreadsheet stays (the extra Enters popped it, then crashed)."""

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            screen.start_query("stature > 0")
            await settle(pilot)
            await pilot.press("a", "e", "v", "x")  # Select All, Exit, Disp. Indv., Disp. More
            await pilot.press("down", "down", "down")  # Next
            for _ in range(3):
                app.post_message(events.Key("enter", "\r"))
            # The first Enter chose Next; the second asked to edit the sheet's
            # cell, the third left it as it was: as typed one by one.
            said = app.message_line.history
            await wait_until(
                pilot,
                lambda: (
                    any(text.startswith("Person 2 of ") for _, text in said)
                    and not app.message_line.prompting
                ),
                lambda: f"{said[-3:]} {message(app)!r} {app.message_line.answer.value!r}",
            )
            await settle(pilot)
            assert app.screen is app.spreadsheet
            assert sum(text.startswith("Person 2 of ") for _, text in said) == 1
            assert app.session.person_index == 1

    drive(scenario())
