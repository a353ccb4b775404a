"""File names as users type them: `~` expanded, in one place for the TUI and the CLI.

A session served to a web browser (`sass serve`, model/served.py) has a
working directory: every file name its prompts take is then a name inside
that directory (`inside`), so a browser session cannot read or write the
server user's other files.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

from sass_tui.model.errors import SassError, reason_text


class PathError(ValueError, SassError):
    """A file name that names no usable file; `reason` is the message without the name."""

    def __init__(self, message: str, reason: str = "") -> None:
        super().__init__(message)
        self.reason = reason or message


def user_path(text: str | Path, workdir: Path | None = None) -> Path:
    """`~` and `~user` expanded; an unknown user is refused with a message
    (Path.expanduser raises RuntimeError for it).  With `workdir` (a served
    session's) the name must lie inside it: see `inside`."""
    if workdir is not None:
        return inside(workdir, text)
    try:
        return Path(text).expanduser()
    except RuntimeError:
        user = str(text).split("/", 1)[0]
        raise PathError(f"{text}: cannot expand {user} (no such user or home)") from None


def inside(workdir: Path, text: str | Path) -> Path:
    """`text`, a relative name, as the path it names inside `workdir`
    (symbolic links followed).  Refused with a message: an absolute name, a
    `~` name, any `..`, and a name a symbolic link leads out of `workdir`."""
    name = str(text)
    if not name.strip():
        raise PathError("no file name given")
    if name.startswith("~") or Path(name).is_absolute():
        raise PathError(f"{name}: give a name inside {workdir}, not an absolute or ~ path")
    if ".." in Path(name).parts:
        raise PathError(f"{name}: '..' is refused; files stay inside {workdir}")
    root = workdir.resolve()
    try:
        path = (root / name).resolve()  # follows every link, as opening it would
    except (RuntimeError, OSError) as exc:  # a loop of links (RuntimeError before 3.13)
        raise PathError(f"{name}: cannot follow its links ({exc})") from None
    # Python 3.13 leaves a loop of links unresolved instead of raising: a link
    # still in the resolved path is one.
    if any(part.is_symlink() for part in (path, *path.parents)):
        raise PathError(f"{name}: cannot follow its links (a loop of symbolic links)")
    if not path.is_relative_to(root):
        raise PathError(f"{name}: a symbolic link leads out of {workdir}; refused")
    return path


# The largest file of each kind a reader takes, refused by its size before a
# byte is read: a file many times the largest plausible one is a mistake (or
# a sparse file), and reading it whole took minutes and gigabytes (a 1 GB
# population file: 61 s and 13.6 GB).  The shipped population files are 1 to
# 9 KB, strength.dat 17 KB, a .fig 3 KB; an id list of a million 20-digit
# ids is 21 MB.
LARGEST_TEXT_FILE = 4 * 2**20  # population, strength and .fig files
LARGEST_ID_LIST = 32 * 2**20
# A table of people (`sass predict --input`), read whole into rows.
LARGEST_PEOPLE_TABLE = 64 * 2**20
# A flat file of the database imports, read whole: 200,000 people's are
# some hundreds of MB.  (ANSUR II CSV files are read in chunks: any size.)
LARGEST_TABLE_FILE = 2**30
# A token file holds one line of a few dozen characters.
LARGEST_TOKEN_FILE = 4096


# Completions listed at most: a directory of thousands is not read whole.
MAX_COMPLETIONS = 200


def complete_path(text: str, workdir: Path | None = None) -> list[str]:
    """The names a file name typed so far may go on to, as typed (a `~`
    kept as `~`), directories ending in `/`, sorted; hidden files only once
    a `.` is typed.  In a served session (`workdir`) only names inside it.
    Nothing (never an error) where the directory cannot be read."""
    if workdir is not None and (text.startswith("~") or Path(text).is_absolute()):
        return []
    head, slash, start = text.rpartition("/")
    folder_text = head + slash
    if workdir is not None and ".." in Path(folder_text).parts:
        return []
    try:
        folder = user_path(folder_text, workdir) if folder_text else (workdir or Path("."))
        entries = []
        with os.scandir(folder) as found:
            for entry in found:
                if entry.name.startswith(start) and (start.startswith(".") or entry.name[0] != "."):
                    end = "/" if entry.is_dir() else ""
                    entries.append(f"{folder_text}{entry.name}{end}")
                    if len(entries) > MAX_COMPLETIONS:
                        break
    except (OSError, PathError):
        return []
    return sorted(entries)


def regular_file(
    text: str | Path,
    workdir: Path | None = None,
    *,
    largest: int | None = None,
    kind: str = "a data file",
) -> Path:
    """The expanded path of an existing regular file.  A FIFO, a device or a
    directory is refused before it is opened: reading a FIFO blocks forever.
    With `largest`, a file of more bytes is refused too, naming its `kind`."""
    path = user_path(text, workdir)
    try:
        status = path.stat()
    except FileNotFoundError:
        raise PathError(f"{path}: no such file", "no such file") from None
    except OSError as exc:  # a loop of links, a name too long, no permission
        reason = reason_text(exc)
        raise PathError(f"{path}: {reason}", reason) from None
    if not stat.S_ISREG(status.st_mode):
        what = "a directory" if stat.S_ISDIR(status.st_mode) else "not a regular file"
        raise PathError(f"{path}: {what}; give a data file", f"{what}; give a data file")
    if largest is not None and status.st_size > largest:
        reason = (
            f"{size_text(status.st_size)} is too large for {kind} "
            f"(at most {size_text(largest)}); nothing was read"
        )
        raise PathError(f"{path}: {reason}", reason)
    return path


def size_text(size: int) -> str:
    """A file's size for a message: '100.0 MiB', '12 KiB', '300 bytes'."""
    if size >= 2**20:
        return f"{size / 2**20:,.1f} MiB"
    return f"{size // 1024} KiB" if size >= 1024 else f"{size} bytes"


def read_user_text(
    text: str | Path, kind: str = "a data file", largest: int = LARGEST_TEXT_FILE
) -> tuple[Path, str]:
    """A data file the user names (a population or strength file): its path
    (`regular_file`, at most `largest` bytes) and its text, UTF-8 or else
    Latin-1 (a file of the report's time has no other), without the
    byte-order mark Windows editors and Excel's "CSV UTF-8" put first.
    PathError, `reason` saying why, when it cannot be read."""
    path = regular_file(text, largest=largest, kind=kind)
    try:
        return path, path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        return path, path.read_text(encoding="latin-1")
    except OSError as exc:
        reason = reason_text(exc)
        raise PathError(f"{path}: cannot read: {reason}", reason) from None


# --- sass's own directories ----------------------------------------------------------
# platformdirs knows each system's place ($XDG_*_HOME or ~/.local/share,
# ~/.cache, ~/.config on Linux; ~/Library/... on macOS; %LOCALAPPDATA% on
# Windows).  Imported when first asked: `sass query --db F` never needs it.


def data_dir() -> Path:
    """Where sass keeps its database and served sessions' directories."""
    return _platform_dir("data")


def cache_dir() -> Path:
    """Where sass keeps what it can rebuild (the database's column copies)."""
    return _platform_dir("cache")


def config_dir() -> Path:
    """Where sass keeps the user's settings."""
    return _platform_dir("config")


def _platform_dir(kind: str) -> Path:
    """sass's directory of a kind ("data", "cache" or "config") on this system."""
    # deferred: platformdirs — off sass query, sass query --count, sass fig … (sass_tui/startup.py)
    import platformdirs

    where = {
        "data": platformdirs.user_data_dir,
        "cache": platformdirs.user_cache_dir,
        "config": platformdirs.user_config_dir,
    }[kind]
    return Path(where("sass", appauthor=False))


def file_kind(mode: int) -> str:
    """What a path is, for a message ("a device", "a file")."""
    if stat.S_ISREG(mode):
        return "a file"
    if stat.S_ISDIR(mode):
        return "a directory"
    if stat.S_ISFIFO(mode):
        return "a FIFO (named pipe)"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "a special file"
