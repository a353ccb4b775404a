"""A body section's shape from its width, depth and tape perimeter
(model/body/body_surface.py fit_section), checked against the perimeter the
section's own points give: the solver lands on the tape's reading, keeps the
measured width, and takes a handful of perimeters where bisection took 40."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from sass_tui.model.body import body_surface
from sass_tui.model.body.body_surface import AROUND, fit_section, perimeter


def test_a_circle_s_perimeter_is_its_polygon_s():
    # AROUND points on a circle of radius r: AROUND chords of 2 r sin(pi / AROUND)
    assert perimeter(0.1, 0.1, 2.0) == pytest.approx(AROUND * 0.2 * math.sin(math.pi / AROUND))


@given(
    width=st.floats(0.05, 0.45),
    depth_share=st.floats(0.4, 1.2),
    between=st.floats(0.0, 1.0),
)
def test_a_section_reaches_the_tape_s_perimeter(width, depth_share, between):
    depth = width * depth_share
    a, b = width / 2, depth / 2
    low, high = perimeter(a, b, 1.2), perimeter(a, b, 12.0)
    circumference = low + between * (high - low)
    fitted_a, fitted_b, n = fit_section(width, depth, circumference)
    assert (fitted_a, fitted_b) == (a, b)  # within reach: only the exponent moves
    assert perimeter(fitted_a, fitted_b, n) == pytest.approx(circumference, rel=1e-10)


@pytest.mark.parametrize(("true_b", "n"), [(0.05, 1.2), (0.2, 12.0)])
def test_a_perimeter_out_of_reach_moves_the_depth(true_b, n):
    # 30 cm wide, 20 cm deep, with the perimeter of a flatter diamond (10 cm
    # deep) or of a deeper box (40 cm): the depth gives way, the width is kept
    circumference = perimeter(0.15, true_b, n)
    fitted_a, fitted_b, fitted_n = fit_section(0.30, 0.20, circumference)
    assert (fitted_a, fitted_n) == (0.15, n)
    assert fitted_b == pytest.approx(true_b, rel=1e-9)


def test_the_solver_takes_few_perimeters(monkeypatch):
    calls = []
    measured = perimeter

    def counted(a: float, b: float, n: float) -> float:
        calls.append(n)
        return measured(a, b, n)

    monkeypatch.setattr(body_surface, "perimeter", counted)
    fit_section(0.30, 0.20, measured(0.15, 0.10, 3.3))
    assert len(calls) <= 16  # two for the range, then the solver's (bisection: 40)
