"""What `--db` / $SASS_DB names: a SQLite file, or a PostgreSQL database by its
address.  Imports nothing, so the TUI's start (which must not import numpy)
can tell the two apart."""

from __future__ import annotations

from pathlib import Path

URL_PREFIXES = ("postgresql://", "postgres://")
# The verbs that take a PostgreSQL database, as the TUI does; the others read a SQLite file.
POSTGRES_COMMANDS = (
    "query",
    "person",
    "fit",
    "target",
    "population",
    "predict",
    "family",
    "fig",
    "export",
    "strength",
    "task",
    "stats",
)
POSTGRES_VERBS = (
    "`sass` (the spreadsheet), "
    + ", ".join(f"`sass {verb}`" for verb in POSTGRES_COMMANDS)
    + " and `sass db init | import-ansur | import-flat`"
)


def is_url(target: str | Path | None) -> bool:
    """Whether `target` names a PostgreSQL server rather than a file."""
    return isinstance(target, str) and target.lower().startswith(URL_PREFIXES)


def sqlite_only(what: str) -> str:
    """The refusal of a PostgreSQL address by a command that reads a SQLite file."""
    return f"{what} reads a SQLite file only; on PostgreSQL use {POSTGRES_VERBS}"
