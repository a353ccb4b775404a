"""Published strength models: the lower limb of Anderson et al. 2007.

D. E. Anderson, M. L. Madigan, M. A. Nussbaum, "Maximum voluntary joint
torque as a function of joint angle and angular velocity: model development
and application to the lower limb", J. Biomech. 40(14):3105-3113 (2007).
Table 3 gives, for hip, knee and ankle extension and flexion, men and women
of 18-25, 55-65 and over 65 years, the mean and standard deviation of the
coefficients of

    T = C1 * m * g * h * cos(C2 * (theta - C3)) * TV(omega)
    TV = (2 C4 C5 + omega (C5 - 3 C4)) / (2 C4 C5 + omega (2 C5 - 4 C4)),  omega >= 0

(torque in N-m, m body mass in kg, g = 9.81 m/s^2, h stature in m, theta
the joint angle in rad, omega the concentric angular velocity in rad/s).
TV(C4) = 0.75 and TV(C5) = 0.5: C4 and C5 are the speeds at which three
quarters and half the isometric torque remain.  The coefficients are shipped
in datasets/anderson2007.csv; docs/strength.md states the angle convention,
the age groups and how a percentile is taken from the published spread.

Pure Python: no numpy, no Textual.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from sass_tui.model import datasets
from sass_tui.model.errors import SassError, reason_text
from sass_tui.model.population.percentile import _STANDARD, check_percentile
from sass_tui.model.units import parse_quantity

FILE_NAME = "anderson2007.csv"
DATA_SET = "anderson2007"
EXAMPLE_DATA_SET = "example"
CITATION = "Anderson et al. 2007"
# What every answer from the invented strength.dat says it is.
EXAMPLE_SOURCE = "example data (invented, for the report's worked examples)"

# Anderson et al. 2007 used g = 9.81 m/s^2 to scale torque by body weight x height.
GRAVITY = 9.81

# The motions of Table 3, each about one axis; the angle is degrees of
# flexion from the standing posture (hip and knee flexion, ankle
# dorsiflexion positive), the paper's theta in degrees.
MOTION_AXIS: dict[str, str] = {
    "hip_flexion": "hip_y",
    "hip_extension": "hip_y",
    "knee_flexion": "knee_y",
    "knee_extension": "knee_y",
    "ankle_plantarflexion": "ankle_y",
    "ankle_dorsiflexion": "ankle_y",
}
LOWER_LIMB_MOTIONS: tuple[str, ...] = tuple(MOTION_AXIS)
LOWER_LIMB_AXES: tuple[str, ...] = ("hip_y", "knee_y", "ankle_y")

# The paper's three age groups: (name, youngest, oldest, words for a label).
AGE_GROUPS: tuple[tuple[str, float, float, str], ...] = (
    ("18-25", 18.0, 25.0, "young"),
    ("55-65", 55.0, 65.0, "middle-aged"),
    ("over-65", 65.0, 100.0, "older"),
)
MIN_AGE, MAX_AGE = 18.0, 100.0
# Between 25 and 55 the paper measured nobody: an age there takes the nearer
# group, 18-25 up to 40 and 55-65 above it (docs/strength.md).
_BETWEEN_GROUPS_SPLIT = 40.0
GENDER_WORDS = {"male": "men", "female": "women"}

_COLUMNS = ("c1", "c2", "c3", "c4", "c5", "c6", "b1", "k1", "b2", "k2")


class PublishedStrengthError(ValueError, SassError):
    """A published model refuses the question (age, motion, percentile)."""


@dataclass(frozen=True)
class Coefficients:
    """One block of Table 3 (mean or standard deviation)."""

    c1: float
    c2: float
    c3: float  # rad
    c4: float  # rad/s
    c5: float  # rad/s
    c6: float
    b1: float
    k1: float
    b2: float
    k2: float


_Key = tuple[str, str, str]  # motion, gender, age group


@dataclass(frozen=True)
class Anderson2007:
    path: str
    mean: dict[_Key, Coefficients]
    sd: dict[_Key, Coefficients]


def default_path() -> Path:
    return datasets.path(FILE_NAME)


@cache
def read_anderson2007(path: str | None = None) -> Anderson2007:
    """The shipped coefficients (or a file of the same layout)."""
    where = str(path or default_path())
    return parse_anderson2007_text(read_published_text(where), where)


def read_published_text(where: str) -> str:
    """A published data set's file (UTF-8, as shipped in datasets/), or why not."""
    try:
        return Path(where).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        reason = reason_text(exc) if isinstance(exc, OSError) else "not UTF-8 text"
        raise PublishedStrengthError(f"{where}: cannot read: {reason}") from None


def parse_anderson2007_text(text: str, where: str = "<text>") -> Anderson2007:
    """The coefficient file's text (its layout: datasets/anderson2007.csv)."""
    tables: dict[str, dict[_Key, Coefficients]] = {"mean": {}, "sd": {}}
    lines = [
        (n, ln)
        for n, ln in enumerate(text.split("\n"), start=1)
        if ln.strip() and not ln.startswith("#")
    ]
    try:
        rows = list(csv.reader(ln for _, ln in lines))
    except csv.Error as exc:
        raise PublishedStrengthError(f"{where}: not comma-separated values: {exc}") from None
    reader = iter(rows)
    header = next(reader, None)
    expected = ["motion", "gender", "age_group", "statistic", *_COLUMNS]
    if header != expected:
        raise PublishedStrengthError(
            f"{where}:{lines[0][0] if lines else 1}: expected the header {','.join(expected)}"
        )
    groups = {g[0] for g in AGE_GROUPS}
    for (lineno, _), row in zip(lines[1:], reader):
        if len(row) != len(expected):
            raise PublishedStrengthError(
                f"{where}:{lineno}: expected {len(expected)} fields, found {len(row)}"
            )
        motion, gender, group, statistic = row[:4]
        if motion not in MOTION_AXIS or gender not in GENDER_WORDS or group not in groups:
            raise PublishedStrengthError(
                f"{where}:{lineno}: unknown motion, gender or age group {row[:3]}"
            )
        if statistic not in tables:
            raise PublishedStrengthError(
                f"{where}:{lineno}: statistic {statistic!r}; expected mean or sd"
            )
        try:
            numbers = [float(x) for x in row[4:]]
        except ValueError:
            numbers = []
        if len(numbers) != len(_COLUMNS) or not all(math.isfinite(x) for x in numbers):
            raise PublishedStrengthError(f"{where}:{lineno}: a coefficient is not a finite number")
        tables[statistic][(motion, gender, group)] = Coefficients(*numbers)
    missing = [
        f"{m} {g} {a[0]}"
        for m in MOTION_AXIS
        for g in GENDER_WORDS
        for a in AGE_GROUPS
        if (m, g, a[0]) not in tables["mean"] or (m, g, a[0]) not in tables["sd"]
    ]
    if missing:
        raise PublishedStrengthError(f"{where}: no coefficients for {', '.join(missing[:3])}")
    return Anderson2007(where, tables["mean"], tables["sd"])


def lower_limb_motion(text: str) -> str | None:
    """'knee extension', 'Knee_Extension' -> 'knee_extension'; None: not one of them."""
    key = " ".join(text.strip().lower().replace("_", " ").split()).replace(" ", "_")
    return key if key in MOTION_AXIS else None


def age_group(age: float) -> str:
    """The Table 3 group an age in years takes (refused outside 18-100)."""
    if not math.isfinite(age) or not MIN_AGE <= age <= MAX_AGE:
        listed = ", ".join(g[0] for g in AGE_GROUPS)
        raise PublishedStrengthError(
            f"age {age:g} is outside {MIN_AGE:g}-{MAX_AGE:g} years; Anderson et al. 2007 "
            f"measured the age groups {listed}"
        )
    if age <= AGE_GROUPS[0][2]:
        return AGE_GROUPS[0][0]
    if age < AGE_GROUPS[1][1]:
        return AGE_GROUPS[0][0] if age <= _BETWEEN_GROUPS_SPLIT else AGE_GROUPS[1][0]
    if age <= AGE_GROUPS[1][2]:
        return AGE_GROUPS[1][0]
    return AGE_GROUPS[2][0]


def group_words(group: str) -> str:
    return next(g[3] for g in AGE_GROUPS if g[0] == group)


def ordinal(number: float) -> str:
    """5 -> '5th', 1 -> '1st', 22 -> '22nd', 2.5 -> '2.5th'."""
    n = f"{number:g}"
    suffix = "th"
    if n.isdigit() and not 11 <= int(n) % 100 <= 13:
        suffix = {"1": "st", "2": "nd", "3": "rd"}.get(n[-1], "th")
    return f"{n}{suffix}"


def percentile_words(percentile: float) -> str:
    if percentile == 50:
        return "mean"
    return f"{ordinal(percentile)} percentile"


def source_label(gender: str, group: str, percentile: float) -> str:
    """'Anderson et al. 2007, young men, mean' (the words every answer carries)."""
    return (
        f"{CITATION}, {group_words(group)} {GENDER_WORDS[gender]}, {percentile_words(percentile)}"
    )


def torque_velocity(c4: float, c5: float, omega: float) -> float:
    """Anderson et al. 2007's concentric torque-velocity factor (omega rad/s >= 0)."""
    if omega < 0:
        raise PublishedStrengthError(
            "the motion speed is concentric and cannot be negative (eccentric is not offered)"
        )
    factor = (2 * c4 * c5 + omega * (c5 - 3 * c4)) / (2 * c4 * c5 + omega * (2 * c5 - 4 * c4))
    return max(0.0, factor)


@dataclass(frozen=True)
class LowerLimbStrength:
    """The maximum voluntary active torque of one motion at one angle."""

    motion: str
    axis: str
    angle: float  # deg
    speed: float  # deg/s, concentric
    torque: float  # N-m
    peak_angle: float  # deg, the paper's C3: where the isometric torque peaks
    c1: float  # the C1 used (at the percentile)
    group: str
    source: str


@dataclass(frozen=True)
class Subject:
    """Who the model is asked about: gender, age (years), mass (kg), stature (m)."""

    gender: str
    age: float
    mass: float
    stature: float


def _c1_at(mean: float, sd: float, percentile: float, where: str) -> float:
    """C1 at a percentile: C1 taken as normal with Table 3's mean and SD."""
    check_percentile(percentile)
    c1 = mean + _STANDARD.inv_cdf(percentile / 100.0) * sd
    if c1 <= 0:
        raise PublishedStrengthError(
            f"{where}: the {percentile_words(percentile)} of C1 (mean {mean:g}, SD {sd:g}) "
            "is not positive; choose a higher percentile"
        )
    return c1


# The between-person spread of C1 (docs/strength.md "The spread between
# people"): Table 3's SD of each group, but never a coefficient of variation
# below the pooled one of the two groups with the most people (18-25 and
# 55-65, 14 people each; over 65, 6): the root mean square of their two CVs
# (equal sizes, equal weights), for the same motion and gender.
LARGE_GROUPS = ("18-25", "55-65")


def pooled_cv(data: Anderson2007, motion: str, gender: str) -> float:
    """The pooled coefficient of variation of C1 of LARGE_GROUPS."""
    cvs = [
        data.sd[(motion, gender, group)].c1 / data.mean[(motion, gender, group)].c1
        for group in LARGE_GROUPS
        if (motion, gender, group) in data.sd and data.mean[(motion, gender, group)].c1 > 0
    ]
    return math.sqrt(sum(cv * cv for cv in cvs) / len(cvs)) if cvs else 0.0


def c1_spread(data: Anderson2007, key: tuple[str, str, str]) -> float:
    """The SD of C1 between people of one group: Table 3's, floored at the
    pooled coefficient of variation times the group's mean."""
    motion, gender, _ = key
    return max(data.sd[key].c1, pooled_cv(data, motion, gender) * data.mean[key].c1)


def lower_limb_strength(
    motion: str,
    subject: Subject,
    angle: float | None = None,
    speed: float = 0.0,
    percentile: float = 50.0,
    data: Anderson2007 | None = None,
) -> LowerLimbStrength:
    """Anderson et al. 2007's torque for `motion` at `angle` deg (None: the
    peak angle C3) and concentric `speed` deg/s (0: isometric)."""
    if motion not in MOTION_AXIS:
        raise PublishedStrengthError(
            f"{CITATION} has no {motion}; it covers {', '.join(LOWER_LIMB_MOTIONS)}"
        )
    if subject.gender not in GENDER_WORDS:
        raise PublishedStrengthError(f"gender must be male or female, not {subject.gender!r}")
    for what, value, unit in (("mass", subject.mass, "kg"), ("stature", subject.stature, "m")):
        if not math.isfinite(value) or value <= 0:
            raise PublishedStrengthError(f"{what} must be positive, got {value:g} {unit}")
    data = data or read_anderson2007()
    group = age_group(subject.age)
    key = (motion, subject.gender, group)
    mean = data.mean[key]
    c1 = _c1_at(
        mean.c1,
        c1_spread(data, key),
        percentile,
        f"{motion} ({GENDER_WORDS[subject.gender]} {group})",
    )
    peak = math.degrees(mean.c3)
    at = peak if angle is None else float(angle)
    theta = math.radians(at)
    active = max(0.0, math.cos(mean.c2 * (theta - mean.c3)))
    tv = torque_velocity(mean.c4, mean.c5, math.radians(speed))
    torque = c1 * subject.mass * GRAVITY * subject.stature * active * tv
    return LowerLimbStrength(
        motion=motion,
        axis=MOTION_AXIS[motion],
        angle=at,
        speed=float(speed),
        torque=torque,
        peak_angle=peak,
        c1=c1,
        group=group,
        source=source_label(subject.gender, group, percentile),
    )


def curve_region(
    motion: str, gender: str, group: str, data: Anderson2007 | None = None
) -> tuple[float, float]:
    """The angles (deg) where the fitted angle term cos(C2 (theta - C3)) is
    positive: C3 +/- 90 deg / C2.  Beyond them the curve gives no torque, so
    the model cannot describe a joint there (the angles the paper measured,
    not printed in its abstract, lie within)."""
    mean = (data or read_anderson2007()).mean[(motion, gender, group)]
    peak, half = math.degrees(mean.c3), 90.0 / mean.c2
    return peak - half, peak + half


def beyond_curve(
    motion: str, gender: str, groups: list[str], angle: float, data: Anderson2007 | None = None
) -> str:
    """Why `angle` is outside the fitted curve of any of `groups` (one
    gender's age groups), or "" when it is inside every one."""
    for group in groups:
        low, high = curve_region(motion, gender, group, data)
        if not low <= angle <= high:
            return (
                f"{motion.replace('_', ' ')} at {angle:g} deg lies outside {low:.0f} to "
                f"{high:.0f} deg, where {CITATION}'s fitted curve ({GENDER_WORDS[gender]} "
                f"{group}) gives any torque: extrapolated"
            )
    return ""


def lower_limb_percent_capable(
    motion: str,
    subject: Subject,
    torque: float,
    angle: float | None = None,
    speed: float = 0.0,
    data: Anderson2007 | None = None,
) -> float:
    """The share (%) of the subject's group able to exert `torque` N-m: C1
    normal with Table 3's mean and SD (docs/strength.md, "Percentiles"), the
    curve's shape at its means, so 100 (1 - Phi((T / (m g h shape) - C1) / SD))."""
    if not math.isfinite(torque) or torque < 0:
        raise PublishedStrengthError(f"load {torque:g} N-m: expected a torque of 0 or more")
    data = data or read_anderson2007()
    mean_c1 = lower_limb_strength(motion, subject, angle, speed, 50.0, data)
    key = (motion, subject.gender, mean_c1.group)
    # the torque per unit of C1 at this angle and speed
    per_c1 = mean_c1.torque / mean_c1.c1
    if per_c1 <= 0:
        return 0.0 if torque > 0 else 100.0
    z = (torque / per_c1 - data.mean[key].c1) / c1_spread(data, key)
    return 100.0 * (1.0 - _STANDARD.cdf(z))


def lower_limb_curve(
    motion: str,
    subject: Subject,
    lower: float,
    upper: float,
    speed: float = 0.0,
    percentile: float = 50.0,
    points: int = 61,
) -> list[tuple[float, float]]:
    """(angle deg, torque N-m) over lower..upper: the torque-angle curve."""
    if not upper > lower or points < 2:
        raise PublishedStrengthError(f"no range to plot: {lower:g} to {upper:g} deg")
    step = (upper - lower) / (points - 1)
    return [
        (
            lower + i * step,
            lower_limb_strength(motion, subject, lower + i * step, speed, percentile).torque,
        )
        for i in range(points)
    ]


def text_plot(
    curve: list[tuple[float, float]],
    unit: str,
    mark: tuple[float, float] | None = None,
    width: int = 61,
    height: int = 12,
    what: str = "torque",
    across: str = "deg",
) -> list[str]:
    """A curve as lines of plain text (no colour, no terminal codes): `what`
    (torque) up, `across` (the angle, deg) across, `*` the curve, `o` the
    point asked about."""
    xs = [x for x, _ in curve]
    ys = [y for _, y in curve]
    top = max(ys + ([mark[1]] if mark else [])) or 1.0
    lo, hi = xs[0], xs[-1]
    grid = [[" "] * width for _ in range(height)]

    def cell(x: float, y: float) -> tuple[int, int]:
        col = round((x - lo) / (hi - lo) * (width - 1))
        row = height - 1 - round(y / top * (height - 1))
        return min(max(row, 0), height - 1), min(max(col, 0), width - 1)

    for x, y in curve:
        r, c = cell(x, y)
        grid[r][c] = "*"
    if mark is not None and lo <= mark[0] <= hi:
        r, c = cell(*mark)
        grid[r][c] = "o"
    label = max(len(f"{top:.0f}"), 1)
    lines = []
    for i, row in enumerate(grid):
        value = top * (height - 1 - i) / (height - 1)
        tick = f"{value:.0f}" if i in (0, height // 2, height - 1) else ""
        lines.append(f"{tick:>{label}} |{''.join(row)}")
    lines.append(f"{'':>{label}} +{'-' * width}")
    left, right = f"{lo:g}", f"{hi:.4g} {across}"
    lines.append(f"{'':>{label}}  {left}{right:>{width - len(left)}}")
    lines.insert(0, f"{'':>{label}}  {what} ({unit})")
    return lines


def fig_section(
    subject: Subject,
    limits: dict[str, tuple[float, float]],
    percentile: float = 50.0,
    age_given: bool = True,
) -> tuple[str, list[tuple[str, float, str]]]:
    """The hip, knee and ankle strength section of a .fig file: each motion's
    isometric torque (N-m) at its peak angle within the joint's limits (lower,
    upper deg per axis), the same for both sides (the paper has no side)."""
    variables = []
    source = ""
    for motion, axis in MOTION_AXIS.items():
        lower, upper = limits[axis]
        peak = lower_limb_strength(motion, subject, None, 0.0, percentile)
        angle = min(max(peak.peak_angle, lower), upper)
        answer = lower_limb_strength(motion, subject, angle, 0.0, percentile)
        source = answer.source
        for side in ("right", "left"):
            variables.append((f"{side}_{motion}_strength", answer.torque, "Nm"))
    note = "" if age_given else f" (age not given: the {AGE_GROUPS[0][0]} group)"
    return (
        f"hip, knee and ankle strength variables: {source}{note}; isometric, at each "
        "motion's peak angle within the joint limits",
        variables,
    )


# --- strength limits of a fit test ---------------------------------------------

_LIMIT_OPERATORS = (">=", "<=", ">", "<", "≥", "≤")
_OPERATOR_WORDS = {"≥": ">=", "≤": "<="}


@dataclass(frozen=True)
class StrengthLimit:
    """`knee_extension >= 150 N-m at knee_y=60`: a design limit on a person's
    predicted torque (Anderson et al. 2007, isometric, the mean of the
    person's group scaled by their own mass and stature)."""

    text: str
    motion: str
    operator: str  # ">=" | "<=" | ">" | "<"
    torque: float  # N-m
    angle: float | None  # deg; None: the motion's peak angle

    def passes(self, gender: str, age: float, mass: float, stature_cm: float) -> float:
        """1.0 passes, 0.0 fails, NaN: the person cannot be predicted (a value
        missing, or an age outside the paper's 18-100)."""
        values = (age, mass, stature_cm)
        if gender not in GENDER_WORDS or not all(math.isfinite(v) and v > 0 for v in values):
            return math.nan
        if not MIN_AGE <= age <= MAX_AGE:
            return math.nan
        subject = Subject(gender, age, mass, stature_cm / 100.0)
        have = lower_limb_strength(self.motion, subject, self.angle).torque
        ok = {
            ">=": have >= self.torque,
            "<=": have <= self.torque,
            ">": have > self.torque,
            "<": have < self.torque,
        }[self.operator]
        return 1.0 if ok else 0.0


def parse_strength_limit(text: str) -> StrengthLimit:
    """'strength.knee_extension >= 150 N-m at knee_y=60' (the `strength.`
    prefix, the unit and the `at AXIS=ANGLE` part are optional; N-m without
    a unit)."""
    shape = "MOTION >= TORQUE [at AXIS=ANGLE], e.g. knee_extension >= 150 N-m at knee_y=60"
    body, _, where = text.strip().partition(" at ")
    operator = next((op for op in _LIMIT_OPERATORS if op in body), None)
    if operator is None:
        raise PublishedStrengthError(f"strength limit {text.strip()!r}: expected {shape}")
    name, _, value = body.partition(operator)
    key = name.strip().lower()
    key = key.removeprefix("strength.")
    motion = lower_limb_motion(key)
    if motion is None:
        raise PublishedStrengthError(
            f"strength limit {text.strip()!r}: {CITATION} covers "
            f"{', '.join(LOWER_LIMB_MOTIONS)}; expected {shape}"
        )
    if not value.strip():
        raise PublishedStrengthError(
            f"strength limit {text.strip()!r}: no torque; expected {shape}"
        )
    try:
        torque = parse_quantity(value, "N_m")
    except SassError as exc:
        raise PublishedStrengthError(f"strength limit {text.strip()!r}: {exc}") from None
    angle = None
    if where.strip():
        axis, sep, degrees = where.strip().partition("=")
        if not sep or axis.strip().lower() != MOTION_AXIS[motion]:
            raise PublishedStrengthError(
                f"strength limit {text.strip()!r}: expected 'at {MOTION_AXIS[motion]}=ANGLE' "
                f"after the torque ({motion} is about {MOTION_AXIS[motion]})"
            )
        try:
            angle = parse_quantity(degrees, "deg")
        except SassError as exc:
            raise PublishedStrengthError(f"strength limit {text.strip()!r}: {exc}") from None
    if not (math.isfinite(torque) and (angle is None or math.isfinite(angle))):
        raise PublishedStrengthError(f"strength limit {text.strip()!r}: not a finite number")
    return StrengthLimit(
        text=" ".join(text.split()),
        motion=motion,
        operator=_OPERATOR_WORDS.get(operator, operator),
        torque=torque,
        angle=angle,
    )
