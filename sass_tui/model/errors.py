"""One base for every error sass reports to a user.

The concrete errors subclass both `ValueError` (what they are) and `SassError`
(that they are the user's to read).  The CLI and TUI edges catch `SassError`
and `OSError`; anything else is a programming bug and shows as one.
"""

from __future__ import annotations


class SassError(Exception):
    """An input, file or request sass refuses; whatever was loaded is unchanged.

    `where` says where the fault is, as precisely as the raiser knows it: a
    `file:line`, a cell such as "Girth / Head / x", or a token in a query.
    """

    where: str | None = None

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        super().__init__(message)
        if where is not None:
            self.where = where

    def pointer(self) -> str:
        """Extra lines that show the fault (a caret under a query column); may be empty."""
        return ""


def reason_text(exc: BaseException) -> str:
    """Why, alone, for a message that names the file itself: an operating
    system's error's own words (`No space left on device`, without Python's
    "[Errno 28]" and the file name), otherwise the error's message."""
    if isinstance(exc, OSError) and exc.strerror:
        return str(exc.strerror)
    return str(exc)


def error_text(exc: BaseException) -> str:
    """What an error the edges catch tells a user: its message; for an
    operating system's error, the file and the reason without Python's
    "[Errno 36]" (`x.db: File name too long`)."""
    text = str(exc)
    # only the operating system's own words: sass's OSErrors (model/files/atomic.py
    # OutputFileError) have theirs
    if isinstance(exc, OSError) and exc.strerror and text.startswith(f"[Errno {exc.errno}] "):
        if exc.filename is None:
            return exc.strerror
        if exc.filename2 is not None:
            return f"{exc.filename} -> {exc.filename2}: {exc.strerror}"
        return f"{exc.filename}: {exc.strerror}"
    return text
