"""Strength: the conditions a strength is exerted under and the angles it may
be exerted at: the modifiers (strength type and speed, handedness, training,
fatigue; report §12.2.4, docs/model.md "Strength") and the figure's joint
limits that bound the strength page's angles.

No Textual import here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from sass_tui.model.body.figure import Figure
from sass_tui.model.errors import SassError
from sass_tui.model.names import JOINT_LIMITS, row_index
from sass_tui.model.text import quoted
from sass_tui.model.vocabulary import JOINT_AXES, MOTION_NAMES

# The row's joint picks the fatigue curve.
MOTION_JOINT = tuple(name.split("_")[0] for name in MOTION_NAMES)

# --- documented constants (docs/model.md, "Strength") ----------------------
# Foley et al. 2025, Sci Rep, doi:10.1038/s41598-025-87413-w: dominant 11.6 % stronger.
DEFAULT_NON_DOMINANT_FACTOR = 1.0 / 1.116
# Shoulder flexion at 45 deg: 46.9 N-m concentric at 50 deg/s, 68.6 N-m static.
ISOKINETIC_DECAY_PER_DEG_S = -math.log(46.9 / 68.6) / 50.0
# No source found: an assumption, stated in docs/model.md.
TRAINING_GAIN_PER_LEVEL = 0.10
# Frey Law & Avin 2010, Ergonomics 53:109-129: endurance time (s) = b0 * f^b1.
# The forearm and wrist have no fit there; they use the elbow's (assumption).
ENDURANCE_POWER_MODEL = {
    "shoulder": (14.86, -1.83),
    "elbow": (17.98, -2.21),
    "forearm": (17.98, -2.21),
    "wrist": (17.98, -2.21),
}


class StrengthError(ValueError, SassError):
    """An angle, motion or parameter the strength model refuses."""


# --- modifiers (each a factor on the strength; docs/model.md) -----------------


def strength_type_factor(strength_type: str, motion_speed: float) -> float:
    """Isometric: 1.  Isokinetic and isotonic (concentric at motion_speed deg/s):
    exp(-k * speed), k = ln(68.6/46.9)/50 per deg/s, through the measured
    shoulder-flexion pair (static 68.6 N-m, 46.9 N-m at 50 deg/s).  Isotonic
    has no separate source: it is taken as the concentric value at the speed."""
    if motion_speed < 0:
        raise StrengthError("motion speed cannot be negative")
    if strength_type == "isometric":
        return 1.0
    if strength_type in ("isokinetic", "isotonic"):
        return math.exp(-ISOKINETIC_DECAY_PER_DEG_S * motion_speed)
    raise StrengthError(
        f"strength type must be isometric, isokinetic or isotonic, not {strength_type!r}"
    )


def handedness_factor(
    side: str, handedness: str, non_dominant_factor: float = DEFAULT_NON_DOMINANT_FACTOR
) -> float:
    """The stored data are the dominant limb's (report §12.2.4): the other limb
    is scaled by the non-dominant factor (default 1/1.116)."""
    return 1.0 if side == handedness else non_dominant_factor


def training_factor(level: float) -> float:
    """1 + 0.10 per training level (0 = none).  An assumption: no source found."""
    if level < 0:
        raise StrengthError("training level cannot be negative")
    return 1.0 + TRAINING_GAIN_PER_LEVEL * level


def fatigue_factor(level: float, joint: str = "shoulder") -> float:
    """Fatigue level = seconds a maximal exertion has been held (0 = rested).

    The endurance power model ET = b0 * f^b1 gives the relative load f that can
    be held for ET seconds; the strength left after `level` seconds is taken as
    f = (level / b0)^(1/b1), at most 1."""
    if level < 0:
        raise StrengthError("fatigue level cannot be negative")
    if level == 0:
        return 1.0
    b0, b1 = ENDURANCE_POWER_MODEL[joint]
    fraction: float = (level / b0) ** (1.0 / b1)
    return min(1.0, fraction)


class StrengthConditions(Protocol):
    """What the modifiers read: a Figure's strength parameters, or the
    conditions a person's own strengths were measured at."""

    @property
    def strength_type(self) -> str: ...
    @property
    def motion_speed(self) -> float: ...
    @property
    def handedness(self) -> str: ...
    @property
    def training_level(self) -> float: ...
    @property
    def fatigue_level(self) -> float: ...


@dataclass(frozen=True)
class MeasuredConditions:
    strength_type: str
    motion_speed: float
    handedness: str
    training_level: float
    fatigue_level: float


# The two modifiers without a solid source: the isokinetic decay (one
# shoulder-flexion pair, used for every joint) and the training gain (an
# assumption).  Off unless asked for, and labelled when on (docs/model.md).
ASSUMED_MODIFIERS = "isokinetic decay and training gain"
ASSUMED_LABEL = f"assumed modifiers on: {ASSUMED_MODIFIERS} (no published source for these motions)"


def assumed_modifiers_asked(figure: StrengthConditions) -> bool:
    """The figure's parameters ask for an assumed modifier (a speed, a training level)."""
    return figure.strength_type != "isometric" or figure.training_level != 0


def modifier_factors(
    figure: StrengthConditions,
    side: str,
    non_dominant_factor: float = DEFAULT_NON_DOMINANT_FACTOR,
    assumed: bool = False,
) -> np.ndarray:
    """The product of every modifier, one factor per motion (14,).  The
    isokinetic decay and the training gain only when `assumed` (they are
    checked either way: a negative speed or level is refused)."""
    kind = strength_type_factor(figure.strength_type, figure.motion_speed)
    training = training_factor(figure.training_level)
    common = handedness_factor(side, figure.handedness, non_dominant_factor)
    if assumed:
        common *= kind * training
    fatigue = {
        joint: fatigue_factor(figure.fatigue_level, joint) for joint in ENDURANCE_POWER_MODEL
    }
    return np.array([common * fatigue[joint] for joint in MOTION_JOINT])


def parse_side_factor(text: str) -> float:
    """The Right->Left factor typed on the message line; RETURN = the default."""
    if not text.strip():
        return DEFAULT_NON_DOMINANT_FACTOR
    try:
        factor = float(text)
    except ValueError:
        raise StrengthError(f"scaling factor {quoted(text.strip())} is not a number") from None
    if not 0 < factor <= 2:
        raise StrengthError(f"scaling factor {factor:g} is outside 0-2")
    return factor


# --- joint limits ---------------------------------------------------------


def joint_limit_range(figure: Figure, side: str, joint_axis: str) -> tuple[float, float]:
    """(lower, upper) deg of a joint axis from the figure's current joint limits.

    NaN, NaN: no motion about this axis (999).  A person the database has no
    joint limits for (every ANSUR II person) gets the population's limits at
    the group percentile, as the figure's outputs do (Figure.output_values)."""
    return _joint_limit_range(figure, side, joint_axis)[:2]


def _joint_limit_range(figure: Figure, side: str, joint_axis: str) -> tuple[float, float, bool]:
    """(lower, upper, taken from the population because not measured)."""
    state = figure.groups[JOINT_LIMITS]
    if not state.loaded:
        raise StrengthError("joint limits are not loaded; angles cannot be checked")
    joint, axis = joint_axis.split("_")
    column = "xyz".index(axis)
    values, filled = figure.output_values(JOINT_LIMITS)
    # the trunk (no side) turns at the waist's joint (HAnim vl5), the neck
    # (no side) at the head-neck joint (HAnim skullbase) with the neck's limits
    stem = {"trunk": "waist", "neck": "neck"}.get(joint, f"{side}_{joint}")
    upper_row = row_index(JOINT_LIMITS, f"{stem}_ul")
    lower_row = row_index(JOINT_LIMITS, f"{stem}_ll")
    from_population = bool(filled[upper_row, column] or filled[lower_row, column])
    return (
        float(values[lower_row, column]),
        float(values[upper_row, column]),
        from_population,
    )


def check_angle(figure: Figure, side: str, joint_axis: str, degrees: float) -> None:
    """Refuse an angle outside the figure's current joint limits, naming the limit
    and where it comes from (the figure's own, or the population's for a person
    whose joint limits were not measured)."""
    lower, upper, from_population = _joint_limit_range(figure, side, joint_axis)
    joint, axis = joint_axis.split("_")
    what = f"{side} {joint} {axis}".strip()
    percentile = figure.groups[JOINT_LIMITS].percentile
    if math.isnan(lower) or math.isnan(upper):
        if degrees != 0:
            raise StrengthError(f"{what}: no motion about this axis (joint limits)")
        return
    source = f"joint limits, {percentile:g}th percentile"
    if from_population:
        source = (
            f"not measured for {figure.person}: the population's joint limits "
            f"at the {percentile:g}th percentile"
        )
    if degrees > upper:
        raise StrengthError(
            f"{what} {degrees:g} deg is above the {f'{side} {joint}'.strip()} upper limit "
            f"{upper:g} deg ({source})"
        )
    if degrees < lower:
        raise StrengthError(
            f"{what} {degrees:g} deg is below the {f'{side} {joint}'.strip()} lower limit "
            f"{lower:g} deg ({source})"
        )


def limits_source(figure: Figure) -> str:
    """Which joint limits the strength page checks angles against, in words."""
    percentile = figure.groups[JOINT_LIMITS].percentile
    if figure.person is not None and figure.groups[JOINT_LIMITS].loaded:
        if figure.output_values(JOINT_LIMITS)[1].any():
            return (
                f"joint limits: not measured for {figure.person}; the population's "
                f"at the {percentile:g}th percentile"
            )
    return f"joint limits: {percentile:g}th percentile"


def parse_joint_axis(text: str) -> int:
    key = text.strip().lower().replace(" ", "_").replace(".", "_")
    if key in JOINT_AXES:
        return JOINT_AXES.index(key)
    raise StrengthError(
        f"unknown joint axis {quoted(text.strip())}; expected one of {', '.join(JOINT_AXES)}"
    )
