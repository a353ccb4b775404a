"""PEABODY body description files (.fig), report §3, §9, §10 and appendix F.

    name = value unit;        (one assignment a line, /* comments */ allowed)
    figure ["body.fig"] ("skinny.a");

The writer follows appendix F.  The reader (a lark grammar) is
model/files/fig_reader.py: nothing of sass reads a .fig file back, and lark is off
every start-up path (sass_tui/startup.py).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from sass_tui.model.errors import SassError
from sass_tui.model.files.atomic import write_text_atomic
from sass_tui.model.names import (
    AXES,
    CENTER_OF_MASS,
    DEFAULT_SCALE,
    FIG_PREFIX,
    FIG_SCALE,
    GIRTH,
    GROUP_TITLES,
    JOINT_LIMITS,
    ROWS,
    center_of_mass_variable,
    joint_limit_variable,
)
from sass_tui.model.text import printable

if TYPE_CHECKING:
    from sass_tui.model.body.figure import Figure

ARCHIVES = {"skinny": "skinny.a", "polybody": "polybody.a"}
# One `name = value unit;` line, and a titled section of them.
FigVariable = tuple[str, float, str]
FigSection = tuple[str, list[FigVariable]]


class FigureIncompleteError(ValueError, SassError):
    """Create Figure needs girth, joint limits and center of mass loaded."""


class FigParseError(ValueError, SassError):
    """A .fig file that does not follow the PEABODY assignment syntax."""


@dataclass
class FigFile:
    variables: dict[str, tuple[float, str]] = field(default_factory=dict)
    body: str = ""
    archive: str = ""


# --- writing -------------------------------------------------------------


def person_joint_lengths(figure: Figure) -> dict[str, float]:
    """A person's limb lengths (cm) from joint centre to joint centre as their
    own landmarks place the joints (model/body/landmarks.py), by girth row: the
    `.fig`'s segment z, so that its joints are the HAnim humanoid's; a length
    set by hand on the spreadsheet stays as set.  Empty for a population
    figure and for a person without those measurements."""
    if not figure.landmarks or math.isnan(figure.stature):
        return {}
    # deferred: model.landmarks — off sass fig (sass_tui/startup.py)
    from sass_tui.model.body.landmarks import joint_lengths, measured_heights

    lengths = joint_lengths(measured_heights(figure.landmarks, figure.stature / 100.0))
    return {
        f"{side}_{stem}": length
        for stem, length in lengths.items()
        if length > 0
        for side in ("right", "left")
        if f"{side}_{stem}" not in figure.hand_set_lengths
    }


def girth_variables(figure: Figure) -> list[FigVariable]:
    """Segment scale variables (cm) and flooroffset, in appendix F order; a
    person's limb z from their joint centres (person_joint_lengths)."""
    values_by_row, _ = figure.output_values(GIRTH)
    values_by_row = values_by_row.copy()
    for name, length in person_joint_lengths(figure).items():
        values_by_row[[r.name for r in ROWS[GIRTH]].index(name), 2] = length
    out: list[FigVariable] = []
    for row, values in zip(ROWS[GIRTH], values_by_row):
        scale = FIG_SCALE.get(row.name, DEFAULT_SCALE)
        for axis, value, factor in zip(AXES, values, scale):
            out.append((f"{FIG_PREFIX[row.name]}{axis}", value * factor, "cm"))
    z = {row.name: values[2] for row, values in zip(ROWS[GIRTH], values_by_row)}
    out.append(("flooroffset", z["right_foot"] + z["right_lower_leg"] + z["right_upper_leg"], "cm"))
    return out


def _axis_variables(
    figure: Figure, group: str, variable_name: Callable[[str, str], str], unit: str
) -> list[FigVariable]:
    """One variable per row and axis that has a value (999 = none, left out)."""
    out: list[FigVariable] = []
    for row, values in zip(ROWS[group], figure.output_values(group)[0]):
        for axis, value in zip(AXES, values):
            if not math.isnan(value):
                out.append((variable_name(row.name, axis), value, unit))
    return out


def joint_limit_variables(figure: Figure) -> list[FigVariable]:
    return _axis_variables(figure, JOINT_LIMITS, joint_limit_variable, "deg")


def center_of_mass_variables(figure: Figure) -> list[FigVariable]:
    return _axis_variables(figure, CENTER_OF_MASS, center_of_mass_variable, "cm")


def _whose_stature_and_mass(figure: Figure) -> str:
    """A population figure's stature and mass say whose statistics they come
    from (a person's are the person's own)."""
    if figure.person is not None or figure.global_stats is None:
        return ""
    return (
        f" (mass percentile {figure.mass_percentile:g}, stature percentile "
        f"{figure.stature_percentile:g} of {_comment(figure.global_stats.title)})"
    )


def _comment(text: str) -> str:
    """A name for a /* comment */: printable (a stored name may hold ESC and
    BEL), and no `*/` that would end the comment early."""
    return printable(text).replace("*/", "* /")


def render_fig(figure: Figure, extra_sections: Sequence[FigSection] = ()) -> str:
    missing = figure.missing_groups()
    if missing:
        raise FigureIncompleteError(
            f"cannot create a figure: {', '.join(missing)} not loaded for {figure.gender}"
        )
    groups = figure.groups
    who = _comment(figure.person or figure.population)
    lines = [
        "/* body description file written by sass */",
        f"/* {who}; {figure.gender}; figure type {figure.figure_type} */",
        f"/* percentiles: girth {groups[GIRTH].percentile:g}, joint limits "
        f"{groups[JOINT_LIMITS].percentile:g}, center of mass {groups[CENTER_OF_MASS].percentile:g}; "
        f"mass {figure.output_mass():.2f} kg, stature "
        f"{'not measured' if math.isnan(figure.stature) else f'{figure.stature:.1f} cm'}"
        f"{_whose_stature_and_mass(figure)} */",
    ]
    counts = []
    for group in (GIRTH, JOINT_LIMITS, CENTER_OF_MASS):
        values, filled = figure.output_values(group)
        if filled.any():
            counts.append(
                f"{int(filled.sum())} of the {int(np.count_nonzero(~np.isnan(values)))} "
                f"{GROUP_TITLES[group].lower()} values (at the {GROUP_TITLES[group].lower()} "
                f"percentile, {groups[group].percentile:g})"
            )
    if math.isnan(figure.mass):
        counts.append(f"the total mass (the population's median, {figure.output_mass():.2f} kg)")
    if counts:
        lines.append(
            f"/* not measured for {who}, so taken from the population "
            f"({_comment(figure.population)}): {'; '.join(counts)} */"
        )
    joints = person_joint_lengths(figure)
    if joints:
        lines.append(
            f"/* limb lengths from joint centre to joint centre, placed from {who}'s own "
            f"landmarks as the HAnim humanoid's (docs/hanim.md): "
            f"{', '.join(sorted({FIG_PREFIX[name] + 'z' for name in joints}))} */"
        )
    lines.append("")
    sections = [
        ("segment dimensions", girth_variables(figure)),
        ("mass variables", [(n, v, "kg") for n, v in figure.segment_masses()]),
        ("joint variables", joint_limit_variables(figure)),
        ("center of mass variables", center_of_mass_variables(figure)),
        *extra_sections,
    ]
    for title, variables in sections:
        lines.append(f"/* {title} */")
        lines += [_assignment(name, value, unit) for name, value, unit in variables]
        lines.append("")
    lines.append(f'figure ["body.fig"] ("{ARCHIVES[figure.figure_type]}");')
    return "\n".join(lines) + "\n"


class FigValueError(ValueError, SassError):
    """A value that cannot be written to a .fig file (not a finite number)."""


def _assignment(name: str, value: float, unit: str) -> str:
    """`name = value unit;`, refusing a value the reader could not read back."""
    if not math.isfinite(value):
        raise FigValueError(f"cannot write the figure: {name} is {value} {unit}, not a number")
    return f"{name} = {value:.2f}{unit};"


def write_fig(figure: Figure, path: str | Path, extra_sections: Sequence[FigSection] = ()) -> Path:
    """Write the figure's .fig file atomically.  Refuses an incomplete figure."""
    text = render_fig(figure, extra_sections)
    write_text_atomic(path, text)
    return Path(path)


def default_fig_name(gender: str, percentile: float, figure_type: str = "skinny") -> str:
    """Report §10: MALE50.FIG, FEMALE05.FIG; PB prefix for polybody."""
    if float(percentile).is_integer():
        number = f"{int(percentile):02d}"
    else:
        number = f"{percentile:g}".replace(".", "_")
    prefix = "PB" if figure_type == "polybody" else ""
    return f"{prefix}{gender.upper()}{number}.FIG"
