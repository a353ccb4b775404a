"""The query-language field a measurement's name stands for (`--measures`,
`--by`, a sample file's column): `stature`, `mass`, `measure.<ANSUR II name>`;
and the error of a manikin family, which an unknown name is.

A module of its own, apart from the families' arithmetic
(model/population/accommodation.py, which brings the figure), because reading a target's
sample needs the names and not the figure (db/populations/virtual.py reads the shipped
one; the `sass predict` row of sass_tui/startup.py).
"""

from __future__ import annotations

from sass_tui.model.errors import SassError
from sass_tui.model.measures import MEASURES, suggest
from sass_tui.model.population.prediction import ALIASES


class AccommodationError(ValueError, SassError):
    """A family that cannot be built (too few people or measurements, bad target)."""


def measure_field(name: str) -> str:
    """A `--measures` name as a query-language field: `stature`, `mass`,
    `measure.sittingheight`; a bare ANSUR II name gains `measure.`, and the
    survey's own `stature` / `weightkg` are the person's stature and mass."""
    word = name.strip().lower()
    if word.startswith("measure."):
        word = word.removeprefix("measure.")
        if word not in MEASURES:
            hint = suggest(word)
            raise AccommodationError(
                f"unknown measurement {name.strip()!r}"
                + (f"; did you mean {', '.join('measure.' + h for h in hint)}?" if hint else "")
            )
    if "." in word or word in ("stature", "mass", "age"):
        return word
    if word in MEASURES:
        return ALIASES.get(f"measure.{word}", f"measure.{word}")
    hint = suggest(word)
    raise AccommodationError(
        f"unknown measurement {name.strip()!r}; expected stature, mass or an ANSUR II "
        "measurement (sittingheight, hipbreadthsitting, ...)"
        + (f"; did you mean {', '.join(hint)}?" if hint else "")
    )
