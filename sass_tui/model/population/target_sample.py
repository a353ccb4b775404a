"""A target population's sample as sass holds it (`Sample`: the values of the
--by fields, a row a person, with the survey weight, gender and age), and the
refusal of a file (`SampleError`).  The CSV file is read by
model/files/sample_file.py (the format is described there): reading it needs the
ANSUR II measure names and the prediction's units, which listing the stored
targets goes without (the `sass target` row of sass_tui/startup.py).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from sass_tui.model.errors import SassError

# A survey's weight column: NHANES's WT... (WTMECPRP, WTINT2YR), or a name
# that says it (survey_weight, sample weight, final_wt); not a body weight.
_SURVEY_WEIGHT = re.compile(
    r"^(wt[a-z0-9_]*|.*\b(survey|sample|sampling|design|final|exam|person|case)[ _]?"
    r"(weight|wt)s?|(weight|wt)[ _]?(survey|sample|sampling|design|final))$"
)


class SampleError(ValueError, SassError):
    """A sample file sass cannot read (nothing was stored)."""

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        SassError.__init__(self, message, where=where)


@dataclass(frozen=True)
class Sample:
    fields: tuple[str, ...]  # the --by fields, in their order
    matrix: npt.NDArray[np.float64]  # (rows with every field, fields), canonical units
    rows: int  # data rows in the file (of the gender asked for)
    incomplete: int  # rows lacking a value of some field (left out)
    # Of the complete rows: the survey weight (1 without --weight), the
    # gender (None without a gender column) and the age (NaN: none).
    weights: npt.NDArray[np.float64] | None = None
    genders: tuple[str, ...] | None = None
    ages: npt.NDArray[np.float64] | None = None
    weighted_by: str | None = None  # the --weight column
    unused_weights: tuple[str, ...] = ()  # columns named like a survey weight, not used
    # Measured values read when the file has their columns (read_sample's
    # `optional`): (complete rows, optional fields), NaN where a row lacks one.
    optional_fields: tuple[str, ...] = ()
    optional: npt.NDArray[np.float64] | None = None

    @property
    def row_weights(self) -> npt.NDArray[np.float64]:
        """Each complete row's weight (1 each without a weight column)."""
        return np.ones(len(self.matrix)) if self.weights is None else self.weights

    def of_gender(self, gender: str) -> Sample:
        """The rows of one gender (the sample must have a gender column)."""
        if self.genders is None:
            return self
        keep = np.array([g == gender for g in self.genders], dtype=bool)
        return Sample(
            self.fields,
            self.matrix[keep],
            int(keep.sum()),
            0,
            None if self.weights is None else self.weights[keep],
            tuple(g for g, k in zip(self.genders, keep) if k),
            None if self.ages is None else self.ages[keep],
            self.weighted_by,
            self.unused_weights,
            self.optional_fields,
            None if self.optional is None else self.optional[keep],
        )


def is_survey_weight(name: str) -> bool:
    """A column name like a survey's weight (WTMECPRP, survey_weight)."""
    return _SURVEY_WEIGHT.match(name.strip().lower()) is not None


def is_weighting_field(field: str) -> bool:
    """A field a target can be made over: stature, mass, measure.<name>."""
    return field in ("stature", "mass") or field.startswith("measure.")
