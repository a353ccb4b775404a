"""The report's appendix L.1 center-of-mass rules, defined once: the
population-file check (`popfile.check_center_of_mass_rules`), the center of
mass of a population made from real people (`db/populations/population.py`) and the
HAnim/glTF foot (`model/body/hanim.py`) all use these.  Plain floats, one
percentile at a time: the first screen checks its files before numpy is imported.  No Textual import here."""

from __future__ import annotations

# L.1, both genders: the lower leg's center of mass lies 0.44 of its length
# below the knee; the foot's lies 0.44 (foot x + toes x) - 0.2516 foot x in
# front of the anklebone, the anklebone 0.2516 foot lengths in front of the heel.
LOWER_LEG_FRACTION = 0.44
FOOT_FRACTION = 0.44
HEEL_BEHIND_ANKLE = 0.2516

# L.1: the female center of mass scaled from the male by segment length.
# (center-of-mass row, girth rows whose z lengths add up to the segment length)
SCALED_BY_LENGTH = {
    "bottom_head": ("bottom_head",),
    "neck": ("neck",),
    "right_upper_arm": ("right_upper_arm",),
    "left_upper_arm": ("left_upper_arm",),
    "right_lower_arm": ("right_lower_arm",),
    "left_lower_arm": ("left_lower_arm",),
    "right_upper_leg": ("right_upper_leg",),
    "left_upper_leg": ("left_upper_leg",),
    "right_hand": ("right_hand", "right_knuckles"),
    "left_hand": ("left_hand", "left_knuckles"),
}


def lower_leg_center(lower_leg_length: float) -> float:
    """The lower leg's center of mass (z) from its length."""
    return LOWER_LEG_FRACTION * lower_leg_length


def foot_center(foot_x: float, toes_x: float) -> float:
    """The foot's center of mass (x) in front of the anklebone."""
    return FOOT_FRACTION * (foot_x + toes_x) - HEEL_BEHIND_ANKLE * foot_x


def toes_implied(foot_center_x: float, foot_x: float) -> float:
    """The toes' length (ball-of-foot x) the foot rule implies from the
    foot's center of mass and length."""
    return (foot_center_x + HEEL_BEHIND_ANKLE * foot_x) / FOOT_FRACTION - foot_x
