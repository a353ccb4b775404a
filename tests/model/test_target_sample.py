"""The target sample's CSV reader (sass_tui/model/population/target_sample.py): units in
the header or on the values, and every error naming file:line and column."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from sass_tui.model.errors import SassError
from sass_tui.model.files.sample_file import read_sample
from sass_tui.model.population.target_sample import SampleError

FIELDS = ["stature", "mass"]
# unit spelling -> factor to the canonical unit (cm or kg), written out here
# rather than taken from sass's registry.
LENGTHS = {"cm": 1.0, "mm": 0.1, "in": 2.54, "inches": 2.54, "m": 100.0}
MASSES = {"kg": 1.0, "lb": 0.45359237, "g": 0.001}


def test_units_in_the_header_and_on_the_values():
    text = "id,stature[in],mass [lb],measure.sittingheight\n1,64,150,85\n2,170 cm,70 kg,\n"
    sample = read_sample(text, [*FIELDS, "measure.sittingheight"], "s.csv")
    assert sample.rows == 2 and sample.incomplete == 1  # row 2 lacks a sitting height
    assert sample.matrix[0].tolist() == pytest.approx([64 * 2.54, 150 * 0.45359237, 85])
    both = read_sample(text, FIELDS, "s.csv")
    assert both.matrix[1].tolist() == pytest.approx([170, 70])


def test_survey_names_are_the_persons_stature_and_mass():
    sample = read_sample("measure.stature,measure.weightkg\n160,60\n", FIELDS, "s.csv")
    assert sample.matrix.tolist() == [[160.0, 60.0]]


@pytest.mark.parametrize(
    ("text", "where", "says"),
    [
        ("id,height,weight\n1,160,60\n", "s.csv:1", "no column for stature, mass"),
        ("stature[furlong],mass\n160,60\n", "s.csv:1: column 1 'stature[furlong]'", "unknown unit"),
        ("stature[kg],mass\n160,60\n", "s.csv:1: column 1", "length"),
        ("stature,mass\n160,60\n150 parsec,60\n", "s.csv:3: column 1 'stature'", "unknown unit"),
        ("stature,mass\n160,sixty\n", "s.csv:2: column 2 'mass'", "expected a number"),
        ("stature,mass\n160,60,1\n", "s.csv:2", "expected 2 fields, found 3"),
        ("stature,mass\n-160,60\n", "s.csv:2: column 1", "greater than 0"),
        ("measure.sitingheight,stature,mass\n1,2,3\n", "s.csv:1: column 1", "sittingheight"),
        ("stature,stature[in],mass\n1,2,3\n", "s.csv:1: column 2", "repeats column 1"),
        ("", "s.csv:1", "empty"),
        # said "no column for stature, mass", or with --gender "no gender column"
        ("stature;mass\n160;60\n", "s.csv:1", "the cells are separated by ';', not commas"),
        (
            "stature,mass\n1e6,60\n",
            "s.csv:2: column 1 'stature'",
            "stature 1e+06 cm is not a human one",
        ),
        ("stature,mass\n1.9,60\n", "s.csv:2: column 1 'stature'", "expected 50-300 cm"),
        ("stature,mass\n160,6e4\n", "s.csv:2: column 2 'mass'", "mass 60000 kg is not a human one"),
    ],
)
def test_bad_samples_say_where(text, where, says):
    with pytest.raises(SampleError) as error:
        read_sample(text, FIELDS, "s.csv")
    assert str(error.value).startswith(where)
    assert says in str(error.value)


@given(
    st.lists(
        st.tuples(st.floats(100, 220), st.floats(30, 200), st.booleans(), st.booleans()),
        min_size=1,
        max_size=20,
    ),
    st.sampled_from(sorted(LENGTHS)),
    st.sampled_from(sorted(MASSES)),
)
def test_values_come_back_in_canonical_units(rows, length_unit, mass_unit):
    """Each value written in the header's unit or with its own comes back in cm and kg."""
    lines = [f"stature[{length_unit}],note,mass[{mass_unit}]"]
    for stature, mass, own_length, own_mass in rows:
        s = (
            f"{stature / LENGTHS['cm']:.6f} cm"
            if own_length
            else f"{stature / LENGTHS[length_unit]!r}"
        )
        m = f"{mass:.6f}kg" if own_mass else f"{mass / MASSES[mass_unit]!r}"
        lines.append(f'{s},"a, b",{m}')
    sample = read_sample("\n".join(lines) + "\n", FIELDS, "s.csv")
    expected = np.array([[s, m] for s, m, _a, _b in rows])
    assert np.allclose(sample.matrix, expected, rtol=1e-6)


def _read_or_refused(text: str) -> None:
    try:
        sample = read_sample(text, FIELDS, "s.csv")
    except SassError as exc:
        assert str(exc).startswith("s.csv:")
    else:
        assert all(math.isfinite(v) and v > 0 for v in sample.matrix.ravel())


@given(st.text(max_size=300))
def test_any_text_is_read_or_refused_with_a_place(text):
    _read_or_refused(text)


TOKENS = ["stature", "mass", "[cm]", "[in]", "[", "]", ",", "\n", "1", "170", " lb", '"', "-", "e9"]


@given(st.lists(st.sampled_from(TOKENS), max_size=60))
def test_csv_like_text_is_read_or_refused_with_a_place(parts):
    _read_or_refused("".join(parts))


MEASURED = ("measure.buttockcircumference", "measure.waistcircumference")
HIP_CELLS = ["", "100", "39 in", "1000 mm", "-3", "0", "abc", "1e400", "nan", '"', "38.5in"]


@given(st.lists(st.sampled_from(HIP_CELLS), min_size=1, max_size=8))
def test_a_measured_column_is_read_or_refused_with_a_place(cells):
    """The optional measured columns a virtual population keeps (NHANES's
    name hip_circumference; model/files/sample_file.py's NHANES_COLUMNS): a
    row is never left out for lacking one; a value is read in cm or the
    row's line and column are named."""
    lines = ["stature,mass,hip_circumference[cm]"] + [f"160,60,{c}" for c in cells]
    text = "\n".join(lines) + "\n"
    try:
        sample = read_sample(text, FIELDS, "s.csv", optional=MEASURED)
    except SassError as exc:
        assert str(exc).startswith("s.csv:")
        return
    assert sample.optional_fields == ("measure.buttockcircumference",)
    assert sample.optional is not None and sample.optional.shape == (len(sample.matrix), 1)
    hips = sample.optional[:, 0]
    assert all(math.isnan(v) or (math.isfinite(v) and v > 0) for v in hips)
    if "39 in" in cells and len(sample.matrix) == len(cells):
        assert hips[cells.index("39 in")] == pytest.approx(99.06)


def test_a_measured_column_is_passed_over_unless_asked():
    text = "stature,mass,hip_circumference[in]\n160,60,40\n161,61,\n"
    assert read_sample(text, FIELDS, "s.csv").optional is None
    kept = read_sample(text, FIELDS, "s.csv", optional=MEASURED)
    assert kept.optional is not None
    assert kept.optional[0, 0] == pytest.approx(101.6) and math.isnan(kept.optional[1, 0])
    assert len(kept.matrix) == 2
