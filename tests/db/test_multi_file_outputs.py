"""Files that belong together are replaced all or none (model/files/atomic.py
`write_files_atomic`): `sass population`'s girth and center-of-mass files, a
.gltf and its .bin, flat-file exports.  A full disk once left a new `p.dat`
beside the old `p-cmass.dat`."""

from __future__ import annotations

import hashlib
import os
from pathlib import Path

import pytest
from _tmpfs import build_small_db, fill, mounted_tmpfs

from sass_tui.cli import main
from sass_tui.model.files.atomic import OutputFileError, write_files_atomic

pytestmark = pytest.mark.sqlite_only("file-system faults under a SQLite file")

PAGE = 4096  # tmpfs counts whole pages


def _digests(folder: Path) -> dict[str, str]:
    return {
        p.name: hashlib.sha256(p.read_bytes()).hexdigest()
        for p in sorted(folder.iterdir())
        if p.name != "filler"
    }


def _population(db: Path, query: str, out: Path) -> list[str]:
    return ["population", "--db", str(db), "--query", query, "-o", str(out)]


@pytest.mark.slow
def test_a_population_that_does_not_fit_replaces_neither_file(tmp_path, capsys):
    db = build_small_db(tmp_path / "small.db")
    with mounted_tmpfs(tmp_path / "m", 256 * 1024) as mnt:
        out = mnt / "p.dat"
        assert main(_population(db, "gender = female AND source = synthetic", out)) == 0
        capsys.readouterr()
        # Room for the new girth file, not for the center-of-mass file too.
        # (Without an old p.dat: replacing one would free its pages for the
        # next file, and the disk would fill one file later.)
        room = -(-out.stat().st_size // PAGE) * PAGE
        out.unlink()
        before = _digests(mnt)
        assert "p-cmass.dat" in before
        filler = fill(mnt)
        os.truncate(filler, filler.stat().st_size - room)
        assert main(_population(db, "gender = male AND source = synthetic", out)) == 2
        said = capsys.readouterr().err
        assert "cannot write" in said and "Traceback" not in said
        filler.unlink()
        assert _digests(mnt) == before  # no new p.dat beside the old p-cmass.dat
        assert not [p for p in mnt.iterdir() if ".sass-tmp-" in p.name]
        # with room, both are replaced
        assert main(_population(db, "gender = male AND source = synthetic", out)) == 0
        after = _digests(mnt)
        assert "p.dat" in after and after["p-cmass.dat"] != before["p-cmass.dat"]


def test_one_target_refused_leaves_every_target_as_it_was(tmp_path):
    first, second = tmp_path / "a.gltf", tmp_path / "a.bin"
    first.write_text("old document")
    second.mkdir()  # a directory: refused before anything is written
    with pytest.raises(OutputFileError, match="a.bin: it is a directory"):
        write_files_atomic({first: "new document", second: b"new buffer"})
    assert first.read_text() == "old document"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.bin", "a.gltf"]


def test_every_file_is_written_before_any_is_renamed(tmp_path, monkeypatch):
    """The second file's write fails after the first is on disk: the first
    target still holds its old text and its temporary is gone."""
    first, second = tmp_path / "p.dat", tmp_path / "p-cmass.dat"
    first.write_text("old girth")
    second.write_text("old cmass")
    real_fsync = os.fsync
    calls = []

    def fsync_failing_the_second(fd: int) -> None:
        calls.append(fd)
        if len(calls) == 2:
            raise OSError(28, "No space left on device")
        real_fsync(fd)

    monkeypatch.setattr(os, "fsync", fsync_failing_the_second)
    with pytest.raises(OutputFileError, match="p-cmass.dat: No space left on device"):
        write_files_atomic({first: "new girth", second: "new cmass"})
    assert (first.read_text(), second.read_text()) == ("old girth", "old cmass")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p-cmass.dat", "p.dat"]
