"""Every cell of sass's RULA and REBA look-up tables against the tables as
published, typed here by hand (not read from datasets/rula.json or reba.json),
and fed through the scoring code (model/strength/rula.py `grand_score`,
reba.py `scores`) so the look-up itself is checked, not only the file.

Sources typed from:
- REBA: the "REBA Employee Assessment Worksheet" (the worksheet that prints
  Hignett & McAtamney 2000, Applied Ergonomics 31:201-205, Tables A, B and C):
  Table A (trunk 1-5 x neck 1-3 x legs 1-4), Table B (upper arm 1-6 x lower
  arm 1-2 x wrist 1-3), Table C (score A 1-12 x score B 1-12).  The text of
  Table C's last rows was legible only to score A 11, score B 1-7; those
  cells are checked and score A 12 is not.
- RULA: the "RULA Employee Assessment Worksheet" (McAtamney & Corlett 1993,
  Applied Ergonomics 24(2):91-99, Tables A and B as printed on it).  Table B
  rows neck 1-4 were legible and are checked.  Table A: the rows below were
  legible and are checked; the worksheet copy found prints other numbers for
  upper arm 1 / lower arm 3 and upper arm 2-4 than datasets/rula.json (which
  follows the paper's Table 1 as cited there), so those rows are not asserted
  here until the paper's own table is read (docs/task.md "RULA and REBA").

No published worked example (the papers' own figures, or the Handbook of
Human Factors and Ergonomics Methods ch. 8 examples) could be read in full
text; none is invented here.
"""

from __future__ import annotations

import pytest

from sass_tui.model.strength.reba import read_tables as read_reba_tables
from sass_tui.model.strength.reba import scores
from sass_tui.model.strength.rula import grand_score

# REBA Table A: [trunk][neck] -> legs 1..4
REBA_A = [
    [[1, 2, 3, 4], [1, 2, 3, 4], [3, 3, 5, 6]],
    [[2, 3, 4, 5], [3, 4, 5, 6], [4, 5, 6, 7]],
    [[2, 4, 5, 6], [4, 5, 6, 7], [5, 6, 7, 8]],
    [[3, 5, 6, 7], [5, 6, 7, 8], [6, 7, 8, 9]],
    [[4, 6, 7, 8], [6, 7, 8, 9], [7, 8, 9, 9]],
]
# REBA Table B: [upper arm][lower arm] -> wrist 1..3
REBA_B = [
    [[1, 2, 2], [1, 2, 3]],
    [[1, 2, 3], [2, 3, 4]],
    [[3, 4, 5], [4, 5, 5]],
    [[4, 5, 5], [5, 6, 7]],
    [[6, 7, 8], [7, 8, 8]],
    [[7, 8, 8], [8, 9, 9]],
]
# REBA Table C: score A (row) -> score B 1..12
REBA_C = [
    [1, 1, 1, 2, 3, 3, 4, 5, 6, 7, 7, 7],
    [1, 2, 2, 3, 4, 4, 5, 6, 6, 7, 7, 8],
    [2, 3, 3, 3, 4, 5, 6, 7, 7, 8, 8, 8],
    [3, 4, 4, 4, 5, 6, 7, 8, 8, 9, 9, 9],
    [4, 4, 4, 5, 6, 7, 8, 8, 9, 9, 9, 9],
    [6, 6, 6, 7, 8, 8, 9, 9, 10, 10, 10, 10],
    [7, 7, 7, 8, 9, 9, 9, 10, 10, 11, 11, 11],
    [8, 8, 8, 9, 10, 10, 10, 10, 10, 11, 11, 11],
    [9, 9, 9, 10, 10, 10, 11, 11, 11, 12, 12, 12],
    [10, 10, 10, 11, 11, 11, 11, 12, 12, 12, 12, 12],
    [11, 11, 11, 11, 12, 12, 12],  # score B 8-12 not legible in the copy read
]

# RULA Table A, legible rows: (upper arm, lower arm) -> wrist 1..4 x twist 1..2
RULA_A = {
    (1, 1): [1, 2, 2, 2, 2, 3, 3, 3],
    (1, 2): [2, 2, 2, 2, 3, 3, 3, 3],
    (5, 1): [5, 5, 5, 5, 5, 6, 6, 7],
    (5, 2): [5, 6, 6, 6, 6, 7, 7, 7],
    (5, 3): [6, 6, 6, 7, 7, 7, 7, 8],
    (6, 1): [7, 7, 7, 7, 7, 8, 8, 9],
    (6, 3): [9, 9, 9, 9, 9, 9, 9, 9],
}
# RULA Table B, legible rows: neck -> trunk 1..6 x legs 1..2
RULA_B = {
    1: [1, 3, 2, 3, 3, 4, 5, 5, 6, 6, 7, 7],
    2: [2, 3, 2, 3, 4, 5, 5, 5, 6, 7, 7, 7],
    3: [3, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 7],
    4: [5, 5, 5, 6, 6, 7, 7, 7, 7, 7, 8, 8],
}


@pytest.mark.parametrize("trunk", range(1, 6))
def test_reba_table_a_every_cell(trunk):
    for neck in range(1, 4):
        for legs in range(1, 5):
            a, _, _ = scores(trunk, neck, legs, 0, 1, 1, 1)
            assert a == REBA_A[trunk - 1][neck - 1][legs - 1], (trunk, neck, legs)


@pytest.mark.parametrize("upper", range(1, 7))
def test_reba_table_b_every_cell(upper):
    for lower in range(1, 3):
        for wrist in range(1, 4):
            _, b, _ = scores(1, 1, 1, 0, upper, lower, wrist)
            assert b == REBA_B[upper - 1][lower - 1][wrist - 1], (upper, lower, wrist)


def test_reba_table_c_every_legible_cell():
    table = read_reba_tables().c
    checked = 0
    for row, published in enumerate(REBA_C):
        for column, cell in enumerate(published):
            assert table[row][column] == cell, (row + 1, column + 1)
            checked += 1
    assert checked == 10 * 12 + 7


def test_reba_load_is_added_to_table_a_before_table_c():
    # trunk 3, neck 2, legs 2: Table A 5; load over 10 kg: +2 -> score A 7;
    # upper arm 3, lower arm 2, wrist 2: Table B 5; Table C (7, 5) = 9
    assert scores(3, 2, 2, 2, 3, 2, 2) == (7, 5, 9)


@pytest.mark.parametrize("where", sorted(RULA_A))
def test_rula_table_a_legible_rows(where):
    upper, lower = where
    for i, cell in enumerate(RULA_A[where]):
        wrist, twist = i // 2 + 1, i % 2 + 1
        a, _, _ = grand_score(upper, lower, wrist, twist, 1, 1, 1, 0, 0)
        assert a == cell, (upper, lower, wrist, twist)


@pytest.mark.parametrize("neck", sorted(RULA_B))
def test_rula_table_b_legible_rows(neck):
    for i, cell in enumerate(RULA_B[neck]):
        trunk, legs = i // 2 + 1, i % 2 + 1
        _, b, _ = grand_score(1, 1, 1, 1, neck, trunk, legs, 0, 0)
        assert b == cell, (neck, trunk, legs)
