"""The human figure as SASS holds it: global data and one state per group.

Values are kept in canonical units (cm, deg, kg); each group also has a
display unit the user can switch (cm|in, deg|rad).  No Textual import here.

A group's values at its percentile (the default figure, a new group
percentile, a new gender) are computed in plain floats: the TUI's first
screen is drawn before numpy is imported, to start sooner.  They become a numpy
array when something asks for the array (a cell edit, an export).
"""

from __future__ import annotations

import copy
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import ModuleType
from typing import TYPE_CHECKING

from sass_tui.model import datasets
from sass_tui.model.body.human import not_human
from sass_tui.model.errors import SassError
from sass_tui.model.files.popfile import (
    PopulationData,
    check_center_of_mass_rules,
    read_population_file,
)
from sass_tui.model.names import (
    CENTER_OF_MASS,
    GIRTH,
    GLOBAL,
    GROUP_TITLES,
    GROUPS,
    JOINT_LIMITS,
    MASS_FRACTIONS,
    ROWS,
    Row,
)
from sass_tui.model.population.percentile import (
    MAX_PERCENTILE,
    MIN_PERCENTILE,
    Cell,
    Grid,
    cell_percentile_of,
    cell_value_at,
    check_percentile,
    grid_at,
    plausible_range,
)
from sass_tui.model.text import printable
from sass_tui.model.units import GROUP_UNITS
from sass_tui.model.vocabulary import FIGURE_TYPES, GENDERS, HANDEDNESS, STRENGTH_TYPES

if TYPE_CHECKING:
    import numpy as np


class FigureError(ValueError, SassError):
    """An edit the model refuses; the figure is unchanged."""


@dataclass
class GroupState:
    """One anthropometric group at the figure's gender.

    `values` (rows, 3; canonical units, NaN = no value) and `percentiles`
    are numpy arrays to whoever reads them; they are held as a Grid of
    plain floats until then, and `cell` reads either without numpy."""

    group: str
    source: PopulationData | None = None
    percentile: float = 50.0
    unit: str = ""
    _values: Grid | np.ndarray | None = None
    _percentiles: Grid | np.ndarray | None = None

    @property
    def values(self) -> np.ndarray | None:
        if isinstance(self._values, list):
            self._values = _array(self._values)
        return self._values

    @values.setter
    def values(self, values: Grid | np.ndarray | None) -> None:
        self._values = values

    @property
    def percentiles(self) -> np.ndarray | None:
        if isinstance(self._percentiles, list):
            self._percentiles = _array(self._percentiles)
        return self._percentiles

    @percentiles.setter
    def percentiles(self, percentiles: Grid | np.ndarray | None) -> None:
        self._percentiles = percentiles

    def cell(self, row: int, axis: int) -> tuple[float, float]:
        """One cell's (value, percentile); the group is loaded."""
        values, percentiles = self._values, self._percentiles
        assert values is not None and percentiles is not None, f"{self.group} not loaded"
        return float(values[row][axis]), float(percentiles[row][axis])

    @property
    def loaded(self) -> bool:
        return self._values is not None

    def __deepcopy__(self, memo: dict[int, object]) -> GroupState:
        """The undo journal's copy: the cells copied; the population's
        statistics shared (a new file replaces them, nothing changes them)."""
        copied = copy.copy(self)
        copied._values, copied._percentiles = _copy(self._values), _copy(self._percentiles)
        return copied

    @property
    def rows(self) -> tuple[Row, ...]:
        return ROWS[self.group]

    # --- the population's statistics at a gender: the percentile model's input ---
    def stats(self, gender: str) -> np.ndarray:
        """(rows, 3, 3): each cell's stored 5th/50th/95th values."""
        assert self.source is not None, f"{self.group} not loaded"
        return self.source.stats(gender)

    def cell_stats(self, gender: str, row: int, axis: int) -> Cell:
        assert self.source is not None, f"{self.group} not loaded"
        return self.source.cell(gender, row, axis)

    def rescale(self, gender: str) -> None:
        """Every cell at the group percentile, in plain floats; nothing loaded
        when the population has no statistics for the gender."""
        source = self.source
        if source is None or not source.has(gender):
            self.values = self.percentiles = None
            return
        self.values, self.percentiles = grid_at(
            lambda row, axis: source.cell(gender, row, axis), len(self.rows), self.percentile
        )


@dataclass
class Figure:
    gender: str = "male"
    figure_type: str = "skinny"
    population: str = ""
    person: str | None = None
    mass: float = float("nan")  # kg
    mass_percentile: float = 50.0
    stature: float = float("nan")  # cm
    stature_percentile: float = 50.0
    strength_type: str = "isometric"
    motion_speed: float = 0.0  # deg/s
    handedness: str = "right"
    training_level: float = 0.0
    fatigue_level: float = 0.0
    global_stats: PopulationData | None = None
    groups: dict[str, GroupState] = field(default_factory=dict)
    # A person's own ANSUR II measurements that place their body landmarks
    # (model/body/landmarks.py: survey names, cm); empty for a population figure,
    # which is placed from its stature.
    landmarks: dict[str, float] = field(default_factory=dict)
    # A predicted person's body measurements as sass predict gives them
    # (ANSUR II names, cm; model/body/body_measures.py shapes the body from them);
    # empty for anyone else.
    predicted_measures: dict[str, float] = field(default_factory=dict)
    # Girth rows whose length (z) was set here by hand: a person's .fig keeps
    # them as set instead of the length between their joints
    # (figfile.person_joint_lengths).  Replaced, never changed in place, so
    # an undo snapshot keeps its own.
    hand_set_lengths: frozenset[str] = frozenset()

    def __post_init__(self) -> None:
        for group in GROUPS:
            self.groups.setdefault(group, GroupState(group, unit=GROUP_UNITS[group][0]))

    # --- construction ----------------------------------------------------
    @classmethod
    def default(cls, gender: str = "male") -> Figure:
        """The NASA crew population of the shipped data sets, all at the 50th."""
        figure = cls(gender=_check_choice(gender, GENDERS, "gender"))
        figure.global_stats = read_population_file(datasets.path("global.dat"), GLOBAL)
        for group in GROUPS:
            figure.load_group(
                group, read_population_file(datasets.path(datasets.FILES[group]), group)
            )
        figure._reset_globals()
        return figure

    def load_group(self, group: str, data: PopulationData) -> None:
        """Replace a group's statistics (Input Data), keeping its percentile."""
        state = self.groups[group]
        state.source = data
        if group == GIRTH and self.person is None:
            self.population = data.title
        state.rescale(self.gender)
        girth, cmass = self.groups[GIRTH].source, self.groups[CENTER_OF_MASS].source
        if (
            group in (GIRTH, CENTER_OF_MASS)
            and girth is not None
            and cmass is not None
            and datasets.is_shipped(girth.path) == datasets.is_shipped(cmass.path)
        ):
            # Appendix L.1's rules tie a center-of-mass file to the girth of its own
            # population: the report's pair, or a pair of the user's.  One of each is
            # two populations, and a warning would name a file the user did not load.
            data.warnings += [
                w for w in check_center_of_mass_rules(cmass, girth) if w not in data.warnings
            ]

    def load_global(self, data: PopulationData) -> None:
        """Replace the stature and mass statistics (a global file, e.g. a weighted
        population's), keeping their percentiles."""
        if not data.has(self.gender):
            raise FigureError(f"{data.path or data.title}: no {self.gender} global statistics")
        self.global_stats = data
        self._reset_globals()

    def for_person(
        self,
        name: str,
        gender: str,
        groups: dict[str, np.ndarray],
        *,
        mass: float = float("nan"),
        stature: float = float("nan"),
        landmarks: Mapping[str, float] | None = None,
        **strength_parameters: str | float | None,
    ) -> Figure:
        """A real person's figure (report §12.4, Disp. Indv.): the person's values
        (canonical units, NaN where the database has none) with percentiles taken
        against this figure's population statistics.  This figure is left as it
        is, so Disp. Pop. returns to it unchanged.  `strength_parameters` are
        strength_type, motion_speed, handedness, training_level, fatigue_level
        (None = keep this figure's); `landmarks` the person's measurements
        that place the HAnim humanoid and the `.fig`'s joints (cm, by the
        survey's names: model/body/landmarks.py)."""
        arrays = _arrays()
        gender = _check_choice(gender, GENDERS, "gender")
        # A stored name may hold ESC or BEL (a shared database, an older file):
        # it goes on into task and strength output, .fig comments and X3D.
        name = printable(name)
        for what, size in (("stature", stature), ("mass", mass)):
            refused = None if math.isnan(size) else not_human(what, size)
            if refused:  # a stored stature of 1e6 cm made an export of 4.5 GB
                raise FigureError(f"{name}: {refused}")
        person = Figure(
            gender=gender,
            figure_type=self.figure_type,
            population=self.population,
            person=str(name),
            global_stats=self.global_stats,
            strength_type=self.strength_type,
            motion_speed=self.motion_speed,
            handedness=self.handedness,
            training_level=self.training_level,
            fatigue_level=self.fatigue_level,
            landmarks={k: float(v) for k, v in (landmarks or {}).items()},
        )
        for group in GROUPS:
            mine, theirs = self.groups[group], person.groups[group]
            if mine.source is None or not mine.source.has(gender):
                raise FigureError(
                    f"no {gender} {GROUP_TITLES[group]} statistics loaded to "
                    f"compare {name} with; load a population file that has them"
                )
            values = arrays.array(groups[group])
            if values.shape != (len(theirs.rows), 3):
                raise FigureError(
                    f"{name}: {GROUP_TITLES[group]} has shape {values.shape}, "
                    f"expected ({len(theirs.rows)}, 3)"
                )
            theirs.source, theirs.unit, theirs.percentile = mine.source, mine.unit, mine.percentile
            theirs.values = values
            theirs.percentiles = arrays.percentiles_against(mine.source.stats(gender), values)
        for parameter, value in strength_parameters.items():
            if value is not None:
                person.set_strength_parameter(parameter, value)
        person.mass, person.stature = float(mass), float(stature)
        person.mass_percentile = _global_percentile(
            person.global_stats, person.gender, "mass", mass
        )
        person.stature_percentile = _global_percentile(
            person.global_stats, person.gender, "stature", stature
        )
        return person

    # --- global data -----------------------------------------------------
    def set_gender(self, gender: str) -> None:
        gender = _check_choice(gender, GENDERS, "gender")
        self.gender = gender
        for state in self.groups.values():
            state.rescale(self.gender)
        self._reset_globals()

    def set_figure_type(self, figure_type: str) -> None:
        self.figure_type = _check_choice(figure_type, FIGURE_TYPES, "figure type")

    def set_mass(self, kg: float) -> None:
        if not kg > 0:
            raise FigureError(f"mass must be positive, got {kg:g} kg")
        if refused := not_human("mass", kg):
            raise FigureError(refused)
        self.mass = float(kg)
        self.mass_percentile = _global_percentile(self.global_stats, self.gender, "mass", kg)

    def set_mass_percentile(self, p: float) -> None:
        check_percentile(p)
        self.mass_percentile = float(p)
        self.mass = _global_value(self.global_stats, self.gender, "mass", p)

    def set_stature(self, cm: float) -> None:
        if refused := not_human("stature", cm):
            raise FigureError(refused)
        self.stature = float(cm)
        self.stature_percentile = _global_percentile(self.global_stats, self.gender, "stature", cm)

    def set_stature_percentile(self, p: float) -> None:
        check_percentile(p)
        self.stature_percentile = float(p)
        self.stature = _global_value(self.global_stats, self.gender, "stature", p)

    def implausible_range(self, name: str) -> tuple[float, float] | None:
        """For a mass or stature set beyond the population's 0.5th-99.5th
        percentile (the ends a percentile may be typed at): that range, in kg
        or cm, lower first; the value stands, a warning names the range.
        None inside it, or without statistics."""
        if name not in ("mass", "stature") or self.global_stats is None:
            return None
        percentile = getattr(self, f"{name}_percentile")
        if math.isnan(percentile) or MIN_PERCENTILE <= percentile <= MAX_PERCENTILE:
            return None
        return plausible_range(*_global_cell(self.global_stats, self.gender, name))

    def set_strength_parameter(self, name: str, value: str | float) -> None:
        if name == "strength_type":
            self.strength_type = _check_choice(str(value), STRENGTH_TYPES, "strength type")
        elif name == "handedness":
            self.handedness = _check_choice(str(value), HANDEDNESS, "handedness")
        elif name in ("motion_speed", "training_level", "fatigue_level"):
            number = float(value)
            if not math.isfinite(number):
                raise FigureError(f"{name.replace('_', ' ')} must be a number, not {value!r}")
            if number < 0:
                raise FigureError(f"{name.replace('_', ' ')} cannot be negative")
            setattr(self, name, number)
        else:
            raise FigureError(f"unknown strength parameter {name!r}")

    # --- group data ------------------------------------------------------
    def set_group_percentile(self, group: str, p: float) -> None:
        check_percentile(p)
        state = self.groups[group]
        state.percentile = float(p)
        state.rescale(self.gender)
        if group == GIRTH:
            self.hand_set_lengths = frozenset(row.name for row in state.rows)

    def set_value(self, group: str, row: int, axis: int, value: float) -> None:
        """Set one cell's value (canonical unit); its percentile follows.  A
        segment size (girth) must be positive."""
        state = self.check_cell(group, row, axis)
        if group == GIRTH and not value > 0:
            raise FigureError(
                f"{state.rows[row].label} {'xyz'[axis]}: a segment size must be "
                f"positive, got {value:g} cm"
            )
        values, percentiles = state.values, state.percentiles
        assert values is not None and percentiles is not None  # check_cell: loaded
        values[row, axis] = value
        percentiles[row, axis] = cell_percentile_of(
            *state.cell_stats(self.gender, row, axis), value
        )
        self._hand_set(group, row, axis)

    def set_cell_percentile(self, group: str, row: int, axis: int, p: float) -> None:
        """Set one cell's percentile; its value follows."""
        check_percentile(p)
        state = self.check_cell(group, row, axis)
        values, percentiles = state.values, state.percentiles
        assert values is not None and percentiles is not None  # check_cell: loaded
        values[row, axis] = cell_value_at(*state.cell_stats(self.gender, row, axis), float(p))
        percentiles[row, axis] = p
        self._hand_set(group, row, axis)

    def _hand_set(self, group: str, row: int, axis: int) -> None:
        if group == GIRTH and axis == 2:
            self.hand_set_lengths = self.hand_set_lengths | {ROWS[GIRTH][row].name}

    def check_cell(self, group: str, row: int, axis: int) -> GroupState:
        """The cell's group; FigureError when the cell cannot be edited (no
        data, or 999)."""
        state = self.groups[group]
        if not state.loaded:
            raise FigureError(f"{GROUP_TITLES[group]} has no {self.gender} data loaded")
        if math.isnan(state.cell_stats(self.gender, row, axis)[1]):
            what = "no motion about this axis" if group == JOINT_LIMITS else "no value here"
            raise FigureError(f"{state.rows[row].label} {'xyz'[axis]}: {what}")
        return state

    def set_unit(self, group: str, unit: str) -> None:
        if unit not in GROUP_UNITS[group]:
            raise FigureError(
                f"{GROUP_TITLES[group]} is shown in {' or '.join(GROUP_UNITS[group])}, not {unit}"
            )
        self.groups[group].unit = unit

    # --- derived data ----------------------------------------------------
    def segment_masses(self) -> list[tuple[str, float]]:
        """(variable, kg) per appendix K fraction of the total mass."""
        mass = self.output_mass()
        return [(name, fraction * mass) for name, fraction in MASS_FRACTIONS]

    def output_values(self, group: str) -> tuple[np.ndarray, np.ndarray]:
        """A group's values for a body description file or an export, and a
        mask of the cells filled in: where a person has no value (ANSUR II
        measures no joint limits, for one) but the population has one, the
        population's value at the group percentile.  A population figure has
        nothing to fill.  999 cells (no motion) stay NaN."""
        state = self.groups[group]
        assert state.values is not None, f"{group} not loaded"  # callers check missing_groups()
        stats = state.stats(self.gender)
        output: tuple[np.ndarray, np.ndarray] = _arrays().filled_values(
            state.values, stats, state.percentile
        )
        return output

    def output_mass(self) -> float:
        """The total mass for output: when a person's is unknown, the
        population's median."""
        if math.isnan(self.mass):
            return _global_value(self.global_stats, self.gender, "mass", 50.0)
        return self.mass

    def value(self, group: str, row_name: str, axis: int) -> float:
        state = self.groups[group]
        index = [r.name for r in state.rows].index(row_name)
        return state.cell(index, axis)[0]

    def missing_groups(self) -> list[str]:
        return [
            GROUP_TITLES[g]
            for g in (GIRTH, JOINT_LIMITS, CENTER_OF_MASS)
            if not self.groups[g].loaded
        ]

    # --- undo (the journal is sass_tui.model.session.Session's) -----------
    def snapshot(self) -> dict[str, object]:
        """Everything an edit may change, for Session's undo journal."""
        return {k: copy.deepcopy(v) if k == "groups" else v for k, v in self.__dict__.items()}

    def restore(self, snapshot: dict[str, object]) -> None:
        """Go back to a snapshot (taken once, restored once).  Display units are a view setting, not an
        edit: the current ones are kept."""
        units = {group: state.unit for group, state in self.groups.items()}
        self.__dict__.update(snapshot)
        for group, unit in units.items():
            self.groups[group].unit = unit

    # --- internals -----------------------------------------------------------
    def _reset_globals(self) -> None:
        if self.global_stats is None or not self.global_stats.has(self.gender):
            return
        self.mass = _global_value(self.global_stats, self.gender, "mass", self.mass_percentile)
        self.stature = _global_value(
            self.global_stats, self.gender, "stature", self.stature_percentile
        )


# --- stature and mass against the global statistics (global.dat's rows) -----
def _global_cell(stats: PopulationData | None, gender: str, name: str) -> Cell:
    if stats is None or not stats.has(gender):
        raise FigureError(f"no {gender} {name} statistics loaded")
    return stats.cell(gender, [r.name for r in ROWS[GLOBAL]].index(name), 0)


def _global_value(stats: PopulationData | None, gender: str, name: str, p: float) -> float:
    check_percentile(p)
    return cell_value_at(*_global_cell(stats, gender, name), float(p))


def _global_percentile(stats: PopulationData | None, gender: str, name: str, value: float) -> float:
    """NaN when no global statistics are loaded: a size can be set without them."""
    try:
        return cell_percentile_of(*_global_cell(stats, gender, name), float(value))
    except FigureError:
        return float("nan")


def _copy(cells: Grid | np.ndarray | None) -> Grid | np.ndarray | None:
    if isinstance(cells, list):
        return [row[:] for row in cells]
    return None if cells is None else cells.copy()


def _array(grid: Grid) -> np.ndarray:
    cells: np.ndarray = _arrays().array(grid)
    return cells


def _arrays() -> ModuleType:
    """model/body/figure_arrays.py, the figure's arithmetic over numpy arrays:
    imported the first time an array is wanted, the one place numpy comes in."""
    # deferred: model.figure_arrays (numpy) — off the first screen (sass_tui/startup.py)
    from sass_tui.model.body import figure_arrays

    return figure_arrays


def _check_choice(value: str, choices: tuple[str, ...], what: str) -> str:
    word = str(value).strip().lower()
    for choice in choices:
        if word == choice or (
            len(word) >= 1
            and choice.startswith(word)
            and sum(c.startswith(word) for c in choices) == 1
        ):
            return choice
    raise FigureError(
        f"{what} must be {', '.join(choices[:-1])} or {choices[-1]}, not {str(value).strip()!r}"
    )
