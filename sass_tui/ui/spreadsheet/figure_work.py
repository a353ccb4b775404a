"""What the spreadsheet and the app do with the figure's model once the first
screen is drawn: the strength sheet and its data (model/strength/strength.py), the
worksheet file (model/files/worksheet.py), the .fig file's name and text
(model/files/figfile.py), the HAnim humanoid's cells (model/body/hanim.py) and the
figure view's outlines and screen (ui/spreadsheet/figure_screen.py).

A module of its own because all of it brings numpy, which the first screen
does without (the row "the first screen", sass_tui/startup.py); the first
screen's next frame draws the figure panel and makes the strength sheet, so
it imports all of this anyway.  The app reaches it in one place
(`SassApp.figure_work`); the spreadsheet's commands, its strength page and
the app's start with `sass --open` go through that.
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import TYPE_CHECKING

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import NOT_IN_HUMANOID
from sass_tui.model.errors import SassError
from sass_tui.model.files.figfile import default_fig_name, render_fig
from sass_tui.model.files.worksheet import (
    DEFAULT_NAME,
    StrengthSettings,
    Worksheet,
    apply_strength,
    population_strength_sheet,
    read_worksheet,
    read_worksheet_and_strength,
    worksheet_text,
)
from sass_tui.model.names import GIRTH, GROUPS
from sass_tui.model.session import Session
from sass_tui.model.strength.strength import (
    DEFAULT_NON_DOMINANT_FACTOR,
    StrengthData,
    StrengthError,
    StrengthRow,
    StrengthSheet,
    default_path,
    fig_section,
    joint_limit_range,
    lower_limb_fig_section,
    read_strength_file,
)
from sass_tui.model.vocabulary import JOINT_AXES
from sass_tui.ui.spreadsheet.figure_screen import FigureScreen, session_outlines

if TYPE_CHECKING:
    from sass_tui.model.body.outline import Outline


def _slug(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name).strip("_") or "person"


class FigureWork:
    """The work on the figure's model past the first screen; holds nothing."""

    # Right -> Left's default scaling of the non-dominant limb.
    non_dominant_factor = DEFAULT_NON_DOMINANT_FACTOR
    # Save As's name when the worksheet has none yet.
    worksheet_name = DEFAULT_NAME

    # --- the strength sheet and its data -----------------------------------------
    def strength_sheet(
        self,
        path: str | Path | None,
        figure: Figure,
        settings: StrengthSettings | None,
        workdir: Path | None = None,
    ) -> tuple[StrengthSheet | None, str]:
        """The population's strength sheet from `path` (None =
        datasets/strength.dat; inside `workdir` when served), or None and why."""
        try:
            return population_strength_sheet(path, figure, settings, workdir), ""
        except (SassError, OSError) as exc:
            return None, f"Strength data is not loaded ({exc}); SASS runs without it."

    def example_strength_path(self) -> Path:
        """The example strength data (docs/strength.md: invented arm data)."""
        return default_path()

    def read_strength_file(self, path: Path) -> StrengthData:
        return read_strength_file(path)

    def strength_rows(self, sheet: StrengthSheet) -> tuple[list[StrengthRow], str]:
        """The strength page's rows, or none and why (no data for this gender)."""
        try:
            return sheet.rows(), ""
        except StrengthError as exc:
            return [], str(exc)

    def joint_limits(self, sheet: StrengthSheet) -> list[tuple[float, float]]:
        """(lower, upper) of each angle column for the side shown; the joint
        limits change with their percentile and the gender, so asked each time."""
        try:
            return [joint_limit_range(sheet.figure, sheet.side, axis) for axis in JOINT_AXES]
        except StrengthError:
            return [(-math.inf, math.inf)] * len(JOINT_AXES)

    # --- Create Figure: the .fig file ----------------------------------------------
    def file_name(self, figure: Figure, suffix: str) -> str:
        """Create Figure's and the exports' file name: the person's shown, else
        the figure's gender and girth percentile (MALE50.FIG)."""
        if figure.person:
            return f"{_slug(figure.person)}{suffix}"
        name = default_fig_name(figure.gender, figure.groups[GIRTH].percentile, figure.figure_type)
        return name if suffix == ".fig" else Path(name).with_suffix(suffix).name

    def fig_strength(self, figure: Figure, strength: StrengthSheet, word: str) -> tuple[list, str]:
        """The .fig file's strength sections for the answer `word` ('', y, yes
        or example) and what to add to the message about them."""
        # No invented strength unless asked for by name (docs/strength.md):
        # the arm's lines are measured data's, or the example data's on 'example'.
        sections = [lower_limb_fig_section(figure)]
        said = ""
        if not strength.data.test_data or word == "example":
            sections.insert(0, fig_section(strength))
        if strength.data.test_data and word == "example":
            said = " Its arm strength is the example data (invented), not measured."
        return sections, said

    def fig_text(self, figure: Figure, sections: list) -> tuple[str, str]:
        """The .fig file's text and what the message says of the values the
        population filled in for a person."""
        text = render_fig(figure, sections)
        filled = sum(int(figure.output_values(g)[1].sum()) for g in GROUPS)
        note = (
            f" {filled} values not measured for {figure.person} came from the population."
            if filled
            else ""
        )
        return text, note

    def not_in_humanoid(self, row: str, axis: int) -> bool:
        """A girth cell the HAnim humanoid does not use (the figure view stands
        the joints at the stature's landmarks)."""
        return (row, axis) in NOT_IN_HUMANOID

    # --- the worksheet file --------------------------------------------------------
    def read_worksheet(self, path: Path) -> Worksheet:
        return read_worksheet(path)

    def worksheet_text(self, session: Session) -> str:
        return worksheet_text(session)

    def read_worksheet_and_strength(
        self, path: Path, workdir: Path | None = None
    ) -> tuple[Worksheet, StrengthData | None, SassError | OSError | None]:
        return read_worksheet_and_strength(path, workdir)

    def open_worksheet(
        self, session: Session, worksheet: Worksheet, strength: StrengthData | None
    ) -> None:
        """Show a worksheet read (and its strength file): the Session's figure
        and strength sheet become the file's."""
        settings = worksheet.strength
        session.open_worksheet(
            worksheet.figure,
            strength,
            None if settings is None else lambda sheet: apply_strength(settings, sheet),
        )
        session.task = worksheet.task

    # --- the figure drawn ----------------------------------------------------------
    def outlines(self, session: Session, overlay: float | None) -> tuple[Outline, ...]:
        return session_outlines(session, overlay)

    def figure_screen(self, session: Session) -> FigureScreen:
        return FigureScreen(session)
