"""What `--db` / $SASS_DB names: a SQLite file, or a PostgreSQL database by its
address, and an address as shown to a user.  Imports only the model's text
module (no urllib.parse, no pathlib), so the TUI's start (which must not
import numpy) can tell the two apart, and a SQLite path need not import
db/engine/postgres.py to show an address."""

from __future__ import annotations

from typing import TYPE_CHECKING

from sass_tui.model.text import without_password

if TYPE_CHECKING:
    from pathlib import Path

URL_PREFIXES = ("postgresql://", "postgres://")
# The verbs that take a PostgreSQL database, as the TUI does; the others read a SQLite file.
POSTGRES_COMMANDS = (
    "query",
    "person",
    "fit",
    "design",
    "target",
    "population",
    "predict",
    "family",
    "fig",
    "export",
    "strength",
    "task",
    "reach",
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


def shown(url: str) -> str:
    """The address without its passwords, for messages (an address the
    driver will refuse, with a port that is no number say, is shown too)."""
    return without_password(url)
