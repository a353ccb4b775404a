"""Text already stored with control characters (a shared PostgreSQL database,
an older file: the importers refuse them now) reaches no terminal and no
file raw: a target's sample file name in `target --list` and `stats`, a
person's name in a .fig file's comments and an X3D file (well-formed XML);
a stored stature no human has is refused, not meshed."""

from __future__ import annotations

import sqlite3
import xml.etree.ElementTree as ET

from sass_tui.cli import main

RETITLE = "\x1b]0;pwned\x07"


def _update(db, sql: str, *args) -> None:
    conn = sqlite3.connect(db)
    with conn:
        conn.execute(sql, args)
    conn.close()


def _first_person(db) -> tuple[int, str]:
    conn = sqlite3.connect(db)
    row = conn.execute(
        "SELECT id_num, name FROM person WHERE name LIKE 'ANSUR II F %' ORDER BY id_num LIMIT 1"
    ).fetchone()
    conn.close()
    return row


def test_a_stored_sample_name_is_shown_escaped(people_db, capsys):
    _update(people_db, "UPDATE target SET sample = ? WHERE name = 'nhanes-2017-2020'", RETITLE)
    capsys.readouterr()
    for argv in (["target", "--list"], ["stats", "--target", "nhanes-2017-2020"]):
        assert main(["--db", str(people_db), *argv]) == 0
        out = capsys.readouterr().out
        assert "\x1b" not in out and "\x07" not in out
        assert "^[]0;pwned^G" in out


def test_a_stored_name_reaches_the_fig_and_x3d_files_escaped(people_db, tmp_path, capsys):
    id_num, _ = _first_person(people_db)
    _update(
        people_db, "UPDATE person SET name = ? WHERE id_num = ?", f"Eve */ x = 1; {RETITLE}", id_num
    )
    fig, x3d = tmp_path / "eve.fig", tmp_path / "eve.x3d"
    person = ["--db", str(people_db), "--person", str(id_num)]
    assert main(["fig", *person, "-o", str(fig)]) == 0
    assert main(["export", "hanim", *person, "-o", str(x3d)]) == 0
    text = fig.read_text()
    assert "\x1b" not in text and "^[]0;pwned^G" in text
    assert "Eve * / x = 1;" in text  # the name cannot end its comment
    document = x3d.read_text()
    assert "\x1b" not in document
    ET.fromstring(document.split("\n", 2)[2])  # well-formed


def test_a_stored_stature_no_human_has_is_refused(people_db, tmp_path, capsys):
    id_num, name = _first_person(people_db)
    _update(people_db, "UPDATE person SET stature = 1e6 WHERE id_num = ?", id_num)
    capsys.readouterr()
    argv = [
        "export",
        "hanim",
        "--db",
        str(people_db),
        "--person",
        str(id_num),
        "-o",
        str(tmp_path / "p.x3d"),
    ]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "stature 1e+06 cm is not a human one; expected 50-300 cm" in err
    assert len(err.splitlines()) == 1


def test_a_stored_name_reaches_strength_and_task_escaped(people_db, capsys):
    id_num, _ = _first_person(people_db)
    _update(people_db, "UPDATE person SET name = ? WHERE id_num = ?", f"Eve{RETITLE}", id_num)
    capsys.readouterr()
    for argv in (
        ["strength", "knee_extension", "--person", str(id_num)],
        ["task", "--person", str(id_num), "--right-load", "20N"],
    ):
        main(
            ["--db", str(people_db), *argv]
            if argv[0] == "task"
            else [*argv, "--db", str(people_db)]
        )
        captured = capsys.readouterr()
        text = captured.out + captured.err
        assert "\x1b" not in text and "\x07" not in text
        assert "Eve^[]0;pwned^G" in text, text
