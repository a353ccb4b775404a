"""What the query screen's workers post: the database opened, progress
while it is built, a query, an import or a population done."""

from __future__ import annotations

from pathlib import Path

from textual.message import Message

from sass_tui.db.query.lists import QueryLists


class DatabaseOpened(Message):
    def __init__(self, lists: QueryLists, path: str | Path) -> None:
        super().__init__()
        self.lists = lists
        self.path = path


class DatabaseFailed(Message):
    def __init__(self, text: str) -> None:
        super().__init__()
        self.text = text


class DatabaseProgress(Message):
    """Work on the database before it opens (the default database being
    built): said on the message line, nothing ends."""

    def __init__(self, text: str) -> None:
        super().__init__()
        self.text = text


class QueryFinished(Message):
    """A query's outcome: the count and first page, or what went wrong."""

    def __init__(
        self,
        count: int = 0,
        rows: list[dict] | None = None,
        error: str = "",
        weighted: str = "",
        hint: str = "",
        lost: str = "",
    ) -> None:
        super().__init__()
        self.count = count
        self.rows = rows or []
        self.error = error
        self.weighted = weighted  # the target's weighted share (ui/query/target_picker.py)
        self.hint = hint  # no real person found: the demonstration people who would be
        self.lost = lost  # what a PostgreSQL server's restart took from the lists


class PopulationMade(Message):
    """Make Population's outcome: the population and the files written, or why not."""

    def __init__(self, result=None, paths: dict | None = None, error: str = "") -> None:
        super().__init__()
        self.result = result
        self.paths = paths or {}
        self.error = error


class ImportFinished(Message):
    def __init__(self, count: int | None, error: str = "") -> None:
        super().__init__()
        self.count = count
        self.error = error
