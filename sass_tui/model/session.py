"""What one user has open: the population figure, the person shown (if any),
the strength sheets (StrengthSheets), the warnings of the last file read, and
one undo journal (Journal).

Every edit goes through a Session method: the edit runs first and an undo
entry is recorded only once it has been accepted, so a refused edit leaves
nothing to undo.  An edit that fails half way is rolled back to the snapshot
taken before it.  The TUI and the CLI both build figures through a Session; it
imports no Textual.
"""

from __future__ import annotations

import copy
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, TypeVar

from sass_tui.model.body.figure import Figure
from sass_tui.model.files.popfile import PopulationData
from sass_tui.model.files.task_settings import TaskSettings
from sass_tui.model.names import AXES, GROUP_TITLES, ROWS
from sass_tui.model.units import GROUP_UNITS
from sass_tui.model.vocabulary import JOINT_AXES

if TYPE_CHECKING:  # numpy-heavy: the TUI makes its strength sheet after the first screen
    from sass_tui.model.strength.strength import StrengthData, StrengthRow, StrengthSheet

JOURNAL_LENGTH = 100
T = TypeVar("T")


@dataclass(frozen=True)
class JournalEntry:
    """One accepted edit: what it changed (`target`), what it was (`what`,
    for the message line: "Undone: Neck x = 7 cm"), how to go back and
    how to do it again (redo)."""

    target: object
    what: str
    restore: Callable[[], None]
    reapply: Callable[[], None]
    number: int


class Journal:
    """The undo journal: the last JOURNAL_LENGTH accepted edits, newest last,
    and the edits undone since the last new edit (redo).  Only the edits of
    what is shown (`live`: the figure, the strength sheet) are undone or
    redone; the others wait until theirs is shown again."""

    def __init__(self) -> None:
        self._entries: list[JournalEntry] = []
        self._undone: list[JournalEntry] = []
        self._numbered = 0
        self._saved: frozenset[int] = frozenset()

    def record(
        self,
        target: object,
        what: str,
        restore: Callable[[], None],
        reapply: Callable[[], None],
    ) -> None:
        self._numbered += 1
        self._entries.append(JournalEntry(target, what, restore, reapply, self._numbered))
        del self._entries[:-JOURNAL_LENGTH]
        self._undone.clear()  # a new edit: what was undone cannot be redone over it

    def can_undo(self, live: tuple[object, ...]) -> bool:
        return any(_among(entry.target, live) for entry in self._entries)

    def undo(self, live: tuple[object, ...]) -> str | None:
        """Undo the newest edit of one of `live`: what it was; None when
        there is none."""
        entry = _take_newest(self._entries, live)
        if entry is None:
            return None
        entry.restore()
        self._undone.append(entry)
        return entry.what

    def redo(self, live: tuple[object, ...]) -> str | None:
        """Do again the edit undone last of one of `live`: what it was;
        None when there is none."""
        entry = _take_newest(self._undone, live)
        if entry is None:
            return None
        entry.reapply()
        self._entries.append(entry)
        return entry.what

    def drop(self, targets: Iterable[object]) -> None:
        """Forget the edits of what is gone (a person left, a sheet replaced)."""
        gone = tuple(t for t in targets if t is not None)
        self._entries = [e for e in self._entries if not _among(e.target, gone)]
        self._undone = [e for e in self._undone if not _among(e.target, gone)]

    def clear(self) -> None:
        self._entries.clear()
        self._undone.clear()

    def mark_saved(self, state: frozenset[int] | None = None) -> None:
        """The worksheet file holds `state` (None: what is applied now)."""
        self._saved = self.applied() if state is None else state

    def unsaved(self) -> bool:
        """Edits applied, or undone, since the worksheet was last saved
        (or, never saved, since the start)."""
        return self.applied() != self._saved

    def applied(self) -> frozenset[int]:
        return frozenset(entry.number for entry in self._entries)


def _take_newest(entries: list[JournalEntry], live: tuple[object, ...]) -> JournalEntry | None:
    for position in range(len(entries) - 1, -1, -1):
        if _among(entries[position].target, live):
            return entries.pop(position)
    return None


def _among(target: object, targets: tuple[object, ...]) -> bool:
    # By identity: two figures with equal values are two figures.
    return any(target is t for t in targets)


class StrengthSheets:
    """A session's strength sheets: the population's, and the one shown (the
    population's, or a person's own, or none with the reason why: `missing`).
    With `later`, the population's sheet is made when first asked for: the TUI
    draws its first screen before the strength data are read, to start
    sooner.  Each sheet computes against `figure()`, the figure shown."""

    def __init__(
        self,
        sheet: StrengthSheet | None,
        later: Callable[[], StrengthSheet | None] | None,
        figure: Callable[[], Figure],
    ) -> None:
        self._later = later
        self._figure = figure
        self._shown = sheet
        # The population's sheet, shown again after a person's own (Disp. Pop.).
        self._population = sheet
        # Why a person shown has no strength (None: the sheet is shown).
        self.missing: str | None = None
        if sheet is not None:
            sheet.figure = figure()

    @property
    def shown(self) -> StrengthSheet | None:
        """The sheet shown: the population's, or a person's own."""
        self.make()
        return self._shown

    @property
    def population(self) -> StrengthSheet | None:
        self.make()
        return self._population

    def made(self) -> StrengthSheet | None:
        """The sheet shown if it has been made, without making it (what the
        first screen shows of it is what a new sheet shows: the right side)."""
        return self._shown

    def make(self) -> None:
        """Make the population's strength sheet now, if it is still to be made."""
        make, self._later = self._later, None
        if make is None:
            return
        sheet = make()
        if sheet is not None:
            sheet.figure = self._figure()
        self._shown = self._population = sheet

    def require(self) -> StrengthSheet:
        sheet = self.shown
        if sheet is None:
            # deferred: model.strength — off the first screen, sass export hanim, sass export gltf (sass_tui/startup.py)
            from sass_tui.model.strength.strength import StrengthError

            raise StrengthError("strength data is not loaded")
        return sheet

    def load(self, data: StrengthData) -> tuple[StrengthSheet, StrengthSheet | None]:
        """A new population sheet from a strength file, and the one it replaces:
        the view settings (side, unit, percentile, factor) survive; the angles
        are the new file's."""
        sheet = _new_sheet(data, self._figure())
        old = self.shown
        if old is not None:
            sheet.side, sheet.unit = old.side, old.unit
            sheet.percentile, sheet.non_dominant_factor = old.percentile, old.non_dominant_factor
        self._shown = self._population = sheet
        self.missing = None
        return sheet, old

    def show_own(self, person: Figure, own_strength: StrengthData | str | None) -> None:
        """A person's own sheet (shown on the population's side and unit), or
        none and why (a sentence), or (None) the population's kept."""
        if isinstance(own_strength, str):
            self.make()
            self._shown, self.missing = None, own_strength
        elif own_strength is not None:
            sheet = _new_sheet(own_strength, person)
            shown = self.population
            if shown is not None:
                sheet.side, sheet.unit = shown.side, shown.unit
            self._shown = sheet

    def show_population(self) -> StrengthSheet | None:
        """Back to the population's sheet; the person's own one it leaves, if any."""
        left = self.shown
        self._shown, self.missing = self._population, None
        return left if left is not self._population else None

    def follow(self, figure: Figure) -> None:
        """The sheet shown computes against `figure` (the figure now shown)."""
        if self.shown is not None:
            self.shown.figure = figure


class Session:
    def __init__(
        self,
        population: Figure,
        strength_sheet: StrengthSheet | None = None,
        *,
        strength_later: Callable[[], StrengthSheet | None] | None = None,
    ) -> None:
        """`strength_later` makes the population's strength sheet when it is
        first asked for, instead of `strength_sheet` now (StrengthSheets)."""
        self.population = population
        self.person: Figure | None = None
        self.person_index = 0
        self.strength_sheets = StrengthSheets(strength_sheet, strength_later, lambda: self.figure)
        self.warnings: list[str] = []
        self._journal = Journal()
        # the Task panel's settings (model/files/task_settings.py), saved in the worksheet
        self.task: TaskSettings | None = None

    @property
    def strength_sheet(self) -> StrengthSheet | None:
        """The sheet shown: the population's, or a person's own."""
        return self.strength_sheets.shown

    @property
    def figure(self) -> Figure:
        """The figure shown and edited: the person while one is shown."""
        return self.person if self.person is not None else self.population

    # --- the undo journal ----------------------------------------------------
    def can_undo(self) -> bool:
        # The sheet as it stands: an entry for it exists only once it is made.
        return self._journal.can_undo((self.figure, self.strength_sheets.made()))

    def undo(self) -> str | None:
        """Undo the newest edit of what is shown (figure or strength angle):
        what it was, for the message line; None when there is none."""
        return self._journal.undo((self.figure, self.strength_sheets.made()))

    def redo(self) -> str | None:
        """Do again the edit undone last (of what is shown): what it was;
        None when there is none (or a new edit came after the undo)."""
        return self._journal.redo((self.figure, self.strength_sheets.made()))

    def unsaved_edits(self) -> bool:
        """Edits since the worksheet was last saved or opened (quit asks)."""
        return self._journal.unsaved()

    def edit_state(self) -> frozenset[int]:
        """What is applied now, for `mark_saved` once a save has been written."""
        return self._journal.applied()

    def mark_saved(self, state: frozenset[int] | None = None) -> None:
        """The worksheet file holds `state` (None: what is applied now)."""
        self._journal.mark_saved(state)

    def _edit_figure(self, what: str, edit: Callable[[Figure], T]) -> T:
        figure = self.figure
        before = figure.snapshot()
        try:
            result = edit(figure)
        except BaseException:
            figure.restore(before)
            raise
        after = figure.snapshot()
        # Each restore takes its own copy: the snapshot stays as it was
        # taken, however often the edit is undone and redone.
        self._journal.record(
            figure,
            what,
            lambda: figure.restore(_fresh(before)),
            lambda: figure.restore(_fresh(after)),
        )
        return result

    # --- figure edits ------------------------------------------------------------
    def set_figure_type(self, figure_type: str) -> None:
        self._edit_figure(f"figure type {figure_type}", lambda f: f.set_figure_type(figure_type))

    def set_gender(self, gender: str) -> None:
        self._edit_figure(f"gender {gender}", lambda f: f.set_gender(gender))

    def set_mass(self, kg: float) -> None:
        self._edit_figure(f"mass {kg:g} kg", lambda f: f.set_mass(kg))

    def set_mass_percentile(self, p: float) -> None:
        self._edit_figure(f"mass percentile {p:g}", lambda f: f.set_mass_percentile(p))

    def set_stature(self, cm: float) -> None:
        self._edit_figure(f"stature {cm:g} cm", lambda f: f.set_stature(cm))

    def set_stature_percentile(self, p: float) -> None:
        self._edit_figure(f"stature percentile {p:g}", lambda f: f.set_stature_percentile(p))

    def set_strength_parameter(self, name: str, value: str | float) -> None:
        self._edit_figure(
            f"{name.replace('_', ' ')} {value}",
            lambda f: f.set_strength_parameter(name, value),
        )

    def set_group_percentile(self, group: str, p: float) -> None:
        self._edit_figure(
            f"{GROUP_TITLES[group]} percentile {p:g}",
            lambda f: f.set_group_percentile(group, p),
        )

    def set_value(self, group: str, row: int, axis: int, value: float) -> None:
        self._edit_figure(
            f"{_cell_name(group, row, axis)} value {value:g} {GROUP_UNITS[group][0]}",
            lambda f: f.set_value(group, row, axis, value),
        )

    def set_cell_percentile(self, group: str, row: int, axis: int, p: float) -> None:
        self._edit_figure(
            f"{_cell_name(group, row, axis)} percentile {p:g}",
            lambda f: f.set_cell_percentile(group, row, axis, p),
        )

    def load_group(
        self, group: str, data: PopulationData, stature_and_mass: PopulationData | None = None
    ) -> None:
        """Input Data for a group: undoable like any edit.  With
        `stature_and_mass` (the people's own, `sass population` wrote them
        beside its girth file) those are loaded in the same edit."""

        def load(figure: Figure) -> None:
            figure.load_group(group, data)
            if stature_and_mass is not None:
                figure.load_global(stature_and_mass)

        self._edit_figure(f"Input Data {GROUP_TITLES[group]} ({data.title or data.path})", load)
        more = stature_and_mass.warnings if stature_and_mass is not None else []
        self.warnings = [*data.warnings, *more]

    def load_global(self, data: PopulationData) -> None:
        """Stature and mass statistics from a global file: undoable like any edit."""
        self._edit_figure(
            f"global statistics ({data.title or data.path})", lambda f: f.load_global(data)
        )
        self.warnings = list(data.warnings)

    def set_unit(self, group: str, unit: str) -> None:
        """A view setting, not an edit: not journalled."""
        self.figure.set_unit(group, unit)

    # --- the strength sheet ---------------------------------------------------------
    def set_angle(self, row: int, column: int, text: str | float) -> StrengthRow:
        sheet = self.strength_sheets.require()
        old = float(sheet.angles[row, column])
        result = sheet.set_angle(row, column, text)
        new = float(sheet.angles[row, column])

        def restore() -> None:
            sheet.angles[row, column] = old

        def reapply() -> None:
            sheet.angles[row, column] = new

        what = f"{result.label}: {JOINT_AXES[column].replace('_', ' ')} {new:g} deg"
        self._journal.record(sheet, what, restore, reapply)
        return result

    def load_strength(self, data: StrengthData) -> StrengthSheet:
        """A new strength file (StrengthSheets.load); the old sheet's edits are
        forgotten."""
        sheet, old = self.strength_sheets.load(data)
        self._journal.drop([old])
        self.warnings = list(data.warnings)
        return sheet

    # --- the worksheet file ------------------------------------------------------
    def open_worksheet(
        self,
        figure: Figure,
        strength: StrengthData | None = None,
        angles: Callable[[StrengthSheet], None] | None = None,
    ) -> None:
        """A worksheet opened (model/files/worksheet.py): its figure is the
        population figure; `strength` (its file, read again) the strength
        sheet, which `angles` then sets as saved.  Not an edit: the journal
        starts afresh, and what is open is what the file holds."""
        self._leave_person()
        self.person = None
        self.population = figure
        if strength is not None:
            sheet = self.load_strength(strength)
            if angles is not None:
                angles(sheet)
        self.strength_sheets.follow(self.figure)
        self._journal.clear()
        self._journal.mark_saved()

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
        self.strength_sheets.show_own(person, own_strength)
        self.strength_sheets.follow(self.figure)

    def show_population(self) -> None:
        self._leave_person()
        self.person = None
        self.strength_sheets.follow(self.figure)

    def _leave_person(self) -> None:
        self._journal.drop([self.strength_sheets.show_population(), self.person])


def _fresh(snapshot: dict[str, object]) -> dict[str, object]:
    """A snapshot to restore, its groups copied (Figure.snapshot's rule)."""
    return {k: copy.deepcopy(v) if k == "groups" else v for k, v in snapshot.items()}


def _cell_name(group: str, row: int, axis: int) -> str:
    return f"{ROWS[group][row].label} {AXES[axis]}"


def _new_sheet(data: StrengthData, figure: Figure) -> StrengthSheet:
    """A strength sheet of `data` for `figure` (model/strength/strength.py, with numpy)."""
    # deferred: model.strength — off the first screen, sass export hanim, sass export gltf (sass_tui/startup.py)
    from sass_tui.model.strength.strength import StrengthSheet

    return StrengthSheet(data, figure)
