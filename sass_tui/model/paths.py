"""File names as users type them: `~` expanded, in one place for the TUI and the CLI."""

from __future__ import annotations

import stat
from pathlib import Path

from sass_tui.model.errors import SassError


class PathError(ValueError, SassError):
    """A file name that names no usable file; `reason` is the message without the name."""

    def __init__(self, message: str, reason: str = "") -> None:
        super().__init__(message)
        self.reason = reason or message


def user_path(text: str | Path) -> Path:
    """`~` and `~user` expanded; an unknown user is refused with a message
    (Path.expanduser raises RuntimeError for it)."""
    try:
        return Path(text).expanduser()
    except RuntimeError:
        user = str(text).split("/", 1)[0]
        raise PathError(f"{text}: cannot expand {user} (no such user or home)") from None


def regular_file(text: str | Path) -> Path:
    """The expanded path of an existing regular file.  A FIFO, a device or a
    directory is refused before it is opened: reading a FIFO blocks forever."""
    path = user_path(text)
    try:
        mode = path.stat().st_mode
    except FileNotFoundError:
        raise PathError(f"{path}: no such file", "no such file") from None
    if not stat.S_ISREG(mode):
        kind = "a directory" if stat.S_ISDIR(mode) else "not a regular file"
        raise PathError(f"{path}: {kind}; give a data file", f"{kind}; give a data file")
    return path
