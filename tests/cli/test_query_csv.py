"""`sass query --format csv` is opened in spreadsheets: a text cell that
would start a formula is written as text (OWASP "CSV Injection"), so an
import's source label such as `=HYPERLINK(1)` stays a label in every
colleague's spreadsheet, with its text kept."""

from __future__ import annotations

import csv
import io
import shutil
import subprocess

import pytest
from _built_once import copy_database_file

from sass_tui.cli import main
from sass_tui.db.engine.schema import connect

# Labels an import may carry; a spreadsheet evaluates each as a formula when
# written as it is (Gnumeric turns "=1+1" into 2).
HOSTILE_SOURCES = (
    "=HYPERLINK(1)",
    "=1+1",
    "+1+1",
    "-1+1",
    "@SUM(1)",
    "\t=1+1",
    "=cmd|' /C calc'!A0",
)


def _csv_of_people_labelled(shipped_db_file, tmp_path, capsys) -> list[list[str]]:
    db = tmp_path / "s.db"
    copy_database_file(shipped_db_file, db)
    conn = connect(db)
    with conn:
        ids = [row[0] for row in conn.execute("SELECT id_num FROM person ORDER BY id_num LIMIT 7")]
        for id_num, source in zip(ids, HOSTILE_SOURCES):
            conn.execute(
                "UPDATE person SET source = ?, name = ?, mass = 499 WHERE id_num = ?",
                (source, source, id_num),
            )
    conn.close()
    assert main(["--db", str(db), "query", "--format", "csv", "mass > 498 kg"]) == 0
    return list(csv.reader(io.StringIO(capsys.readouterr().out)))


def test_csv_cells_that_would_start_a_formula_are_written_as_text(
    shipped_db_file, tmp_path, capsys
):
    rows = _csv_of_people_labelled(shipped_db_file, tmp_path, capsys)
    header, people = rows[0], rows[1:]
    assert len(people) == len(HOSTILE_SOURCES)
    name, source = header.index("name"), header.index("source")
    # a tab is shown as ^I, as in every text sass prints (model/text.py)
    expected = ["'" + label if label[0] != "\t" else "^I=1+1" for label in HOSTILE_SOURCES]
    assert [person[source] for person in people] == expected
    assert [person[name] for person in people] == expected


@pytest.mark.skipif(shutil.which("ssconvert") is None, reason="needs Gnumeric's ssconvert")
def test_a_spreadsheet_opens_the_labels_as_text(shipped_db_file, tmp_path, capsys):
    """Gnumeric reads the CSV as a spreadsheet and writes back each cell's
    value: every label comes back as its text, not a formula's result."""
    rows = _csv_of_people_labelled(shipped_db_file, tmp_path, capsys)
    exported = tmp_path / "query.csv"
    with exported.open("w", newline="") as out:
        csv.writer(out).writerows(rows)
    opened = tmp_path / "opened.csv"
    subprocess.run(
        ["ssconvert", str(exported), str(opened)], check=True, capture_output=True, timeout=60
    )
    values = list(csv.reader(io.StringIO(opened.read_text())))
    source = values[0].index("source")
    shown = [label if label[0] != "\t" else "^I=1+1" for label in HOSTILE_SOURCES]
    assert [row[source] for row in values[1:]] == shown
