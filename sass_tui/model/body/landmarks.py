"""A real person standing: their body landmarks where their own ANSUR II
measurements put them, and the joint centres that follow from those
landmarks (docs/hanim.md, "A real person").

The HAnim humanoid (model/body/hanim.py) and the person's `.fig` (model/files/figfile.py)
both take their placements from here, so the two agree.  A figure without
measured landmarks (a percentile figure) is placed from its stature alone
(hanim.LANDMARK_FRACTIONS), as before; a person missing one landmark takes
that one from the stature.

Joint centres from the landmarks (the humanoid stands in the "I" pose of
ISO/IEC 19774-1 clause 4.8.2, arms hanging, palms to the thighs):
  shoulder  below the acromion by 17 % of the biacromial breadth (Rab,
            Petuskey & Bagley 2002, "A method for determination of upper
            extremity kinematics", Gait & Posture 15:113-119: the constant
            offset of the glenohumeral centre from the acromion), and medial
            of the acromion's lateral edge by the humeral head's radius,
            25 mm (Iannotti et al. 1992, J. Bone Joint Surg. Am. 74:491-500:
            mean radius of curvature of the head), since the acromion
            overhangs the head's lateral surface;
  elbow     at radiale height (the top of the radial head, the humeroradial
            joint line): the acromial height less the acromion-radiale length,
            both measured standing with the arm hanging;
  wrist     at wrist height (stylion, the tip of the radial styloid);
  hip       at trochanterion height: the tip of the greater trochanter is
            level with the centre of the femoral head (the radiographic
            relation hip arthroplasty is planned on); sideways in the middle
            of the thigh's width inside the hip breadth (hanim._joint_centers);
  knee      at the lateral femoral epicondyle (the flexion axis runs through
            the epicondyles);
  ankle     at the lateral malleolus (the talocrural axis runs through the
            malleoli's tips);
  vl5       at iliocristale height (the iliac crest, at L4-L5); skull base at
            tragion height (stature less tragion-top of head).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from sass_tui.model.body.body_measures import SURFACE_MEASURES

# The ANSUR II measurements (the survey's column names, canonical unit cm)
# that place a person's landmarks and shape their body's surface
# (model/body/body_measures.py); db/people/individual.py reads exactly these.
_PLACING: tuple[str, ...] = (
    "stature",
    "tragiontopofhead",
    "cervicaleheight",
    "suprasternaleheight",
    "acromialheight",
    "biacromialbreadth",
    "acromionradialelength",
    "wristheight",
    "waistheightomphalion",
    "iliocristaleheight",
    "bicristalbreadth",
    "trochanterionheight",
    "hipbreadth",
    "lateralfemoralepicondyleheight",
    "tibialheight",
    "lateralmalleolusheight",
    "bimalleolarbreadth",
)
# What a person's reach takes beyond those (model/body/reach.py): the
# sitting height, the grip's place in the hand and the survey's own reach
# measures, which set the person's shoulder travel.
REACH_LANDMARKS: tuple[str, ...] = (
    "sittingheight",
    "forearmhandlength",
    "forearmcenterofgriplength",
    "thumbtipreach",
    "overheadfingertipreachsitting",
    "span",
)
LANDMARK_MEASURES: tuple[str, ...] = (
    *_PLACING,
    *(name for name in SURFACE_MEASURES if name not in _PLACING),
    *REACH_LANDMARKS,
)

# Rab, Petuskey & Bagley (2002): the shoulder centre below the acromion, as a
# share of the distance between the two acromia.  The one glenohumeral rule:
# a real person's own biacromial breadth, a percentile figure's its stature's
# share of it (BIACROMIAL_FRACTION).
SHOULDER_BELOW_ACROMION_SHARE = 0.17
# The mean biacromial breadth / stature of ANSUR II (Gordon et al. 2014; 4,082
# men, 1,986 women): `python scripts/hanim_landmarks.py` computes and checks it.
BIACROMIAL_FRACTION = {"male": 0.2368, "female": 0.2244}
# Iannotti et al. (1992): the humeral head's mean radius of curvature (m).
# Placing the shoulder centre this far medial of the acromion's edge is
# sass's own assumption (the acromion overhangs the head's lateral surface),
# not Rab's.
HUMERAL_HEAD_RADIUS = 0.025


def shoulder_below_acromion(biacromial_breadth: float) -> float:
    """How far (m) the glenohumeral centre lies below the acromion: Rab et
    al.'s 17 % of the distance between the acromia (m)."""
    return SHOULDER_BELOW_ACROMION_SHARE * biacromial_breadth


# landmark (as hanim.LANDMARK_FRACTIONS names it) -> the ANSUR II column of its height
HEIGHT_COLUMNS: dict[str, str] = {
    "lateral_malleolus": "lateralmalleolusheight",
    "femoral_epicondyle": "lateralfemoralepicondyleheight",
    "tibiale": "tibialheight",
    "trochanterion": "trochanterionheight",
    "iliocristale": "iliocristaleheight",
    "omphalion": "waistheightomphalion",
    "wrist": "wristheight",
    "suprasternale": "suprasternaleheight",
    "acromion": "acromialheight",
    "cervicale": "cervicaleheight",
}
# half-breadth (m from the mid-sagittal plane) -> the ANSUR II breadth column
BREADTH_COLUMNS: dict[str, str] = {
    "acromion": "biacromialbreadth",
    "iliocristale": "bicristalbreadth",
    "trochanterion": "hipbreadth",
    "malleoli": "bimalleolarbreadth",
}


def measured(landmarks: Mapping[str, float], name: str) -> float | None:
    """The measurement `name` in metres, None when the person has none."""
    value = landmarks.get(name)
    if value is None or not math.isfinite(value) or value <= 0:
        return None
    return float(value) / 100.0


def measured_heights(landmarks: Mapping[str, float], stature: float) -> dict[str, float]:
    """The landmark and joint-centre heights (m) the person's measurements
    give; a height they do not give is absent (the caller takes it from the
    stature).  `stature` in m."""
    out: dict[str, float] = {}
    for landmark, column in HEIGHT_COLUMNS.items():
        value = measured(landmarks, column)
        if value is not None:
            out[landmark] = value
    top = measured(landmarks, "tragiontopofhead")
    if top is not None:
        out["tragion"] = stature - top
    acromion = out.get("acromion")
    breadth = measured(landmarks, "biacromialbreadth")
    if acromion is not None and breadth is not None:
        out["shoulder"] = acromion - shoulder_below_acromion(breadth)
    arm = measured(landmarks, "acromionradialelength")
    if acromion is not None and arm is not None:
        out["radiale"] = acromion - arm
    return out


def half_breadths(landmarks: Mapping[str, float]) -> dict[str, float]:
    """Half of each measured breadth (m): how far the left and right
    landmarks stand from the mid-sagittal plane."""
    out = {}
    for name, column in BREADTH_COLUMNS.items():
        value = measured(landmarks, column)
        if value is not None:
            out[name] = value / 2
    return out


def joint_lengths(heights: Mapping[str, float]) -> dict[str, float]:
    """Joint-to-joint lengths (cm) of the standing person, for the `.fig`'s
    segment z: (SASS girth row stem) -> length, only where both ends are
    placed from the person's own landmarks."""
    spans = {
        "upper_leg": ("trochanterion", "femoral_epicondyle"),
        "lower_leg": ("femoral_epicondyle", "lateral_malleolus"),
        "upper_arm": ("shoulder", "radiale"),
        "lower_arm": ("radiale", "wrist"),
    }
    return {
        stem: (heights[top] - heights[bottom]) * 100.0
        for stem, (top, bottom) in spans.items()
        if top in heights and bottom in heights
    }
