"""Every cell of sass's RULA and REBA look-up tables against the tables as
published, typed here by hand (not read from datasets/rula.json or reba.json),
and fed through the scoring code (model/strength/rula.py `grand_score`,
reba.py `scores`) so the look-up itself is checked, not only the file.

Sources typed from:
- REBA: the "REBA Employee Assessment Worksheet" (the worksheet that prints
  Hignett & McAtamney 2000, Applied Ergonomics 31:201-205, Tables A, B and C):
  Table A (trunk 1-5 x neck 1-3 x legs 1-4), Table B (upper arm 1-6 x lower
  arm 1-2 x wrist 1-3), Table C (score A 1-12 x score B 1-12).  The text of
  Table C's last rows was legible only to score A 11, score B 1-7; the rest
  of score A 11 and score A 12 (every cell 12) are typed from the open
  implementations that print the whole table and agree on it
  (rs9000/ergonomics, the PyPI package ergonomics-metrics, reba.py's
  Table C; qaz1996001/reba-tool's Table C).
- RULA: the "RULA Employee Assessment Worksheet" (McAtamney & Corlett 1993,
  Applied Ergonomics 24(2):91-99, Tables A and B as printed on it).  Table B
  rows neck 1-4 were legible and are checked.  Table A: the rows below were
  legible and are checked.
- RULA Table A's other rows and Table C: two versions of Table A are in
  print.  The one most tools use (the step-by-step RULA worksheet, and the
  open implementations swish1995/Skeleton_analyzer's rula_calculator.py,
  ChristianMaurerGrubinger/RULA's RULA_tables and
  MohamedMBashir/ergonomic-risk-analyzer's rula_evaluator.py, which agree
  cell for cell) is datasets/rula.json's and is checked whole below
  (RULA_A_WORKSHEET).  The Cornell "RULA Employee Assessment Worksheet" copy
  read prints 31 of its 144 cells one lower (two once), all in upper arm 1 /
  lower arm 3, upper arms 2-4 and upper arm 6 / lower arm 2
  (RULA_A_CORNELL_DIFFERS); which one is the paper's Table 1 is not known
  until the paper is read (docs/task.md "RULA and REBA").  Table C is the
  same in every copy read (those three and the Cornell one).

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
    # score B 8-12 not legible in the worksheet read: from the implementations
    [11, 11, 11, 11, 12, 12, 12, 12, 12, 12, 12, 12],
    [12] * 12,  # score A 12: from the implementations (module docstring)
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
# RULA Table A as the step-by-step worksheet and the open implementations
# print it (module docstring): (upper arm, lower arm) -> wrist 1..4 x twist 1..2
RULA_A_WORKSHEET = {
    (1, 1): [1, 2, 2, 2, 2, 3, 3, 3],
    (1, 2): [2, 2, 2, 2, 3, 3, 3, 3],
    (1, 3): [2, 3, 3, 3, 3, 3, 4, 4],
    (2, 1): [2, 3, 3, 3, 3, 4, 4, 4],
    (2, 2): [3, 3, 3, 3, 3, 4, 4, 4],
    (2, 3): [3, 4, 4, 4, 4, 4, 5, 5],
    (3, 1): [3, 3, 4, 4, 4, 4, 5, 5],
    (3, 2): [3, 4, 4, 4, 4, 4, 5, 5],
    (3, 3): [4, 4, 4, 4, 4, 5, 5, 5],
    (4, 1): [4, 4, 4, 4, 4, 5, 5, 5],
    (4, 2): [4, 4, 4, 4, 4, 5, 5, 5],
    (4, 3): [4, 4, 4, 5, 5, 5, 6, 6],
    (5, 1): [5, 5, 5, 5, 5, 6, 6, 7],
    (5, 2): [5, 6, 6, 6, 6, 7, 7, 7],
    (5, 3): [6, 6, 6, 7, 7, 7, 7, 8],
    (6, 1): [7, 7, 7, 7, 7, 8, 8, 9],
    (6, 2): [8, 8, 8, 8, 8, 9, 9, 9],
    (6, 3): [9, 9, 9, 9, 9, 9, 9, 9],
}
# The Cornell worksheet's rows where they differ (31 cells)
RULA_A_CORNELL_DIFFERS = {
    (1, 3): [2, 3, 2, 3, 3, 3, 4, 4],
    (2, 1): [2, 2, 2, 3, 3, 3, 4, 4],
    (2, 2): [2, 2, 2, 3, 3, 3, 4, 4],
    (2, 3): [2, 3, 3, 3, 3, 4, 4, 5],
    (3, 1): [2, 3, 3, 3, 4, 4, 5, 5],
    (3, 2): [2, 3, 3, 3, 4, 4, 5, 5],
    (3, 3): [2, 3, 3, 4, 4, 4, 5, 5],
    (4, 1): [3, 4, 4, 4, 4, 4, 5, 5],
    (4, 2): [3, 4, 4, 4, 4, 4, 5, 5],
    (4, 3): [3, 4, 4, 5, 5, 5, 6, 6],
    (6, 2): [7, 8, 8, 8, 8, 9, 9, 9],
}
# RULA Table C: score C 1..8+ -> score D 1..7+ (every copy read agrees)
RULA_C = [
    [1, 2, 3, 3, 4, 5, 5],
    [2, 2, 3, 4, 4, 5, 5],
    [3, 3, 3, 4, 4, 5, 6],
    [3, 3, 3, 4, 5, 6, 6],
    [4, 4, 4, 5, 6, 7, 7],
    [4, 4, 5, 6, 6, 7, 7],
    [5, 5, 6, 6, 7, 7, 7],
    [5, 5, 6, 7, 7, 7, 7],
]
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


def test_reba_table_c_every_cell():
    table = read_reba_tables().c
    checked = 0
    for row, published in enumerate(REBA_C):
        for column, cell in enumerate(published):
            assert table[row][column] == cell, (row + 1, column + 1)
            checked += 1
    assert checked == 12 * 12


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


@pytest.mark.parametrize("where", sorted(RULA_A_WORKSHEET))
def test_rula_table_a_every_cell_as_the_worksheet_most_tools_use(where):
    upper, lower = where
    for i, cell in enumerate(RULA_A_WORKSHEET[where]):
        wrist, twist = i // 2 + 1, i % 2 + 1
        a, _, _ = grand_score(upper, lower, wrist, twist, 1, 1, 1, 0, 0)
        assert a == cell, (upper, lower, wrist, twist)


def test_the_two_printed_rula_table_as_differ_where_the_docs_say():
    """The legible rows of the Cornell copy (RULA_A) are the worksheet's, and
    the rows that differ differ only in the 31 cells named, each lower."""
    for where, row in RULA_A.items():
        assert RULA_A_WORKSHEET[where] == row
    differing = [
        (where, i)
        for where, row in RULA_A_CORNELL_DIFFERS.items()
        for i, cell in enumerate(row)
        if cell != RULA_A_WORKSHEET[where][i]
    ]
    assert len(differing) == 31
    assert all(
        RULA_A_CORNELL_DIFFERS[where][i] < RULA_A_WORKSHEET[where][i] for where, i in differing
    )


def test_rula_table_c_every_cell():
    for c, row in enumerate(RULA_C, start=1):
        for d, cell in enumerate(row, start=1):
            # posture scores A and B of 1 (every part 1), and the force and
            # muscle-use extras making score C = c and score D = d
            _, _, score = grand_score(1, 1, 1, 1, 1, 1, 1, c - 1, d - 1)
            assert score == cell, (c, d)
    # beyond the table's last row and column (8+, 7+) the last cell answers
    _, _, score = grand_score(6, 3, 4, 2, 6, 6, 2, 3, 3)
    assert score == RULA_C[-1][-1]
