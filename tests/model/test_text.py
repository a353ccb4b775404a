"""Control characters never reach a terminal (a person named
"\\x1b[2J\\x1b]0;pwned\\x07" once cleared the screen when listed)."""

from __future__ import annotations

from _built_once import copy_database_file
from hypothesis import given
from hypothesis import strategies as st

from sass_tui.cli import main
from sass_tui.model.text import (
    FORMULA_STARTS,
    may_start_a_formula,
    printable,
    spreadsheet_text,
)

HOSTILE = "\x1b[2J\x1b]0;pwned\x07"


def test_escape_sequences_are_made_visible():
    assert printable(HOSTILE) == "^[[2J^[]0;pwned^G"
    assert printable("a\tb\nc\rd\x00") == "a^Ib^Jc^Md^@"
    assert printable("\x7f\x9b2J") == "^?\\x9b2J"
    assert printable("abc\u202edef") == "abc\\u202edef"
    assert printable("lone \ud800") == "lone \\ud800"


def test_ordinary_text_is_unchanged():
    for text in ("ANSUR II M 10037", "Zoë Ångström", "名前", "García-Núñez", ""):
        assert printable(text) == text
    assert printable(None) == ""
    assert printable(12) == "12"


@given(st.text())
def test_no_control_character_survives(text):
    shown = printable(text)
    assert not any(ord(c) < 0x20 or 0x7F <= ord(c) <= 0x9F for c in shown)
    assert not any(0xD800 <= ord(c) <= 0xDFFF for c in shown)
    shown.encode("utf-8")  # printable on any UTF-8 terminal


def test_sass_query_table_shows_a_hostile_name_inertly(shipped_db_file, tmp_path, capsys):
    from sass_tui.db.engine.schema import connect

    db = tmp_path / "s.db"
    copy_database_file(shipped_db_file, db)
    conn = connect(db)
    with conn:
        first = conn.execute("SELECT MIN(id_num) FROM person").fetchone()[0]
        conn.execute(
            "UPDATE person SET name = ?, source = ? WHERE id_num = ?",
            (HOSTILE, "file\x1b]0;title\x07.dat", first),
        )
    conn.close()
    assert main(["--db", str(db), "query", "mass > 0"]) == 0
    out = capsys.readouterr().out
    assert "\x1b" not in out and "\x07" not in out
    assert "^[[2J^[]0;pwned^G" in out
    assert "file^[]0;title^G.dat" in out


def test_error_messages_show_no_control_characters(tmp_path, capsys):
    bad = tmp_path / "s.dat"
    bad.write_text("P x\nG MALE\nL RIGHT\n1 2 3 4 5 6 7 8 50 /* \x1b[2Jshoulder */\n")
    assert main(["strength", "--file", str(bad), "shoulder_abduction"]) == 2
    err = capsys.readouterr().err
    assert "\x1b" not in err and "error:" in err


def _line_field_by_field(row: tuple) -> str:
    """A `sass query` table line made as before the fast path: every text
    through printable(), every number formatted on its own."""
    id_num, name, gender, mass, stature, hand, age, source = row
    return (
        f"{id_num:>7}  {printable(name):<20.20} {printable(gender):<6} "
        f"{'' if mass is None else f'{mass:.1f}':>7} "
        f"{'' if stature is None else f'{stature:.1f}':>10} {printable(hand):<6} "
        f"{'' if age is None else f'{age:.0f}':>4}  {printable(source)}\n"
    )


_TEXT = st.text(max_size=25) | st.sampled_from(["male", "female", "right", "ansur2", HOSTILE])
_NUMBER = st.floats(allow_nan=False, allow_infinity=False, width=32) | st.integers(-999, 9999)


@given(
    st.lists(
        st.tuples(
            st.integers(1, 10**9),
            _TEXT | st.none() | st.integers(),
            _TEXT,
            _NUMBER | st.none(),
            _NUMBER | st.none(),
            _TEXT | st.none(),
            _NUMBER | st.none(),
            _TEXT,
        ),
        max_size=6,
    )
)
def test_the_query_table_is_the_same_made_at_once(rows):
    # For speed, the table is made with one format per row and checked for
    # control characters once; it must be what printable() per field made.
    from sass_tui.cli.query import _table_lines

    assert _table_lines(rows) == "".join(_line_field_by_field(row) for row in rows)


def test_a_chunk_is_printable_lines_only_without_controls_or_extra_newlines():
    from sass_tui.model.text import is_printable_lines

    assert is_printable_lines("a b\nZoë\n", 2)
    assert not is_printable_lines("a\nb\nc\n", 2)  # a newline inside a value
    assert not is_printable_lines(f"a{HOSTILE}\nb\n", 2)
    assert not is_printable_lines("a\u202e\n", 1)


def test_no_control_character_is_isprintable():
    # printable() skips its regex for text that str.isprintable(): that is
    # right only if every character it escapes is not isprintable().
    from sass_tui.model.text import _control

    escaped = [c for c in map(chr, range(0x110000)) if _control().match(c)]
    assert len(escaped) > 2000  # C0, DEL, C1, bidi controls, surrogates
    assert not any(c.isprintable() for c in escaped)


@given(st.text())
def test_a_csv_cell_never_starts_a_formula_and_keeps_its_text(text):
    cell = spreadsheet_text(text)
    assert cell[:1] not in tuple(FORMULA_STARTS)
    assert cell == text or cell == "'" + text
    assert cell == text or may_start_a_formula([text])  # the chunk check never misses one


def test_a_formula_anywhere_in_a_chunk_is_found():
    assert may_start_a_formula(["ANSUR II", "=HYPERLINK(1)"])
    assert not may_start_a_formula(["ANSUR II", "a=b", "A-1", ""])
