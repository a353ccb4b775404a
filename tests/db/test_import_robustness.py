"""Imports refuse what is not a plausible number: non-finite and
absurd values, ids that are not whole or too large, with file:line; UTF-8
with a byte-order mark is read; duplicate ids name both lines; the ANSUR
reader streams (memory bounded by a chunk); the database is unchanged after
every refusal.

Both engines where the database is written: the import goes through the
Database service or the CLI with the engine's address (`engine_target`, a
private copy, or for the refusals `refusal_target`, one copy the module's
refusals share; on PostgreSQL staged in SQLite and copied, db/engine/postgres.py).  The
readers' own tests (read_ansur, iter_ansur) touch no database."""

from __future__ import annotations

import gzip
import math
from contextlib import closing

import pytest
from _paths import DATASETS
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sass_tui.cli import main
from sass_tui.db.engine.database import Database
from sass_tui.db.engine.schema import row_counts
from sass_tui.db.people.ansur import AnsurImportError, import_ansur_into, iter_ansur, read_ansur
from sass_tui.db.people.flatfile import FlatFileError, FlatFiles, import_flat_into

MALE = DATASETS / "ansur2" / "ANSUR_II_MALE_Public.csv.gz"


@pytest.fixture(scope="module")
def male_lines() -> list[str]:
    """Header and the first 30 subjects of the shipped male file."""
    return gzip.decompress(MALE.read_bytes()).decode("cp1252").splitlines()[:31]


def _header(lines: list[str]) -> list[str]:
    return [h.lower() for h in lines[0].split(",")]


def _with_value(lines: list[str], row: int, column: str, value: str) -> list[str]:
    k = _header(lines).index(column)
    out = list(lines)
    fields = out[row].split(",")
    fields[k] = value
    out[row] = ",".join(fields)
    return out


def _write(tmp_path, lines: list[str], name: str = "ansur.csv", bom: bool = False):
    path = tmp_path / name
    data = ("\r\n".join(lines) + "\r\n").encode("utf-8")
    path.write_bytes((b"\xef\xbb\xbf" if bom else b"") + data)
    return path


BAD_VALUES = [
    ("stature", "nan", "column stature: 'nan' is not a plausible value"),
    ("stature", "-1755", "column stature: '-1755' is not a plausible value"),
    ("stature", "", "column stature: expected a number, found ''"),
    ("weightkg", "1e309", "column weightkg: '1e309' is not a plausible value"),
    ("weightkg", "inf", "column weightkg: 'inf' is not a plausible value"),
    ("handlength", "99999", "column handlength: '99999' is not a plausible value"),
    ("age", "-3", "column age: '-3' is not a plausible value"),
    ("subjectid", "1e30", "expected a whole number from 1 to 999999999999, found '1e30'"),
    ("subjectid", "10037.9", "found '10037.9'"),
    ("subjectid", "99999999999999999999", "found '99999999999999999999'"),
    ("subjectid", "9223372036854775807", "found '9223372036854775807'"),
    ("subjectid", "-5", "found '-5'"),
]


@pytest.mark.parametrize("column, value, message", BAD_VALUES)
def test_bad_values_are_refused_with_file_and_line(
    refusal_target, refusal_db, tmp_path, male_lines, column, value, message
):
    before = row_counts(refusal_db)
    path = _write(tmp_path, _with_value(male_lines, 7, column, value))
    with closing(Database.open(refusal_target)) as db, pytest.raises(AnsurImportError) as caught:
        import_ansur_into(db, [path], label="ansur2")
    assert str(caught.value).startswith(f"{path}:8: ")
    assert message in str(caught.value)
    assert row_counts(refusal_db) == before


def test_a_byte_order_mark_is_read(engine_target, engine_db_copy, tmp_path, male_lines):
    path = _write(tmp_path, male_lines, bom=True)
    with closing(Database.open(engine_target)) as db:
        counts = import_ansur_into(db, [path], label="bom-test")
    assert counts == {"male": 30, "female": 0}
    stored = "SELECT count(*) FROM person WHERE source = 'bom-test' AND gender = 'male'"
    assert engine_db_copy.execute(stored).fetchone()[0] == 30
    assert read_ansur(path).stature[0] == pytest.approx(float(male_lines[1].split(",")[75]) / 10)


def test_cp1252_text_is_still_read(tmp_path, male_lines):
    """The published male file is cp1252, not UTF-8."""
    lines = _with_value(male_lines, 3, "subjectsbirthlocation", "Curaçao")
    path = tmp_path / "cp1252.csv"
    path.write_bytes(("\n".join(lines) + "\n").encode("cp1252"))
    assert len(read_ansur(path)) == 30


def test_duplicate_ids_name_both_lines(refusal_target, refusal_db, tmp_path, male_lines):
    before = row_counts(refusal_db)
    first = male_lines[2].split(",")[0]
    path = _write(tmp_path, _with_value(male_lines, 20, "subjectid", first))
    with (
        closing(Database.open(refusal_target)) as db,
        pytest.raises(
            AnsurImportError, match=rf":21: duplicate subject id {first} \(first on line 3\)"
        ),
    ):
        import_ansur_into(db, [path], label="dup")
    assert row_counts(refusal_db) == before


def test_rows_are_read_a_chunk_at_a_time(tmp_path, male_lines):
    """The reader hands over chunks before it has read the rest of the file:
    a bad last line is found only after the first chunks were yielded."""
    path = _write(tmp_path, _with_value(male_lines, 30, "stature", "nan"))
    chunks = iter_ansur(path, chunk_rows=4)
    first = next(chunks)
    assert len(first) == 4
    with pytest.raises(AnsurImportError, match=":31: column stature"):
        list(chunks)


def test_gzip_files_import(engine_target, engine_db_copy, tmp_path, male_lines):
    path = tmp_path / "few.csv.gz"
    path.write_bytes(gzip.compress(("\n".join(male_lines) + "\n").encode("cp1252")))
    with closing(Database.open(engine_target)) as db:
        assert import_ansur_into(db, [path], label="gz") == {"male": 30, "female": 0}
    assert engine_db_copy.execute("SELECT count(*) FROM person WHERE source = 'gz'").fetchone() == (
        30,
    )


def test_cli_reports_the_line(refusal_target, refusal_db, tmp_path, male_lines, capsys):
    before = row_counts(refusal_db)
    path = _write(tmp_path, _with_value(male_lines, 5, "weightkg", "1e309"))
    assert main(["db", "import-ansur", "--db", refusal_target, str(path)]) == 2
    err = capsys.readouterr().err
    assert f"{path}:6: column weightkg" in err and "Traceback" not in err
    assert row_counts(refusal_db) == before


@settings(
    max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(
    value=st.text(max_size=12).filter(lambda t: "," not in t and "\n" not in t and "\r" not in t)
)
def test_any_stature_text_imports_or_is_refused_cleanly(tmp_path_factory, male_lines, value):
    tmp = tmp_path_factory.mktemp("fuzz")
    path = _write(tmp, _with_value(male_lines[:3], 1, "stature", value))
    try:
        batch = read_ansur(path)
    except AnsurImportError as exc:
        assert ":2: " in str(exc)
        return
    assert math.isfinite(batch.stature[0]) and 0 < batch.stature[0] <= 300


# --- flat files -------------------------------------------------------------------

PERSON = "7,JANE_DOE,female,165.0,60.5,left,31,hand-made test person\n"


def _flat(tmp_path, person: str, bom: bool = False) -> FlatFiles:
    data = person.encode("utf-8")
    (tmp_path / "person.db").write_bytes((b"\xef\xbb\xbf" if bom else b"") + data)
    (tmp_path / "cmass.db").write_text(person.split(",")[0] + ",NECK, 0.0, 0.0, 5.2\n")
    return FlatFiles.in_directory(tmp_path)


@pytest.mark.parametrize(
    "person, message",
    [
        ("99999999999999999999" + PERSON[1:], "person.db:1: id_num: expected a whole number"),
        ("9223372036854775807" + PERSON[1:], "person.db:1: id_num: expected a whole number"),
        (PERSON.replace("165.0", "-1755"), "person.db:1: stature: '-1755' is not plausible"),
        (PERSON.replace("165.0", "nan"), "person.db:1: stature: expected a finite number"),
        (PERSON.replace("60.5", "1e309"), "person.db:1: mass: expected a finite number"),
        (PERSON.replace("60.5", "6000"), "person.db:1: mass: '6000' is not plausible"),
        (PERSON.replace(",31,", ",-31,"), "person.db:1: age: '-31' is not plausible"),
    ],
)
def test_flat_files_refuse_absurd_values(refusal_target, refusal_db, tmp_path, person, message):
    before = row_counts(refusal_db)
    with (
        closing(Database.open(refusal_target)) as db,
        pytest.raises(FlatFileError, match=message.replace("(", r"\(")),
    ):
        import_flat_into(db, _flat(tmp_path, person))
    assert row_counts(refusal_db) == before


def test_flat_files_with_a_byte_order_mark(engine_target, engine_db_copy, tmp_path):
    with closing(Database.open(engine_target)) as db:
        assert import_flat_into(db, _flat(tmp_path, PERSON, bom=True)) == 1
    assert engine_db_copy.execute("SELECT name FROM person WHERE id_num = 7").fetchone() == (
        "JANE_DOE",
    )


def test_imports_after_a_large_id_still_work(engine_target, engine_db_copy, tmp_path):
    """The largest id accepted leaves room for the ids given after it."""
    male = gzip.decompress(MALE.read_bytes()).decode("cp1252").splitlines()[:3]
    path = _write(tmp_path, male)
    with closing(Database.open(engine_target)) as db:
        import_flat_into(db, _flat(tmp_path, "999999999999" + PERSON[1:]))
        assert import_ansur_into(db, [path], label="after") == {"male": 2, "female": 0}
    ids = engine_db_copy.execute(
        "SELECT id_num FROM person WHERE source = 'after' ORDER BY id_num"
    ).fetchall()
    assert ids == [(10**12,), (10**12 + 1,)]


def test_a_missing_weight_column_is_refused(tmp_path, male_lines):
    k = _header(male_lines).index("weightkg")
    lines = [",".join(f for j, f in enumerate(line.split(",")) if j != k) for line in male_lines]
    with pytest.raises(AnsurImportError, match=":1: missing column weightkg"):
        read_ansur(_write(tmp_path, lines))


def test_optional_survey_columns_may_be_absent(tmp_path, male_lines):
    """A file in ANSUR format without the survey's subject fields still imports."""
    drop = {_header(male_lines).index(c) for c in ("branch", "dodrace", "span")}
    lines = [
        ",".join(f for j, f in enumerate(line.split(",")) if j not in drop) for line in male_lines
    ]
    batch = read_ansur(_write(tmp_path, lines))
    assert batch.attributes["branch"] == [None] * 30
    assert batch.attributes["component"][0] == "Regular Army"
    assert batch.measures is not None and math.isnan(batch.measures[0, 73])  # span


@pytest.mark.parametrize(
    ("value", "message"),
    [
        ("17\r5", ":2: not a CSV record"),  # a stray carriage return inside a line
        ("9" * 200_000, ":2: not a CSV record"),  # over csv's field size limit
    ],
)
def test_csv_level_faults_name_the_line(tmp_path, male_lines, value, message):
    path = _write(tmp_path, _with_value(male_lines[:3], 1, "stature", value))
    with pytest.raises(AnsurImportError, match=message):
        read_ansur(path)


def test_a_subject_id_in_superscript_digits_is_refused(tmp_path, male_lines):
    path = _write(tmp_path, _with_value(male_lines[:3], 1, "subjectid", "¹²"))
    with pytest.raises(AnsurImportError, match=":2: column subjectid"):
        read_ansur(path)


def test_a_subject_id_of_30000_digits_is_refused_cleanly(tmp_path, male_lines):
    # int() refuses strings over 4,300 digits with a ValueError of its own.
    path = _write(tmp_path, _with_value(male_lines[:3], 1, "subjectid", "9" * 30_000))
    with pytest.raises(AnsurImportError, match=r":2: column subjectid.*30000 characters"):
        read_ansur(path)
