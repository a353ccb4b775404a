"""Percent capable over many people at once: each person's probability of
exerting a hip, knee or ankle torque (Anderson et al. 2007, C1 normal with
Table 3's mean and SD for the person's gender and age group, the curve's
shape at its means; docs/strength.md "Percent capable"), as numpy arrays, for
`sass fit --strength` and `sass task` over a population.

published_strength.lower_limb_percent_capable answers for one subject; this
is the same arithmetic for thousands.  No Textual import here.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from sass_tui.model.strength.published_strength import (
    AGE_GROUPS,
    MAX_AGE,
    MIN_AGE,
    Anderson2007,
    StrengthLimit,
    Subject,
    age_group,
    c1_spread,
    lower_limb_strength,
    read_anderson2007,
)

FloatArray = npt.NDArray[np.float64]
_ERF = np.vectorize(math.erf, otypes=[float])


def normal_survival(z: npt.ArrayLike) -> FloatArray:
    """1 - Phi(z), elementwise."""
    share: FloatArray = 0.5 * (1.0 - _ERF(np.asarray(z, dtype=float) / math.sqrt(2.0)))
    return share


def lower_limb_capable(
    motion: str,
    gender: npt.ArrayLike,
    age: npt.ArrayLike,
    mass: npt.ArrayLike,
    stature_m: npt.ArrayLike,
    torque: npt.ArrayLike,
    angle: float | None = None,
    speed: float = 0.0,
    data: Anderson2007 | None = None,
) -> FloatArray:
    """Each person's probability (0-1) of exerting `torque` N-m (one for all,
    or one each) in `motion` at
    `angle` deg (None: the peak) and concentric `speed` deg/s; NaN where the
    model cannot say (gender, age outside 18-100, mass or stature missing)."""
    data = data or read_anderson2007()
    genders = np.asarray(gender, dtype=object)
    ages, masses, statures = (np.asarray(v, dtype=float) for v in (age, mass, stature_m))
    out = np.full(genders.shape, np.nan)
    torques = np.broadcast_to(np.asarray(torque, dtype=float), genders.shape)
    known = (
        np.isfinite(ages)
        & (ages >= MIN_AGE)
        & (ages <= MAX_AGE)
        & np.isfinite(masses)
        & (masses > 0)
        & np.isfinite(statures)
        & (statures > 0)
    )
    groups = np.full(genders.shape, "", dtype=object)
    groups[known] = [age_group(float(a)) for a in ages[known]]
    for sex in ("male", "female"):
        for group, youngest, oldest, _ in AGE_GROUPS:
            mine = known & (genders == sex) & (groups == group)
            if not mine.any():
                continue
            # torque per unit of C1, per kg and per m of stature: the curve's shape
            unit = lower_limb_strength(
                motion, Subject(sex, (youngest + oldest) / 2, 1.0, 1.0), angle, speed, 50.0, data
            )
            per_c1 = unit.torque / unit.c1
            key = (motion, sex, group)
            if per_c1 <= 0:
                out[mine] = np.where(torques[mine] > 0, 0.0, 1.0)
                continue
            needed = torques[mine] / (per_c1 * masses[mine] * statures[mine])
            out[mine] = normal_survival((needed - data.mean[key].c1) / c1_spread(data, key))
    return out


def strength_limit_probability(
    limit: StrengthLimit,
    gender: npt.ArrayLike,
    age: npt.ArrayLike,
    mass: npt.ArrayLike,
    stature_cm: npt.ArrayLike,
) -> FloatArray:
    """Each person's probability of meeting `limit` (`>=`/`>`: exerting at least
    its torque; `<=`/`<`: at most), NaN where it cannot be predicted."""
    capable = lower_limb_capable(
        limit.motion,
        gender,
        age,
        mass,
        np.asarray(stature_cm, dtype=float) / 100.0,
        limit.torque,
        limit.angle,
    )
    if limit.operator in ("<=", "<"):
        return 1.0 - capable
    return capable
