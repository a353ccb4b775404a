"""ctrl+p finds and runs the screen's commands; F1 and ? list every binding."""

from __future__ import annotations

from textual.command import CommandPalette
from textual.widgets import DataTable

from sass_tui.ui.app import SassApp
from sass_tui.ui.figure_screen import FigureScreen
from sass_tui.ui.palette import HelpScreen, key_name


def help_rows(app) -> list[tuple[str, str, str]]:
    table = app.screen.query_one(DataTable)
    return [tuple(str(cell) for cell in table.get_row_at(i)) for i in range(table.row_count)]


def test_the_palette_finds_create_figure_and_runs_it(drive):
    async def scenario():
        app = SassApp()
        async with app.run_test(size=(100, 30)) as pilot:
            await pilot.press("ctrl+p")
            await pilot.pause()
            assert isinstance(app.screen, CommandPalette)
            await pilot.press(*"create fig")
            await pilot.pause(0.3)
            await pilot.press("enter")
            await pilot.pause(0.2)
            # Create Figure asks for the file name, as `f` does.
            assert app.spreadsheet.message_line.prompting
            assert "Figure file name" in str(
                app.spreadsheet.message_line.query_one("#message").render()
            )

    drive(scenario())


def test_the_palette_runs_see_figure_a_command_not_in_the_menu(drive):
    async def scenario():
        app = SassApp()
        async with app.run_test(size=(100, 30)) as pilot:
            await pilot.press("ctrl+p", *"see figure")
            await pilot.pause(0.3)
            await pilot.press("enter")
            await pilot.pause(0.2)
            assert isinstance(app.screen, FigureScreen)

    drive(scenario())


def test_f1_and_question_mark_list_every_binding_of_the_screen(drive):
    async def scenario():
        app = SassApp()
        async with app.run_test(size=(100, 30)) as pilot:
            sheet = app.spreadsheet
            every_key = {key_name(k) for k in sheet._bindings.key_to_bindings}
            for opener in ("f1", "question_mark"):
                await pilot.press(opener)
                await pilot.pause()
                assert isinstance(app.screen, HelpScreen)
                rows = help_rows(app)
                listed = {k for keys, _, _ in rows for k in keys.split(", ")}
                assert listed == every_key
                names = {name for _, name, _ in rows}
                assert {"Create Figure", "Undo", "See figure", "Warnings", "Help"} <= names
                await pilot.press("escape")
                await pilot.pause()
                assert app.screen is sheet

    drive(scenario())


def test_help_on_the_figure_screen_lists_its_own_keys(drive):
    async def scenario():
        app = SassApp()
        async with app.run_test(size=(100, 30)) as pilot:
            await pilot.press("b", "f1")
            await pilot.pause()
            names = {name for _, name, _ in help_rows(app)}
            assert {"Overlay", "Back", "Undo", "Help"} <= names
            assert "Create Figure" not in names

    drive(scenario())


def test_palette_snapshot(snap_compare):
    async def type_query(pilot):
        await pilot.press("ctrl+p", *"create fig")
        await pilot.pause(0.3)

    assert snap_compare(SassApp(), run_before=type_query, terminal_size=(80, 24))


def test_help_screen_snapshot(snap_compare):
    assert snap_compare(SassApp(), press=["f1"], terminal_size=(80, 24))
