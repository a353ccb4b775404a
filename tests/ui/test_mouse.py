"""The mouse: a click chooses a cell, a second click (or a double click) edits
it; the wheel pages the data section and the query list."""

from __future__ import annotations

from test_query_screen import open_query_screen
from textual import events

from sass_tui.ui.widgets import DataSheet

SIZE = (100, 30)


def prompt_text(app) -> str:
    return str(app.spreadsheet.message_line.query_one("#message").render())


def test_a_click_chooses_a_cell_and_a_second_click_edits_it(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            sheet = app.screen.query_one("#sheet", DataSheet)
            top = sheet.content_region.y - sheet.region.y  # the border
            left = sheet.content_region.x - sheet.region.x
            start, _ = sheet._column_start(2)
            target = (left + start + 1, top + DataSheet.HEADER_LINES + 3)  # 4th row, y value
            await pilot.click("#sheet", offset=target)
            await pilot.pause()
            assert (sheet.cursor_row, sheet.cursor_column) == (3, 2)
            assert not app.spreadsheet.message_line.prompting
            await pilot.click("#sheet", offset=target)
            await pilot.pause()
            assert app.spreadsheet.message_line.prompting

    drive(scenario())


def test_a_double_click_edits_another_cell_at_once(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            sheet = app.screen.query_one("#sheet", DataSheet)
            sheet.focus()
            top = sheet.content_region.y - sheet.region.y
            left = sheet.content_region.x - sheet.region.x
            start, _ = sheet._column_start(0)
            offset = (left + start + 1, top + DataSheet.HEADER_LINES + 1)
            await pilot.click("#sheet", offset=offset, times=2)
            await pilot.pause()
            assert (sheet.cursor_row, sheet.cursor_column) == (1, 0)
            assert app.spreadsheet.message_line.prompting

    drive(scenario())


def test_the_wheel_pages_the_data_section(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            sheet = app.screen.query_one("#sheet", DataSheet)
            assert sheet.pages > 1 and sheet.page == 0
            region = sheet.region
            x, y = region.x + 2, region.y + 4

            def scroll(kind):
                return kind(
                    sheet,
                    x - region.x,
                    y - region.y,
                    0,
                    0,
                    0,
                    False,
                    False,
                    False,
                    screen_x=x,
                    screen_y=y,
                )

            sheet.post_message(scroll(events.MouseScrollDown))
            await pilot.pause()
            assert sheet.page == 1
            sheet.post_message(scroll(events.MouseScrollUp))
            await pilot.pause()
            assert sheet.page == 0
            assert not app.spreadsheet.message_line.prompting

    drive(scenario())


async def wheel(pilot, selector: str, event_class) -> None:
    """A wheel turn where the mouse is, routed by the screen as the driver's are."""
    await pilot._post_mouse_events([event_class], selector, offset=(4, 4))


def test_the_wheel_pages_the_query_list(drive, app_at, db):
    from sass_tui.ui.query.query_screen import ListSheet

    async def scenario():
        async with app_at((120, 40), db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            screen.start_query("stature > 0")
            await app.workers.wait_for_complete()
            await pilot.pause()
            sheet = screen.query_one(ListSheet)
            assert sheet.total > sheet.page_size and sheet.first == 0
            await wheel(pilot, "#list", events.MouseScrollDown)
            assert sheet.first == sheet.page_size
            await wheel(pilot, "#list", events.MouseScrollUp)
            assert sheet.first == 0
            await wheel(pilot, "#list", events.MouseScrollUp)
            assert sheet.first == 0
            assert "first page" in str(screen.query_one("#message").render())

    drive(scenario())
