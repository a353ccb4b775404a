"""The spreadsheet at a small and a large terminal: at 80x24 the strength
page keeps rows beside the Task panel, whose notes (balance and not
covered, limiting, lifting) show whole, wrapped, and whose table scrolls; at
250x70 the figure panel takes the room the data leave and the figure is
drawn at least half the terminal's height; the message line says only what
is current.  Snapshots at 80x24 and 160x50."""

from __future__ import annotations

from _screen import message, settle, wait_until

from sass_tui.ui.spreadsheet.figure_view import FILL
from sass_tui.ui.spreadsheet.strength_page import StrengthPage

SMALL = (80, 24)
MEDIUM = (160, 50)
HUGE = (250, 70)


def figure_rows(view) -> int:
    """Rows of the canvas the figure is drawn on (its fill colour), top to bottom."""
    canvas = view.canvas
    fill = FILL.rich_color
    rows = [
        y
        for y in range(canvas.size.height)
        if any(
            segment.style is not None and fill in (segment.style.color, segment.style.bgcolor)
            for segment in canvas.render_line(y)
        )
    ]
    return max(rows) - min(rows) + 1 if rows else 0


def test_a_large_terminal_draws_a_large_figure(drive, app_at):
    async def scenario():
        async with app_at(HUGE) as (app, pilot):
            view = app.screen.figure_panel
            await wait_until(
                pilot, lambda: view.canvas is not None and figure_rows(view) > 0, "no figure"
            )
            width, height = HUGE
            assert view.size.width > width - 100  # the data keep about 80 columns
            assert figure_rows(view) >= height / 2, figure_rows(view)

    drive(scenario())


async def strength_with_task(pilot) -> None:
    # The sheet ready first (a snapshot's app may still be starting), then each
    # key's screen before the next key.
    await settle(pilot)
    await wait_until(pilot, lambda: pilot.app.screen.query(StrengthPage), "no sheet")
    await pilot.press("s")
    await wait_until(
        pilot, lambda: pilot.app.screen.query_one(StrengthPage).display, "no strength page"
    )
    await pilot.press("T")
    await settle(pilot)
    await wait_until(pilot, lambda: "Limiting" in str(task_answer(pilot.app)), "no answer")


def task_answer(app):
    """The Task panel's notes as drawn; empty while the panel is still being mounted."""
    answers = app.screen.query("#task-answer")
    return answers.first().render() if answers else ""


def test_80x24_strength_page_keeps_rows_beside_the_task_panel(drive, app_at):
    async def scenario():
        async with app_at(SMALL) as (app, pilot):
            await strength_with_task(pilot)
            page = app.query_one(StrengthPage)
            text = str(page.render())
            assert "Shoulder abduction" in text, text
            assert_task_panel_whole(app)
            # The table's rows below the panel: the arrows on the Task cells scroll to them.
            scroll = app.screen.query_one("#task-table-scroll")
            assert scroll.max_scroll_y > 0
            await pilot.press(*["down"] * scroll.max_scroll_y)
            await wait_until(
                pilot, lambda: scroll.scroll_y == scroll.max_scroll_y, lambda: scroll.scroll_y
            )
            # T again: the global data and the menu come back.
            await pilot.press("T")
            await pilot.pause()
            assert app.screen.query_one("#top").display

    drive(scenario())


def assert_task_panel_whole(app) -> None:
    """Every note line shown whole, wrapped at the panel's width, inside the
    panel and the screen; every table row there to scroll to."""
    screen = app.screen
    panel = screen.query_one("#task-panel")
    notes = screen.query_one("#task-answer")
    width = notes.content_size.width
    lines = str(notes.render()).splitlines()
    assert lines[1].startswith("Limiting") and lines[-1].startswith("Lifting"), lines
    shown = [
        "".join(segment.text for segment in notes.render_line(y)).rstrip()
        for y in range(notes.size.height)
    ]
    # The notes' words, in order, on the rows drawn: nothing cut off.
    assert " ".join(shown).split() == " ".join(lines).split(), shown
    assert all(len(row) <= width for row in shown)
    assert panel.region.contains_region(notes.region), (panel.region, notes.region)
    assert screen.region.contains_region(panel.region)
    table = screen.query_one("#task-table")
    scroll = screen.query_one("#task-table-scroll")
    rows = str(table.render()).splitlines()
    assert rows[0].startswith("Joint") and len(rows) == table.size.height
    assert max(map(len, rows)) <= scroll.content_size.width


def test_160x50_task_panel_shows_its_table_and_notes_whole(drive, app_at):
    async def scenario():
        async with app_at(MEDIUM) as (app, pilot):
            await strength_with_task(pilot)
            assert_task_panel_whole(app)
            scroll = app.screen.query_one("#task-table-scroll")
            assert scroll.max_scroll_y == 0  # the whole table at once

    drive(scenario())


def test_a_group_message_follows_a_resize(drive, app_at):
    async def scenario():
        async with app_at((120, 40)) as (app, pilot):
            await pilot.press("j", "g")
            assert message(app) == "Girth: 25 rows, 1 page."
            await pilot.resize_terminal(80, 24)
            await pilot.pause()
            assert message(app) == "Girth: 25 rows, 3 pages.", message(app)

    drive(scenario())


def test_strength_and_task_panel_80x24_snapshot(snap_compare, new_app):
    async def run_before(pilot):
        await strength_with_task(pilot)

    assert snap_compare(new_app(), run_before=run_before, terminal_size=SMALL)


def test_strength_and_task_panel_160x50_snapshot(snap_compare, new_app):
    async def run_before(pilot):
        await strength_with_task(pilot)

    assert snap_compare(new_app(), run_before=run_before, terminal_size=MEDIUM)


def test_start_screen_160x50_snapshot(snap_compare, new_app):
    async def run_before(pilot):
        def drawn() -> bool:
            view = pilot.app.screen.figure_panel
            return view is not None and view.canvas is not None and figure_rows(view) > 0

        await wait_until(pilot, drawn, "no figure")

    assert snap_compare(new_app(), run_before=run_before, terminal_size=MEDIUM)


def test_an_answered_question_does_not_stay_on_the_line(drive, app_at):
    """A question whose handler says nothing (it opened another screen)
    leaves the line empty, not showing the question answered."""

    async def scenario():
        async with app_at((120, 40)) as (app, pilot):
            line = app.message_line
            line.ask("Population to test:", lambda text: None)
            await pilot.pause()
            await pilot.press("x", "enter")
            await pilot.pause()
            assert message(app) == ""
            line.ask("Name:", lambda text: line.say(f"Hello {text}."))
            await pilot.press("y", "enter")
            await pilot.pause()
            assert message(app) == "Hello y."

    drive(scenario())
