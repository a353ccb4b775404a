"""Every number of the shipped data sets against the report's appendices."""

from __future__ import annotations

import re

import numpy as np
import pytest
from _paths import DATASETS

from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS
from sass_tui.model.popfile import read_population_file

ROW = re.compile(r"^\s*(-?[\d.]+(?:[,\s]+-?[\d.]+){8})[,\s]*/\*(.*?)\*/")


def appendix_rows(
    lines: list[str], start_heading: str, stop_heading: str
) -> list[tuple[list[float], str]]:
    """Rows of 9 numbers between two headings of the report (the appendix body)."""
    start = next(i for i, ln in enumerate(lines) if ln.strip() == start_heading)
    stop = next(i for i, ln in enumerate(lines) if i > start and ln.strip() == stop_heading)
    rows = []
    for line in lines[start:stop]:
        match = ROW.match(line)
        if match:
            numbers = [float(t) for t in re.split(r"[,\s]+", match.group(1).strip())]
            rows.append((numbers, match.group(2).strip()))
    return rows


def split_sections(rows, marker_count):
    return rows[:marker_count], rows[marker_count:]


def file_rows(name: str) -> dict[str, list[list[float]]]:
    """The data rows of a data set file, per T section, as printed (999 kept)."""
    sections: dict[str, list[list[float]]] = {}
    current = None
    for line in (DATASETS / name).read_text().splitlines():
        if line.startswith("T "):
            current = line[2:].strip().lower()
            sections[current] = []
        elif line.strip() and not line.startswith("C"):
            numbers = line.split("/*")[0].replace(",", " ").split()
            sections[current].append([float(t) for t in numbers])
    return sections


def test_girth_matches_appendices_b_and_c(report_lines):
    male = appendix_rows(report_lines, "B Male Girths", "C Female Girths")
    female = appendix_rows(report_lines, "C Female Girths", "D Figure definition file, BODY.FIG")
    assert len(male) == 25 and len(female) == 27
    shipped = file_rows("girth.dat")
    assert shipped["male"] == [r[0] for r in male]
    assert shipped["female"] == [r[0] for r in female]


def test_joint_limits_match_appendices_h_and_i(report_lines):
    male = appendix_rows(report_lines, "H Male Joint Limits", "I Female Joint Limits")
    female = appendix_rows(report_lines, "I Female Joint Limits", "J JLIMITS.H")
    assert len(male) == 40 and len(female) == 40
    shipped = file_rows("jntlmt.dat")
    assert shipped["male"] == [r[0] for r in male]
    assert shipped["female"] == [r[0] for r in female]
    # The report's own inconsistency is kept, not silently corrected.
    assert shipped["male"][1][5] == 103.0


def test_center_of_mass_matches_appendix_l2(report_lines):
    rows = appendix_rows(report_lines, "L.2 The Database", "M List of Psurfs – Skinnybody")
    assert len(rows) == 42
    shipped = file_rows("cmass.dat")
    assert shipped["male"] == [r[0] for r in rows[:21]]
    assert shipped["female"] == [r[0] for r in rows[21:]]


@pytest.mark.parametrize(
    "name,group",
    [("girth.dat", GIRTH), ("jntlmt.dat", JOINT_LIMITS), ("cmass.dat", CENTER_OF_MASS)],
)
def test_reader_holds_every_number(name, group):
    data = read_population_file(DATASETS / name, group)
    shipped = file_rows(name)
    for gender in ("male", "female"):
        stats = data.stats(gender).reshape(len(data.stats(gender)), 9)
        printed = np.array(shipped[gender][: len(stats)])
        if gender == "female" and group == GIRTH:
            # the third of appendix C's three 'eye location' rows is the one used
            printed = np.array(shipped[gender][:20] + shipped[gender][22:])
        printed[printed == 999] = np.nan
        np.testing.assert_array_equal(stats, printed)


def test_male_50th_mass_is_what_appendix_f_implies(report_lines):
    from sass_tui.model.figure import Figure

    assert Figure.default().mass == pytest.approx(82.2, abs=1e-9)
