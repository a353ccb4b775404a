"""What one user has open: the population figure, the person shown (if any),
the strength sheet, the warnings of the last file read, and one undo journal.

Every edit goes through a Session method: the edit runs first and an undo
entry is recorded only once it has been accepted, so a refused edit leaves
nothing to undo.  An edit that fails half way is rolled back to the snapshot
taken before it.  The TUI and the CLI both build figures through a Session; it
imports no Textual.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, TypeVar

from sass_tui.model.figure import Figure
from sass_tui.model.popfile import PopulationData

if TYPE_CHECKING:  # numpy-heavy: the TUI makes its strength sheet after the first screen
    from sass_tui.model.strength import StrengthData, StrengthRow, StrengthSheet

JOURNAL_LENGTH = 100
T = TypeVar("T")


@dataclass(frozen=True)
class JournalEntry:
    """One accepted edit: what it changed (`target`) and how to go back."""

    target: object
    restore: Callable[[], None]


class Session:
    def __init__(
        self,
        population: Figure,
        strength_sheet: StrengthSheet | None = None,
        *,
        strength_later: Callable[[], StrengthSheet | None] | None = None,
    ) -> None:
        """`strength_later` makes the population's strength sheet when it is
        first asked for, instead of `strength_sheet` now: the TUI draws its
        first screen before the strength data are read, to start sooner."""
        self.population = population
        self.person: Figure | None = None
        self.person_index = 0
        self._strength_later = strength_later
        self._strength_sheet = strength_sheet
        # The population's sheet, shown again after a person's own (Disp. Pop.).
        self._population_strength = strength_sheet
        # Why a person shown has no strength (None: the sheet is shown).
        self.strength_missing: str | None = None
        if strength_sheet is not None:
            strength_sheet.figure = population
        self.warnings: list[str] = []
        self._journal: list[JournalEntry] = []

    # --- the strength sheets, made on first use with strength_later ------------
    @property
    def strength_sheet(self) -> StrengthSheet | None:
        """The sheet shown: the population's, or a person's own."""
        self.make_strength_sheet()
        return self._strength_sheet

    @strength_sheet.setter
    def strength_sheet(self, sheet: StrengthSheet | None) -> None:
        self.make_strength_sheet()
        self._strength_sheet = sheet

    @property
    def population_strength(self) -> StrengthSheet | None:
        self.make_strength_sheet()
        return self._population_strength

    @population_strength.setter
    def population_strength(self, sheet: StrengthSheet | None) -> None:
        self.make_strength_sheet()
        self._population_strength = sheet

    def made_strength_sheet(self) -> StrengthSheet | None:
        """The sheet shown if it has been made, without making it (what the
        first screen shows of it is what a new sheet shows: the right side)."""
        return self._strength_sheet

    def make_strength_sheet(self) -> None:
        """Make the population's strength sheet now, if it is still to be made."""
        make, self._strength_later = self._strength_later, None
        if make is None:
            return
        sheet = make()
        if sheet is not None:
            sheet.figure = self.figure
        self._strength_sheet = self._population_strength = sheet

    @property
    def figure(self) -> Figure:
        """The figure shown and edited: the person while one is shown."""
        return self.person if self.person is not None else self.population

    # --- the undo journal ----------------------------------------------------
    def _record(self, target: object, restore: Callable[[], None]) -> None:
        self._journal.append(JournalEntry(target, restore))
        del self._journal[:-JOURNAL_LENGTH]

    def _live(self, entry: JournalEntry) -> bool:
        # The sheet as it stands: an entry for it exists only once it is made.
        return entry.target is self.figure or entry.target is self._strength_sheet

    def can_undo(self) -> bool:
        return any(self._live(entry) for entry in self._journal)

    def undo(self) -> bool:
        """Undo the newest edit of what is shown (figure or strength angle).
        False when there is none."""
        for position in range(len(self._journal) - 1, -1, -1):
            entry = self._journal[position]
            if self._live(entry):
                del self._journal[position]
                entry.restore()
                return True
        return False

    def _edit_figure(self, edit: Callable[[Figure], T]) -> T:
        figure = self.figure
        before = figure.snapshot()
        try:
            result = edit(figure)
        except BaseException:
            figure.restore(before)
            raise
        self._record(figure, lambda: figure.restore(before))
        return result

    # --- figure edits ------------------------------------------------------------
    def set_figure_type(self, figure_type: str) -> None:
        self._edit_figure(lambda f: f.set_figure_type(figure_type))

    def set_gender(self, gender: str) -> None:
        self._edit_figure(lambda f: f.set_gender(gender))

    def set_mass(self, kg: float) -> None:
        self._edit_figure(lambda f: f.set_mass(kg))

    def set_mass_percentile(self, p: float) -> None:
        self._edit_figure(lambda f: f.set_mass_percentile(p))

    def set_stature(self, cm: float) -> None:
        self._edit_figure(lambda f: f.set_stature(cm))

    def set_stature_percentile(self, p: float) -> None:
        self._edit_figure(lambda f: f.set_stature_percentile(p))

    def set_strength_parameter(self, name: str, value: str | float) -> None:
        self._edit_figure(lambda f: f.set_strength_parameter(name, value))

    def set_group_percentile(self, group: str, p: float) -> None:
        self._edit_figure(lambda f: f.set_group_percentile(group, p))

    def set_value(self, group: str, row: int, axis: int, value: float) -> None:
        self._edit_figure(lambda f: f.set_value(group, row, axis, value))

    def set_cell_percentile(self, group: str, row: int, axis: int, p: float) -> None:
        self._edit_figure(lambda f: f.set_cell_percentile(group, row, axis, p))

    def load_group(self, group: str, data: PopulationData) -> None:
        """Input Data for a group: undoable like any edit."""
        self._edit_figure(lambda f: f.load_group(group, data))
        self.warnings = list(data.warnings)

    def load_global(self, data: PopulationData) -> None:
        """Stature and mass statistics from a global file: undoable like any edit."""
        self._edit_figure(lambda f: f.load_global(data))
        self.warnings = list(data.warnings)

    def set_unit(self, group: str, unit: str) -> None:
        """A view setting, not an edit: not journalled."""
        self.figure.set_unit(group, unit)

    # --- the strength sheet ---------------------------------------------------------
    def set_angle(self, row: int, column: int, text: str | float) -> StrengthRow:
        sheet = self._require_strength()
        old = float(sheet.angles[row, column])
        result = sheet.set_angle(row, column, text)

        def restore() -> None:
            sheet.angles[row, column] = old

        self._record(sheet, restore)
        return result

    def load_strength(self, data: StrengthData) -> StrengthSheet:
        """A new strength file: the view settings (side, unit, percentile,
        factor) survive; the angles are the new file's."""
        # deferred: model.strength — off the first screen, sass export hanim, sass export gltf (sass_tui/startup.py)
        from sass_tui.model.strength import StrengthSheet

        sheet = StrengthSheet(data, self.figure)
        old = self.strength_sheet
        if old is not None:
            sheet.side, sheet.unit = old.side, old.unit
            sheet.percentile, sheet.non_dominant_factor = old.percentile, old.non_dominant_factor
        self.strength_sheet = self.population_strength = sheet
        self.strength_missing = None
        self._drop_entries_of([old])
        self.warnings = list(data.warnings)
        return sheet

    def _require_strength(self) -> StrengthSheet:
        if self.strength_sheet is None:
            # deferred: model.strength — off the first screen, sass export hanim, sass export gltf (sass_tui/startup.py)
            from sass_tui.model.strength import StrengthError

            raise StrengthError("strength data is not loaded")
        return self.strength_sheet

    # --- the person shown ----------------------------------------------------------------
    def show_person(
        self, person: Figure, index: int, own_strength: StrengthData | str | None = None
    ) -> None:
        """Show a person (Disp. Indv., or a predicted figure); the population is
        kept to come back to.  `own_strength`: the person's own strength data
        (shown instead of the population's), a sentence saying why they have
        none (the strength page shows it), or None to keep the population's
        strength (a predicted figure)."""
        self._leave_person()
        self.person, self.person_index = person, index
        if isinstance(own_strength, str):
            self.strength_sheet, self.strength_missing = None, own_strength
        elif own_strength is not None:
            # deferred: model.strength — off the first screen, sass export hanim, sass export gltf (sass_tui/startup.py)
            from sass_tui.model.strength import StrengthSheet

            sheet = StrengthSheet(own_strength, person)
            shown = self.population_strength
            if shown is not None:
                sheet.side, sheet.unit = shown.side, shown.unit
            self.strength_sheet = sheet
        self._follow_figure()

    def show_population(self) -> None:
        self._leave_person()
        self.person = None
        self._follow_figure()

    def _leave_person(self) -> None:
        if self.strength_sheet is not self.population_strength:
            self._drop_entries_of([self.strength_sheet])
        self._drop_entries_of([self.person])
        self.strength_sheet, self.strength_missing = self.population_strength, None

    def _follow_figure(self) -> None:
        if self.strength_sheet is not None:
            self.strength_sheet.figure = self.figure

    def _drop_entries_of(self, targets: Iterable[object]) -> None:
        gone = [t for t in targets if t is not None]
        self._journal = [e for e in self._journal if not any(e.target is t for t in gone)]
