"""The pop-up query builder (report §12.3.3, figure 13).

Query Menu → Global Information menu (→ a value menu such as Gender, or the
Relational Operation Menu) or Anthropometric Group menu → item menu
(segments, joints, motions) → Axis Menu → Relational Operation Menu →
"Type in the constraint value:" → Conjunction Menu (And, Or, Done,
Previous Menu).  Each choice adds a piece of the query text (spec §4), so what
the menus build is exactly what `sass query` accepts; Previous Menu takes the
last piece off and shows the menu it was chosen in again.

`QueryBuilder` is the menu logic (no widgets, easy to test); `QueryPopup`
shows its current menu; `QueryBuilderScreen` is the modal screen that holds
the pop-up over the query screen, owns its keys (Escape, `e`) and its message
line (the live query, the constraint prompt), and is dismissed with the query
to run (None: aborted).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Protocol

from textual.app import ComposeResult
from textual.binding import Binding
from textual.screen import ModalScreen

from sass_tui.db.query.query import QueryError, compile_query
from sass_tui.model.measures import MEASURE_UNITS, MEASURES
from sass_tui.model.names import CENTER_OF_MASS_ROWS, GIRTH_ROWS, JOINT_LIMIT_ROWS
from sass_tui.model.strength.strength import MOTIONS
from sass_tui.model.vocabulary import PERSON_HANDEDNESS as HANDEDNESS
from sass_tui.model.vocabulary import STRENGTH_TYPES
from sass_tui.ui.base import SassScreen
from sass_tui.ui.footer import Footer
from sass_tui.ui.query.query_popup import PREVIOUS, Item, Menu, QueryPopup
from sass_tui.ui.widgets import MessageLine

VALUE_PROMPT = "Type in the constraint value:"


class _Row(Protocol):
    @property
    def label(self) -> str: ...
    @property
    def name(self) -> str: ...


def _rows_menu(key: str, title: str, rows: Iterable[_Row], then: str, suffix: str = "") -> Menu:
    return Menu(key, title, tuple(Item(r.label, f".{r.name}{suffix}", then) for r in rows))


def _words_menu(key: str, title: str, words: Iterable[str]) -> Menu:
    return Menu(key, title, tuple(Item(w.capitalize(), f" = {w}", "conjunction") for w in words))


_NUMERIC = "operation"
_TEXT = "text_operation"  # = / != and a typed value put in quotes
# The 93 ANSUR II measurements, as the survey spells them, with their unit.
MEASUREMENTS_MENU = Menu(
    "measure",
    "Measurements",
    tuple(Item(f"{n} ({MEASURE_UNITS[n]})", f"measure.{n}", _NUMERIC) for n in MEASURES),
    searchable=True,
)
MENUS: dict[str, Menu] = {
    m.key: m
    for m in (
        Menu(
            "query",
            "Query Menu",
            (
                Item("Global Information", "", "global"),
                Item("Anthropometric Groups", "", "group"),
                Item("Measurements", "", "measure"),
                Item("Re_execute", "", "re_execute"),
                Item("Abort", "", "abort"),
            ),
            previous=False,
        ),
        Menu(
            "global",
            "Global Information",
            (
                Item("Gender", "gender", "gender"),
                Item("Mass (kg)", "mass", _NUMERIC),
                Item("Stature (cm)", "stature", _NUMERIC),
                Item("Age (years)", "age", _NUMERIC),
                Item("Source", "source", "source"),
                Item("Component", "component", _TEXT),
                Item("Branch", "branch", _TEXT),
                Item("Writing Preference", "writingpreference", "handedness"),
                Item("Ethnicity", "ethnicity", _TEXT),
                Item("Subject Numeric Race", "subjectnumericrace", _NUMERIC),
                Item("DoD Race", "dodrace", _NUMERIC),
                Item("Strength Type", "strength_type", "strength_type"),
                Item("Handedness", "handedness", "handedness"),
                Item("Motion Speed", "motion_speed", _NUMERIC),
                Item("Training Level", "training_level", _NUMERIC),
                Item("Fatigue Level", "fatigue_level", _NUMERIC),
            ),
        ),
        _words_menu("gender", "Gender", ("male", "female")),
        _words_menu("strength_type", "Strength Type", STRENGTH_TYPES),
        _words_menu("handedness", "Handedness", HANDEDNESS),
        Menu(
            "group",
            "Anthropometric Group",
            (
                Item("Girth", "girth", "girth"),
                Item("Joint Limit", "joint_limit", "joint_limit"),
                Item("Center of Mass", "center_of_mass", "center_of_mass"),
                Item("Strength", "strength", "strength"),
            ),
        ),
        _rows_menu("girth", "Girth Menu", GIRTH_ROWS, "axis"),
        _rows_menu("joint_limit", "Joint Limit Menu", JOINT_LIMIT_ROWS, "axis"),
        _rows_menu("center_of_mass", "Center of Mass Menu", CENTER_OF_MASS_ROWS, "axis"),
        # A motion has one number to query, its maximum strength: no Axis Menu.
        _rows_menu("strength", "Strength Menu", MOTIONS, _NUMERIC, ".max"),
        Menu(
            "axis", "Axis Menu", tuple(Item(f"{a.upper()} Axis", f".{a}", _NUMERIC) for a in "xyz")
        ),
        Menu(
            _NUMERIC,
            "Relational Operation Menu",
            (
                Item("Less Than (<)", " < ", "value"),
                Item("Greater Than (>)", " > ", "value"),
                Item("Less Than or Equal (≤)", " <= ", "value"),
                Item("Greater Than or Equal (≥)", " >= ", "value"),
                Item("Equal (=)", " = ", "value"),
                Item("Not Equal (≠)", " != ", "value"),
            ),
        ),
        Menu(
            _TEXT,
            "Relational Operation Menu",
            (Item("Equal (=)", " = ", "value"), Item("Not Equal (≠)", " != ", "value")),
        ),
        MEASUREMENTS_MENU,
        Menu(
            "conjunction",
            "Conjunction Menu",
            (
                Item("And", " AND ", "query"),
                Item("Or", " OR ", "query"),
                Item("Done", "", "done"),
            ),
        ),
    )
}


@dataclass
class Step:
    shown: str  # the menu (or "value" prompt) the choice was made in
    text: str


TYPE_A_SOURCE = "Another: type it (= or ≠)"


def sources_menu(sources: Iterable[str]) -> Menu:
    """The Source menu: the sources the database holds, each a choice, and
    a typed one (a source yet to be imported, or ≠)."""
    items = tuple(
        Item(source, f" = {quote}{source}{quote}", "conjunction")
        for source in sources
        for quote in ['"' if "'" in source else "'"]
    )
    return Menu("source", "Source", (*items, Item(TYPE_A_SOURCE, "", _TEXT)))


@dataclass
class QueryBuilder:
    """Where the user is in the menus and the query built so far; `sources`:
    the sources of the database's people, offered by the Source menu."""

    steps: list[Step] = field(default_factory=list)
    current: str = "query"  # a menu key, or "value" while the constraint is typed
    sources: tuple[str, ...] = ()

    @property
    def text(self) -> str:
        return "".join(step.text for step in self.steps)

    @property
    def menu(self) -> Menu | None:
        if self.current == "source":
            return sources_menu(self.sources)
        return MENUS.get(self.current)

    def choose(self, label: str) -> str:
        """Apply a menu choice; returns what happens next: a menu key, "value",
        "previous", or one of the endings "re_execute", "abort", "done"."""
        if label == PREVIOUS:
            self.previous()
            return "previous"
        menu = self.menu
        item = next((i for i in menu.items if i.label == label), None) if menu else None
        if item is None:
            raise ValueError(f"{label!r} is not in the {menu.title if menu else self.current}")
        if item.next in ("re_execute", "abort", "done"):
            return item.next
        self.steps.append(Step(self.current, item.text))
        self.current = item.next
        return item.next

    def previous(self) -> None:
        if self.steps:
            step = self.steps.pop()
            self.current = step.shown

    def constraint(self, typed: str) -> None:
        """The typed constraint value; raises QueryError (builder unchanged) when
        the condition it completes is not valid, e.g. not a number."""
        typed = self._completed_value(typed.strip())
        condition = self._condition_text() + typed
        try:
            compile_query(condition)
        except QueryError as exc:
            reason = re.sub(r"^column \d+: ", "", str(exc))
            raise QueryError(f"{typed.strip()!r} is not a valid constraint: {reason}") from None
        self.steps.append(Step("value", typed))
        self.current = "conjunction"

    def _completed_value(self, typed: str) -> str:
        """A text field's value goes in quotes (unless typed in quotes); a
        measurement's bare number gets the measurement's unit."""
        if len(self.steps) < 2 or not typed:
            return typed
        field_step, operation_step = self.steps[-2], self.steps[-1]
        if operation_step.shown == _TEXT and typed[0] not in "'\"":
            quote = '"' if "'" in typed else "'"
            return f"{quote}{typed}{quote}"
        if field_step.text.startswith("measure."):
            try:
                float(typed)
            except ValueError:
                return typed
            return f"{typed} {MEASURE_UNITS[field_step.text.removeprefix('measure.')]}"
        return typed

    def replace_text(self, text: str) -> None:
        """The query edited as text on the message line: it becomes one piece,
        and the Conjunction Menu follows (Done runs it, And/Or extend it)."""
        self.steps = [Step("query", text.strip())] if text.strip() else []
        self.current = "conjunction" if text.strip() else "query"

    def _condition_text(self) -> str:
        """The condition being built: the text after the last AND / OR."""
        pieces: list[str] = []
        for step in reversed(self.steps):
            if step.shown == "conjunction":
                break
            pieces.append(step.text)
        return "".join(reversed(pieces))


class QueryBuilderScreen(SassScreen, ModalScreen[str | None]):
    """The pop-up query builder over the query screen (figure 13).

    It is handed the query screen's `QueryBuilder` (the query screen shows
    the query being built in its summary: `on_change` tells it to redraw),
    the last query run (for Re_execute) and where the pop-up goes.  It is
    dismissed with the query to run (Done, Re_execute) or None (Abort).
    Escape is Previous Menu (Abort in the Query Menu); `e` edits the query as
    text on the message line."""

    CSS_PATH = Path(__file__).with_name("query.tcss")
    BINDINGS = [
        Binding("escape", "back", "Previous Menu"),
        Binding("e", "edit_text", "Edit query"),
        # The app's palette key works over a modal screen, but the footer lists
        # only this screen's keys: name it here so the footer shows it.
        Binding("ctrl+p", "app.command_palette", "palette", show=False),
    ]

    def __init__(
        self,
        builder: QueryBuilder,
        last_query: str | None,
        offset: tuple[int, int] | None = None,
        on_change: Callable[[], None] | None = None,
    ) -> None:
        super().__init__(id="query-builder")
        self.builder = builder
        self.last_query = last_query
        self.popup_offset = offset
        self.on_change = on_change

    def compose(self) -> ComposeResult:
        popup = QueryPopup(id="popup", classes="pop-up-menu")
        if self.popup_offset is not None:
            popup.styles.offset = self.popup_offset
        yield popup
        yield MessageLine(id="message-line")
        yield Footer(compact=True)  # this screen's keys, not the query screen's

    def on_mount(self) -> None:
        self._show_current()

    @property
    def popup(self) -> QueryPopup:
        return self.query_one(QueryPopup)

    def on_message_line_answered(self, event: MessageLine.Answered) -> None:
        event.stop()
        if not self.message_line.prompting and self.popup.display:
            self.popup.focus_menu()

    def _changed(self) -> None:
        if self.on_change is not None:
            self.on_change()

    def _show_live(self) -> None:
        self.say(f"Query: {self.builder.text}▏  (e: edit the query as text)")

    def _show_current(self) -> None:
        builder = self.builder
        self._changed()
        menu = builder.menu
        if menu is None:  # "value": the constraint is typed on the message line
            self.popup.display = False
            self.ask(VALUE_PROMPT, self._constraint, on_cancel=self._previous)
            return
        self.popup.show_menu(menu)
        self._show_live()

    def _previous(self) -> None:
        self._choose(PREVIOUS, None)

    def _constraint(self, typed: str) -> None:
        try:
            self.builder.constraint(typed)
        except QueryError as exc:
            # The builder stays where it was: ask again, saying what was wrong.
            self.ask(
                f"{exc}. {VALUE_PROMPT}", self._constraint, on_cancel=self._previous, kind="error"
            )
            return
        self._show_current()

    def on_query_popup_chosen(self, event: QueryPopup.Chosen) -> None:
        event.stop()
        self._choose(event.label, event.menu)

    def _choose(self, label: str, menu: str | None) -> None:
        builder = self.builder
        if self.app.screen is not self:
            return  # dismissed: a choice still queued (Enter typed twice at once) is dropped
        if menu is not None and menu != builder.current:
            # Enter pressed again before the next menu was up: it chose in a menu
            # that is gone, so it is dropped rather than applied to the wrong one.
            return
        outcome = builder.choose(label)
        if outcome == "abort":
            self.dismiss(None)
        elif outcome == "re_execute":
            if not self.last_query:
                self.complain("There is no previous query to re-execute.")
                return
            self.dismiss(self.last_query)
        elif outcome == "done":
            text = builder.text
            try:
                compile_query(text)
            except QueryError as exc:
                self.complain(f"{exc}; edit the query (e) or use Previous Menu.")
                return
            self.dismiss(text)
        else:
            self._show_current()

    def action_back(self) -> None:
        self._choose(PREVIOUS if PREVIOUS in self.popup.labels else "Abort", self.popup.menu_key)

    def action_edit_text(self) -> None:
        def edited(text: str) -> None:
            self.builder.replace_text(text)
            self._show_current()

        self.ask(
            "Query:", edited, on_cancel=self._show_current, initial=self.builder.text, cursor=-1
        )
