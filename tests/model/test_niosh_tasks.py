"""A multi-task job file for `sass niosh --tasks`: CSV and JSON read alike,
the form chosen by the first h with a unit, and any bad row refused with
its file:line (hypothesis: any text gives tasks or one such message); and
the options' own readers (lengths, loads, angles, frequencies, couplings of
`sass niosh`, loads of `sass handling`): any text, a value or a message."""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.cli.handling import parse_load
from sass_tui.model.errors import SassError
from sass_tui.model.strength import niosh_input
from sass_tui.model.strength.niosh import NioshError
from sass_tui.model.strength.niosh_tasks import read_tasks

CSV = """name,load,load_max,h,v,d,a,f,coupling,dest_h,dest_v
# a comment line
top,8kg,10kg,30cm,100cm,40cm,0,2,good,,
bottom,8,,45,20,,30,1,fair,40,80
"""


def test_csv_and_json_read_alike():
    of, tasks = read_tasks(CSV, "job.csv", "long")
    assert of.name == "metric" and [name for name, _ in tasks] == ["top", "bottom"]
    bottom = tasks[1][1]
    assert bottom.d == 60  # |80 - 20|, from dest_v
    assert bottom.destination is not None and bottom.destination.a == 30
    assert tasks[0][1].load_max == 10
    rows = [
        {"name": "top", "load": "8kg", "load_max": "10kg", "h": "30cm", "v": "100cm", "d": 40,
         "a": 0, "f": 2, "coupling": "good"},
        {"name": "bottom", "load": 8, "h": 45, "v": 20, "a": 30, "f": 1, "dest_h": 40,
         "dest_v": 80},
    ]  # fmt: skip
    of2, tasks2 = read_tasks(json.dumps({"tasks": rows}, indent=1), "job.json", "long")
    assert of2 == of and tasks2 == tasks


def test_inches_choose_the_us_form():
    of, tasks = read_tasks("h,v,d,f,load\n16in,30,20,1,40\n", "job.csv", "short")
    assert of.name == "us" and of.load_constant == 51
    assert tasks[0][1].load == 40 and tasks[0][1].origin.v == 30


@pytest.mark.parametrize(
    ("text", "file", "where", "words"),
    [
        ("h,v,f,load\n30,70,2\n", "j.csv", "j.csv:2", "3 cells, the header has 4"),
        ("h,v,f,load\n30,seventy,2,8\n", "j.csv", "j.csv:2", "expected a number"),
        ("h,v,f\n30,70,2\n", "j.csv", "j.csv:2", "no load"),
        # the header's line, where the column is (it said j.csv:2)
        ("h,v,f,load,x\n30,70,2,8,1\n", "j.csv", "j.csv:1", "unknown column 'x'"),
        ("# a job\nh,v,f,load,x\n", "j.csv", "j.csv:2", "unknown column 'x'"),
        ("h;v;f;load\n30;70;2;8\n", "j.csv", "j.csv:1", "the cells are separated by ';'"),
        ("h\tv\tf\tload\n30\t70\t2\t8\n", "j.csv", "j.csv:1", "separated by tabs"),
        ("h,v,f,load,coupling\n30,70,2,8,great\n", "j.csv", "j.csv:2", "expected good"),
        ("h,v,f,load,load_max\n30,70,2,8,5\n", "j.csv", "j.csv:2", "load_max is below"),
        (
            '[{"h": 30, "v": 70, "f": 2, "load": 8},\n {"h": "3x", "v": 70}]',
            "j.json",
            "j.json:2",
            "unknown unit",
        ),
        ('[{"h": 30, "v": 70, "f": 2, "load": [8]}]', "j.json", "j.json:1", "not a number"),
        ("{not json", "j.json", "j.json:1", "not JSON"),
        ("", "j.csv", "j.csv", "no header"),
        # given twice: one of the two would be left unread, or a result named ambiguously
        ("h,v,f,load,h\n30,70,2,8,40\n", "j.csv", "j.csv:1", "'h' is given twice (cells 1 and 5)"),
        (
            "name,h,v,d,f,load\nlift,30,70,40,2,8\n# a comment\nlift,40,70,40,2,8\n",
            "j.csv",
            "j.csv:4",
            "task name 'lift' is given twice (first on line 2)",
        ),
        (
            "name,h,v,d,f,load\n,30,70,40,2,8\ntask 1,40,70,40,2,8\n",
            "j.csv",
            "j.csv:3",
            "task name 'task 1' is given twice",
        ),
        (
            '[{"h": 30, "v": 70, "f": 2, "load": 8, "h": 40}]',
            "j.json",
            "j.json:1",
            "'h' is given twice",
        ),
        (
            '[{"h": 30, "v": 70, "f": 2, "load": 8},\n {"h": 30, "v": 70, "f": 2, "LOAD": 9, "load": 8}]',
            "j.json",
            "j.json:2",
            "task 2: 'load' is given twice",
        ),
        ('{"tasks": [], "tasks": [{"h": 30}]}', "j.json", "j.json", '"tasks" is given twice'),
    ],
)
def test_bad_rows_name_file_and_line(text, file, where, words):
    with pytest.raises(NioshError) as caught:
        read_tasks(text, file, "long")
    assert caught.value.where == where
    assert words in str(caught.value) and str(caught.value).startswith(f"{where}: ")


CELL = st.one_of(
    st.text(max_size=8),
    st.floats(allow_nan=True, allow_infinity=True).map(str),
    st.sampled_from(["30cm", "12in", "8kg", "2", "good", "-5", "1e400", "", "fair"]),
)


@settings(max_examples=60, deadline=None)
@given(
    header=st.lists(
        st.sampled_from(["name", "load", "load_max", "h", "v", "d", "a", "f", "coupling",
                         "dest_h", "dest_v", "dest_a", "dest_coupling", "extra"]),
        min_size=1,
        max_size=8,
        unique=True,
    ),
    rows=st.lists(st.lists(CELL, min_size=1, max_size=8), max_size=4),
    as_json=st.booleans(),
)  # fmt: skip
def test_any_job_file_gives_tasks_or_one_message(header, rows, as_json):
    if as_json:
        text = json.dumps([dict(zip(header, row, strict=False)) for row in rows], indent=1)
        file = "job.json"
    else:
        text = "\n".join(",".join(f'"{c}"' for c in line) for line in [header, *rows])
        file = "job.csv"
    try:
        of, tasks = read_tasks(text, file, "moderate")
    except SassError as exc:
        assert exc.where is not None and str(exc).startswith(exc.where)
        return
    assert of.name in ("metric", "us") and 1 <= len(tasks) <= len(rows)
    for _, lift in tasks:
        assert lift.f >= 0 and lift.d >= 0 and lift.load is not None


@settings(max_examples=80, deadline=None)
@given(text=st.one_of(st.text(max_size=12), CELL))
def test_any_option_text_is_a_value_or_a_message(text):
    for read in (
        lambda t: niosh_input.form_of([t]),
        lambda t: niosh_input.length(t, niosh_input.form_of([])),
        lambda t: niosh_input.load(t, niosh_input.form_of([])),
        niosh_input.angle,
        niosh_input.frequency,
        niosh_input.coupling,
        lambda t: parse_load(t, "push"),
        lambda t: parse_load(t, "lift"),
    ):
        try:
            value = read(text)
        except SassError as exc:
            assert str(exc)
        else:
            assert value is not None
