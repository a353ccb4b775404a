"""Every reader bounds what it reads: a file over its kind's plausible size
is refused by its size before a byte is read (model/files/paths.py
`regular_file(largest=...)`), and a message quotes at most a few dozen
characters of a bad value (model/text.py `quoted`).  A 1 GB sparse file
given to `sass fig --girth` ran 61 s, peaked at 13.6 GB and printed a 4 GB
message; `sass population --ids` of 100 MB took 40 s and 7.7 GB."""

from __future__ import annotations

import os

import pytest
from _built_once import copy_database_file

from sass_tui.cli import main
from sass_tui.db.populations.population import IdListError, parse_id_list
from sass_tui.model.files.paths import (
    LARGEST_ID_LIST,
    LARGEST_PEOPLE_TABLE,
    LARGEST_TABLE_FILE,
    LARGEST_TEXT_FILE,
)
from sass_tui.model.files.popfile import PopulationFileError, parse_population_text
from sass_tui.model.names import GIRTH
from sass_tui.model.strength.strength import StrengthFileError, parse_strength_text
from sass_tui.model.text import QUOTE_LIMIT, quoted

# A message's plausible length: a path, a line number, what was expected.
LONGEST_MESSAGE = 400


def sparse(path, size: int) -> str:
    """A file of `size` zero bytes that takes no disk (a hole)."""
    with open(path, "wb") as handle:
        handle.truncate(size)
    return str(path)


@pytest.mark.parametrize(
    ("argv", "largest", "kind"),
    [
        (["fig", "-o", "{out}", "--girth", "{f}"], LARGEST_TEXT_FILE, "a population file"),
        (["fig", "-o", "{out}", "--cmass", "{f}"], LARGEST_TEXT_FILE, "a population file"),
        (["fig", "-o", "{out}", "--strength", "{f}"], LARGEST_TEXT_FILE, "a strength file"),
        (["fig", "-o", "{out}", "--jntlmt", "{f}"], LARGEST_TEXT_FILE, "a population file"),
        (
            ["population", "--db", "{db}", "--ids", "{f}", "-o", "{out}"],
            LARGEST_ID_LIST,
            "a list of person ids",
        ),
        pytest.param(
            ["predict", "--db", "{db}", "--gender", "male", "--input", "{f}", "--output", "{out}"],
            LARGEST_PEOPLE_TABLE,
            "a table of people",
            marks=pytest.mark.slow,  # the second, smaller file is read and fitted
        ),
        (
            [
                "db",
                "import-flat",
                "--db",
                "{db}",
                "--person",
                "{f}",
                "--girth",
                "{f}",
                "--jntlmt",
                "{f}",
                "--cmass",
                "{f}",
            ],
            LARGEST_TABLE_FILE,
            "a flat file",
        ),  # fmt: skip
    ],
    ids=["girth", "cmass", "strength", "jntlmt", "ids", "predict", "import-flat"],
)
def test_a_file_over_its_kinds_size_is_refused_unread(
    argv, largest, kind, default_db_file, tmp_path, capsys
):
    huge = sparse(tmp_path / "huge.dat", largest + 1)
    out = tmp_path / "out.x"
    db = tmp_path / "s.db"
    copy_database_file(default_db_file, db)
    before = db.read_bytes()
    assert main([a.format(f=huge, out=out, db=db) for a in argv]) == 2
    said = capsys.readouterr().err
    assert f"is too large for {kind}" in said and huge in said, said
    assert len(said) < LONGEST_MESSAGE and "Traceback" not in said
    assert not out.exists() and db.read_bytes() == before
    # a smaller file is read (and refused for what it holds, not for its size)
    os.truncate(huge, 2**16)
    main([a.format(f=huge, out=out, db=db) for a in argv])
    assert "too large" not in capsys.readouterr().err


def test_the_fig_reader_refuses_a_huge_fig_by_its_size(tmp_path):
    from sass_tui.model.files.fig_reader import read_fig
    from sass_tui.model.files.paths import PathError

    with pytest.raises(PathError, match=r"is too large for a \.fig file \(at most 4\.0 MiB\)"):
        read_fig(sparse(tmp_path / "huge.fig", LARGEST_TEXT_FILE + 1))


# One value of 3,000,000 characters, inside the size limits: the message
# quotes its first QUOTE_LIMIT characters and says how long it is.
HUGE = 3_000_000


@pytest.mark.parametrize(
    ("parse", "text", "error"),
    [
        (
            lambda t: parse_population_text(t, GIRTH, "g.dat"),
            "T " + "x" * HUGE,
            PopulationFileError,
        ),
        (
            lambda t: parse_population_text(t, GIRTH, "g.dat"),
            "T MALE\n" + "x" * HUGE + " 1 2 3 4 5 6 7 8",
            PopulationFileError,
        ),
        (
            lambda t: parse_population_text(t, GIRTH, "g.dat"),
            "T MALE\n" + "9" * HUGE + " 1 2 3 4 5 6 7 8 /* head */",
            PopulationFileError,
        ),
        (
            lambda t: parse_population_text(t, GIRTH, "g.dat"),
            "T MALE\n1 2 3 4 5 6 7 8 9 /* head */ " + "y" * HUGE,
            PopulationFileError,
        ),
        (lambda t: parse_strength_text(t, "s.dat"), "P x\nG " + "x" * HUGE, StrengthFileError),
        (
            lambda t: parse_strength_text(t, "s.dat"),
            "P x\nG MALE\nL " + "\x1b" * HUGE,
            StrengthFileError,
        ),
        (
            lambda t: parse_strength_text(t, "s.dat"),
            "P t\nG MALE\nL RIGHT\n1 45 0 90 0 0 0 17 50 /* " + "shoulder" * (HUGE // 8) + " */",
            StrengthFileError,
        ),
        (lambda t: parse_id_list(t, "ids.txt"), "1\n" + "9" * HUGE, IdListError),
        (lambda t: parse_id_list(t, "ids.txt"), "1\n" + "\x1b[2J" * HUGE, IdListError),
    ],
    ids=[
        "T-line",
        "token",
        "digits",
        "after-comment",
        "G-line",
        "L-line",
        "motion",
        "id",
        "id-escapes",
    ],
)
def test_a_message_quotes_a_few_dozen_characters_of_a_huge_value(parse, text, error):
    with pytest.raises(error) as raised:
        parse(text)
    message = str(raised.value)
    assert len(message) < LONGEST_MESSAGE, message[:LONGEST_MESSAGE]
    assert "characters)" in message and "\x1b" not in message


def test_quoted_cuts_and_counts():
    assert quoted("abc") == "'abc'"
    long = "z" * (QUOTE_LIMIT + 1)
    assert quoted(long) == f"'{'z' * QUOTE_LIMIT}…' ({QUOTE_LIMIT + 1} characters)"
    assert quoted("\x1b" * 100, escape=True).startswith("'^[^[")


@pytest.mark.parametrize("column", ["stature", "Gender"])
def test_an_ansur_field_of_100000_characters_is_quoted_short(column, tmp_path, capsys):
    """csv lets a field grow to 131,072 characters: the message quotes 40."""
    import gzip

    from sass_tui.model import datasets

    shipped = datasets.directory() / "ansur2" / "ANSUR_II_MALE_Public.csv.gz"
    header, first = gzip.open(shipped, "rt", encoding="latin-1").read().split("\n")[:2]
    cells = first.split(",")
    cells[header.split(",").index(column)] = "x" * 100_000
    survey = tmp_path / "survey.csv"
    survey.write_text(f"{header}\n{','.join(cells)}\n", encoding="latin-1")
    assert main(["db", "import-ansur", "--db", str(tmp_path / "new.db"), str(survey)]) == 2
    said = capsys.readouterr().err
    assert f"{survey}:2: column {column.lower()}" in said and "(100,000 characters)" in said
    assert len(said) < LONGEST_MESSAGE


def test_ids_on_standard_input_are_bounded_too(default_db_file, tmp_path, monkeypatch, capsys):
    """`--ids -` reads a pipe, which has no size to check first: it reads
    one character past the limit and stops there."""
    import io

    from sass_tui.model.files.paths import LARGEST_ID_LIST

    class Endless(io.TextIOBase):
        """A pipe that never ends (`yes 1 | sass population --ids -`)."""

        served = 0

        def read(self, size: int | None = -1) -> str:
            assert size is not None and size > 0, "an unbounded read of standard input"
            self.served += size
            return "1\n" * (size // 2) + "1" * (size % 2)

    endless = Endless()
    monkeypatch.setattr("sys.stdin", endless)
    db = tmp_path / "s.db"
    copy_database_file(default_db_file, db)
    out = tmp_path / "p.dat"
    assert main(["population", "--db", str(db), "--ids", "-", "-o", str(out)]) == 2
    said = capsys.readouterr().err
    assert "standard input: over 32.0 MiB, too large for a list of person ids" in said
    assert endless.served == LARGEST_ID_LIST + 1 and not out.exists()
