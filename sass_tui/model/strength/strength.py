"""Strength: the strength page's state (the StrengthSheet: one limb side, one
configuration per motion) and the strength sections of a .fig file (report
§12.2.2-§12.2.4, figure 5; spec §2 "Strength").

The file format and the prediction equation are strength_data.py, the
modifiers and joint limits strength_conditions.py; their names are also
importable from here.  No Textual import here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from sass_tui.model.body.figure import Figure
from sass_tui.model.names import JOINT_AXIS_LABELS, MOTIONS, STRENGTH
from sass_tui.model.population.percentile import check_percentile
from sass_tui.model.strength import published_strength as published
from sass_tui.model.strength.strength_conditions import (
    ASSUMED_LABEL,
    ASSUMED_MODIFIERS,
    DEFAULT_NON_DOMINANT_FACTOR,
    ENDURANCE_POWER_MODEL,
    ISOKINETIC_DECAY_PER_DEG_S,
    MOTION_JOINT,
    TRAINING_GAIN_PER_LEVEL,
    MeasuredConditions,
    StrengthConditions,
    StrengthError,
    assumed_modifiers_asked,
    check_angle,
    fatigue_factor,
    handedness_factor,
    joint_limit_range,
    limits_source,
    modifier_factors,
    parse_joint_axis,
    parse_side_factor,
    strength_type_factor,
    training_factor,
)
from sass_tui.model.strength.strength_data import (
    EXTRAPOLATION_MARGIN_DEG,
    FILE_NAME,
    LARGEST_ANGLE,
    LARGEST_STRENGTH,
    N_ANGLES,
    N_FEATURES,
    STRENGTH_CV,
    TEST_DATA_LABEL,
    TEST_DATA_MARKER,
    MotionFit,
    StrengthData,
    StrengthFileError,
    StrengthModel,
    StrengthSection,
    default_path,
    design,
    motion_index,
    parse_strength_text,
    percentile_factor,
    person_strength_data,
    read_strength_file,
    strength_percentile,
)
from sass_tui.model.units import DISPLAY, GROUP_UNITS, convert, parse_quantity, unit_name
from sass_tui.model.vocabulary import JOINT_AXES, MOTION_NAMES, SIDES

__all__ = [
    "ASSUMED_LABEL",
    "ASSUMED_MODIFIERS",
    "assumed_modifiers_asked",
    "DEFAULT_NON_DOMINANT_FACTOR",
    "ENDURANCE_POWER_MODEL",
    "EXTRAPOLATION_MARGIN_DEG",
    "FILE_NAME",
    "ISOKINETIC_DECAY_PER_DEG_S",
    "JOINT_AXIS_LABELS",
    "LARGEST_ANGLE",
    "LARGEST_STRENGTH",
    "MOTIONS",
    "MOTION_JOINT",
    "MOTION_NAMES",
    "N_ANGLES",
    "N_FEATURES",
    "STRENGTH_CV",
    "TEST_DATA_LABEL",
    "TEST_DATA_MARKER",
    "TRAINING_GAIN_PER_LEVEL",
    "MotionFit",
    "StrengthConditions",
    "StrengthData",
    "StrengthError",
    "StrengthFileError",
    "StrengthModel",
    "StrengthRow",
    "StrengthSection",
    "StrengthSheet",
    "check_angle",
    "default_path",
    "design",
    "fatigue_factor",
    "fig_section",
    "fit_summary",
    "handedness_factor",
    "joint_limit_range",
    "limits_source",
    "lower_limb_fig_section",
    "modifier_factors",
    "motion_index",
    "parse_joint_axis",
    "parse_side_factor",
    "parse_strength_text",
    "percentile_factor",
    "person_strength_data",
    "read_strength_file",
    "strength_percentile",
    "strength_type_factor",
    "training_factor",
]


# --- the strength page's state --------------------------------------------------


@dataclass(frozen=True)
class StrengthRow:
    """One row of the strength page, in the sheet's current unit."""

    index: int
    motion: str
    label: str
    side: str
    angles: tuple[float, ...]  # deg, in JOINT_AXES order
    value: float  # NaN = no data for this motion
    source: str  # "stored" | "predicted" | "no data"
    unit: str  # display spelling, "ft-lb" | "N-m"
    # "" or why a predicted value is an extrapolation (angles outside the data)
    extrapolated: str = ""


class StrengthSheet:
    """What the strength page shows: one limb side, one configuration per motion.

    Values are computed on demand from the figure's current gender, joint
    limits and strength parameters, so a changed global parameter shows at
    the next rows() call."""

    ROWS_PER_PAGE = 14

    def __init__(self, data: StrengthData, figure: Figure) -> None:
        self.data = data
        self.figure = figure
        self.side = "right"
        self.unit = GROUP_UNITS[STRENGTH][0]
        self.percentile = 50.0
        self.non_dominant_factor = DEFAULT_NON_DOMINANT_FACTOR
        # the isokinetic decay and the training gain: off unless asked for
        self.assumed_modifiers = False
        self.angles = self._default_angles()

    @classmethod
    def default(cls, figure: Figure) -> StrengthSheet:
        return cls(read_strength_file(), figure)

    def _default_angles(self) -> np.ndarray:
        """Each motion at its first stored configuration (figure 5 shows the
        report's point first); neutral with the elbow at 90 deg without data."""
        angles = np.tile(np.array([0, 0, 0, 90, 0, 0, 0], dtype=float), (len(MOTIONS), 1))
        try:
            section, _ = self.data.section(self.figure.gender, self.side)
        except StrengthError:
            return angles
        for motion in range(len(MOTIONS)):
            rows = np.flatnonzero(section.motions == motion)
            if rows.size:
                angles[motion] = section.angles[rows[0]]
        return angles

    # --- reading -------------------------------------------------------------
    def values(self) -> tuple[np.ndarray, np.ndarray]:
        """Every row's strength (ft-lb, modifiers applied) and stored? mask.

        A person's own data were measured at their own conditions: the
        modifiers scale from those (at the same conditions and side, the
        measured value comes back unchanged)."""
        model = self.data.model(self.figure.gender, self.side)
        base, stored = model.evaluate(np.arange(len(MOTIONS)), self.angles, self.percentile)
        assumed = self.assumed_modifiers
        factors = modifier_factors(self.figure, self.side, self.non_dominant_factor, assumed)
        if self.data.measured_at is not None:
            kind, speed, training, fatigue = self.data.measured_at
            measured = MeasuredConditions(
                strength_type=kind,
                motion_speed=speed,
                training_level=training,
                fatigue_level=fatigue,
                handedness=self.figure.handedness,
            )
            factors = factors / modifier_factors(
                measured, model.section.side, self.non_dominant_factor, assumed
            )
        return base * factors, stored

    def rows(self) -> list[StrengthRow]:
        values, stored = self.values()
        shown = convert(values, GROUP_UNITS[STRENGTH][0], self.unit)
        model = self.data.model(self.figure.gender, self.side)
        return [
            StrengthRow(
                i,
                m.name,
                m.label,
                self.side,
                tuple(map(float, self.angles[i])),
                float(shown[i]),
                "no data" if math.isnan(values[i]) else "stored" if stored[i] else "predicted",
                DISPLAY[self.unit],
                "" if stored[i] or math.isnan(values[i]) else model.coverage(i, self.angles[i])[0],
            )
            for i, m in enumerate(MOTIONS)
        ]

    @property
    def title(self) -> str:
        """What the page shows, for its title: the data's label and source,
        and the assumed modifiers when on (or asked for and off)."""
        data = self.data
        # The source first: a narrow page crops the end of its title.
        title = f"Strength: {data.label}"
        if data.source != data.label:
            title = f"Strength: {data.source}; {data.label}"
        if self.assumed_modifiers:
            return f"{title}; {ASSUMED_LABEL}"
        if assumed_modifiers_asked(self.figure):
            return f"{title}; {ASSUMED_MODIFIERS} off (no published source)"
        return title

    def toggle_assumed_modifiers(self) -> str:
        """Turn the isokinetic decay and the training gain on or off; the message."""
        self.assumed_modifiers = not self.assumed_modifiers
        if self.assumed_modifiers:
            return f"{ASSUMED_LABEL[0].upper()}{ASSUMED_LABEL[1:]}."
        return f"{ASSUMED_MODIFIERS.capitalize()} off: no published source for these motions."

    def row(self, index: int) -> StrengthRow:
        return self.rows()[index]

    def page(self, number: int) -> list[StrengthRow]:
        start = number * self.ROWS_PER_PAGE
        return self.rows()[start : start + self.ROWS_PER_PAGE]

    @property
    def pages(self) -> int:
        return -(-len(MOTIONS) // self.ROWS_PER_PAGE)

    # --- editing -----------------------------------------------------------
    def set_angle(self, index: int, joint_axis: str | int, value: str | float) -> StrengthRow:
        """Set one angle (text like "30", "0.5 rad", or deg) and recompute the row.

        Refused (StrengthError, nothing changed) outside the joint limits."""
        column = joint_axis if isinstance(joint_axis, int) else parse_joint_axis(joint_axis)
        degrees = parse_quantity(value, "deg") if isinstance(value, str) else float(value)
        check_angle(self.figure, self.side, JOINT_AXES[column], degrees)
        self.angles[index, column] = degrees
        return self.row(index)

    def set_unit(self, unit: str) -> None:
        name = unit_name(unit) if unit not in GROUP_UNITS[STRENGTH] else unit
        if name not in GROUP_UNITS[STRENGTH]:
            raise StrengthError(f"strength is shown in ft-lb or N-m, not {unit}")
        self.unit = name

    def toggle_unit(self) -> str:
        a, b = GROUP_UNITS[STRENGTH]
        self.unit = b if self.unit == a else a
        return DISPLAY[self.unit]

    def set_percentile(self, p: float) -> None:
        check_percentile(p)
        self.percentile = float(p)

    def switch_side(self, factor_text: str = "") -> str:
        """Right->Left / Left->Right: show the other limb, the non-dominant one
        scaled by the typed factor (RETURN = the default).  Returns the message."""
        factor = parse_side_factor(factor_text)
        self.non_dominant_factor = factor
        self.side = SIDES[1 - SIDES.index(self.side)]
        return f"Showing the {self.side} limb; non-dominant limb scaled by {factor:.3f}" + (
            " (default)" if not factor_text.strip() else ""
        )

    def fig_variables(self) -> list[tuple[str, float, str]]:
        """.fig strength variables: `<side>_<motion>_strength` in Nm for both
        limbs at the sheet's configurations (docs/model.md)."""
        out = []
        current = self.side
        try:
            for side in SIDES:
                self.side = side
                values, _ = self.values()
                for motion, value in zip(MOTION_NAMES, convert(values, "ft_lb", "N_m")):
                    if not math.isnan(value):
                        out.append((f"{side}_{motion}_strength", float(value), "Nm"))
        finally:
            self.side = current
        return out


def _label_and_source(data: StrengthData) -> str:
    """'TEST DATA, ... (strength.dat); source: example data (invented, ...)'."""
    if data.source == data.label:
        return data.label
    return f"{data.label}; source: {data.source}"


def fig_section(sheet: StrengthSheet) -> tuple[str, list[tuple[str, float, str]]]:
    """The strength section for figfile.render_fig(extra_sections=[...]); its
    title says what the values are and where they come from (test data, or
    the file's title)."""
    title = f"strength variables: {_label_and_source(sheet.data)}"
    if sheet.assumed_modifiers:
        title += f"; {ASSUMED_LABEL}"
    return (title, sheet.fig_variables())


def lower_limb_fig_section(
    figure: Figure, side: str = "right", percentile: float = 50.0
) -> tuple[str, list[tuple[str, float, str]]]:
    """The figure's hip, knee and ankle strength (Anderson et al. 2007) for a
    .fig file, from its gender, mass and stature (a figure has no age: the
    18-25 group) within its joint limits."""
    subject = published.Subject(
        figure.gender, published.AGE_GROUPS[0][1], figure.output_mass(), figure.stature / 100.0
    )
    limits = {axis: joint_limit_range(figure, side, axis) for axis in published.LOWER_LIMB_AXES}
    return published.fig_section(subject, limits, percentile, age_given=False)


def fit_summary(data: StrengthData) -> list[tuple[str, str, MotionFit]]:
    """(gender, side, fit) for every fitted motion (docs/model.md's table)."""
    out = []
    for gender, side in data.sections:
        model = data.model(gender, side)
        out += [(gender, side, fit) for fit in model.fits if fit is not None]
    return out
