"""The worksheet file (model/files/worksheet.py): saved and opened again, the same
sheet cell for cell; a file that is not one is refused whole, naming the
field."""

from __future__ import annotations

import functools
import json
import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sass_tui.model.body.figure import Figure
from sass_tui.model.errors import SassError
from sass_tui.model.files.worksheet import (
    WorksheetError,
    apply_strength,
    parse_worksheet,
    read_worksheet,
    read_worksheet_and_strength,
    worksheet_text,
)
from sass_tui.model.names import AXES_OF, CENTER_OF_MASS, GIRTH, GROUPS, JOINT_LIMITS, row_index
from sass_tui.model.session import Session
from sass_tui.model.strength.strength import StrengthSheet, read_strength_file

ARM = row_index(GIRTH, "right_upper_arm")


def same(a: float, b: float) -> bool:
    return (math.isnan(a) and math.isnan(b)) or a == b


def assert_same_sheet(saved: Figure, opened: Figure) -> None:
    """Every group's values and percentiles cell by cell, the global data and
    the statistics each cell is measured against."""
    for name in (
        "gender", "figure_type", "population", "person", "strength_type", "handedness",
        "mass", "mass_percentile", "stature", "stature_percentile", "motion_speed",
        "training_level", "fatigue_level", "hand_set_lengths", "landmarks",
    ):  # fmt: skip
        a, b = getattr(saved, name), getattr(opened, name)
        assert same(a, b) if isinstance(a, float) else a == b, name
    for group in GROUPS:
        mine, theirs = saved.groups[group], opened.groups[group]
        assert (mine.percentile, mine.unit, mine.loaded) == (
            theirs.percentile,
            theirs.unit,
            theirs.loaded,
        ), group
        assert mine.source.title == theirs.source.title and mine.source.path == theirs.source.path
        for row in range(len(mine.rows)):
            for axis in range(AXES_OF[group]):
                a, b = mine.cell(row, axis), theirs.cell(row, axis)
                assert same(a[0], b[0]) and same(a[1], b[1]), (group, row, axis, a, b)
                for gender in ("male", "female"):
                    stats = zip(
                        mine.cell_stats(gender, row, axis),
                        theirs.cell_stats(gender, row, axis),
                        strict=True,
                    )
                    assert all(same(x, y) for x, y in stats), (group, gender, row, axis)


def edited_session() -> Session:
    figure = Figure.default("female")
    session = Session(figure, StrengthSheet.default(figure))
    session.set_value(GIRTH, ARM, 2, 31.25)
    session.set_cell_percentile(GIRTH, 0, 0, 12.5)
    session.set_group_percentile(JOINT_LIMITS, 95)
    session.set_value(JOINT_LIMITS, 0, 1, 33.0)
    session.set_cell_percentile(CENTER_OF_MASS, 2, 0, 80)
    session.set_mass(61.5)
    session.set_stature_percentile(5)
    session.set_strength_parameter("training_level", 2)
    session.set_strength_parameter("handedness", "left")
    session.set_unit(GIRTH, "in")
    session.set_angle(0, 0, 30)
    session.strength_sheet.percentile = 95.0
    return session


def open_into(text: str, name: str = "w.json") -> Session:
    worksheet = parse_worksheet(text, name)
    session = Session(Figure.default())
    strength = None if worksheet.strength is None else read_strength_file(worksheet.strength.path)
    session.open_worksheet(
        worksheet.figure,
        strength,
        lambda sheet: apply_strength(worksheet.strength, sheet),
    )
    return session


def test_saved_and_opened_is_the_same_sheet_cell_for_cell():
    session = edited_session()
    opened = open_into(worksheet_text(session))
    assert_same_sheet(session.figure, opened.figure)
    saved_sheet, opened_sheet = session.strength_sheet, opened.strength_sheet
    assert (opened_sheet.angles == saved_sheet.angles).all()
    assert opened_sheet.angles[0, 0] == 30
    assert (opened_sheet.side, opened_sheet.unit, opened_sheet.percentile) == (
        saved_sheet.side,
        saved_sheet.unit,
        95.0,
    )
    assert opened_sheet.data.path == saved_sheet.data.path
    # The strength the sheet computes is the same, so are its rows.
    assert [r.value for r in opened_sheet.rows()] == [r.value for r in saved_sheet.rows()]
    assert not opened.unsaved_edits() and not opened.can_undo()


def test_the_file_is_readable_json_with_sass_version_and_the_population_source():
    text = worksheet_text(edited_session())
    document = json.loads(text)
    assert document["format"] == "sass worksheet" and document["sass_version"]
    assert document["groups"]["girth"]["statistics"]["file"].endswith("girth.dat")
    assert document["groups"]["girth"]["values"][ARM][2] == 31.25
    assert document["figure"]["gender"] == "female"
    # A row of numbers is one line, as in a population file.
    assert any(line.strip().startswith("[") and line.count(",") == 2 for line in text.splitlines())


def test_a_saved_file_opens_from_disk(tmp_path):
    session = edited_session()
    path = tmp_path / "day.sass.json"
    path.write_text(worksheet_text(session))
    assert_same_sheet(session.figure, read_worksheet(path).figure)


def test_edits_since_the_last_save_are_what_is_unsaved():
    session = edited_session()
    assert session.unsaved_edits()
    session.mark_saved()
    assert not session.unsaved_edits()
    session.set_mass(70)
    assert session.unsaved_edits()
    session.undo()
    assert not session.unsaved_edits()  # back to what the file holds
    session.undo()
    assert session.unsaved_edits()


@pytest.mark.parametrize(
    ("change", "expected"),
    [
        (lambda d: d.update(format="other"), 'not a sass worksheet (no "format"'),
        (lambda d: d["figure"].update(gender="cat"), 'figure.gender: expected "female" or "male"'),
        (
            lambda d: d["groups"]["girth"]["values"].pop(),
            "groups.girth.values: expected a list of",
        ),
        (
            lambda d: d["groups"]["joint_limits"]["values"][3].__setitem__(1, "x"),
            'groups.joint_limits.values[3][1]: expected a number, not "x"',
        ),
        (lambda d: d["figure"].update(mass=True), "figure.mass: expected a number, not true"),
        (lambda d: d["strength"].update(side="up"), "strength.side: expected"),
        (lambda d: d["strength"]["angles"].pop(), "strength.angles: expected a list of 14"),
    ],
)
def test_a_bad_field_is_named_and_nothing_opens(change, expected):
    document = json.loads(worksheet_text(edited_session()))
    change(document)
    with pytest.raises(WorksheetError) as caught:
        parse_worksheet(json.dumps(document), "day.json")
    assert str(caught.value).startswith("day.json: ")
    assert expected in str(caught.value)
    assert "\n" not in str(caught.value)


def test_text_that_is_not_json_is_refused_with_its_line():
    with pytest.raises(WorksheetError, match=r"^day.json:3: not a sass worksheet"):
        parse_worksheet('{\n "format":\n  oops', "day.json")


json_values = st.recursive(
    st.none() | st.booleans() | st.floats(allow_nan=False) | st.integers() | st.text(max_size=5),
    lambda children: (
        st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=8), children, max_size=4)
    ),
    max_leaves=20,
)


@pytest.mark.slow
@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(path=st.lists(st.sampled_from(["figure", "groups", "girth", "values", 0, 1, "strength",
                                      "angles", "statistics", "by_gender", "male"]),
                     min_size=1, max_size=5),
       value=json_values)  # fmt: skip
def test_any_damage_is_a_worksheet_error_or_opens(path, value):
    """Whatever one field is replaced with, the parser opens the file or
    refuses it with a WorksheetError; nothing else escapes."""
    document = json.loads(saved_text())
    node = document
    for key in path[:-1]:
        try:
            node = node[key]
        except (KeyError, IndexError, TypeError):
            return
    try:
        node[path[-1]] = value
    except (IndexError, TypeError):
        return
    try:
        parse_worksheet(json.dumps(document), "w.json")
    except SassError as exc:
        assert isinstance(exc, WorksheetError) and str(exc).startswith("w.json")


@functools.cache
def saved_text() -> str:
    return worksheet_text(edited_session())


@pytest.mark.parametrize(
    ("change", "expected"),
    [
        (lambda d: d["figure"].update(stature=1e308), "figure.stature: stature 1e+308 cm is not a human one"),
        (lambda d: d["figure"].update(stature=-170), "figure.stature: stature -170 cm is not a human one"),
        (lambda d: d["figure"].update(mass=0), "figure.mass: mass 0 kg is not a human one"),
        (lambda d: d["figure"].update(stature_percentile=500), "figure.stature_percentile: expected a percentile"),
        (lambda d: d["figure"].update(motion_speed=-1), "figure.motion_speed: expected a number of at least 0"),
        (lambda d: d.update(format_version=True), "format_version True: this sass opens version 1"),
        (lambda d: d.update(format_version=1.0), "format_version 1.0: this sass opens version 1"),
        (lambda d: d["figure"]["landmarks"].update(stature=1e6), "figure.landmarks.stature: expected a number 0-300 cm"),
        (lambda d: d["groups"]["girth"]["values"][ARM].__setitem__(2, 1e9),
         f"groups.girth.values[{ARM}][2]: expected a number of at most 300 in size"),
        (lambda d: d["groups"]["girth"]["percentile"].__class__ and d["groups"]["girth"].update(percentile=100),
         "groups.girth.percentile: expected a percentile between 0 and 100"),
        (lambda d: d["global_statistics"]["by_gender"]["male"][0][0].__setitem__(2, 250.0)
         or d["global_statistics"]["by_gender"]["male"][1][0].__setitem__(1, 5e3),
         "global_statistics.by_gender.male[1]: mass 5000 kg is not a human one"),
        (lambda d: d["global_statistics"]["by_gender"]["male"][1][0].__setitem__(1, 0),
         "global_statistics.by_gender.male[1]: mass 0 kg is not a human one"),
        (lambda d: d["strength"].update(percentile=-3), "strength.percentile: expected a percentile"),
        (lambda d: d["strength"].update(non_dominant_factor=9), "strength.non_dominant_factor: expected a number 0-2"),
    ],
)  # fmt: skip
def test_every_number_is_checked_as_a_typed_one_is(change, expected):
    """A worksheet is what engineers hand each other: its numbers are checked
    as typed ones are (a stature of 1e308 drew a ruler of 11 GB)."""
    document = json.loads(saved_text())
    change(document)
    with pytest.raises(WorksheetError) as caught:
        parse_worksheet(json.dumps(document), "day.json")
    assert str(caught.value).startswith("day.json: ")
    assert expected in str(caught.value)


@pytest.mark.parametrize(
    ("swap", "expected"),
    [
        ('"stature": NaN', "figure.stature: expected a finite number, not NaN"),
        ('"stature": Infinity', "figure.stature: expected a finite number, not Infinity"),
        ('"stature": 1e400', "figure.stature: expected a finite number"),
        ('"stature": 1' + "0" * 1000, "figure.stature: expected a finite number, not 1000"),
        ('"stature": 1' + "0" * 5000, "not a sass worksheet (JSON: Exceeds the limit"),
        (
            '"stature": ' + "[" * 100_000 + "]" * 100_000,
            "not a sass worksheet (JSON: nested too deep)",
        ),
    ],
)
def test_numbers_json_allows_but_no_figure_has_are_refused(swap, expected):
    text = saved_text()
    stature = json.dumps(json.loads(text)["figure"]["stature"])
    changed = text.replace(f'"stature": {stature}', swap, 1)
    assert changed != text
    with pytest.raises(WorksheetError) as caught:
        parse_worksheet(changed, "day.json")
    assert str(caught.value).startswith("day.json")
    assert expected in str(caught.value)
    assert len(str(caught.value)) < 200


@pytest.mark.parametrize(
    ("named", "refused"),
    [
        ("/etc/hostname", "give a name inside"),
        ("../../etc/hostname", "'..' is refused"),
        ("strength.dat", None),
        ("{workdir}/strength.dat", None),
    ],
)
def test_a_served_worksheet_reads_only_files_inside_the_workdir(tmp_path, named, refused):
    """A worksheet handed to a served session named /etc/shadow as its
    strength file, and its first word was shown to the web user."""
    workdir = tmp_path / "work"
    workdir.mkdir()
    shipped = read_strength_file()
    (workdir / "strength.dat").write_text(open(shipped.path, encoding="utf-8").read())
    document = json.loads(saved_text())
    document["strength"]["file"] = named.format(workdir=workdir)
    sheet = workdir / "w.json"
    sheet.write_text(json.dumps(document))
    _, strength, unread = read_worksheet_and_strength(sheet, workdir)
    if refused is None:
        assert unread is None and strength is not None
    else:
        assert strength is None and refused in str(unread) and str(workdir) in str(unread)
