"""The Arm Force Field: manual arm strength from the hand's place and the
force's direction (La Delfa & Potvin 2017, Applied Ergonomics 59A:410-421,
doi:10.1016/j.apergo.2016.09.012).

sass's own implementation of the published method, on the authors'
coefficients (CC-BY 4.0; datasets/arm_force_field.json, written from their
script by scripts/make_arm_force_field.py; docs/strength.md):

1. The shoulder axis system: z along the shoulders (left to right shoulder),
   x = trunk (L5/S1 to C7/T1) x z, forward; y = z x x, up.
2. The hand, wrist and elbow relative to the exerting shoulder, and the force's
   unit vector, in that system; for the left arm the lateral axis is turned
   so that lateral is positive for either arm.
3. An artificial neural network (18 inputs: the hand's place, its projections,
   the force's direction cosines, the moment arm and its powers; 13 tanh
   nodes) gives the mean zero-gravity strength of women, bounded to the
   least and greatest the authors measured for the hand's height band and the
   signs of the force's three components.
4. The spread: SD = mean x the coefficient of variation 0.277 (normal).
5. The arm's own weight: the upper arm's, forearm's and hand's weights
   (shares of body mass, at their centres of mass along each segment) make a
   moment at the shoulder; that moment over the reach is a force at the hand,
   whose part along the exerted force helps (positive) or opposes it.

Men: the authors' worksheet scales the women's mean by 1.66 and takes a body
mass of 88.1 kg for the arm's weight.

Pure numpy; no Textual.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np
import numpy.typing as npt

from sass_tui.model import datasets
from sass_tui.model.body.human import joint_too_far
from sass_tui.model.errors import SassError
from sass_tui.model.population.percentile import _STANDARD
from sass_tui.model.text import quoted

FILE_NAME = "arm_force_field.json"
CITATION = "La Delfa & Potvin 2017 (Arm Force Field)"
GRAVITY = 9.81  # m/s^2, the authors' script's

# The HAnim joint centres a posture gives (metres, +x the body's left, +y up,
# +z forward), as the authors' script orders its points.
POSTURE_JOINTS: tuple[str, ...] = (
    "l_metacarpophalangeal_3",
    "l_radiocarpal",
    "l_elbow",
    "l_shoulder",
    "r_metacarpophalangeal_3",
    "r_radiocarpal",
    "r_elbow",
    "r_shoulder",
    "vc7",
    "vl5",
)
ARM_SIDES = ("left", "right")
DIRECTIONS: dict[str, tuple[float, float, float]] = {
    "up": (0.0, 1.0, 0.0),
    "down": (0.0, -1.0, 0.0),
    "forward": (0.0, 0.0, 1.0),
    "back": (0.0, 0.0, -1.0),
    "left": (1.0, 0.0, 0.0),
    "right": (-1.0, 0.0, 0.0),
}
# A hand closer to its shoulder than this has no direction from it.
SMALLEST_REACH_M = 0.01
_GRAVITY_DIRECTION = np.array([0.0, -1.0, 0.0])


class ArmForceError(ValueError, SassError):
    """A posture, direction or load the Arm Force Field cannot take."""


@dataclass(frozen=True)
class Coefficients:
    """The published model (datasets/arm_force_field.json)."""

    source: str
    cv: float
    women_body_mass: float
    women_stature: float
    men_factor: float
    men_body_mass: float
    men_stature: float
    cog_ratio: tuple[float, float, float]  # upper arm, forearm, hand: from the proximal joint
    mass_ratio: tuple[float, float, float]  # of body mass
    input_offset: npt.NDArray[np.float64]
    input_gain: npt.NDArray[np.float64]
    input_min: float
    layer1_bias: npt.NDArray[np.float64]
    layer1_weights: npt.NDArray[np.float64]  # (13, 18)
    layer2_bias: float
    layer2_weights: npt.NDArray[np.float64]
    output_min: float
    output_gain: float
    output_offset: float
    bound_min: npt.NDArray[np.float64]  # (3, 3, 3, 3): height, ant/post, sup/inf, med/lat
    bound_max: npt.NDArray[np.float64]
    height_band: float


@cache
def read_coefficients(path: str | None = None) -> Coefficients:
    where = str(path or datasets.path(FILE_NAME))
    try:
        raw = json.loads(Path(where).read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError) as exc:
        raise ArmForceError(f"{where}: cannot read the Arm Force Field: {exc}") from None

    def array(key: str) -> npt.NDArray[np.float64]:
        return np.asarray(raw[key], dtype=float)

    return Coefficients(
        source=str(raw["source"]),
        cv=float(raw["coefficient_of_variation"]),
        women_body_mass=float(raw["women_body_mass_kg"]),
        women_stature=float(raw["women_stature_m"]),
        men_factor=float(raw["men_factor"]),
        men_body_mass=float(raw["men_body_mass_kg"]),
        men_stature=float(raw["men_stature_m"]),
        cog_ratio=(
            float(raw["upper_arm_cog_ratio"]),
            float(raw["forearm_cog_ratio"]),
            float(raw["hand_cog_ratio"]),
        ),
        mass_ratio=(
            float(raw["upper_arm_mass_ratio"]),
            float(raw["forearm_mass_ratio"]),
            float(raw["hand_mass_ratio"]),
        ),
        input_offset=array("input_offset"),
        input_gain=array("input_gain"),
        input_min=float(raw["input_min"]),
        layer1_bias=array("layer1_bias"),
        layer1_weights=array("layer1_weights"),
        layer2_bias=float(raw["layer2_bias"]),
        layer2_weights=array("layer2_weights"),
        output_min=float(raw["output_min"]),
        output_gain=float(raw["output_gain"]),
        output_offset=float(raw["output_offset"]),
        bound_min=array("bound_min_N").reshape(3, 3, 3, 3),
        bound_max=array("bound_max_N").reshape(3, 3, 3, 3),
        height_band=float(raw["height_band_m"]),
    )


Posture = dict[str, npt.NDArray[np.float64]]


def check_posture(points: dict[str, object], where: str = "posture") -> Posture:
    """The ten joint centres as arrays, or a message naming the field that is
    missing, unknown or not three finite numbers."""
    if not isinstance(points, dict):
        raise ArmForceError(f"{where}: expected an object of joint names and [x, y, z] in m")
    unknown = [k for k in points if k not in POSTURE_JOINTS]
    if unknown:
        raise ArmForceError(
            f"{where}: unknown joint {unknown[0]!r}; expected {', '.join(POSTURE_JOINTS)}"
        )
    missing = [k for k in POSTURE_JOINTS if k not in points]
    if missing:
        raise ArmForceError(f"{where}: no {', '.join(missing)} (metres, HAnim axes)")
    out: Posture = {}
    for name in POSTURE_JOINTS:
        value = points[name]
        numbers: list[float] = []
        if isinstance(value, (list, tuple)) and len(value) == 3:
            numbers = [
                _float(v) for v in value if isinstance(v, (int, float)) and not isinstance(v, bool)
            ]
        shown = quoted(repr(value))
        if len(numbers) != 3:
            raise ArmForceError(f"{where}: {name}: expected [x, y, z] in metres, got {shown}")
        if not all(math.isfinite(v) for v in numbers):
            raise ArmForceError(f"{where}: {name}: {shown} is not three finite numbers")
        out[name] = np.array(numbers, dtype=float)
    # One check of a joint's place for every verb (model/body/human.py).
    root = POSTURE_JOINTS[-1]
    for name in POSTURE_JOINTS:
        refused = joint_too_far(name, float(np.linalg.norm(out[name] - out[root])), root)
        if refused:
            raise ArmForceError(f"{where}: {refused}")
    return out


def _float(value: float) -> float:
    """float(value), infinity for an integer too large for one (3,000 digits)."""
    try:
        return float(value)
    except OverflowError:
        return math.inf


def parse_direction(text: str, name: str = "direction") -> npt.NDArray[np.float64]:
    """'up', 'forward', ... or 'X,Y,Z' on HAnim's axes -> the unit vector;
    `name`: what a message calls it (a command line's option)."""
    key = text.strip().lower()
    if key in DIRECTIONS:
        return np.array(DIRECTIONS[key])
    parts = key.split(",")
    try:
        vector = np.array([float(p) for p in parts], dtype=float)
    except ValueError:
        vector = np.array([])
    words = ", ".join(DIRECTIONS)
    if vector.shape != (3,):
        raise ArmForceError(f"{name} {text.strip()!r}: expected one of {words}, or X,Y,Z")
    return check_direction(vector, f"{name} {text.strip()!r}")


def check_direction(vector: npt.ArrayLike, where: str = "direction") -> npt.NDArray[np.float64]:
    v = np.asarray(vector, dtype=float)
    if v.shape != (3,) or not np.isfinite(v).all():
        raise ArmForceError(f"{where}: expected three finite numbers X,Y,Z")
    largest = float(np.abs(v).max())
    if largest == 0.0:
        raise ArmForceError(f"{where}: the zero vector has no direction")
    v = v / largest  # no overflow in the norm of 1e200,1e200,0
    return v / float(np.linalg.norm(v))


def shoulder_axes(posture: Posture) -> npt.NDArray[np.float64]:
    """Rows x (forward), y (up), z (lateral, to the right shoulder) of the
    shoulder axis system, from the shoulders, C7/T1 and L5/S1."""
    lateral = posture["r_shoulder"] - posture["l_shoulder"]
    if np.linalg.norm(lateral) == 0.0:
        raise ArmForceError("posture: l_shoulder and r_shoulder are the same point")
    axes = np.zeros((3, 3))
    axes[2] = lateral / np.linalg.norm(lateral)
    trunk = posture["vc7"] - posture["vl5"]
    if np.linalg.norm(trunk) == 0.0:
        raise ArmForceError("posture: vc7 and vl5 are the same point")
    trunk = trunk / np.linalg.norm(trunk)
    forward = np.cross(trunk, axes[2])
    if np.linalg.norm(forward) < 1e-9:
        raise ArmForceError("posture: the trunk (vl5 to vc7) lies along the shoulders")
    axes[0] = forward / np.linalg.norm(forward)
    axes[1] = np.cross(axes[2], axes[0])
    return axes


@dataclass(frozen=True)
class ArmLocal:
    """One arm in its shoulder axis system (lateral positive for either arm)."""

    hand: npt.NDArray[np.float64]
    wrist: npt.NDArray[np.float64]
    elbow: npt.NDArray[np.float64]
    force: npt.NDArray[np.float64]  # unit
    gravity: npt.NDArray[np.float64]  # unit, as the authors' script turns it (not mirrored)


def arm_local(posture: Posture, side: str, direction: npt.ArrayLike) -> ArmLocal:
    if side not in ARM_SIDES:
        raise ArmForceError(f"--side {side!r}: expected left or right")
    axes = shoulder_axes(posture)
    s = side[0]
    shoulder = posture[f"{s}_shoulder"]
    mirror = np.array([1.0, 1.0, -1.0 if side == "left" else 1.0])

    def local(joint: str) -> npt.NDArray[np.float64]:
        placed: npt.NDArray[np.float64] = (posture[joint] - shoulder) @ axes.T * mirror
        return placed

    hand = local(f"{s}_metacarpophalangeal_3")
    if np.linalg.norm(hand) < SMALLEST_REACH_M:
        raise ArmForceError(
            f"posture: {s}_metacarpophalangeal_3 is within {SMALLEST_REACH_M * 100:g} cm of "
            f"{s}_shoulder; the hand must be away from the shoulder"
        )
    unit = check_direction(direction)
    return ArmLocal(
        hand=hand,
        wrist=local(f"{s}_radiocarpal"),
        elbow=local(f"{s}_elbow"),
        force=np.dot(unit, axes.T) * mirror,
        gravity=np.dot(_GRAVITY_DIRECTION, axes.T),
    )


def network_inputs(arm: ArmLocal) -> npt.NDArray[np.float64]:
    """The 18 inputs: (superior, anterior, lateral) order, as published."""
    r = (arm.hand[1], arm.hand[0], arm.hand[2])
    f = (arm.force[1], arm.force[0], arm.force[2])
    moment = (r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0])
    arm3d = math.sqrt(sum(m * m for m in moment))
    planar = (math.hypot(r[1], r[2]), math.hypot(r[0], r[2]), math.hypot(r[0], r[1]))
    return np.array(
        [
            *r,
            *planar,
            *f,
            *moment,
            arm3d,
            arm3d**2,
            arm3d**3,
            planar[0] * f[0],
            planar[1] * f[1],
            planar[2] * f[2],
        ]
    )


def _sign_code(value: float) -> int:
    return 0 if value == 0 else (1 if value > 0 else -1)


def zero_gravity_mean(arm: ArmLocal, inputs: npt.NDArray[np.float64], c: Coefficients) -> float:
    """Women's mean zero-gravity strength (N), bounded as the authors bound it;
    `inputs` are network_inputs(arm)."""
    p = c.input_gain * (inputs - c.input_offset) + c.input_min
    hidden = np.tanh(c.layer1_bias + c.layer1_weights @ p)
    out = c.layer2_bias + float(c.layer2_weights @ hidden)
    mean = (out - c.output_min) / c.output_gain + c.output_offset
    height = arm.hand[1]
    band = 0 if abs(height) <= c.height_band else (1 if height > 0 else -1)
    code = (band + 1, *(_sign_code(v) + 1 for v in (arm.force[0], arm.force[1], arm.force[2])))
    low, high = float(c.bound_min[code]), float(c.bound_max[code])
    return min(max(mean, low), high)


# The network's inputs are scaled as MATLAB's mapminmax scales them: the least
# and greatest of the data it was fitted on go to input_min (-1) and +1, so
# input_offset is the least and input_offset + (1 - input_min) / input_gain the
# greatest.  Inputs 0-2 are the hand's place (up, forward, lateral of the
# shoulder, m, as network_inputs orders them); the others are built from the
# place and the force's direction (its cosines always lie within their range).
HAND_INPUTS = ("up", "forward", "lateral")
# Rounding of the published scaling is not extrapolation.
FITTED_TOLERANCE = 1e-6


def fitted_ranges(c: Coefficients) -> list[tuple[float, float]]:
    """(least, greatest) of each network input over the data it was fitted on."""
    return [
        (float(lo), float(lo + (1.0 - c.input_min) / gain))
        for lo, gain in zip(c.input_offset, c.input_gain)
    ]


def outside_fitted(inputs: npt.NDArray[np.float64], c: Coefficients) -> str:
    """Empty, or the words saying that this hand place and direction lie outside
    the inputs the network was fitted on (its answer is then extrapolated,
    beyond the bounds the authors put on its output); `inputs` are
    network_inputs of the arm."""
    ranges = fitted_ranges(c)
    out = [
        i
        for i, (value, (low, high)) in enumerate(zip(inputs, ranges))
        if not (low - FITTED_TOLERANCE <= value <= high + FITTED_TOLERANCE)
    ]
    if not out:
        return ""
    hand = [
        f"{inputs[i]:.2f} m {HAND_INPUTS[i]} (fitted {ranges[i][0]:.2f} to {ranges[i][1]:.2f})"
        for i in out
        if i < len(HAND_INPUTS)
    ]
    what = (
        "the hand " + ", ".join(hand)
        if hand
        else "the hand's place with this force direction (its moment about the shoulder)"
    )
    return f"{what} lies outside the hand places the Arm Force Field was fitted on: extrapolated"


def gravity_along_force(arm: ArmLocal, body_mass: float, c: Coefficients) -> float:
    """The arm's own weight as a force at the hand, along the exerted force (N):
    positive helps, negative opposes.  0 when the arm's weight makes no moment
    at the shoulder (the arm hanging straight down)."""
    cogs = (
        arm.elbow * c.cog_ratio[0],
        arm.elbow + (arm.wrist - arm.elbow) * c.cog_ratio[1],
        arm.wrist + (arm.hand - arm.wrist) * c.cog_ratio[2],
    )
    moment = sum(
        (np.cross(cog, arm.gravity) * body_mass * ratio * GRAVITY)
        for cog, ratio in zip(cogs, c.mass_ratio)
    )
    size = float(np.linalg.norm(moment))
    reach = float(np.linalg.norm(arm.hand))
    if size < 1e-12:
        return 0.0
    assist = np.cross(moment / size, arm.hand / reach)
    assist_size = float(np.linalg.norm(assist))
    if assist_size < 1e-12:
        return 0.0
    effect = assist * (size / reach) / assist_size
    return float(effect @ arm.force)


@dataclass(frozen=True)
class ArmForce:
    """What the Arm Force Field answers for one arm, one direction and one
    population (women or men)."""

    side: str
    gender: str
    mean: float  # N, zero gravity, bounded
    sd: float  # N
    gravity: float  # N, the arm's weight along the force
    body_mass: float  # kg, for the arm's weight
    hand: tuple[float, float, float]  # m from the shoulder: forward, up, lateral
    source: str
    # "" or why the answer is extrapolated: the hand's place (or the force's
    # moment about the shoulder) outside what the network was fitted on
    outside_fitted: str = ""

    def strength(self, capable: float) -> float:
        """The force (N, gravity included) `capable` percent of people can exert."""
        check_capable(capable)
        return self.mean + _STANDARD.inv_cdf(1.0 - capable / 100.0) * self.sd + self.gravity

    def percent_capable(self, load: float) -> float:
        """The share (%) able to exert `load` N along the direction, gravity included."""
        return percent_capable(load - self.gravity, self.mean, self.sd)


def check_capable(capable: float) -> None:
    if not (math.isfinite(capable) and 0.0 < capable < 100.0):
        raise ArmForceError(f"--capable {capable:g}: expected a percent between 0 and 100")


def percent_capable(load: float, mean: float, sd: float) -> float:
    """100 (1 - Phi((load - mean) / sd)): the share of a normal strength that
    reaches `load`."""
    if not math.isfinite(load):
        raise ArmForceError(f"load {load!r}: expected a finite force")
    return 100.0 * (1.0 - _STANDARD.cdf((load - mean) / sd))


def body_mass_for(gender: str, c: Coefficients) -> float:
    return c.men_body_mass if gender == "male" else c.women_body_mass


def arm_force(
    posture: Posture,
    side: str,
    direction: npt.ArrayLike,
    gender: str = "female",
    body_mass: float | None = None,
    coefficients: Coefficients | None = None,
) -> ArmForce:
    """The Arm Force Field's answer for `side`'s hand pushing along `direction`
    (HAnim axes) in `posture`.  Women as published; men as the worksheet
    scales them.  `body_mass` (kg) for the arm's weight: default the published
    73.5 kg (women) or 88.1 kg (men)."""
    c = coefficients or read_coefficients()
    if gender not in ("female", "male"):
        raise ArmForceError(f"gender {gender!r}: expected female or male")
    mass = body_mass_for(gender, c) if body_mass is None else float(body_mass)
    if not (math.isfinite(mass) and mass > 0):
        raise ArmForceError(f"body mass {mass!r} kg: expected a positive number")
    arm = arm_local(posture, side, direction)
    inputs = network_inputs(arm)
    mean = zero_gravity_mean(arm, inputs, c)
    if gender == "male":
        mean *= c.men_factor
    words = "women, as published" if gender == "female" else "men (women x 1.66, worksheet)"
    return ArmForce(
        side=side,
        gender=gender,
        mean=mean,
        sd=mean * c.cv,
        gravity=gravity_along_force(arm, mass, c),
        body_mass=mass,
        hand=(float(arm.hand[0]), float(arm.hand[1]), float(arm.hand[2])),
        source=f"{CITATION}, {words}; arm's weight for {mass:g} kg",
        outside_fitted=outside_fitted(inputs, c),
    )
