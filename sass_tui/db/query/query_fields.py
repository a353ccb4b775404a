"""Every field of the query language with its unit and what it is: the list
`sass query --fields` prints and docs/query-language.md describes.

The names and units are the compiler's own (`db/query/query.py`'s `field_names`
and `resolve_field`), so the list cannot name a field the compiler refuses.
"""

from __future__ import annotations

from typing import NamedTuple

from sass_tui.db.query.query import TEXT, field_names, resolve_field
from sass_tui.model.measures import MEASURE_TITLES
from sass_tui.model.names import GIRTH_ROWS, JOINT_LIMIT_ROWS

# The person's own fields (db/query/query.py's _GLOBAL_FIELDS).
_PERSON = {
    "gender": "the person's gender",
    "mass": "body mass (ANSUR II: weightkg)",
    "stature": "standing height (ANSUR II: stature)",
    "age": "age in years (a plain number: no unit)",
    "handedness": "the hand the person writes with",
    "writingpreference": "the same as handedness (ANSUR II's name)",
    "source": "where the person comes from: ansur2, synthetic (the demonstration "
    "people) or an import's label; a query that names no source reaches real people only",
    "component": "ANSUR II: Regular Army, Army National Guard or Army Reserve",
    "branch": "ANSUR II: Combat Arms, Combat Support or Combat Service Support",
    "ethnicity": "ANSUR II's self-reported ethnicity, as written",
    "subjectnumericrace": "ANSUR II's race code (digits of the races a person named)",
    "dodrace": "ANSUR II's DoD race code (1 White, 2 Black, 3 Hispanic, 4 Asian, "
    "5 Native American, 6 Pacific Islander, 8 Other)",
    "strength_type": "how the strength was measured",
    "motion_speed": "the speed of an isokinetic strength measurement",
    "training_level": "the strength data's training level (a plain number)",
    "fatigue_level": "the strength data's fatigue level (a plain number)",
}
# Segment dimensions' axes (report §10; docs/model.md).
_GIRTH_AXES = {"x": "depth (thickness)", "y": "width", "z": "length"}
_LIMITS = {"ul": "upper limit", "ll": "lower limit"}
# A stored unit as a query writes it (model/units.py's registry name N_m is typed N·m).
_SHOWN_UNITS = {"N_m": "N·m"}


class FieldDoc(NamedTuple):  # not a dataclass: off sass query's path (model.names.Row)
    name: str
    unit: str  # the stored unit; "text" free text; "word" one of a list; "-" a plain number
    description: str


def field_reference() -> list[FieldDoc]:
    """Every queryable field, in field_names()'s order."""
    labels = {row.name: row.label for row in GIRTH_ROWS + JOINT_LIMIT_ROWS}
    out: list[FieldDoc] = []
    for name, _unit in field_names():
        parts = name.split(".")
        _table, _column, unit, words = resolve_field(parts)
        if words is TEXT:
            shown = "text"
        elif words is not None:
            shown = "word"
        else:
            shown = _SHOWN_UNITS.get(unit or "-", unit or "-")
        out.append(FieldDoc(name, shown, _description(parts, words, labels)))
    return out


def _description(parts: list[str], words: tuple[str, ...] | None, labels: dict[str, str]) -> str:
    head = parts[0]
    if len(parts) == 1:
        text = _PERSON[head]
        if words is not None and words is not TEXT:
            text += f": {', '.join(words)}"
        return text
    if head == "measure":
        return f"ANSUR II measurement: {MEASURE_TITLES[parts[1]]}"
    row, axis = parts[1], parts[2]
    label = labels.get(row, row.replace("_", " "))
    if head == "girth":
        return f"segment dimension: {label}, {_GIRTH_AXES[axis]} ({axis})"
    if head == "center_of_mass":
        return f"center of mass: {label}, along {axis}"
    if head == "joint_limit":
        joint, limit = row.rsplit("_", 1)
        joint_label = label.rsplit(" ", 1)[0]
        return f"joint limit: {joint_label}, {_LIMITS[limit]}, about {axis}"
    return f"strength: {row.replace('_', ' ')}, the maximum"
