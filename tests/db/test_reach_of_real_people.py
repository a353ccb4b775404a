"""`sass reach --person`: a real person's measured reach (read here from the
independent ANSUR II copy) and the model's from their other measurements,
the same on both engines (tests/db/conftest.py)."""

from __future__ import annotations

import csv
import json

import pytest

from sass_tui.cli import main
from tests._paths import ANSUR


def test_a_real_person_s_reach_on_either_engine(shared_target, capsys):
    if not ANSUR.is_dir():
        pytest.skip(f"the independent ANSUR II copy is not at {ANSUR}")
    with open(ANSUR / "ANSUR_II_MALE_Public.csv", encoding="latin-1", newline="") as handle:
        row = {k.lower(): v for k, v in next(csv.DictReader(handle)).items()}
    name = f"ANSUR II M {row['subjectid']}"
    assert main(["reach", "--db", shared_target, "--person", name, "--format", "json"]) == 0
    got = json.loads(capsys.readouterr().out)
    assert got["figure"] == name
    for measure in ("thumbtipreach", "overheadfingertipreachsitting", "span"):
        assert got[measure]["value"] == pytest.approx(float(row[measure]) / 10, abs=0.05)
        assert got[measure]["source"] == "measured"
