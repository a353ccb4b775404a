"""What `--db` / $SASS_DB names: a SQLite file, or a PostgreSQL database by its
address, and an address as shown to a user.  Imports only urllib.parse
(which pathlib imports already), so the TUI's start (which must not import
numpy) can tell the two apart, and a SQLite path need not import
db/engine/postgres.py to show an address."""

from __future__ import annotations

from pathlib import Path
from urllib.parse import urlsplit, urlunsplit

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
    """The address without its password, for messages."""
    parts = urlsplit(url)
    if parts.password is None:
        return url
    host = parts.hostname or ""
    user = parts.username or ""
    port = f":{parts.port}" if parts.port else ""
    return urlunsplit(parts._replace(netloc=f"{user}:***@{host}{port}"))
