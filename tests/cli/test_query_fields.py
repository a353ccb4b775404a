"""`sass query --fields`: every field the compiler takes, with its unit and
what it is; the units checked by pint against a value each field holds."""

from __future__ import annotations

import csv
import json

import pint
import pytest

from sass_tui.cli import main
from sass_tui.db.query.query import compile_query, field_names
from sass_tui.model.measures import MEASURES

UNITS = pint.UnitRegistry()
# A unit of the dimension each stored unit must have (pint's own reading of its name).
DIMENSIONS = {"cm": "metre", "kg": "gram", "deg": "radian", "deg/s": "radian / s", "N·m": "joule"}


def listed(capsys, *argv: str) -> list[dict[str, str]]:
    assert main(["query", "--fields", "--format", "csv", *argv]) == 0
    return list(csv.DictReader(capsys.readouterr().out.splitlines()))


def test_every_field_the_compiler_takes_is_listed_once(capsys):
    rows = listed(capsys)
    assert [r["field"] for r in rows] == [name for name, _ in field_names()]
    measures = [r for r in rows if r["field"].startswith("measure.")]
    assert len(measures) == len(MEASURES) == 93
    assert all(r["description"] for r in rows)


def test_buttock_circumference_is_listed_with_its_unit(capsys):
    assert main(["query", "--fields"]) == 0
    out = capsys.readouterr().out
    line = next(x for x in out.splitlines() if x.startswith("measure.buttockcircumference "))
    assert line.split()[1] == "cm"
    assert "buttock circumference" in line
    assert out.splitlines()[-1] == f"{len(field_names())} fields"


def test_each_unit_is_the_one_a_query_converts_from(capsys):
    """A value typed in the listed unit is stored unchanged, and pint agrees
    on the unit's dimension: the list names the stored unit, not a guess."""
    for row in listed(capsys):
        name, unit = row["field"], row["unit"]
        if unit in ("word", "text", "-"):
            continue
        pint_unit = UNITS.Unit(unit.replace("·", "*"))
        assert pint_unit.dimensionality == UNITS.Unit(DIMENSIONS[unit]).dimensionality, name
        compiled = compile_query(f"{name} > 12.5 {unit} AND source = ansur2")
        assert compiled.params[0] == pytest.approx(12.5), name


def test_word_and_text_fields_say_what_they_take(capsys):
    rows = {r["field"]: r for r in listed(capsys)}
    assert rows["gender"]["unit"] == "word" and "male, female" in rows["gender"]["description"]
    assert rows["branch"]["unit"] == "text"
    assert rows["age"]["unit"] == "-"
    assert "real people only" in rows["source"]["description"]
    compile_query("branch = 'Combat Arms' AND gender = female AND age > 30")


def test_json_lists_the_same_fields(capsys):
    assert main(["query", "--fields", "--format", "json"]) == 0
    fields = json.loads(capsys.readouterr().out)["fields"]
    assert [f["field"] for f in fields] == [name for name, _ in field_names()]
    assert fields[1] == {"field": "mass", "unit": "kg", "description": fields[1]["description"]}


def test_no_query_and_no_fields_says_what_to_give(capsys):
    assert main(["query"]) != 0
    err = capsys.readouterr().err
    assert "give a QUERY" in err and "--fields" in err
    assert len(err.strip().splitlines()) == 1
