"""Everything stored about one person as lines of text (db/people/individual.py's
person_record): what `sass person` prints and the query screen's person
view shows.  Canonical units (cm, kg, deg, N-m); names, sources and survey
fields come from files and are shown escaped (model/text.py)."""

from __future__ import annotations

from typing import Any

from sass_tui.db.query.scope import DEMONSTRATION_SOURCE, VIRTUAL_PREFIX
from sass_tui.model.measures import MEASURE_UNITS
from sass_tui.model.text import printable

ATTRIBUTES = ("handedness", "component", "branch", "subjectnumericrace", "dodrace", "ethnicity")
GROUP_WORDS = (("girth", "cm"), ("joint_limit", "deg"), ("center_of_mass", "cm"))


def number_text(value: object) -> str:
    return "—" if value is None else f"{value:.2f}" if isinstance(value, float) else str(value)


def person_lines(record: dict[str, Any]) -> list[str]:
    """The record's lines: who, the survey's attributes, each group's rows
    (x y z), strength, the measures with their units, how many unmeasured."""
    values: dict[str, object] = record["values"]
    source = str(record["source"])
    demonstration = (
        ", a synthetic demonstration person, not a real one"
        if source.lower() == DEMONSTRATION_SOURCE
        else ", a VIRTUAL person: stature, mass and age a survey's, the rest predicted"
        if source.lower().startswith(VIRTUAL_PREFIX)
        else ""
    )
    lines = [
        f"{printable(record['name'])} (id {record['id']}{demonstration}): "
        f"{printable(record['gender'])}, stature "
        f"{number_text(record['stature'])} cm, mass {number_text(record['mass'])} kg, age "
        f"{number_text(record['age'])}; source {printable(source)}"
    ]
    attributes = [f"{name} {printable(values[name])}" for name in ATTRIBUTES if name in values]
    if attributes:
        lines.append("  " + "; ".join(attributes))
    for word, unit in GROUP_WORDS:
        rows: dict[str, list[object]] = {}
        for name, value in values.items():
            if name.startswith(word + "."):
                _group, row, axis = name.split(".")
                rows.setdefault(row, [None, None, None])["xyz".index(axis)] = value
        lines.append(f"{word} ({unit}):{'' if rows else ' nothing measured'}")
        for row, cells in rows.items():
            lines.append(f"  {row:<22} " + " ".join(f"{number_text(c):>8}" for c in cells))
    strengths = {k: v for k, v in values.items() if k.startswith("strength.")}
    lines.append(
        f"strength (N-m, largest of the person's experiments):{'' if strengths else ' none'}"
    )
    for name, value in strengths.items():
        lines.append(f"  {name.split('.')[1]:<26} {number_text(value):>8}")
    measures: dict[str, float] = record["measures"]
    lines.append(f"measures:{'' if measures else ' none'}")
    for name, value in measures.items():
        lines.append(f"  {name:<32} {value:>8.2f} {MEASURE_UNITS[name]}")
    lines.append(f"unmeasured: {len(record['unmeasured'])} values")
    return lines
