"""Inputs that left a traceback: each is a one-line message now, nothing stored."""

from __future__ import annotations

import errno
import json
from pathlib import Path

import pytest

from sass_tui.cli import main
from sass_tui.model.errors import error_text, reason_text
from sass_tui.model.files.atomic import OutputFileError

POSTURE = {
    "l_metacarpophalangeal_3": [0.3, 1.0, 0.4], "l_radiocarpal": [0.3, 1.0, 0.3],
    "l_elbow": [0.25, 1.1, 0.1], "l_shoulder": [0.2, 1.4, 0.0],
    "r_metacarpophalangeal_3": [-0.3, 1.0, 0.4], "r_radiocarpal": [-0.3, 1.0, 0.3],
    "r_elbow": [-0.25, 1.1, 0.1], "r_shoulder": [-0.2, 1.4, 0.0],
    "vc7": [0.0, 1.45, -0.05], "vl5": [0.0, 1.0, 0.0],
}  # fmt: skip


def _one_line_error(capsys, verb: str) -> str:
    err = capsys.readouterr().err
    assert err.startswith(f"sass {verb}: error:") and len(err.splitlines()) == 1, err
    return err


@pytest.mark.parametrize("key", ["99999999999999999999999", "²"])
def test_a_person_id_no_database_holds(people_db, capsys, key):
    assert main(["--db", str(people_db), "person", key]) == 2
    assert "no person with id or name" in _one_line_error(capsys, "person")


@pytest.mark.parametrize(
    ("text", "says"),
    [
        ("[" * 100_000 + "]" * 100_000, "nested too deep"),
        (json.dumps(POSTURE).replace("0.25, 1.1", "1" + "0" * 3000 + ", 1.1", 1), "not three finite"),
        (json.dumps({**POSTURE, "l_elbow": [1e15, 1.1, 0.1]}), "l_elbow is 1e+15 m from vl5"),
    ],
)  # fmt: skip
def test_a_posture_no_body_has(tmp_path, capsys, text, says):
    path = tmp_path / "p.json"
    path.write_text(text)
    assert main(["strength", "arm_force", "--posture", str(path), "--direction", "up"]) == 2
    assert says in _one_line_error(capsys, "strength")


@pytest.mark.parametrize("text", ["stature,mass,gender\n", "stature,mass,gender\n\n\n"])
def test_a_sample_of_no_rows(people_db, tmp_path, capsys, text):
    path = tmp_path / "s.csv"
    path.write_text(text)
    assert main(["--db", str(people_db), "target", "t", "--sample", str(path)]) == 2
    assert "the sample has no rows" in _one_line_error(capsys, "target")


@pytest.mark.parametrize(
    ("query", "note"),
    [
        ("stature <= 1.9", "stature 1.9 cm is not a human one; expected 50-300 cm; did you mean `stature <= 1.9 m`?"),
        ("mass > 70000", "did you mean `mass > 70000 g`?"),
        ("stature <= 1.9 m", None),
        ("mass > 0 AND stature > 0", None),
    ],
)  # fmt: skip
def test_a_bare_number_no_human_has_gets_a_note(people_db, capsys, query, note):
    """`stature <= 1.9` asked for 1.9 cm and answered 0 without a word."""
    assert main(["--db", str(people_db), "query", "--count", query]) == 0
    err = capsys.readouterr().err
    assert (note in err) if note else "note:" not in err


@pytest.mark.parametrize(
    ("options", "says"),
    [
        (["--percentiles", "50.00001,50.00002"], "'50.00002' is shown as p50, as 50.00001 is"),
        (["--unit", "kg"], "--unit kg is a unit of mass, and no measure asked is a mass"),
    ],
)
def test_stats_options_that_would_be_passed_over(people_db, capsys, options, says):
    """Two p50 columns (and one JSON key); a mass unit on a length, ignored."""
    try:
        status = main(["--db", str(people_db), "stats", "stature", *options])
    except SystemExit as exc:  # argparse's refusal: the usage, then the error
        status = exc.code
    assert status == 2
    last = capsys.readouterr().err.splitlines()[-1]
    assert last.startswith("sass stats: error:") and says in last


def test_a_command_line_of_thousands_of_words_is_refused_at_once(capsys):
    """argparse's time grows with the square of the words: 54,000 took 35 s."""
    assert main(["stats", *(["--gender", "male"] * 5000)]) == 2
    assert "10,001 arguments; sass takes at most 1,000" in capsys.readouterr().err


def test_an_operating_system_error_is_said_without_its_errno(tmp_path, capsys):
    """`sass --db` of a name too long for the file system said Python's
    `[Errno 36] File name too long: '…'`; the TUI's Save As said the same."""
    name = tmp_path / ("a" * 300 + ".db")
    assert main(["--db", str(name), "query", "--count", "stature > 150 cm"]) == 2
    err = _one_line_error(capsys, "query")
    assert err == f"sass query: error: {name}: File name too long\n"


def test_an_error_is_said_as_its_file_and_reason():
    assert error_text(OSError(errno.ENAMETOOLONG, "File name too long", "x.db")) == (
        "x.db: File name too long"
    )
    assert error_text(OSError(errno.EXDEV, "Invalid cross-device link", "a", None, "b")) == (
        "a -> b: Invalid cross-device link"
    )
    assert error_text(OSError(errno.ENOSPC, "No space left on device")) == "No space left on device"
    assert error_text(OSError("made by sass: said as it is")) == "made by sass: said as it is"
    assert error_text(ValueError("x")) == "x"
    written = OutputFileError(Path("x.fig"), "no such directory: .")
    assert error_text(written) == str(written) == "cannot write x.fig: no such directory: ."


def test_a_reason_beside_the_file_a_message_names_is_the_reason_alone():
    """reason_text: what follows `PATH: cannot write: ` in a message that
    names the file itself (the workers' messages, the readers' errors)."""
    assert reason_text(OSError(errno.ENOSPC, "No space left on device", "x.db")) == (
        "No space left on device"
    )
    assert reason_text(OSError("made by sass: said as it is")) == "made by sass: said as it is"
    assert reason_text(OutputFileError(Path("x.fig"), "no such directory: .")) == (
        "no such directory: ."
    )
    assert reason_text(ValueError("x")) == "x"
