"""Small holes a reliability pass found, each refused with one line saying
where: a negative segment size in a girth file (it went on into the .fig as
`botheadx = -25.00cm`), a loop of symbolic links (a raw `[Errno 40]`), a
.fig token of megabytes (quoted whole)."""

from __future__ import annotations

import os

import pytest

from sass_tui.cli import main
from sass_tui.model import datasets
from sass_tui.model.files.fig_reader import parse_fig
from sass_tui.model.files.figfile import FigParseError
from sass_tui.model.files.popfile import PopulationFileError, parse_population_text
from sass_tui.model.names import GIRTH


def _girth_with_first_value(value: str) -> str:
    lines = datasets.path("girth.dat").read_text().split("\n")
    for i, line in enumerate(lines):
        if line.strip() and line[0] not in "CT":
            lines[i] = " ".join([value, *line.split()[1:]])
            return "\n".join(lines)
    raise AssertionError("no data row")


def test_a_negative_segment_size_is_refused_at_its_line():
    with pytest.raises(PopulationFileError) as refused:
        parse_population_text(_girth_with_first_value("-25"), GIRTH, "g.dat")
    assert str(refused.value).startswith("g.dat:13: Bottom Head x: -25/")
    assert "a segment size cannot be negative" in str(refused.value)
    # 999 (no value) is no negative size
    parse_population_text(_girth_with_first_value("999"), GIRTH, "g.dat")


def test_sass_fig_writes_no_negative_girth(tmp_path, capsys):
    girth = tmp_path / "g.dat"
    girth.write_text(_girth_with_first_value("-25"))
    out = tmp_path / "x.fig"
    assert main(["fig", "--girth", str(girth), "-o", str(out)]) == 2
    assert "cannot be negative" in capsys.readouterr().err
    assert not out.exists()


def test_a_loop_of_links_is_named_without_an_errno(tmp_path, capsys):
    loop = tmp_path / "loop.dat"
    os.symlink(loop, loop)
    assert main(["fig", "--girth", str(loop), "-o", str(tmp_path / "x.fig")]) == 2
    said = capsys.readouterr().err
    assert "Too many levels of symbolic links" in said and str(loop) in said
    assert "[Errno" not in said and said.count("\n") == 1


def test_a_huge_fig_token_is_quoted_short():
    with pytest.raises(FigParseError) as refused:
        parse_fig("botheadx = 1 cm " + "y" * 1_000_000 + ";")
    assert len(str(refused.value)) < 300 and "characters)" in str(refused.value)
