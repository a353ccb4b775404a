"""The command palette (ctrl+p) and the help screen (F1, `?`), both built
from the active screen's own BINDINGS and command menus, never from a list
kept by hand: a new binding shows up in both by itself.

A command's name is its menu label (`CommandSpec.label`) when the screen has
a menu button for it, else the binding's description, else its action's
name; its help text is the first line of the `action_` method's docstring.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial
from typing import Any

from rich.text import Text
from textual.binding import Binding
from textual.command import DiscoveryHit, Hit, Hits, Provider
from textual.containers import Vertical
from textual.screen import ModalScreen
from textual.widgets import DataTable, Static

from sass_tui.ui.widgets import CommandMenu

# Keys Textual shows better than their names.
KEY_NAMES = {"question_mark": "?", "escape": "Esc", "pagedown": "PgDn", "pageup": "PgUp"}


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


def _help_text(screen, action: str) -> str:
    target = screen.app if action.startswith("app.") else screen
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
    commands: dict[str, ScreenCommand] = {}
    for key, bindings in screen._bindings.key_to_bindings.items():
        for binding in bindings:
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
            name = labels.get(binding.action) or binding.description or _humanize(binding.action)
            commands[binding.action] = ScreenCommand(
                binding.action, name, (key,), _help_text(screen, binding.action), binding.show
            )
    return list(commands.values())


class ScreenCommands(Provider):
    """The palette's commands: those of the screen it was opened on."""

    def _commands(self) -> list[tuple[str, str, Callable[[], Any]]]:
        screen = self.screen
        runner = getattr(screen, "run_command", None)
        found: list[tuple[str, str, Callable[[], Any]]] = []
        for command in screen_commands(screen):
            if runner is None or not screen.check_action(command.action, ()):
                continue
            keys = ", ".join(key_name(k) for k in command.keys)
            help_text = f"{command.help} ({keys})" if command.help else f"Key: {keys}"
            found.append((command.name, help_text, partial(runner, command.action)))
        return found

    async def discover(self) -> Hits:
        for name, help_text, callback in self._commands():
            yield DiscoveryHit(name, callback, help=help_text)

    async def search(self, query: str) -> Hits:
        matcher = self.matcher(query)
        for name, help_text, callback in self._commands():
            score = matcher.match(name)
            if score > 0:
                yield Hit(score, matcher.highlight(name), callback, help=help_text)


class HelpScreen(ModalScreen[None]):
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

    def compose(self):
        with Vertical() as box:
            box.border_title = self.help_title
            yield DataTable(id="help-table", cursor_type="row", zebra_stripes=True)
            yield Static("ctrl+p: search and run these commands.  Esc: close.", id="help-hint")

    def on_mount(self) -> None:
        table = self.query_one(DataTable)
        table.add_columns("Key", "Command", "What it does")
        for command in self.commands:
            table.add_row(
                Text(", ".join(key_name(k) for k in command.keys)),
                Text(command.name),
                Text(command.help),
            )
        table.focus()
