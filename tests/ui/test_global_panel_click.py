"""The global panel (report §12.2.2) takes the mouse as the data section
does (widgets/editor.py EditorKeys.on_click): a click chooses a value, a
second click on it or a double click edits it."""

from __future__ import annotations

from sass_tui.ui.widgets import GlobalPanel
from sass_tui.ui.widgets.global_panel import GLOBAL_CELLS

SIZE = (120, 40)


def offset_of(panel: GlobalPanel, field: str) -> tuple[int, int]:
    cell = next(c for c in GLOBAL_CELLS if c.field == field)
    start, _span = panel._slot_span(cell.slot)
    left = panel.content_region.x - panel.region.x
    top = panel.content_region.y - panel.region.y
    return left + start + 1, top + cell.row


def test_a_click_chooses_a_value_a_second_click_or_a_double_click_edits_it(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            panel = app.screen.query_one("#global", GlobalPanel)
            line = app.spreadsheet.message_line
            where = offset_of(panel, "stature")
            await pilot.click("#global", offset=where)
            await pilot.pause()
            assert panel.cursor.field == "stature" and panel.has_focus
            assert not line.prompting
            await pilot.click("#global", offset=where)
            await pilot.pause()
            assert line.prompting
            await pilot.press("escape")
            await pilot.pause()
            # The group percentile's row has no percentile column: a click there chooses nothing.
            x, _y = offset_of(panel, "mass_percentile")
            _x, y = offset_of(panel, "group_percentile")
            await pilot.click("#global", offset=(x, y))
            await pilot.pause()
            assert panel.cursor.field == "stature" and not line.prompting
            # A double click edits another value at once.
            await pilot.click("#global", offset=offset_of(panel, "mass"), times=2)
            await pilot.pause()
            assert panel.cursor.field == "mass" and line.prompting

    drive(scenario())
