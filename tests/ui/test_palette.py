"""ctrl+p finds and runs every screen's commands; F1 and ? list every binding
of the screen shown."""

from __future__ import annotations

import pytest
from _screen import settle, wait_until
from test_query_screen import open_query_screen
from textual.command import CommandPalette
from textual.widgets import DataTable

from sass_tui.model.body.figure import Figure
from sass_tui.ui.palette import SCREENS, HelpScreen, ScreenCommands, class_commands, key_name
from sass_tui.ui.query.query_screen import QueryScreen
from sass_tui.ui.spreadsheet.figure_screen import FigureScreen
from sass_tui.ui.spreadsheet.figure_view import FigureView


def help_rows(app) -> list[tuple[str, str, str]]:
    table = app.screen.query_one(DataTable)
    return [tuple(str(cell) for cell in table.get_row_at(i)) for i in range(table.row_count)]


def asks_for_the_figure_file(app) -> bool:
    """Create Figure ran on the spreadsheet: it asks for the file name, as `f` does."""
    line = app.spreadsheet.message_line
    return line.prompting and "Figure file name" in str(line.query_one("#message").render())


async def choose_in_palette(pilot, text: str) -> None:
    """ctrl+p, type `text`, Enter on the best hit."""
    await pilot.press("ctrl+p", *text)
    await settle(pilot)  # the palette searches in a worker
    await pilot.press("enter")
    await settle(pilot)


def test_the_palette_finds_create_figure_and_runs_it(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            await pilot.press("ctrl+p")
            await pilot.pause()
            assert isinstance(app.screen, CommandPalette)
            await pilot.press(*"create fig")
            await settle(pilot)  # the palette searches in a worker
            await pilot.press("enter")
            await settle(pilot)
            assert asks_for_the_figure_file(app)

    drive(scenario())


def test_the_palette_runs_see_figure_a_command_not_in_the_menu(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            await choose_in_palette(pilot, "see figure")
            assert isinstance(app.screen, FigureScreen)

    drive(scenario())


def test_f1_and_question_mark_list_every_binding_of_the_screen(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            sheet = app.spreadsheet
            every_key = {key_name(k) for k in sheet._bindings.key_to_bindings}
            for opener in ("f1", "question_mark"):
                await pilot.press(opener)
                await pilot.pause()
                assert isinstance(app.screen, HelpScreen)
                rows = help_rows(app)
                listed = {k for keys, _, _ in rows for k in keys.split(", ")}
                assert listed >= every_key
                # The sheet's own keys first: arrows, Enter, digits, Escape, undo.
                first = [(keys, name) for keys, name, _ in rows[:6]]
                assert first == [
                    ("↑ ↓ ← →, Home, End", "Move"),
                    ("Enter", "Edit"),
                    ("0-9 . - +", "Type a value"),
                    ("Esc", "Cancel"),
                    ("u, ctrl+z", "Undo"),
                    ("U, ctrl+y", "Redo"),
                ]
                names = {name for _, name, _ in rows}
                assert {"Create Figure", "Undo", "See figure", "Warnings", "Help"} <= names
                await pilot.press("escape")
                await pilot.pause()
                assert app.screen is sheet

    drive(scenario())


def test_help_on_the_figure_screen_lists_its_own_keys(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            await pilot.press("b", "f1")
            await pilot.pause()
            names = {name for _, name, _ in help_rows(app)}
            assert {"Overlay", "Back", "Undo", "Help"} <= names
            assert "Create Figure" not in names

    drive(scenario())


def test_help_wraps_what_each_key_does_at_80_columns(drive, app_at):
    """F1 at 80x24: every column fits the box (no sideways scrolling) and a
    long "What it does" wraps onto more lines instead of being cut off."""

    async def scenario():
        async with app_at((80, 24)) as (app, pilot):
            await pilot.press("f1")
            await pilot.pause()
            table = app.screen.query_one(DataTable)
            assert table.virtual_size.width <= table.scrollable_content_region.width
            assert not table.show_horizontal_scrollbar
            help_width = list(table.columns.values())[2].width
            for row_key, command in zip(table.rows, app.screen.commands, strict=True):
                lines = -(-len(command.help) // help_width)  # at least
                assert table.rows[row_key].height >= max(1, lines), command.name

    drive(scenario())


def test_help_says_that_it_scrolls(drive, app_at):
    """At 80x24 the list is longer than its box: the box's lower border says
    which lines are shown and that more follow, and follows the cursor."""

    async def scenario():
        async with app_at((80, 24)) as (app, pilot):
            await pilot.press("f1")
            await pilot.pause()
            box = app.screen.query_one("Vertical")
            await wait_until(pilot, lambda: box.border_subtitle, "no scroll hint")
            assert box.border_subtitle.startswith("lines 1-")
            assert box.border_subtitle.endswith("↓ PgDn more")
            await pilot.press("pagedown")
            await wait_until(
                pilot,
                lambda: not box.border_subtitle.startswith("lines 1-"),
                lambda: box.border_subtitle,
            )

    drive(scenario())


def test_palette_snapshot(snap_compare, new_app):
    async def type_query(pilot):
        await pilot.press("ctrl+p", *"create fig")
        await settle(pilot)  # the palette searches in a worker

    assert snap_compare(new_app(), run_before=type_query, terminal_size=(80, 24))


def test_help_screen_snapshot(snap_compare, new_app):
    assert snap_compare(new_app(), press=["f1"], terminal_size=(80, 24))


def palette_entries(app) -> list[tuple[str, str]]:
    """(name, help) of every command the palette offers on the screen shown."""
    palette = app.screen
    assert isinstance(palette, CommandPalette)
    provider = ScreenCommands(app.screen_stack[-2])
    return [(name, help_text) for name, help_text, _ in provider._commands()]


def test_the_palette_lists_every_screens_commands_with_their_screen(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            await pilot.press("ctrl+p")
            await pilot.pause()
            entries = palette_entries(app)
            names = {name for name, _ in entries}
            # The spreadsheet's own, the query screen's, the figure screen's, the family's.
            assert {"Create Figure", "Undo", "See figure"} <= names
            assert {"Input DB", "Query DB", "Build query", "Make Population", "Fit Test"} <= names
            assert {"Overlay", "Write files", "New family"} <= names
            helps = dict((name, help_text) for name, help_text in entries)
            assert "(Query screen, i)" in helps["Input DB"]
            assert "(Figure screen, o)" in helps["Overlay"]
            assert "(Spreadsheet screen, f)" in helps["Create Figure"]
            # Every binding of every other screen is there, but its way back (Esc).
            for route in SCREENS[1:]:
                screen_class = route.screen_class()
                for command in class_commands(screen_class, app):
                    if "escape" in command.keys or command.action in ("help", "quit"):
                        continue
                    if command.action.startswith(("app.", "screen.")):
                        continue  # the screen shown has them too (quit, focus, copy)
                    assert command.help, f"{route.title}: {command.name} has no help text"
                    assert (command.name, helps.get(command.name)) in entries, command

    drive(scenario())


@pytest.mark.slow
def test_the_palette_runs_a_query_screen_command_from_the_spreadsheet(drive, app_at, db):
    async def scenario():
        async with app_at((100, 30), db=True) as (app, pilot):
            await pilot.press("ctrl+p", *"input db")
            await settle(pilot)  # the palette searches in a worker
            await pilot.press("enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            # The query screen opened, its database opened, then Input DB asked.
            assert isinstance(app.screen, QueryScreen)
            assert app.screen.message_line.prompting
            assert "Person" in str(app.screen.query_one("#message").render())
            await pilot.press("escape")
            await pilot.pause()
            # And back: a spreadsheet command from the query screen goes back to it.
            await choose_in_palette(pilot, "create figure")
            assert app.screen is app.spreadsheet
            assert asks_for_the_figure_file(app)

    drive(scenario())


@pytest.mark.slow
def test_the_palette_opens_the_figure_screen_for_its_overlay(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            await choose_in_palette(pilot, "overlay")
            assert isinstance(app.screen, FigureScreen)
            assert app.figure_overlay == 50
            assert len(app.screen.query_one(FigureView).outlines) == 2

    drive(scenario())


def test_a_screen_that_cannot_open_from_here_says_how_to_get_there(drive, app_at, db):
    async def scenario():
        async with app_at((100, 30), db=True) as (app, pilot):
            # A person is shown: Query opens from the population only.
            app.session.show_person(Figure.default("female"), -1)
            app.spreadsheet.refresh_screen()
            await choose_in_palette(pilot, "input db")
            assert app.screen is app.spreadsheet
            assert "Disp. Pop. (o) first" in str(
                app.spreadsheet.message_line.query_one("#message").render()
            )

    drive(scenario())


@pytest.mark.slow
def test_on_the_query_builder_pop_up_the_palette_lists_its_own_commands(drive, app_at, db):
    from sass_tui.ui.query.query_builder import QueryBuilderScreen

    async def scenario():
        async with app_at((120, 40), db=True) as (app, pilot):
            await open_query_screen(pilot)
            await pilot.press("d", "b")
            await pilot.pause()
            builder = app.screen
            assert isinstance(builder, QueryBuilderScreen)
            entries = ScreenCommands(builder)._commands()
            assert entries
            assert not [
                help_text for _, help_text, _ in entries if "Spreadsheet screen" in help_text
            ]

    drive(scenario())
