"""Imported text is data, never terminal commands: a survey field, a person's
name or source, or an import's --source label holding a control character
(ESC, BEL, C0/C1, DEL) is refused at import with file:line and the field, and
nothing is stored; text already stored so is shown escaped by `sass person`
and `sass query` (table, CSV, JSON).  The imports write a SQLite connection
(a PostgreSQL import is staged through them in SQLite); the escaped output is
checked on both engines (tests/db/conftest.py)."""

from __future__ import annotations

import gzip
import json

import pytest
from _paths import DATASETS
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sass_tui.cli import main
from sass_tui.db.engine.dialect import mark_of, writing
from sass_tui.db.engine.schema import connect, row_counts
from sass_tui.db.people.ansur import AnsurImportError, import_ansur
from sass_tui.db.people.flatfile import FlatFileError, FlatFiles, import_flat_files
from sass_tui.model.text import control_character

MALE = DATASETS / "ansur2" / "ANSUR_II_MALE_Public.csv.gz"
RETITLE_AND_CLEAR = "\x1b]0;pwned\x07\x1b[2J"  # sets the window title, clears the screen
RED = "\x1b[31m"
CONTROLS = ["\x1b", "\x07", "\x00", "\x1f", "\x7f", "\x9b", "\x85", "\t"]


@pytest.fixture(scope="module")
def male_lines() -> list[str]:
    """Header and the first 5 subjects of the shipped male file."""
    return gzip.decompress(MALE.read_bytes()).decode("cp1252").splitlines()[:6]


def _with_branch(lines: list[str], row: int, value: str) -> list[str]:
    k = [h.lower() for h in lines[0].split(",")].index("branch")
    out = list(lines)
    fields = out[row].split(",")
    fields[k] = value
    out[row] = ",".join(fields)
    return out


def _write(tmp_path, lines: list[str]):
    path = tmp_path / "survey.csv"
    path.write_bytes(("\r\n".join(lines) + "\r\n").encode("utf-8"))
    return path


def test_a_survey_field_with_an_escape_sequence_is_refused_with_file_line_and_field(
    tmp_path, male_lines
):
    path = _write(tmp_path, _with_branch(male_lines, 3, f"Combat Arms{RETITLE_AND_CLEAR}"))
    conn = connect(tmp_path / "s.db", create=True)
    before = row_counts(conn)
    with pytest.raises(AnsurImportError) as info:
        import_ansur(conn, [path])
    message = str(info.value)
    assert f"{path}:4: column branch: a control character (^[) at character 12" in message
    assert "\x1b" not in message and "\x07" not in message
    assert row_counts(conn) == before  # nothing stored


@settings(
    max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
# inside the text: at either end a field's blanks, which \x1f, \x85 and \t are, are trimmed
@given(control=st.sampled_from(CONTROLS), at=st.integers(1, 5))
def test_every_control_character_in_a_field_is_refused(tmp_path, male_lines, control, at):
    value = "Combat"[:at] + control + "Combat"[at:]
    path = _write(tmp_path, _with_branch(male_lines, 2, value))
    conn = connect(":memory:", create=True)
    with pytest.raises(
        AnsurImportError, match=rf":3: column branch: a control character .* at character {at + 1};"
    ):
        import_ansur(conn, [path])
    assert conn.execute("SELECT count(*) FROM person").fetchone() == (0,)


def test_a_hostile_source_label_is_refused_and_never_printed_raw(tmp_path, male_lines, capsys):
    path = _write(tmp_path, male_lines)
    db = tmp_path / "s.db"
    argv = ["db", "import-ansur", "--db", str(db), "--source", f"mine{RED}", str(path)]
    assert main(argv) == 2
    said = capsys.readouterr()
    assert "source label" in said.err and "control character (^[)" in said.err
    assert "\x1b" not in said.err + said.out
    assert main(["db", "import-ansur", "--db", str(db), "--source", "mine", str(path)]) == 0
    capsys.readouterr()
    conn = connect(db)
    assert dict(conn.execute("SELECT source, count(*) FROM person GROUP BY source")) == {"mine": 5}


PERSON = "7,JANE_DOE,female,165.0,60.5,left,31,test\n"


@pytest.mark.parametrize(
    "person, where",
    [
        (
            PERSON.replace("JANE_DOE", f"JANE{RETITLE_AND_CLEAR}"),
            "person.db:1: name: a control character (^[) at character 5",
        ),
        (
            PERSON.replace(",test", f",test{RED}"),
            "person.db:1: source: a control character (^[) at character 5",
        ),
        (
            PERSON.replace("JANE_DOE", "JANE\x7fDOE"),
            "person.db:1: name: a control character (^?) at character 5",
        ),
    ],
)
def test_a_person_file_with_a_hostile_name_or_source_is_refused(tmp_path, person, where):
    (tmp_path / "person.db").write_text(person)
    conn = connect(tmp_path / "s.db", create=True)
    with pytest.raises(FlatFileError) as info:
        import_flat_files(conn, FlatFiles.in_directory(tmp_path))
    assert where in str(info.value) and "\x1b" not in str(info.value)
    assert conn.execute("SELECT count(*) FROM person").fetchone() == (0,)


def test_text_stored_before_is_shown_escaped_by_every_output(engine_target, engine_db_copy, capsys):
    """On both engines (tests/db/conftest.py)."""
    conn, db, mark = engine_db_copy, engine_target, mark_of(engine_db_copy)
    with writing(conn):
        (first,) = conn.execute(  # the one man under 18 of the survey
            "SELECT id_num FROM person WHERE source = 'ansur2' AND gender = 'male' AND age < 18"
        ).fetchone()
        conn.execute(
            f"UPDATE person SET name = {mark}, branch = {mark} WHERE id_num = {mark}",
            (f"X{RETITLE_AND_CLEAR}", f"Arms{RETITLE_AND_CLEAR}", first),
        )
    for fmt in ("table", "csv", "json"):
        assert main(["query", "--db", db, "--format", fmt, "gender = male AND age < 18"]) == 0
        out = capsys.readouterr().out
        assert "\x1b" not in out and "\x07" not in out, fmt
        if fmt == "json":
            assert json.loads(out)["persons"][0]["name"] == f"X{RETITLE_AND_CLEAR}"  # escaped, kept
        else:
            assert "X^[]0;pwned^G^[[2J" in out, fmt
    assert main(["person", "--db", db, str(first)]) == 0
    out = capsys.readouterr().out
    assert "\x1b" not in out and "X^[]0;pwned^G^[[2J" in out and "Arms^[]0;pwned" in out


def test_control_character_names_the_first_one():
    assert control_character("Combat Arms") is None
    assert control_character("Zoë Ångström 名前") is None
    assert control_character("ab\x1bc") == "a control character (^[) at character 3"
    assert control_character("\x9b2J") == "a control character (\\x9b) at character 1"
