"""The low back of a task: the moment at L5/S1 from everything above it, and
its compression and shear by a single equivalent muscle (docs/task.md
"The low back").

- The joint: the HAnim humanoid's lumbar joint `vl5` (at the iliac crest's
  height, model/body/hanim.py), its axes turned with the trunk.
- The moment: the weights of the segments above (trunk above the pelvis,
  head, arms) and what the objects push back on the hands, about the joint.
- The muscle: one extensor acting along the trunk 5 cm behind the joint
  (the erector spinae's moment arm of Chaffin, Andersson & Martin 2006,
  ch. 6, the "static sagittal plane" model), carrying the flexing moment in
  the sagittal plane alone: F = M / 0.05 m.  No abdominal pressure or
  abdominal muscle term: a moment that extends the trunk is carried by the
  abdominals, which this model leaves out (compression is then the forces
  alone, said in the answer).  Lateral bending and twisting moments are
  reported, not turned into compression.
- Compression: the muscle's force plus the forces above along the trunk;
  shear: the forces above across the trunk, front to back (+: the part
  above pushed forward).
- Limits: compression against NIOSH's action limit 3400 N and upper limit
  6400 N (NIOSH 1981, Work practices guide for manual lifting); shear
  against Gallagher & Marras (2012): 700 N for frequent loading (over 100
  times a day), 1000 N occasional.

No Textual import here.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from sass_tui.model.body.posture import PosedBody
from sass_tui.model.strength.statics import Force, Vector, moment_about, weights

MOMENT_ARM_M = 0.05  # erector spinae, Chaffin, Andersson & Martin 2006
MUSCLE_SOURCE = "Chaffin, Andersson & Martin 2006: one extensor, 5 cm behind L5/S1"
COMPRESSION_LIMITS = (
    ("compression: NIOSH action limit", 3400.0),
    ("compression: NIOSH upper limit", 6400.0),
)
SHEAR_LIMITS = (
    ("shear: Gallagher & Marras 2012, frequent", 700.0),
    ("shear: Gallagher & Marras 2012, occasional", 1000.0),
)
# the segments the lumbar joint carries
ABOVE = (
    "l5",
    "skull",
    "l_upperarm",
    "l_forearm",
    "l_carpal",
    "r_upperarm",
    "r_forearm",
    "r_carpal",
)


@dataclass(frozen=True)
class LowBack:
    """L5/S1: the moment (N-m) about the trunk's own axes (x lateral: +
    flexes forward; y along the trunk: + twists left; z forward: + bends to
    the right), compression and shear (N) and the limits passed."""

    moment: tuple[float, float, float]
    compression: float
    shear: float
    muscle: float  # N, the equivalent extensor
    limits: dict[str, bool]  # limit words -> within it
    notes: tuple[str, ...]

    @property
    def flexion_moment(self) -> float:
        return self.moment[0]


def low_back(body: PosedBody, hands: list[Force]) -> LowBack:
    """The low back of `body` with `hands` (what the objects push back on the hands)."""
    forces = weights(body, list(ABOVE)) + hands
    joint = body.centers["vl5"]
    turn = np.eye(3) if body.turns is None else body.turns["vl5"]
    lateral, along, forward = turn[:, 0], turn[:, 1], turn[:, 2]
    world = moment_about(joint, forces)
    moment = (
        float(world @ lateral),
        float(world @ along),
        float(world @ -forward),  # + bends to the right: about -z
    )
    total: Vector = np.sum([f for _, f in forces], axis=0)
    muscle = max(moment[0], 0.0) / MOMENT_ARM_M
    compression = muscle - float(total @ along)
    shear = float(total @ forward)
    notes = []
    if moment[0] < 0:
        notes.append(
            f"the low back's moment extends the trunk ({-moment[0]:.1f} N-m): the abdominal "
            "muscles carry it, which the single-muscle model leaves out; compression is the "
            "forces alone"
        )
    limits = {words: compression <= limit for words, limit in COMPRESSION_LIMITS}
    limits |= {words: abs(shear) <= limit for words, limit in SHEAR_LIMITS}
    return LowBack(moment, compression, shear, muscle, limits, tuple(notes))


def limit_words() -> list[str]:
    """The limits with their values, for the text answer."""
    return [f"{words} {limit:g} N" for words, limit in (*COMPRESSION_LIMITS, *SHEAR_LIMITS)]
