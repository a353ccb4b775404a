"""A population file and a strength file are read by one function
(model/files/paths.py `read_user_text`): a regular file only (a FIFO would block
forever), UTF-8 or else Latin-1, without a byte-order mark, and the same words
when one cannot be read."""

from __future__ import annotations

import os

import pytest

from sass_tui.model import datasets
from sass_tui.model.body.figure import Figure
from sass_tui.model.files.popfile import PopulationFileError, read_population_file
from sass_tui.model.files.worksheet import read_worksheet, worksheet_text
from sass_tui.model.names import GIRTH
from sass_tui.model.session import Session
from sass_tui.model.strength.strength import StrengthFileError, read_strength_file


def read_girth(path):
    return read_population_file(path, GIRTH)


READERS = [(read_girth, PopulationFileError), (read_strength_file, StrengthFileError)]


@pytest.mark.parametrize(("read", "error"), READERS)
def test_what_cannot_be_read_is_refused_alike(tmp_path, read, error):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    with pytest.raises(error, match=f"^{fifo}: cannot read: not a regular file; give a data file$"):
        read(fifo)
    with pytest.raises(error, match=f"^{tmp_path}: cannot read: a directory; give a data file$"):
        read(tmp_path)
    missing = tmp_path / "missing.dat"
    with pytest.raises(error, match=f"^{missing}: cannot read: no such file$"):
        read(missing)


def test_a_latin_1_population_file_is_read_as_latin_1(tmp_path):
    shipped = datasets.path("girth.dat").read_bytes()
    path = tmp_path / "montreal.dat"
    path.write_bytes("C Équipe de Montréal\n".encode("latin-1") + shipped)
    assert read_girth(path).title == "Équipe de Montréal"


def test_a_latin_1_strength_file_is_read_as_latin_1(tmp_path):
    shipped = datasets.path("strength.dat").read_text(encoding="utf-8")
    path = tmp_path / "force.dat"
    lines = shipped.split("\n")
    title = next(k for k, line in enumerate(lines) if line.startswith("P"))
    lines[title] = "P Données de Montréal"
    path.write_bytes("\n".join(lines).encode("latin-1"))
    assert read_strength_file(path).title == "Données de Montréal"


BOM = "\ufeff".encode()  # what Notepad and Excel's "CSV UTF-8" put first


def test_a_byte_order_mark_is_not_part_of_the_file(tmp_path):
    """A byte-order mark was the first character of the first line: a job
    file's first column was '\\ufeffh', unknown; a worksheet or a posture file
    was no JSON."""
    girth = tmp_path / "girth.dat"
    girth.write_bytes(BOM + datasets.path("girth.dat").read_bytes())
    shipped = read_girth(datasets.path("girth.dat"))
    assert read_girth(girth).title == shipped.title
    strength = tmp_path / "strength.dat"
    strength.write_bytes(BOM + datasets.path("strength.dat").read_bytes())
    assert (
        read_strength_file(strength).title
        == read_strength_file(datasets.path("strength.dat")).title
    )
    sheet = tmp_path / "sheet.json"
    sheet.write_bytes(BOM + worksheet_text(Session(Figure.default("female"))).encode())
    assert read_worksheet(sheet).figure.gender == "female"
