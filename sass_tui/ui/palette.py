"""The command palette (ctrl+p) and the help screen (F1, `?`), built from
the screens' own BINDINGS and command menus, never from a list of commands
kept by hand: a new binding shows up in both by itself.

The help screen lists the active screen's bindings.  The palette lists those
first, then every command of every other screen in SCREENS (its class's
BINDINGS), each with the screen it belongs to.  Choosing one of another
screen goes there (back down the screen stack, or opened from the
spreadsheet by the command that opens it) and runs it once that screen can
take it (`SassScreen.run_when_ready`); a screen that only opens from
another's answer (the fit test) says how to get there instead.

The palette finds a command by its name (Textual's fuzzy match, best
first), and also by the words of its name and help as an engineer says
them: each word typed must begin a word of the command's, or one of its
synonyms (SYNONYMS: "stats" finds the percentile table, "civilian" the
target population, "accommodate" the fit test).  A few things done outside
the TUI (`sass serve`) are listed too, and say how.

A command's name is its menu label (`CommandSpec.label`) when the screen has
a menu button for it, else the binding's tooltip (the full name of a short
footer label), else its description, else its action's name; its help text
is the first line of the `action_` method's docstring.
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial
from typing import Any

from rich.text import Text
from textual import events
from textual.binding import Binding, BindingsMap
from textual.command import DiscoveryHit, Hit, Hits, Provider
from textual.containers import Vertical
from textual.screen import ModalScreen, Screen
from textual.widgets import DataTable, Static

from sass_tui.ui.palette_words import OUTSIDE, word_score
from sass_tui.ui.pop_up import PopUpScreen
from sass_tui.ui.textual_api import bindings_of, class_bindings
from sass_tui.ui.widgets import CommandMenu

# Keys Textual shows better than their names.
KEY_NAMES = {
    "question_mark": "?",
    "escape": "Esc",
    "pagedown": "PgDn",
    "pageup": "PgUp",
    "enter": "Enter",
}


@dataclass(frozen=True)
class ScreenRoute:
    """A screen whose commands the palette lists, and how to reach it."""

    title: str
    module: str
    name: str  # the class
    opener: str | None  # the spreadsheet's action that opens it (None: see `how`)
    how: str  # how a user gets there, said where the palette cannot take them

    def screen_class(self) -> type[Screen]:
        screen_class: type[Screen] = getattr(importlib.import_module(self.module), self.name)
        return screen_class


# The screens the palette takes commands from (modal pop-ups are not listed:
# their keys are the choices they show).
SCREENS: tuple[ScreenRoute, ...] = (
    ScreenRoute(
        "Spreadsheet",
        "sass_tui.ui.spreadsheet.spreadsheet",
        "SpreadsheetScreen",
        None,
        "Esc (or Exit Query) goes back to it",
    ),
    ScreenRoute(
        "Query",
        "sass_tui.ui.query.query_screen",
        "QueryScreen",
        "query",
        "Query (d) on the spreadsheet",
    ),
    ScreenRoute(
        "Figure",
        "sass_tui.ui.spreadsheet.figure_screen",
        "FigureScreen",
        "see_figure",
        "b on the spreadsheet",
    ),
    ScreenRoute(
        "Family",
        "sass_tui.ui.query.family_screen",
        "FamilyScreen",
        "family",
        "Family (y) on the spreadsheet",
    ),
    ScreenRoute(
        "Strength curves",
        "sass_tui.ui.spreadsheet.strength_curve_screen",
        "StrengthCurveScreen",
        "strength_curve",
        "t on the spreadsheet",
    ),
    ScreenRoute(
        "Fit Test",
        "sass_tui.ui.query.fit_screen",
        "FitScreen",
        None,
        "on the query screen, run a query, then Fit Test (f)",
    ),
    ScreenRoute(
        "Stats",
        "sass_tui.ui.query.stats_screen",
        "StatsScreen",
        None,
        "on the query screen, run a query (or none: every real person), then Stats (S)",
    ),
)


@dataclass(frozen=True)
class ScreenCommand:
    action: str
    name: str
    keys: tuple[str, ...]
    help: str
    shown: bool  # in the footer


def key_name(key: str) -> str:
    return KEY_NAMES.get(key, key)


def _humanize(action: str) -> str:
    """`select_group('girth')` -> `Select group: girth`."""
    name, _, argument = action.removeprefix("app.").partition("(")
    text = name.replace("_", " ").capitalize()
    argument = re.sub(r"['\")]", "", argument)
    return f"{text}: {argument.replace('_', ' ')}" if argument else text


def _help_text(screen, action: str, app=None) -> str:
    """`screen` is a screen or a screen class (then `app` is given)."""
    target = (app or screen.app) if action.startswith("app.") else screen
    name = action.removeprefix("app.").partition("(")[0]
    method = getattr(target, f"action_{name}", None)
    if not getattr(method, "__module__", "").startswith("sass_tui"):
        return ""  # Textual's own docstrings are written for programmers
    doc = (getattr(method, "__doc__", None) or "").strip()
    return doc.splitlines()[0] if doc else ""


def screen_commands(screen) -> list[ScreenCommand]:
    """Every binding of `screen` (its class's BINDINGS, in order), one entry
    per action with all its keys."""
    labels = {}
    for menu in screen.query(CommandMenu):
        for spec in menu.commands:
            labels[spec.action] = spec.label(menu.context)
    return _commands(screen, bindings_of(screen), labels)


def help_commands(screen) -> list[ScreenCommand]:
    """What F1 lists: the keys of the screen's sheet first (its `SHEET_KEYS`:
    the arrows, Enter, digits, Escape, undo, which no binding of the
    screen's names), then every binding of the screen not among them."""
    own = [
        ScreenCommand(action, name, keys, help_text, True)
        for action, name, keys, help_text in getattr(screen, "SHEET_KEYS", ())
    ]
    listed = {command.action for command in own}
    return own + [c for c in screen_commands(screen) if c.action not in listed]


def class_commands(screen_class: type[Screen], app) -> list[ScreenCommand]:
    """Every binding of a screen that is not shown: as `screen_commands`,
    its menu labels those that do not depend on what the screen shows."""
    labels = {}
    for spec in getattr(screen_class, "COMMAND_SPECS", ()):
        try:
            labels[spec.action] = spec.label(None)
        except AttributeError:  # a label that reads the screen ("void" or not)
            labels[spec.action] = _humanize(spec.name)
    return _commands(screen_class, class_bindings(screen_class), labels, app)


def _commands(screen, bindings: BindingsMap, labels: dict[str, str], app=None):
    commands: dict[str, ScreenCommand] = {}
    for key, bindings_of_key in bindings.key_to_bindings.items():
        for binding in bindings_of_key:
            known = commands.get(binding.action)
            if known is not None:
                commands[binding.action] = ScreenCommand(
                    known.action,
                    known.name,
                    (*known.keys, key),
                    known.help,
                    known.shown or binding.show,
                )
                continue
            name = (
                labels.get(binding.action)
                or binding.tooltip
                or binding.description
                or _humanize(binding.action)
            )
            commands[binding.action] = ScreenCommand(
                binding.action, name, (key,), _help_text(screen, binding.action, app), binding.show
            )
    return list(commands.values())


def _title_of(screen) -> str:
    route = next((r for r in SCREENS if r.name == type(screen).__name__), None)
    return route.title if route else type(screen).__name__.removesuffix("Screen")


def _elsewhere(command: ScreenCommand) -> bool:
    """Listed for another screen: not its way back (Esc), help, or what
    every screen has (quit, focus, copy), which the screen shown runs itself."""
    return (
        "escape" not in command.keys
        and command.action not in ("help", "quit")
        and not command.action.startswith(("app.", "screen."))
    )


async def run_elsewhere(app, route: ScreenRoute, action: str, name: str) -> None:
    """Go to `route`'s screen and run `action` there, or say how to get there."""
    screen_class = route.screen_class()
    shown = app.screen
    stack = list(app.screen_stack)
    target = next((s for s in reversed(stack) if isinstance(s, screen_class)), None)
    say = getattr(shown, "say", None) or app.notify
    if target is None and route.opener is None:
        say(f"{name} is a command of the {route.title} screen: {route.how}.")
        return
    base = target or stack[0]  # the spreadsheet opens the others
    above = stack[stack.index(base) + 1 :]
    busy = [
        s
        for s in above
        if getattr(s, "running", False) or any(w.node is s and w.is_running for w in app.workers)
    ]
    if busy:
        say(f"{_title_of(busy[-1])} is busy: {name} runs once it is done (or Esc back first).")
        return
    for _ in above:
        app.pop_screen()
    if above:
        refresh = getattr(base, "refresh_screen", None)
        if refresh is not None:
            refresh()  # what the screens above changed
    run_on_base = getattr(base, "run_command", None)
    if run_on_base is None:
        return
    if target is not None:
        await run_on_base(action)
        return
    await run_on_base(route.opener)
    opened = app.screen
    when_ready = getattr(opened, "run_when_ready", None)
    if isinstance(opened, screen_class) and when_ready is not None:
        when_ready(action)
    # else the spreadsheet said why it did not open (e.g. Query while a person is shown)


def _help_line(command: ScreenCommand, title: str) -> str:
    keys = ", ".join(key_name(k) for k in command.keys)
    where = f"{title} screen, {keys}"
    return f"{command.help} ({where})" if command.help else where


class ScreenCommands(Provider):
    """The palette's commands: the screen's it was opened on, then every
    other screen's, each saying which screen it belongs to."""

    def _commands(self) -> list[tuple[str, str, Callable[[], Any]]]:
        screen = self.screen
        runner = getattr(screen, "run_command", None)
        if runner is None:
            return []  # a pop-up (help, the More menu): its own keys only
        found: list[tuple[str, str, Callable[[], Any]]] = []
        title = _title_of(screen)
        for command in screen_commands(screen):
            if not screen.check_action(command.action, ()):
                continue
            found.append(
                (command.name, _help_line(command, title), partial(runner, command.action))
            )
        if isinstance(screen, ModalScreen):
            return found  # a pop-up (the query builder): its own choices only
        for route in SCREENS:
            screen_class = route.screen_class()
            if isinstance(screen, screen_class):
                continue
            for command in class_commands(screen_class, self.app):
                if _elsewhere(command):
                    run = partial(run_elsewhere, self.app, route, command.action, command.name)
                    found.append((command.name, _help_line(command, route.title), run))
        say = getattr(screen, "say", None) or self.app.notify
        found += [(name, help_text, partial(say, how)) for name, help_text, how in OUTSIDE]
        return found

    async def discover(self) -> Hits:
        for name, help_text, callback in self._commands():
            yield DiscoveryHit(name, callback, help=help_text)

    async def search(self, query: str) -> Hits:
        matcher = self.matcher(query)
        for name, help_text, callback in self._commands():
            # Words typed that begin the command's words (or their synonyms)
            # first, scored 0.5-1; then Textual's fuzzy match of the name
            # (letters scattered; its score has no upper bound), under 0.5.
            words = word_score(query, name, help_text)
            fuzzy = matcher.match(name)
            score = 0.5 + words / 2 if words > 0 else fuzzy / (1 + fuzzy) / 2
            if score > 0:
                shown = matcher.highlight(name) if fuzzy > 0 else name
                yield Hit(score, shown, callback, help=help_text)


HELP_SCROLLBAR = 2
HELP_NAME_WIDTH = 20  # longer command names wrap


class HelpScreen(PopUpScreen[None]):
    """Every binding of the screen it was opened on: key, command, help."""

    BINDINGS = [
        Binding("escape", "dismiss", "Close"),
        Binding("f1", "dismiss", show=False),
        Binding("question_mark", "dismiss", show=False),
        Binding("q", "dismiss", show=False),
    ]
    DEFAULT_CSS = """
    HelpScreen { align: center middle; }
    HelpScreen > Vertical {
        width: 90%; height: 90%; border: round $accent; background: $panel;
    }
    HelpScreen DataTable { height: 1fr; }
    HelpScreen #help-hint { height: 1; color: $text-muted; }
    """

    def __init__(self, commands: list[ScreenCommand], title: str) -> None:
        super().__init__()
        self.commands = commands
        self.help_title = title
        self._filled_for = -1  # the screen width the table was laid out for

    def compose(self):
        with Vertical() as box:
            box.border_title = self.help_title
            yield DataTable(id="help-table", cursor_type="row", zebra_stripes=True)
            yield Static(
                "↑ ↓ PgUp PgDn scroll.  ctrl+p: search and run these commands.  Esc: close.",
                id="help-hint",
            )

    def on_mount(self) -> None:
        self._fill(self.size.width)
        self.query_one(DataTable).focus()

    def on_resize(self, event: events.Resize) -> None:
        self._fill(event.size.width)

    def _fill(self, screen_width: int) -> None:
        """One row a command; "What it does" wraps within the box (at 80
        columns it would otherwise be cut off at the right)."""
        if screen_width == self._filled_for:
            return  # the mount and the first resize give the same width
        self._filled_for = screen_width
        table = self.query_one(DataTable)
        keys = [", ".join(key_name(k) for k in command.keys) for command in self.commands]
        key_width = max(map(len, keys), default=3)
        name_width = min(
            HELP_NAME_WIDTH, max((len(command.name) for command in self.commands), default=7)
        )
        # The box is 90% wide with a border; each column pads one cell each
        # side; the vertical scrollbar takes HELP_SCROLLBAR cells.
        box = int(screen_width * 0.9) - 2
        help_width = max(12, box - key_width - name_width - 3 * 2 - HELP_SCROLLBAR)
        table.clear(columns=True)
        table.add_column("Key", width=key_width)
        table.add_column("Command", width=name_width)
        table.add_column("What it does", width=help_width)
        for key, command in zip(keys, self.commands, strict=True):
            table.add_row(Text(key), Text(command.name), Text(command.help), height=None)
        self.call_after_refresh(self._say_more)

    def _say_more(self) -> None:
        """The box's lower border says that the list goes on below, and how
        far down it is: F1's list is longer than a small terminal."""
        table = self.query_one(DataTable)
        box = self.query_one(Vertical)
        if table.max_scroll_y <= 0:
            box.border_subtitle = ""
            return
        shown = table.scrollable_content_region.height
        first = int(table.scroll_y)
        box.border_subtitle = (
            f"lines {first + 1}-{min(first + shown, table.virtual_size.height)} of "
            f"{table.virtual_size.height}; ↓ PgDn more"
        )

    def on_data_table_row_highlighted(self) -> None:
        self.call_after_refresh(self._say_more)
