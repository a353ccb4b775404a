"""Strength data: the file format, lookup, a person's own strength and the
prediction equation (report §12.2.2-§12.2.3, figures 5 and 8; spec §2
"Strength").  The modifiers and joint limits are strength_conditions.py, the
strength page's state strength.py.

File format (figure 8):

    P title
    C comment
    G MALE | G FEMALE        (starts a gender)
    L RIGHT | L LEFT         (starts a limb side within it; data rows follow)
    sx sy sz  ey  wx wy wz  value  percentile  /* motion[: note] */

Angles in degrees, strength in ft-lb, 999 = no value.  The comment names the
motion impetus; a motion may have many rows (configurations).  Errors and
warnings follow popfile.py: a broken file is rejected whole with file:line,
suspicious rows are warned about and loading goes on.

Prediction (docs/model.md, "Strength"): per gender, side and motion,
    ln S50 = b0 + sum_j (b_j t_j + c_j t_j^2),   t_j = angle_j / 100 deg,
fitted by least squares over the stored configurations of that motion
(values first brought to the 50th percentile with the coefficient of
variation).  Every motion uses the same 15-column design so the whole page
is predicted with one numpy expression.

No Textual import here: the strength page asks a StrengthSheet for rows.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import numpy.typing as npt

from sass_tui.model import datasets
from sass_tui.model.errors import SassError
from sass_tui.model.files.paths import PathError, read_user_text
from sass_tui.model.files.popfile import NO_VALUE, split_data_row
from sass_tui.model.names import JOINT_AXIS_LABELS, MOTIONS, normalise_label
from sass_tui.model.population.percentile import _STANDARD
from sass_tui.model.population.percentile_arrays import check_percentiles, z_score
from sass_tui.model.strength.published_strength import EXAMPLE_SOURCE
from sass_tui.model.strength.strength_conditions import StrengthError
from sass_tui.model.text import quoted
from sass_tui.model.units import convert
from sass_tui.model.vocabulary import GENDERS, JOINT_AXES, MOTION_NAMES, SIDES

FILE_NAME = "strength.dat"

_MOTION_ALIASES = {
    "shoulder internal rotation": "shoulder_medial_rotation",
    "shoulder external rotation": "shoulder_lateral_rotation",
    "wrist radial abduction": "wrist_radial_deviation",
    "wrist ulnar adduction": "wrist_ulnar_deviation",
}

N_ANGLES = len(JOINT_AXES)
N_FEATURES = 1 + 2 * N_ANGLES
_ANGLE_SCALE = 100.0  # keeps t^2 near 1 so lstsq is well conditioned

# --- documented constants (docs/model.md, "Strength") ----------------------
# La Delfa & Potvin 2017, Applied Ergonomics 59:410-421.
STRENGTH_CV = 0.277


# A prediction for an angle further than this outside the angles a motion's
# data cover is refused: the fitted quadratic has nothing to hold it there
# (shoulder flexion at 180 deg, data to 75 deg, predicted 0.01 ft-lb).
EXTRAPOLATION_MARGIN_DEG = 20.0
# A file whose 'P' title says this is test data, and every output from it says so.
TEST_DATA_MARKER = "test data"
TEST_DATA_LABEL = "TEST DATA, not measured strength"


class StrengthFileError(ValueError, SassError):
    """The strength file breaks the format; nothing of it was loaded."""


# --- the file -------------------------------------------------------------


@dataclass
class StrengthSection:
    """The rows of one `G gender` / `L side` section that can be used."""

    gender: str
    side: str
    line: int
    motions: np.ndarray  # (n,) index into MOTIONS
    angles: np.ndarray  # (n, 7) deg
    values: np.ndarray  # (n,) ft-lb at `percentiles`
    percentiles: np.ndarray  # (n,)
    lines: np.ndarray  # (n,) file line of each row
    notes: list[str] = field(default_factory=list)


@dataclass
class StrengthData:
    title: str
    path: str
    sections: dict[tuple[str, str], StrengthSection] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    # A person's own measurements: the conditions they were measured at
    # (strength_type, motion_speed, training_level, fatigue_level); the
    # modifiers then scale from these, not from rested isometric strength.
    measured_at: tuple[str, float, float, float] | None = None
    _models: dict[tuple[str, str], StrengthModel] = field(default_factory=dict, repr=False)

    @property
    def test_data(self) -> bool:
        """The file says (in its P title) that its values are test data."""
        return TEST_DATA_MARKER in self.title.lower()

    @property
    def label(self) -> str:
        """What the numbers are, for a page title or a file comment."""
        if self.test_data:
            return f"{TEST_DATA_LABEL} ({Path(self.path).name})"
        if self.measured_at is not None:
            return self.title
        return f"{self.title} ({Path(self.path).name})"

    @property
    def source(self) -> str:
        """Where the numbers come from, in the words every answer carries."""
        return EXAMPLE_SOURCE if self.test_data else self.label

    def section(self, gender: str, side: str) -> tuple[StrengthSection, bool]:
        """The section for gender and side, or the other side's (measured=False)."""
        if (gender, side) in self.sections:
            return self.sections[(gender, side)], True
        other = SIDES[1 - SIDES.index(side)]
        if (gender, other) in self.sections:
            return self.sections[(gender, other)], False
        raise StrengthError(f"{self.path}: no {gender} strength data")

    def model(self, gender: str, side: str) -> StrengthModel:
        section, _ = self.section(gender, side)
        key = (section.gender, section.side)
        if key not in self._models:
            self._models[key] = StrengthModel(section)
        return self._models[key]


_WIDTH = N_ANGLES + 2
# A data row as read: (line, motion index, the 9 numbers, its /* comment */).
_RawRow = tuple[int, int, list[float], str]
_LAYOUT = "(shoulder x y z, elbow y, wrist x y z, strength value, percentile)"


def default_path() -> Path:
    return datasets.path(FILE_NAME)


def read_strength_file(path: str | Path | None = None) -> StrengthData:
    where = default_path() if path is None else path
    try:
        read, text = read_user_text(where, "a strength file")
    except PathError as exc:
        raise StrengthFileError(f"{where}: cannot read: {exc.reason}") from None
    return parse_strength_text(text, str(read))


def motion_index(text: str) -> int:
    """'shoulder abduction', 'Shoulder_Abduction', 'r shoulder abduction' -> row index."""
    key = normalise_label(text).replace("_", " ")
    key = re.sub(r"^(r|l|right|left) ", "", key)
    key = _MOTION_ALIASES.get(key, key).replace(" ", "_")
    if key in MOTION_NAMES:
        return MOTION_NAMES.index(key)
    raise StrengthError(
        f"unknown motion {quoted(text.strip())}; expected one of {', '.join(MOTION_NAMES)}"
    )


def parse_strength_text(text: str, name: str = "<text>") -> StrengthData:
    lines = text.splitlines()
    if not any(ln.strip() for ln in lines):
        raise StrengthFileError(
            f"{name}:1: the file is empty; expected a 'P' title, "
            "'G MALE' or 'G FEMALE', 'L RIGHT' or 'L LEFT' and rows of "
            f"{_WIDTH} numbers"
        )
    title = ""
    gender: str | None = None
    key: tuple[str, str] | None = None
    raw: dict[tuple[str, str], tuple[int, list[_RawRow]]] = {}
    warnings: list[str] = []
    for lineno, line in enumerate(lines, start=1):
        where = f"{name}:{lineno}"
        if not line.strip():
            continue
        tag = line[0]
        if tag == "C":
            continue
        if tag == "P":
            if not title:
                title = line[1:].strip()
            continue
        if tag == "G":
            word = line[1:].strip().lower()
            if word not in GENDERS:
                raise StrengthFileError(
                    f"{where}: expected 'G MALE' or 'G FEMALE', found {quoted(line.strip())}"
                )
            gender, key = word, None
            continue
        if tag == "L":
            word = line[1:].strip().lower()
            if word not in SIDES:
                raise StrengthFileError(
                    f"{where}: expected 'L RIGHT' or 'L LEFT', found {quoted(line.strip())}"
                )
            if gender is None:
                raise StrengthFileError(
                    f"{where}: 'L {word.upper()}' before 'G MALE' or 'G FEMALE'"
                )
            key = (gender, word)
            if key in raw:
                raise StrengthFileError(
                    f"{where}: a second G {gender.upper()} / "
                    f"L {word.upper()} section (first at line "
                    f"{raw[key][0]})"
                )
            raw[key] = (lineno, [])
            continue
        numbers, comment = split_data_row(line, where, _WIDTH, _LAYOUT, StrengthFileError)
        if key is None:
            raise StrengthFileError(f"{where}: data before 'G MALE|FEMALE' and 'L RIGHT|LEFT'")
        if not comment:
            raise StrengthFileError(
                f"{where}: no /* motion */ comment; expected the motion "
                "impetus, e.g. /* shoulder abduction */"
            )
        label = comment.split(":", 1)[0]
        try:
            motion = motion_index(label)
        except StrengthError as exc:
            raise StrengthFileError(f"{where}: {exc}") from None
        _check_magnitudes(numbers, where)
        percentile = numbers[-1]
        if percentile != NO_VALUE and not 0.5 <= percentile <= 99.5:
            raise StrengthFileError(
                f"{where}: percentile {percentile:g} is outside 0.5-99.5 (value 9)"
            )
        raw[key][1].append((lineno, motion, numbers, comment))
    if not raw:
        raise StrengthFileError(
            f"{name}:{len(lines)}: no 'G MALE|FEMALE' with an 'L RIGHT|LEFT' section"
        )
    data = StrengthData(title=title or Path(name).name, path=name, warnings=warnings)
    for key, (section_line, entries) in raw.items():
        data.sections[key] = _build_section(key, section_line, entries, name, warnings)
    return data


# No joint turns further than a full circle, and no human joint exerts more
# than a few hundred ft-lb: beyond these a number is a typing error, and left
# in it would overflow the fit (t^2 of an angle of 1e200 is infinite).
LARGEST_ANGLE = 360.0
LARGEST_STRENGTH = 10_000.0  # ft-lb


def _check_magnitudes(numbers: list[float], where: str) -> None:
    """Refuse angles and strength values no measurement can have (999 = no value)."""
    for col, angle in enumerate(numbers[:N_ANGLES], start=1):
        if angle != NO_VALUE and abs(angle) > LARGEST_ANGLE:
            raise StrengthFileError(
                f"{where}: value {col} ({JOINT_AXIS_LABELS[col - 1]}) is {angle:g} deg; "
                f"expected an angle within ±{LARGEST_ANGLE:g} deg (999 = no value)"
            )
    value = numbers[N_ANGLES]
    if value != NO_VALUE and abs(value) > LARGEST_STRENGTH:
        raise StrengthFileError(
            f"{where}: value {N_ANGLES + 1} (strength) is {value:g} ft-lb; "
            f"expected at most {LARGEST_STRENGTH:g} ft-lb (999 = no value)"
        )


def _build_section(
    key: tuple[str, str],
    section_line: int,
    entries: list[_RawRow],
    name: str,
    warnings: list[str],
) -> StrengthSection:
    gender, side = key
    heading = f"G {gender.upper()} / L {side.upper()}"
    kept: dict[tuple[int, tuple[float, ...]], int] = {}
    rows: list[tuple[int, int, list[float], float, float, str]] = []
    last_motion = -1
    for lineno, motion, numbers, comment in entries:
        where = f"{name}:{lineno}: {MOTIONS[motion].label}"
        angles, value, percentile = numbers[:N_ANGLES], numbers[-2], numbers[-1]
        if motion < last_motion:
            warnings.append(
                f"{where}: out of display order (after {MOTIONS[last_motion].label}); kept"
            )
        last_motion = max(last_motion, motion)
        if NO_VALUE in angles:
            missing = [JOINT_AXES[i] for i, a in enumerate(angles) if a == NO_VALUE]
            warnings.append(f"{where}: no value for {', '.join(missing)}; row not used")
            continue
        if value == NO_VALUE or percentile == NO_VALUE:
            warnings.append(f"{where}: no strength value; row not used")
            continue
        if value <= 0:
            warnings.append(f"{where}: strength {value:g} is not positive; row not used")
            continue
        config = (motion, tuple(round(a, 3) for a in angles))
        if config in kept:
            warnings.append(
                f"{where}: configuration given again (first at line "
                f"{rows[kept[config]][0]}); this later row is used"
            )
            rows[kept[config]] = (lineno, motion, angles, value, percentile, comment)
            continue
        kept[config] = len(rows)
        rows.append((lineno, motion, angles, value, percentile, comment))
    present = {r[1] for r in rows}
    missing_motions = [MOTIONS[i].label for i in range(len(MOTIONS)) if i not in present]
    if missing_motions:
        warnings.append(
            f"{name}:{section_line}: {heading} has no data for "
            f"{', '.join(missing_motions)}; those rows stay blank"
        )
    return StrengthSection(
        gender=gender,
        side=side,
        line=section_line,
        motions=np.array([r[1] for r in rows], dtype=int),
        angles=np.array([r[2] for r in rows], dtype=float).reshape(-1, N_ANGLES),
        values=np.array([r[3] for r in rows], dtype=float),
        percentiles=np.array([r[4] for r in rows], dtype=float),
        lines=np.array([r[0] for r in rows], dtype=int),
        notes=[r[5] for r in rows],
    )


# --- a person's own strength ---------------------------------------------------


def person_strength_data(
    name: str,
    gender: str,
    measurements: list[tuple[str, str, tuple[float, ...], float, tuple[str, float, float, float]]],
    conditions: tuple[str, float, float, float] | None = None,
) -> StrengthData:
    """A person's own strength (report §12.4, Disp. Indv.) as strength data the
    strength page shows like a file's: one stored row per experiment and
    motion, at the person's angles, in ft-lb.  `measurements` are
    (side, motion, 7 angles deg, strength N-m, conditions) as
    db.individual.strength_measurements gives them.  Only the experiments
    measured at `conditions` (strength_type, motion_speed, training_level,
    fatigue_level; default: those most of the experiments share) are used, so
    that isokinetic values are not fitted together with isometric ones.
    StrengthError when the person has no strength experiments."""
    if not measurements:
        raise StrengthError(f"{name} has no strength experiments in the database")
    if conditions is None or not any(m[4] == conditions for m in measurements):
        counts: dict[tuple[str, float, float, float], int] = {}
        for m in measurements:
            counts[m[4]] = counts.get(m[4], 0) + 1
        conditions = max(counts, key=lambda c: counts[c])
    kind, speed, training, fatigue = conditions
    what = kind if kind == "isometric" else f"{kind} at {speed:g} deg/s"
    title = (
        f"{name}'s own strength experiments ({what}, training {training:g}, "
        f"fatigue {fatigue:g}; database)"
    )
    source = f"database:{name}"
    warnings: list[str] = []
    data = StrengthData(title=title, path=source, warnings=warnings, measured_at=conditions)
    for side in SIDES:
        entries = []
        for i, (where, motion, angles, value_nm, measured) in enumerate(measurements):
            if where != side or measured != conditions:
                continue
            value = float(convert(value_nm, "N_m", "ft_lb"))
            numbers = [*map(float, angles), value, 50.0]
            entries.append((i + 1, MOTION_NAMES.index(motion), numbers, f"{motion}: measured"))
        if entries:
            entries.sort(key=lambda e: e[1])
            data.sections[(gender, side)] = _build_section(
                (gender, side), 0, entries, source, warnings
            )
    # A person measures a few motions: the others are "no data", not a warning.
    data.warnings[:] = [w for w in warnings if "has no data for" not in w]
    return data


# --- percentiles ------------------------------------------------------------


def percentile_factor(p: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Strength at percentile p over the 50th: 1 + z(p) * CV (normal, CV 0.277)."""
    check_percentiles(p)
    return 1.0 + z_score(p) * STRENGTH_CV


def strength_percentile(value: float, median: float) -> float:
    """Percentile of a strength against the 50th-percentile value (inverse)."""
    if not (median > 0) or math.isnan(value):
        return float("nan")
    return _STANDARD.cdf((value / median - 1.0) / STRENGTH_CV) * 100.0


# --- the prediction equation -------------------------------------------------


def design(angles: np.ndarray) -> np.ndarray:
    """(k, 7) angles in deg -> (k, 15) columns [1, t_1..t_7, t_1^2..t_7^2]."""
    t = np.asarray(angles, dtype=float) / _ANGLE_SCALE
    return np.concatenate([np.ones((t.shape[0], 1)), t, t * t], axis=1)


@dataclass
class MotionFit:
    motion: str
    points: int
    coefficients: np.ndarray  # (15,), zero for columns the data never vary
    rms_percent: float  # relative fit error over the stored points
    max_percent: float
    varied: tuple[str, ...]


class StrengthModel:
    """Stored lookup and the fitted equations for one gender/side section."""

    def __init__(self, section: StrengthSection) -> None:
        self.section = section
        n = len(MOTIONS)
        self.coefficients = np.zeros((n, N_FEATURES))
        self.available = np.zeros(n, dtype=bool)
        self.ceiling = np.full(n, np.nan)
        self.fits: list[MotionFit | None] = [None] * n
        self._stored: list[dict[tuple[float, ...], tuple[float, float]]] = [{} for _ in range(n)]
        # the angles each motion's data cover (deg): lowest and highest per axis
        self.low = np.full((n, N_ANGLES), np.nan)
        self.high = np.full((n, N_ANGLES), np.nan)
        median = section.values / percentile_factor(section.percentiles)
        for row, motion in enumerate(section.motions):
            key = _config_key(section.angles[row])
            self._stored[motion][key] = (section.values[row], section.percentiles[row])
        for motion in range(n):
            mask = section.motions == motion
            if mask.any():
                self.low[motion] = section.angles[mask].min(axis=0)
                self.high[motion] = section.angles[mask].max(axis=0)
                fit = self._fit(motion, section.angles[mask], median[mask])
                self.fits[motion] = fit
                self.coefficients[motion] = fit.coefficients
                self.available[motion] = True
                # A quadratic can rise without bound away from the data.
                self.ceiling[motion] = median[mask].max()

    def _fit(self, motion: int, angles: np.ndarray, median: np.ndarray) -> MotionFit:
        full = design(angles)
        # Distinct values by set, not np.unique (which imports numpy.ma: 25 ms of `sass fig`).
        distinct = [len(set(angles[:, j].tolist())) for j in range(N_ANGLES)]
        used = (
            [0]
            + [1 + j for j in range(N_ANGLES) if distinct[j] >= 2]
            + [1 + N_ANGLES + j for j in range(N_ANGLES) if distinct[j] >= 3]
        )
        target = np.log(median)
        if not (np.isfinite(full).all() and np.isfinite(target).all()):
            # lstsq never returns on an infinite entry and LAPACK prints on NaN.
            raise StrengthError(f"{MOTIONS[motion].label}: the data hold a number too large to fit")
        try:
            solution, *_ = np.linalg.lstsq(full[:, used], target, rcond=None)
        except np.linalg.LinAlgError as exc:
            raise StrengthError(f"{MOTIONS[motion].label}: the fit failed ({exc})") from None
        coefficients = np.zeros(N_FEATURES)
        coefficients[used] = solution
        relative = np.minimum(np.exp(full @ coefficients), median.max()) / median - 1.0
        return MotionFit(
            motion=MOTION_NAMES[motion],
            points=len(median),
            coefficients=coefficients,
            rms_percent=float(np.sqrt(np.mean(relative**2)) * 100.0),
            max_percent=float(np.abs(relative).max() * 100.0),
            varied=tuple(JOINT_AXES[j] for j in range(N_ANGLES) if distinct[j] >= 2),
        )

    def coverage(self, motion: int, angles: npt.ArrayLike) -> tuple[str, bool]:
        """(note, refused) for a prediction at `angles`: the note names every
        angle outside the data of this motion ('' inside them); refused when a
        varied angle lies more than EXTRAPOLATION_MARGIN_DEG outside."""
        if not self.available[motion]:
            return "", False
        notes, refused = [], False
        for j, angle in enumerate(np.asarray(angles, dtype=float)):
            low, high = self.low[motion, j], self.high[motion, j]
            if low - 1e-9 <= angle <= high + 1e-9:
                continue
            axis = JOINT_AXES[j]
            if low == high:
                notes.append(
                    f"{axis} {angle:g} deg: the data hold {axis} only at {low:g} deg, "
                    "so the prediction does not vary with it"
                )
                continue
            off = low - angle if angle < low else angle - high
            far = off > EXTRAPOLATION_MARGIN_DEG
            refused = refused or far
            notes.append(
                f"{axis} {angle:g} deg is outside the data's {low:g} to {high:g} deg"
                + (
                    f", more than {EXTRAPOLATION_MARGIN_DEG:g} deg: not to be trusted"
                    if far
                    else ""
                )
            )
        return "; ".join(notes), refused

    def stored(self, motion: int, angles: Iterable[float]) -> tuple[float, float] | None:
        """(value ft-lb, its percentile) when the configuration is in the data."""
        return self._stored[motion].get(_config_key(angles))

    def predict_median(self, motions: np.ndarray, angles: np.ndarray) -> np.ndarray:
        """50th-percentile strength (ft-lb) by the equation; NaN without data."""
        motions = np.asarray(motions, dtype=int)
        log_value = np.einsum("ij,ij->i", design(angles), self.coefficients[motions])
        value = np.minimum(np.exp(log_value), self.ceiling[motions])
        return np.where(self.available[motions], value, np.nan)

    def evaluate(
        self, motions: npt.ArrayLike, angles: npt.ArrayLike, percentile: float = 50.0
    ) -> tuple[np.ndarray, np.ndarray]:
        """Strength (ft-lb, before modifiers) at `percentile`, and a stored? mask.

        A stored value is scaled from its own percentile to `percentile` (it
        comes back unchanged at that percentile); the rest are predicted.
        """
        motions = np.asarray(motions, dtype=int)
        angles = np.asarray(angles, dtype=float).reshape(-1, N_ANGLES)
        target = percentile_factor(percentile)
        values = self.predict_median(motions, angles) * target
        stored = np.zeros(len(motions), dtype=bool)
        for i, motion in enumerate(motions):
            hit = self._stored[motion].get(_config_key(angles[i]))
            if hit is not None:
                value, at = hit
                values[i] = value if at == percentile else value * target / percentile_factor(at)
                stored[i] = True
        return values, stored


def _config_key(angles: Iterable[float]) -> tuple[float, ...]:
    return tuple(round(float(a), 3) for a in angles)
