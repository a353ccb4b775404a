"""The query screen's commands for finding people in its list: a query typed
whole (`/`), every value of the highlighted person (Enter), sort by any
column (`o`), jump to an id or a name (`j`), and the message log (`L`)."""

from __future__ import annotations

from sass_tui.db.query.lists import SORT_COLUMNS
from sass_tui.db.query.query import QueryError, compile_query, field_column
from sass_tui.ui.message_log import MessageLog
from sass_tui.ui.query.person_screen import PersonScreen
from sass_tui.ui.query.query_base import QueryScreenBase
from sass_tui.ui.query.query_list import LIST_COLUMNS, LIST_TITLES

# What the sort prompt takes for each column: its key and its title's first
# word, in any case ("stature", "Stature", "str" for strength_type).
SORT_TITLES = {key: title for title, key, _, _ in LIST_COLUMNS if key in SORT_COLUMNS}


def sort_column(text: str) -> tuple[str, bool] | None:
    """A sort asked for: `stature`, `-stature` (largest first), a column's
    start (`stat`), or any field `sass query --fields` lists
    (`measure.poplitealheight`, or the measurement's name alone); None for
    the list's own order (empty).  SortError when the words name no column
    or field, or more than one column."""
    word = text.strip().lower()
    descending = word.startswith("-")
    word = word.lstrip("-+ ").replace(" ", "_")
    if not word:
        return None
    names = {key: (key, title.split()[0].lower()) for key, title in SORT_TITLES.items()}
    exact = [key for key, spellings in names.items() if word in spellings]
    starts = [key for key, spellings in names.items() if any(s.startswith(word) for s in spellings)]
    found = exact or starts
    if len(found) == 1:
        return found[0], descending
    for field in (word, f"measure.{word}"):
        try:
            field_column(field)
        except QueryError:
            continue
        return field, descending
    choices = ", ".join(SORT_TITLES)
    what = "more than one column" if found else "no column or field"
    raise SortError(
        f"{text.strip()!r} names {what}; sort by one of {choices}, or a field "
        "(sass query --fields), e.g. measure.poplitealheight"
    )


class SortError(ValueError):
    """A sort that names no column (said on the message line)."""


class PeopleCommands(QueryScreenBase):
    def action_free_query(self) -> None:
        """Type a query whole, e.g. gender = female AND stature > 175 cm."""
        if self.ready_lists() is None:
            return
        last = self.lists.last_query if self.lists is not None else None
        # The last query selected: typing replaces it, an arrow keeps it to edit.
        self.ask("Query:", self._free_query, initial=last or "", cursor=-1)

    def _free_query(self, text: str) -> None:
        if not text.strip():
            self.say("No query given; nothing was run.")
            return
        try:
            compile_query(text.strip())
        except QueryError as exc:
            # Asked again with the text as typed, the cursor where the error is.
            reason = str(exc).partition(": ")[2] if exc.column else str(exc)
            column = exc.column - 1 + len(text) - len(text.lstrip()) if exc.column else None
            self.ask(
                f"Not run: {reason} (at the cursor). Query:",
                self._free_query,
                initial=text,
                kind="error",
                cursor=column if column is not None else len(text),
            )
            return
        self.start_query(text.strip())

    def start_query(self, text: str) -> None:
        raise NotImplementedError  # the query screen's

    def action_show_person(self) -> None:
        """Show every value of the highlighted person."""
        person = self.sheet.highlighted
        if person is None:
            self.say(f"The {LIST_TITLES[self.which].lower()} is empty.")
            return

        def show() -> None:
            with self._database() as lists:
                record = lists.person_record(person["id"])
            self.app.push_screen(PersonScreen(record))

        self._list_command(show)

    def action_sort(self) -> None:
        """Sort the list by a column (-column: largest first)."""
        columns = ", ".join(title.split()[0].lower() for title in SORT_TITLES.values())
        self.ask(
            f"Sort by ({columns}, or a field such as measure.poplitealheight; "
            "-stature: largest first; empty: the list's order):",
            self._sort_by,
        )

    def _sort_by(self, text: str) -> None:
        try:
            sort = sort_column(text)
        except SortError as exc:
            self.complain(f"{exc}; the order is unchanged.")
            return

        def resort() -> None:
            self.sort = sort
            self.sheet.sort = sort
            self.sheet.cursor = 0
            self.show_page(0)
            if sort is None:
                self.say(f"{LIST_TITLES[self.which]} in its own order.")
            else:
                way = "largest first" if sort[1] else "smallest first"
                title = SORT_TITLES.get(sort[0], sort[0])
                self.say(f"{LIST_TITLES[self.which]} sorted by {title}, {way}.")

        self._list_command(resort)

    def action_jump(self) -> None:
        """Jump to a person of the list by id or name."""
        self.ask("Jump to (an id, a name or its start):", self._jump_to)

    def _jump_to(self, text: str) -> None:
        if not text.strip():
            self.say("No id or name given.")
            return

        def jump() -> None:
            with self._database() as lists:
                place = lists.position(self.which, text, self.sort)
            if place is None:
                self.say(f"Nobody in the {LIST_TITLES[self.which].lower()} is {text.strip()!r}.")
                return
            size = self.sheet.page_size
            self.show_page(place // size * size)
            self.sheet.cursor = place % size
            self.sheet.refresh()
            person = self.sheet.highlighted
            name = person["name"] if person is not None else text.strip()
            self.say(f"{name}: number {place + 1:,} of the {LIST_TITLES[self.which].lower()}.")

        self._list_command(jump)

    def action_message_log(self) -> None:
        """List the messages shown so far, each whole."""
        self.app.push_screen(MessageLog(self.message_line.history))
