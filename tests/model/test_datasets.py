"""Every number of the shipped data sets against the report's appendices."""

from __future__ import annotations

import re

import numpy as np
import pytest
from _paths import DATASETS

from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS

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


CORRECTED = re.compile(
    r'^C corrected: (MALE|FEMALE) "([^"]+)" ([xyz]) ((?:\d+th/?)+): printed ([-\d. ]+?) in\b ?(.*)$'
)


def corrections(name: str) -> list[tuple[str, str, int, list[int], list[float], str]]:
    """The "C corrected:" lines of a data set file: (gender, row label, axis,
    percentile columns, the values the report printed, the evidence)."""
    lines = (DATASETS / name).read_text().splitlines()
    out = []
    for i, line in enumerate(lines):
        match = CORRECTED.match(line)
        if match:
            gender, label, axis, percentiles, printed, evidence = match.groups()
            for more in lines[i + 1 :]:
                if not more.startswith("C   "):
                    break
                evidence = (evidence + " " + more[1:].strip()).strip()
            columns = [(5, 50, 95).index(int(p[:-2])) for p in percentiles.split("/")]
            values = [float(v) for v in printed.split()]
            assert len(values) == len(columns), line
            out.append((gender.lower(), label, "xyz".index(axis), columns, values, evidence))
    return out


def test_joint_limits_match_appendices_h_and_i(report_lines):
    """Every number as printed, except the cells the file lists as corrected;
    with those put back the file is appendices H and I exactly."""
    male = appendix_rows(report_lines, "H Male Joint Limits", "I Female Joint Limits")
    female = appendix_rows(report_lines, "I Female Joint Limits", "J JLIMITS.H")
    assert len(male) == 40 and len(female) == 40
    shipped = file_rows("jntlmt.dat")
    labels = [label for _, label in male]
    fixed = corrections("jntlmt.dat")
    assert {(g, label, axis) for g, label, axis, *_ in fixed} == {
        ("male", "Neck ll", 1),
        ("male", "R shoulder ll", 2),
        ("male", "L shoulder ll", 2),
    }
    for gender, label, axis, columns, printed, evidence in fixed:
        row = shipped[gender][labels.index(label)]
        for column, value in zip(columns, printed):
            cell = 3 * axis + column
            # a corrected cell differs from the print only in its sign
            assert row[cell] == -value != value
            row[cell] = value
        assert "appendix" in evidence
    assert shipped["male"] == [r[0] for r in male]
    assert shipped["female"] == [r[0] for r in female]


def _appendix_f_limits(report_lines) -> dict[str, float]:
    start = report_lines.index("F Sample Figure Description File, MALE50.FIG")
    stop = report_lines.index("G Joint motion variable list")
    out = {}
    for line in report_lines[start:stop]:
        match = re.match(r"(\w+_[xyz]_[ul]limit) = (-?[\d.]+)deg;", line.strip())
        if match:
            out[match[1]] = float(match[2])
    return out


def test_each_correction_has_the_reports_evidence(report_lines):
    """The corrected sign is the one appendix J or F prints for the same cell,
    or the one the female table (appendix I) gives the same row."""
    from sass_tui.model.files.figfile import joint_limit_variable
    from sass_tui.model.names import ROWS

    jlimits = appendix_rows(report_lines, "J JLIMITS.H", "K Mass Values")
    appendix_f = _appendix_f_limits(report_lines)
    shipped = file_rows("jntlmt.dat")
    labels = [row.label.lower() for row in ROWS[JOINT_LIMITS]]
    for gender, label, axis, columns, _, _ in corrections("jntlmt.dat"):
        index = labels.index(label.lower())
        row = shipped[gender][index]
        variable = joint_limit_variable(ROWS[JOINT_LIMITS][index].name, "xyz"[axis])
        if 2 in columns:  # appendix F is the 95th percentile figure
            assert appendix_f[variable] == row[3 * axis + 2]
        for column in columns:
            cell = 3 * axis + column
            j_row = jlimits[index if gender == "male" else 40 + index][0]
            female = shipped["female"][index]
            assert j_row[cell] == row[cell] or (female[cell] * row[cell] > 0), (label, cell)


def test_appendix_f_differences_are_documented(report_lines):
    """Appendix F's limits that are not appendix H's 95th percentile are named
    in docs/model.md (they are not corrected: no second source agrees)."""
    from sass_tui.model.files.figfile import joint_limit_variable
    from sass_tui.model.names import ROWS

    docs = (DATASETS.parent / "docs" / "model.md").read_text()
    male = file_rows("jntlmt.dat")["male"]
    differ = []
    for i, row in enumerate(ROWS[JOINT_LIMITS]):
        for axis in range(3):
            variable = joint_limit_variable(row.name, "xyz"[axis])
            printed = _appendix_f_limits(report_lines).get(variable)
            if printed is not None and printed != male[i][3 * axis + 2]:
                differ.append((variable, printed))
    assert len(differ) == 10
    for variable, printed in differ:
        assert variable in docs and f"{printed:g}" in docs, variable


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
    from sass_tui.model.body.figure import Figure

    assert Figure.default().mass == pytest.approx(82.2, abs=1e-9)
