"""The table of ANSUR II derivations against appendices B and C in
docs/data-sources.md is what scripts/ansur_derivations.py writes,
and the choices it documents are the ones the import makes."""

from __future__ import annotations

import csv
import math
import runpy

import numpy as np
import pytest
from _paths import ROOT

from sass_tui.db.people.ansur import read_ansur
from sass_tui.model.names import GIRTH, ROWS


@pytest.fixture(scope="module")
def script(ansur_dir):
    return runpy.run_path(str(ROOT / "scripts" / "ansur_derivations.py"))


def test_the_docs_table_is_the_scripts_output(script, ansur_dir):
    docs = (ROOT / "docs" / "data-sources.md").read_text()
    assert script["table"](ansur_dir) in docs


def test_lower_torso_depth_and_thigh_as_documented(ansur_dir):
    """Computed here from the CSV, independently of _derive."""
    path = ansur_dir / "ANSUR_II_FEMALE_Public.csv"
    with path.open(encoding="latin-1", newline="") as handle:
        rows = [{k.lower(): v for k, v in r.items()} for r in csv.DictReader(handle)]
    girth = read_ansur(path).girth
    index = {row.name: i for i, row in enumerate(ROWS[GIRTH])}
    for person, row in zip(girth[:50], rows[:50]):
        assert person[index["lower_torso"], 0] == pytest.approx(
            float(row["abdominalextensiondepthsitting"]) / 10
        )
        assert person[index["right_upper_leg"], 0] == pytest.approx(
            float(row["thighclearance"]) / 10
        )
        mid = (float(row["thighcircumference"]) + float(row["lowerthighcircumference"])) / 2
        assert person[index["left_upper_leg"], 1] == pytest.approx(mid / 10 / math.pi)
        assert person[index["right_foot"], 2] == pytest.approx(
            float(row["lateralmalleolusheight"]) / 10
        )


def test_no_center_of_mass_cell_is_derived(ansur_dir):
    """ANSUR II measured no centres of mass: the import stores none, so the
    table has no centre-of-mass rows to compare."""
    batch = read_ansur(ansur_dir / "ANSUR_II_MALE_Public.csv")
    assert batch.center_of_mass is None and batch.joint_limits is None
    assert not np.isnan(batch.girth[:, :, :3]).all()
