"""The words sass uses for choices, each defined once.

The figure, the strength model, the database, the query language and the
command line all take their choices from here.
"""

from __future__ import annotations

from typing import Final, Literal, get_args

# The groups of a person's measures (and the strength sheet, and the global
# statistics): here, not in model/names.py, so that the unit table
# (model/units.py) names them without building names.py's row tables.
GIRTH = "girth"
JOINT_LIMITS = "joint_limits"
CENTER_OF_MASS = "center_of_mass"
STRENGTH = "strength"
GLOBAL = "global"

Gender = Literal["male", "female"]
GENDERS: Final[tuple[Gender, ...]] = get_args(Gender)

# A figure's dominant hand; the database also records "either" (ANSUR II's
# "either hand (no preference)"), which a figure cannot be.
Handedness = Literal["right", "left"]
HANDEDNESS: Final[tuple[Handedness, ...]] = get_args(Handedness)
PersonHandedness = Literal["right", "left", "either"]
PERSON_HANDEDNESS: Final[tuple[PersonHandedness, ...]] = get_args(PersonHandedness)

Side = Literal["right", "left"]
SIDES: Final[tuple[Side, ...]] = get_args(Side)

StrengthType = Literal["isometric", "isokinetic", "isotonic"]
STRENGTH_TYPES: Final[tuple[StrengthType, ...]] = get_args(StrengthType)

FigureType = Literal["skinny", "polybody"]
FIGURE_TYPES: Final[tuple[FigureType, ...]] = get_args(FigureType)

# The figure's strength parameters (report §12.2.1), in the order of the
# spreadsheet's global data; the database stores all but handedness per
# strength experiment.
StrengthParameter = Literal[
    "strength_type", "motion_speed", "handedness", "training_level", "fatigue_level"
]
STRENGTH_PARAMETERS: Final[tuple[StrengthParameter, ...]] = get_args(StrengthParameter)
EXPERIMENT_PARAMETERS: Final[tuple[StrengthParameter, ...]] = (
    "strength_type",
    "motion_speed",
    "training_level",
    "fatigue_level",
)

# The strength page's motions in display order (report figure 5).
Motion = Literal[
    "shoulder_abduction",
    "shoulder_adduction",
    "shoulder_flexion",
    "shoulder_extension",
    "shoulder_medial_rotation",
    "shoulder_lateral_rotation",
    "elbow_flexion",
    "elbow_extension",
    "forearm_pronation",
    "forearm_supination",
    "wrist_flexion",
    "wrist_extension",
    "wrist_radial_deviation",
    "wrist_ulnar_deviation",
]
MOTION_NAMES: Final[tuple[Motion, ...]] = get_args(Motion)

# The joint-angle columns of a strength experiment (report figure 8).
JointAxis = Literal[
    "shoulder_x", "shoulder_y", "shoulder_z", "elbow_y", "wrist_x", "wrist_y", "wrist_z"
]
JOINT_AXES: Final[tuple[JointAxis, ...]] = get_args(JointAxis)
