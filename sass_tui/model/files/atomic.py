"""Atomic file writes: a reader never sees a half-written file.

Every file sass writes goes through `write_text_atomic`: the text goes to a
temporary file beside the target (`.NAME.sass-tmp-PID-RANDOM`), is flushed to
disk, then renamed over the target.  So that nothing surprising happens:

- the new file gets the mode a plain `open(path, "w")` would give it
  (0666 & ~umask), or keeps the mode of the file it replaces;
- a target that is not a regular file (a FIFO, a device such as /dev/null,
  a directory) is refused: renaming over it would replace it;
- errors name the target, never the temporary file;
- a write killed half-way leaves a temporary file; the next write of the same
  target removes it once its process is gone;
- files that belong together (a population's girth and center-of-mass
  files, a .gltf and its .bin, flat-file exports) are written by
  `write_files_atomic`: every one is written to its temporary first, and only
  when all are on disk is any renamed into place; a full disk leaves every
  target as it was.
"""

from __future__ import annotations

import errno
import os
import stat
from collections.abc import Mapping
from pathlib import Path

from sass_tui.model.errors import SassError, reason_text
from sass_tui.model.files.paths import file_kind

_TEMP_MARK = ".sass-tmp-"


class OutputFileError(OSError, SassError):
    """The output file cannot be written; the message names the target.

    `strerror` is the reason alone ("no such directory: /x"), `filename` the
    target, for callers that word the message themselves.
    """

    def __init__(self, path: Path, reason: str, errno_code: int | None = None) -> None:
        super().__init__(f"cannot write {path}: {reason}")
        self.errno = errno_code
        self.strerror = reason
        self.filename = str(path)

    def __str__(self) -> str:
        return str(self.args[0])


def temporary_name(path: Path, pid: int | None = None) -> Path:
    """Where the text for `path` is written before the rename."""
    pid = os.getpid() if pid is None else pid
    # os.urandom is what secrets.token_hex uses; importing secrets (hmac,
    # hashlib, random) cost `sass fig` 4 ms.
    return path.with_name(f".{path.name}{_TEMP_MARK}{pid}-{os.urandom(4).hex()}")


def write_text_atomic(path: str | Path, text: str, encoding: str = "utf-8") -> None:
    """Write `text` to `path` atomically, or raise OutputFileError naming `path`."""
    write_bytes_atomic(path, text.encode(encoding))


def write_bytes_atomic(path: str | Path, data: bytes) -> None:
    """Write `data` to `path` atomically, or raise OutputFileError naming `path`
    (binary files: a glTF's .glb)."""
    write_files_atomic({Path(os.fspath(path)): data})


def write_files_atomic(files: Mapping[Path, bytes | str]) -> None:
    """Write several files, all or none: each to its temporary (text as
    UTF-8), flushed to disk, and only then each renamed over its target, in
    the order given.  A write that fails (a full disk, a target that is not
    a regular file) leaves every target as it was and no temporary behind.
    A rename within a directory takes no space; one refused after others
    were done (a file system gone read-only in between) is the one window
    where some files are new and others not, and the error says so."""
    targets = [Path(os.fspath(path)) for path in files]
    if len(set(targets)) != len(targets):
        raise OutputFileError(targets[0], "the same file is named twice")
    modes = [_mode_for(path) for path in targets]
    written: list[tuple[Path, Path]] = []  # (temporary, target)
    try:
        for path, mode, data in zip(targets, modes, files.values()):
            remove_stale_temporaries(path)
            tmp = temporary_name(path)
            try:
                fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o600)
            except OSError as exc:
                raise _error(path, exc) from None
            written.append((tmp, path))
            try:
                with os.fdopen(fd, "wb") as handle:
                    handle.write(data.encode("utf-8") if isinstance(data, str) else data)
                    handle.flush()
                    os.fchmod(handle.fileno(), mode)
                    os.fsync(handle.fileno())
            except OSError as exc:
                raise _error(path, exc) from None
        for done, (tmp, path) in enumerate(written):
            try:
                os.replace(tmp, path)
            except OSError as exc:
                error = _error(path, exc)
                if done:
                    replaced = ", ".join(str(p) for _, p in written[:done])
                    error = OutputFileError(path, f"{error.strerror}; already replaced: {replaced}")
                raise error from None
    except BaseException:
        for tmp, _ in written:
            try:
                os.unlink(tmp)
            except FileNotFoundError:
                pass
        raise


def make_directory(path: str | Path) -> Path:
    """`path` as a directory, made with its parents when missing: an
    OutputFileError naming it when it cannot be (a file in its place or on
    its way, no permission), where mkdir's own said "[Errno 17] File exists"."""
    directory = Path(os.fspath(path))
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except FileExistsError:
        try:
            kind = file_kind(os.stat(directory).st_mode)
        except OSError:  # a dangling symbolic link
            kind = "a file"
        raise OutputFileError(directory, f"it is {kind}, not a directory", errno.EEXIST) from None
    except NotADirectoryError:
        blocking = next((p for p in directory.parents if p.exists() and not p.is_dir()), None)
        reason = f"not a directory: {blocking if blocking is not None else directory.parent}"
        raise OutputFileError(directory, reason, errno.ENOTDIR) from None
    except OSError as exc:
        raise OutputFileError(directory, reason_text(exc), exc.errno) from None
    return directory


def check_target(path: str | Path) -> None:
    """Refuse, as a write would, a target that cannot be written: a
    directory, a FIFO, a device, a missing directory.  A prompt asks this
    before offering to overwrite (it offered to overwrite a directory, then
    refused it)."""
    _mode_for(Path(os.fspath(path)))


def _mode_for(path: Path) -> int:
    """The mode the written file gets; refuses a target that is not a regular file."""
    parent = path.parent
    if not parent.is_dir():
        what = "not a directory" if parent.exists() else "no such directory"
        raise OutputFileError(path, f"{what}: {parent}", errno.ENOENT)
    try:
        info = os.stat(path)
    except FileNotFoundError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask
    except OSError as exc:
        raise _error(path, exc) from None
    if not stat.S_ISREG(info.st_mode):
        kind = file_kind(info.st_mode)
        raise OutputFileError(path, f"it is {kind}, not a regular file")
    return stat.S_IMODE(info.st_mode)


def remove_stale_temporaries(path: Path) -> None:
    """Remove temporaries of `path` left by a write that was killed (a
    database built aside too, db/people/default.py, and its journal).

    A temporary is stale when the process that made it (the PID in its name)
    is gone; a write still going in another process keeps its own.
    """
    prefix = f".{path.name}{_TEMP_MARK}"
    try:
        names = os.listdir(path.parent)
    except OSError:
        return
    for name in names:
        if not name.startswith(prefix):
            continue
        pid_text = name[len(prefix) :].split("-", 1)[0]
        if pid_text.isdigit() and process_alive(int(pid_text)):
            continue
        try:
            os.unlink(path.parent / name)
        except OSError:
            pass


def process_alive(pid: int) -> bool:
    """Whether process `pid` runs (this one does; a PID of another user's
    process counts as running)."""
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    except OSError:
        return False
    return True


def _error(path: Path, exc: OSError) -> OutputFileError:
    reason = reason_text(exc)
    if exc.errno == errno.ENOENT:
        reason = f"no such directory: {path.parent}"
    return OutputFileError(path, reason, exc.errno)
