"""The spread of strength between people (published_strength.c1_spread):
Anderson et al. 2007's Table 3 gives per age group the SD of C1 over that
group's subjects (14 aged 18-25, 14 aged 55-65, 6 over 65).  No group's
between-person coefficient of variation is below the pooled one of the two
groups with the most people; computed here from the data file with csv."""

from __future__ import annotations

import csv
import math

import pytest

from sass_tui.model.strength.published_strength import (
    Subject,
    c1_spread,
    lower_limb_percent_capable,
    lower_limb_strength,
    read_anderson2007,
)
from tests._paths import DATASETS


def table3() -> dict[tuple[str, str, str, str], float]:
    with open(DATASETS / "anderson2007.csv", encoding="utf-8", newline="") as handle:
        rows = csv.DictReader(line for line in handle if not line.startswith("#"))
        return {
            (r["motion"], r["gender"], r["age_group"], r["statistic"]): float(r["c1"]) for r in rows
        }


def test_no_group_spreads_less_than_the_large_groups_pooled():
    c1 = table3()
    data = read_anderson2007()
    motions = {(m, g) for m, g, _, _ in c1}
    for motion, gender in motions:
        cvs = [
            c1[(motion, gender, a, "sd")] / c1[(motion, gender, a, "mean")]
            for a in ("18-25", "55-65")
        ]
        pooled = math.sqrt((cvs[0] ** 2 + cvs[1] ** 2) / 2)
        for group in ("18-25", "55-65", "over-65"):
            key = (motion, gender, group)
            mean = c1[(*key, "mean")]
            spread = c1_spread(data, key)
            assert spread / mean >= pooled - 1e-12
            assert spread == pytest.approx(max(c1[(*key, "sd")], pooled * mean))
    # hip extension, women: 18-25 CV 0.047/0.181, 55-65 0.032/0.140; over 65 0.003/0.138
    hip = [0.047 / 0.181, 0.032 / 0.140]
    assert c1_spread(data, ("hip_extension", "female", "over-65")) == pytest.approx(
        0.138 * math.sqrt((hip[0] ** 2 + hip[1] ** 2) / 2)
    )


def test_older_women_are_not_all_capable_of_a_torque_below_their_mean():
    """The issue's case: a hip-extension torque 12 % below the mean of
    70-year-old women is no longer 100 % capable, their 5th percentile well below."""
    woman = Subject("female", 70.0, 70.0, 1.60)
    mean = lower_limb_strength("hip_extension", woman, 30.0).torque
    share = lower_limb_percent_capable("hip_extension", woman, 0.88 * mean, 30.0)
    assert 60.0 < share < 80.0
    fifth = lower_limb_strength("hip_extension", woman, 30.0, percentile=5.0).torque
    assert fifth < 0.7 * mean
