"""Non-finite and absurd numbers are refused where they enter:
population and strength files, the figure's strength parameters, the .fig
reader and writer, the query language, JSON."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from _built_once import copy_database_file

from sass_tui.cli import main
from sass_tui.model.body.figure import Figure, FigureError
from sass_tui.model.files.fig_reader import parse_fig
from sass_tui.model.files.figfile import FigParseError, FigValueError, render_fig
from sass_tui.model.files.popfile import PopulationFileError, parse_population_text
from sass_tui.model.names import GIRTH
from sass_tui.model.strength.strength import (
    StrengthData,
    StrengthError,
    StrengthFileError,
    StrengthModel,
    default_path,
    parse_strength_text,
)

ROOT = Path(__file__).resolve().parents[2]
STRENGTH_TEXT = default_path().read_text(encoding="utf-8")
FIRST_ROW = "    30.0   45.0    0.0    90.0     0.0    0.0    0.0     17.98   50.0"


def _line_of(text: str, fragment: str) -> int:
    return next(i for i, line in enumerate(text.splitlines(), 1) if fragment in line)


@pytest.mark.parametrize(
    "replacement,message",
    [
        ("1e309", "value 8: '1e309' is not a usable number"),
        ("1e200", "value 8: '1e200' is not a usable number"),
        ("20000", r"value 8 \(strength\) is 20000 ft-lb; expected at most 10000"),
        ("-1e400", "value 8: '-1e400' is not a usable number"),
    ],
)
def test_a_huge_strength_value_is_refused_at_its_line(replacement, message):
    text = STRENGTH_TEXT.replace(FIRST_ROW, FIRST_ROW.replace("17.98", replacement), 1)
    line = _line_of(STRENGTH_TEXT, FIRST_ROW)
    with pytest.raises(StrengthFileError, match=f"s.dat:{line}: {message}"):
        parse_strength_text(text, "s.dat")


def test_a_huge_angle_is_refused_at_its_line():
    text = STRENGTH_TEXT.replace(FIRST_ROW, FIRST_ROW.replace("45.0", "400", 1), 1)
    line = _line_of(STRENGTH_TEXT, FIRST_ROW)
    with pytest.raises(
        StrengthFileError, match=rf"s.dat:{line}: value 2 \(Shoulder y\) is 400 deg"
    ):
        parse_strength_text(text, "s.dat")


def _cli(tmp_path, *argv):
    return subprocess.run(
        [sys.executable, "-m", "sass_tui", *argv],
        capture_output=True,
        text=True,
        timeout=60,
        cwd=tmp_path,
    )


@pytest.mark.parametrize("value", ["1e309", "1e200"])
def test_sass_strength_with_a_huge_value_ends_with_a_message(tmp_path, value):
    # Before: 1e309 made lstsq run forever, 1e200 raised LinAlgError and LAPACK
    # printed "DLASCL" lines on stdout.
    bad = tmp_path / "s.dat"
    bad.write_text(STRENGTH_TEXT.replace(FIRST_ROW, FIRST_ROW.replace("17.98", value), 1))
    done = _cli(tmp_path, "strength", "--file", str(bad), "shoulder_abduction", "shoulder_x=40")
    assert done.returncode == 2
    assert done.stdout == ""
    assert "error:" in done.stderr and "Traceback" not in done.stderr


def test_the_fit_refuses_numbers_it_cannot_fit_without_printing(capfd):
    data = parse_strength_text(STRENGTH_TEXT, "s.dat")
    section = data.sections[("male", "right")]
    section.values[0] = np.inf  # past the parser, e.g. data built in code
    with pytest.raises(StrengthError, match="too large to fit"):
        StrengthModel(section)
    section.values[0] = np.nan
    with pytest.raises(StrengthError, match="too large to fit"):
        StrengthModel(section)
    assert capfd.readouterr().out == ""
    assert isinstance(data, StrengthData)


POPULATION_ROW = "21.80"


@pytest.mark.parametrize("value", ["1e400", "-1e309", "1e16"])
def test_population_files_refuse_huge_numbers(value):
    text = (ROOT / "datasets" / "girth.dat").read_text(encoding="utf-8")
    line = next(i for i, ln in enumerate(text.splitlines(), 1) if ln.startswith(" ") and "/*" in ln)
    lines = text.splitlines()
    first = lines[line - 1].split()
    lines[line - 1] = lines[line - 1].replace(first[0], value, 1)
    with pytest.raises(PopulationFileError, match=f"g.dat:{line}: value 1: '{value}'"):
        parse_population_text("\n".join(lines), GIRTH, "g.dat")


@pytest.mark.parametrize("name", ["training_level", "fatigue_level", "motion_speed"])
@pytest.mark.parametrize("value", [float("nan"), float("inf"), "nan"])
def test_strength_parameters_refuse_non_finite(name, value):
    figure = Figure.default()
    before = getattr(figure, name)
    with pytest.raises(FigureError, match="must be a number"):
        figure.set_strength_parameter(name, value)
    assert getattr(figure, name) == before


def test_sass_strength_training_level_nan_is_refused(capsys):
    assert main(["strength", "shoulder_abduction", "--training-level", "nan"]) == 2
    assert "training level must be a number" in capsys.readouterr().err


def test_the_fig_writer_never_writes_a_non_finite_number(tmp_path):
    figure = Figure.default()
    figure.groups[GIRTH].values[0, 0] = np.inf  # as a stored inf would arrive
    with pytest.raises(FigValueError, match="botheadx is inf cm"):
        render_fig(figure)


def test_the_fig_reader_refuses_a_non_finite_number():
    with pytest.raises(FigParseError, match=r"f.fig:1:12: botheadx = 1e400: too large"):
        parse_fig('botheadx = 1e400cm;\nfigure ["body.fig"] ("skinny.a");\n', "f.fig")


def test_sass_fig_in_huge_units_is_refused(tmp_path, capsys):
    assert main(["fig", "-o", str(tmp_path / "x.fig"), "--stature", "1e400 cm"]) == 2
    assert "not a usable number" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_json_output_refuses_a_stored_infinity(shipped_db_file, tmp_path, capsys):
    from sass_tui.db.engine.schema import connect

    db = tmp_path / "s.db"
    copy_database_file(shipped_db_file, db)
    conn = connect(db)
    with conn:
        conn.execute(
            "UPDATE person SET mass = 1e309 WHERE id_num = "
            "(SELECT MIN(id_num) FROM person WHERE source = 'ansur2')"  # a real person
        )
    conn.close()
    assert main(["--db", str(db), "query", "--format", "json", "mass > 0"]) == 2
    captured = capsys.readouterr()
    assert "Infinity" not in captured.out
    assert "mass is inf in the database" in captured.err
    assert main(["--db", str(db), "query", "--format", "json", "mass < 1000"]) == 0
    json.loads(capsys.readouterr().out)  # strict JSON parses
