"""The Textual private API sass reads (sass_tui/ui/textual_api.py) still is
where, and what, sass expects: when a Textual release moves it, this test
fails first and says what moved, before the screens' keys, the help screen and
the palette go wrong in ways harder to read."""

from __future__ import annotations

from textual.binding import BindingsMap
from textual.dom import DOMNode
from textual.widgets import Input

from sass_tui.ui import textual_api
from sass_tui.ui.query.query_screen import QueryScreen
from sass_tui.ui.spreadsheet.spreadsheet import SpreadsheetScreen

MOVED = "Textual moved {what}: sass_tui/ui/textual_api.py reads it; follow the move there"


def actions(bindings: BindingsMap, key: str) -> list[str]:
    return [binding.action for binding in bindings.key_to_bindings.get(key, ())]


def test_a_class_s_bindings_are_merged_down_its_bases():
    assert callable(getattr(DOMNode, "_merge_bindings", None)), MOVED.format(
        what="DOMNode._merge_bindings"
    )
    spreadsheet = textual_api.class_bindings(SpreadsheetScreen)
    assert isinstance(spreadsheet, BindingsMap), MOVED.format(what="the bindings map's type")
    assert actions(spreadsheet, "f") == ["create_figure"]  # its own BINDINGS
    assert actions(spreadsheet, "f1") == ["help"]  # SassScreen's, inherited
    assert actions(textual_api.class_bindings(QueryScreen), "m") == ["make_population"]
    assert "left" in textual_api.class_bindings(Input).key_to_bindings  # Textual's own widget


def test_a_node_s_bindings_are_those_it_has_now(drive, app_at):
    async def scenario():
        async with app_at((100, 37)) as (app, _pilot):
            screen = app.screen
            assert isinstance(screen, SpreadsheetScreen)
            assert hasattr(screen, "_bindings"), MOVED.format(what="DOMNode._bindings")
            now = textual_api.bindings_of(screen)
            assert isinstance(now, BindingsMap), MOVED.format(what="the bindings map's type")
            assert actions(now, "f") == ["create_figure"]
            assert actions(now, "question_mark") == ["help"]
            # The same keys as the class's, for a screen that binds nothing at run time.
            expected = textual_api.class_bindings(SpreadsheetScreen).key_to_bindings
            assert set(now.key_to_bindings) == set(expected)

    drive(scenario())


def test_the_footer_says_when_it_has_its_bindings(drive, app_at):
    from sass_tui.ui.footer import Footer

    async def scenario():
        async with app_at((100, 37)) as (app, pilot):
            footer = app.screen.query_one(Footer)
            assert hasattr(footer, "_bindings_ready"), MOVED.format(what="Footer._bindings_ready")
            await pilot.pause()
            assert textual_api.footer_bindings_ready(footer) is True

    drive(scenario())
