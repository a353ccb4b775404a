"""The population file reader: format errors are refused whole, oddities warned."""

from __future__ import annotations

import numpy as np
import pytest
from _paths import DATASETS

from sass_tui.model.body.figure import Figure
from sass_tui.model.files.popfile import (
    PopulationFileError,
    parse_population_text,
    read_population_file,
    render_population_file,
)
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GLOBAL, JOINT_LIMITS

GIRTH_TEXT = (DATASETS / "girth.dat").read_text()


def _line_of(text: str, needle: str) -> int:
    return next(i for i, ln in enumerate(text.splitlines(), 1) if needle in ln)


def test_title_sections_and_rows():
    data = read_population_file(DATASETS / "girth.dat", GIRTH)
    assert data.title == "NASA Crewmember Trainees"
    assert set(data.sections) == {"male", "female"}
    assert data.stats("male").shape == (25, 3, 3)
    # right upper arm length (z) 5/50/95 from appendix B
    assert list(data.stats("male")[4, 2]) == [33.7, 36.6, 39.4]


def test_999_is_no_value():
    data = read_population_file(DATASETS / "jntlmt.dat", JOINT_LIMITS)
    elbow_ul = data.stats("male")[10]
    assert np.isnan(elbow_ul[0]).all() and np.isnan(elbow_ul[2]).all()
    assert list(elbow_ul[1]) == [140.5, 149.75, 159.0]


def test_report_inconsistencies_are_warnings_with_file_and_line():
    data = read_population_file(DATASETS / "jntlmt.dat", JOINT_LIMITS)
    text = (DATASETS / "jntlmt.dat").read_text()
    neck_ll = _line_of(text, "/* Neck ll */")
    # corrected in the shipped file (docs/model.md); the report's print warns
    assert not any(f":{neck_ll}:" in w for w in data.warnings)
    printed = text.replace("-84.2 -103.0", "-84.2  103.0", 1)
    as_printed = parse_population_text(printed, JOINT_LIMITS, "h.dat")
    assert any(
        w.startswith(f"h.dat:{neck_ll}: Neck ll y") and "sign" in w for w in as_printed.warnings
    )
    hip = _line_of(text, "/* R hip ll */")
    assert any(f":{hip}: R Hip ll z: 50th value -23" in w for w in data.warnings)
    girth = read_population_file(DATASETS / "girth.dat", GIRTH)
    assert any("Eye Location' given again" in w for w in girth.warnings)
    assert any("T FEMALE has 27 rows; expected 25" in w for w in girth.warnings)


def test_decreasing_rows_are_not_suspicious():
    data = read_population_file(DATASETS / "jntlmt.dat", JOINT_LIMITS)
    text = (DATASETS / "jntlmt.dat").read_text()
    wrist_ll = _line_of(text, "/* R wrist ll */")
    assert not any(f":{wrist_ll}:" in w for w in data.warnings)


def test_commas_or_blanks_and_positional_rows():
    rows = "\n".join(" ".join(["1", "2", "3"] * 3) + f" /* row {i} */" for i in range(21))
    data = parse_population_text("C Mine\nT FEMALE\n" + rows, CENTER_OF_MASS, "mine.dat")
    assert data.title == "Mine" and data.has("female") and not data.has("male")
    assert any("unknown row label 'row 0'" in w for w in data.warnings)
    commas = "C t\nT MALE\n" + "\n".join("1.0, 2.0, 3.0, 1,2,3, 4 5 6 /* x */" for _ in range(21))
    assert parse_population_text(commas, CENTER_OF_MASS).stats("male")[0, 2, 2] == 6.0


BAD_INPUTS = [
    (
        "truncated",
        GIRTH_TEXT[: GIRTH_TEXT.index("r Lower Leg") + 5],
        "girth.dat:{}: comment '/*' is not closed",
    ),
    (
        "eight numbers",
        GIRTH_TEXT.replace(
            "  11.3   12.3   13.3   11.3   12.3   13.3    7.7",
            "  11.3   12.3   13.3   11.3   12.3   13.3",
            1,
        ),
        "girth.dat:{}: 8 numbers; expected 9",
    ),
    (
        "text in a number",
        GIRTH_TEXT.replace("21.8", "2l.8", 1),
        "girth.dat:{}: value 1 is '2l.8'; expected a number",
    ),
    (
        "unknown gender",
        GIRTH_TEXT.replace("T FEMALE", "T ALIEN"),
        "girth.dat:{}: expected 'T MALE' or 'T FEMALE', found 'T ALIEN'",
    ),
    (
        "data before a section",
        "C title\n 1 2 3 4 5 6 7 8 9 /* neck */\n",
        "girth.dat:2: data before 'T MALE'",
    ),
    (
        "missing rows",
        GIRTH_TEXT[
            : GIRTH_TEXT.rfind(
                "\n", 0, GIRTH_TEXT.index("/* r Foot */", GIRTH_TEXT.index("T FEMALE"))
            )
            + 1
        ],
        "girth.dat:{}: T FEMALE ends without",
    ),
    ("empty", "", "girth.dat:1: the file is empty"),
]


@pytest.mark.parametrize("label,text,message", BAD_INPUTS, ids=[b[0] for b in BAD_INPUTS])
def test_malformed_files_are_refused_with_file_and_line(tmp_path, label, text, message):
    path = tmp_path / "girth.dat"
    path.write_text(text)
    bad_line = {
        "truncated": len(text.splitlines()),
        "eight numbers": _line_of(text, "/* Neck */") if "/* Neck */" in text else 0,
        "text in a number": _line_of(text, "2l.8") if "2l.8" in text else 0,
        "unknown gender": _line_of(text, "T ALIEN") if "T ALIEN" in text else 0,
        "missing rows": len(text.splitlines()),
    }.get(label)
    expected = message.format(bad_line)
    with pytest.raises(PopulationFileError) as info:
        read_population_file(path, GIRTH)
    assert expected in str(info.value)
    assert str(info.value).startswith(str(path))


def test_a_refused_file_leaves_the_figure_as_it_was(tmp_path):
    figure = Figure.default()
    before = figure.groups[GIRTH].values.copy()
    path = tmp_path / "bad.dat"
    path.write_text(GIRTH_TEXT.replace("21.8", "abc", 1))
    with pytest.raises(PopulationFileError):
        figure.load_group(GIRTH, read_population_file(path, GIRTH))
    np.testing.assert_array_equal(figure.groups[GIRTH].values, before)
    assert figure.population == "NASA Crewmember Trainees"


def test_missing_file_is_a_clear_error(tmp_path):
    with pytest.raises(PopulationFileError, match="cannot read"):
        read_population_file(tmp_path / "nope.dat", GIRTH)


@pytest.mark.parametrize(
    ("row", "message"),
    [
        ("164.8 175.5 1e6 /* stature */\n62.6 82.2 107.6 /* mass */",
         "g.dat:3: male stature 1e+06 cm is not a human one; expected 50-300 cm"),
        ("1.6 1.75 1.87 /* stature */\n62.6 82.2 107.6 /* mass */",
         "g.dat:3: male stature 1.6 cm is not a human one"),
        ("164.8 175.5 187 /* stature */\n62.6 82.2 -5 /* mass */",
         "g.dat:4: male mass -5 kg is not a human one; expected 0-500 kg"),
    ],
)  # fmt: skip
def test_a_global_file_s_statures_and_masses_are_human_ones(row, message):
    """A global file's stature of 1e6 cm went on into the exported body's
    mesh (8.7 GB); it is refused as a typed one is, at its line."""
    with pytest.raises(PopulationFileError) as caught:
        parse_population_text(f"C g\nT MALE\n{row}\n", GLOBAL, "g.dat")
    assert str(caught.value).startswith(message)


@pytest.mark.parametrize("breaks", ["\n", "\r\n", "\r", "\u2028"])
def test_a_title_of_two_lines_is_written_as_one_comment(breaks):
    """The default title is the query, which may be typed on two lines: the
    second was written as a row of values, and the file did not read back."""
    data = parse_population_text(GIRTH_TEXT, GIRTH, "girth.dat")
    data.title = f"Population of stature > 150 cm{breaks}AND mass > 50 kg"
    again = parse_population_text(render_population_file(data), GIRTH, "again.dat")
    assert again.title == "Population of stature > 150 cm AND mass > 50 kg"
    for gender in data.sections:
        np.testing.assert_array_equal(again.stats(gender), data.stats(gender))
