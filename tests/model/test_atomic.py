"""Output files: modes, targets that are not regular files, messages (a
missing folder is "no such directory"), and killed writes."""

from __future__ import annotations

import os
import signal
import stat
import subprocess
import sys
import textwrap

import pytest
from _tmpfs import mounted_tmpfs, remount_read_only

from sass_tui.cli import main
from sass_tui.model.errors import SassError
from sass_tui.model.files.atomic import OutputFileError, temporary_name, write_text_atomic


@pytest.fixture
def umask_027():
    old = os.umask(0o027)
    yield 0o027
    os.umask(old)


def _mode(path) -> int:
    return stat.S_IMODE(os.stat(path).st_mode)


def test_a_new_file_gets_0666_less_the_umask(tmp_path, umask_027):
    out = tmp_path / "a.txt"
    write_text_atomic(out, "x\n")
    assert _mode(out) == 0o640
    os.umask(0o022)
    write_text_atomic(tmp_path / "b.txt", "x\n")
    assert _mode(tmp_path / "b.txt") == 0o644


def test_a_replaced_file_keeps_its_mode(tmp_path, umask_027):
    out = tmp_path / "a.txt"
    out.write_text("old")
    os.chmod(out, 0o604)
    write_text_atomic(out, "new\n")
    assert out.read_text() == "new\n"
    assert _mode(out) == 0o604


def test_sass_fig_output_mode(tmp_path, umask_027):
    out = tmp_path / "x.fig"
    assert main(["fig", "-o", str(out)]) == 0
    assert _mode(out) == 0o640


def test_a_fifo_is_refused_and_left_alone(tmp_path, capsys):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    with pytest.raises(OutputFileError, match="FIFO"):
        write_text_atomic(fifo, "x")
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert main(["fig", "-o", str(fifo)]) == 2
    err = capsys.readouterr().err
    assert f"cannot write {fifo}: it is a FIFO" in err
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pipe"]


def test_a_device_is_refused(capsys):
    # As root, renaming over /dev/null would replace the system's /dev/null.
    before = os.stat(os.devnull)
    with pytest.raises(OutputFileError, match="a device"):
        write_text_atomic(os.devnull, "x")
    assert main(["fig", "-o", os.devnull]) == 2
    assert "it is a device, not a regular file" in capsys.readouterr().err
    after = os.stat(os.devnull)
    assert stat.S_ISCHR(after.st_mode) and after.st_ino == before.st_ino


def test_a_directory_is_refused(tmp_path):
    (tmp_path / "d").mkdir()
    with pytest.raises(OutputFileError, match="a directory"):
        write_text_atomic(tmp_path / "d", "x")
    assert (tmp_path / "d").is_dir()


def test_a_missing_directory_is_named(tmp_path, capsys):
    target = tmp_path / "nowhere" / "x.fig"
    assert main(["fig", "-o", str(target)]) == 2
    err = capsys.readouterr().err
    assert f"no such directory: {tmp_path / 'nowhere'}" in err
    assert ".tmp" not in err and "sass-tmp" not in err


def test_errors_name_the_target_not_the_temporary(tmp_path):
    if os.geteuid() == 0:
        # chmod does not stop root; a read-only file system does
        with mounted_tmpfs(tmp_path / "locked", 64 * 1024) as locked:
            remount_read_only(locked)
            _refused_naming_the_target(locked)
        return
    locked = tmp_path / "locked"
    locked.mkdir()
    os.chmod(locked, 0o500)
    try:
        _refused_naming_the_target(locked)
    finally:
        os.chmod(locked, 0o700)


def _refused_naming_the_target(locked):
    with pytest.raises(OutputFileError) as info:
        write_text_atomic(locked / "x.fig", "x")
    message = str(info.value)
    assert message.startswith(f"cannot write {locked / 'x.fig'}: ")
    assert "sass-tmp" not in message and ".x.fig." not in message
    assert isinstance(info.value, SassError) and isinstance(info.value, OSError)
    assert list(locked.iterdir()) == []


def test_a_stale_temporary_of_a_dead_process_is_cleaned(tmp_path):
    out = tmp_path / "x.fig"
    dead = subprocess.run(
        [sys.executable, "-c", "import os; print(os.getpid())"],
        capture_output=True,
        text=True,
        check=True,
    )
    stale = temporary_name(out, int(dead.stdout))
    stale.write_text("half")
    other = temporary_name(tmp_path / "y.fig", int(dead.stdout))
    other.write_text("someone else's")
    write_text_atomic(out, "whole\n")
    assert not stale.exists()
    assert other.exists()  # another target's temporary is not ours to judge
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([out.name, other.name])


def test_a_temporary_of_a_live_process_is_kept(tmp_path):
    out = tmp_path / "x.fig"
    live = temporary_name(out, os.getppid())
    live.write_text("being written")
    write_text_atomic(out, "whole\n")
    assert live.exists()


def test_a_write_killed_half_way_is_cleaned_by_the_next(tmp_path):
    out = tmp_path / "x.fig"
    out.write_text("old\n")
    # A writer that stops for good between creating its temporary and the rename.
    code = textwrap.dedent(
        f"""
        import os, sys, time
        import sass_tui.model.files.atomic as atomic
        real_replace = os.replace
        def hang(src, dst):
            print("ready", flush=True)
            time.sleep(60)
        atomic.os.replace = hang
        atomic.write_text_atomic({str(out)!r}, "new\\n" * 1000)
        """
    )
    writer = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    assert writer.stdout.readline().strip() == "ready"
    os.kill(writer.pid, signal.SIGKILL)
    writer.wait()
    leftovers = [p for p in tmp_path.iterdir() if p.name != "x.fig"]
    assert len(leftovers) == 1 and "sass-tmp" in leftovers[0].name
    assert out.read_text() == "old\n"  # the reader never saw a half-written file
    write_text_atomic(out, "next\n")
    assert [p.name for p in tmp_path.iterdir()] == ["x.fig"]
    assert out.read_text() == "next\n"


def test_an_error_in_the_temporary_names_the_target(tmp_path):
    # A name that fits the directory but whose temporary name is too long:
    # the failure happens on the temporary, the message names the target.
    out = tmp_path / ("n" * 240)
    with pytest.raises(OutputFileError) as info:
        write_text_atomic(out, "x")
    message = str(info.value)
    assert message.startswith(f"cannot write {out}: ")
    assert "sass-tmp" not in message
    assert list(tmp_path.iterdir()) == []


def test_the_error_carries_the_reason_and_the_target(tmp_path):
    # The TUI words it "{path}: cannot write: {strerror}".
    target = tmp_path / "nowhere" / "x.fig"
    with pytest.raises(OutputFileError) as info:
        write_text_atomic(target, "x")
    assert info.value.strerror == f"no such directory: {tmp_path / 'nowhere'}"
    assert info.value.filename == str(target)
    assert str(info.value) == f"cannot write {target}: {info.value.strerror}"
