"""Editing the anthropometric spreadsheet (report §12.2.2, §12.2.3): a data
cell, a strength angle or a global value, asked for on the message line and
made through the Session."""

from __future__ import annotations

import math

from sass_tui.model.errors import SassError
from sass_tui.model.names import (
    AXES,
    GIRTH,
    GROUP_TITLES,
    JOINT_AXIS_LABELS,
    MOTIONS,
    STRENGTH,
)
from sass_tui.model.population.percentile import (
    MAX_PERCENTILE,
    MIN_PERCENTILE,
    has_spread,
    plausible_range,
)
from sass_tui.model.units import DISPLAY, GROUP_UNITS, convert, parse_quantity
from sass_tui.model.vocabulary import STRENGTH_PARAMETERS
from sass_tui.ui.spreadsheet.spreadsheet_base import (
    AnswerError,
    SheetScreenBase,
    parse_percentile,
)
from sass_tui.ui.spreadsheet.strength_page import format_angle, format_strength
from sass_tui.ui.widgets import (
    DataSheet,
    GlobalPanel,
    format_percentile,
    format_value,
    global_text,
)

GLOBAL_HINTS = {
    "figure_type": "skinny or polybody",
    "gender": "male or female",
    "mass": "kg, or e.g. 180 lb",
    "stature": "cm, or e.g. 70 in",
    "mass_percentile": "percentile",
    "stature_percentile": "percentile",
    "strength_type": "isometric, isokinetic or isotonic",
    "motion_speed": "deg/s",
    "handedness": "right or left",
    "training_level": "0 = no training",
    "fatigue_level": "0 = not tired",
}


class EditCommands(SheetScreenBase):
    def on_data_sheet_edit_requested(self, event: DataSheet.EditRequested) -> None:
        event.stop()
        if self._pass_to_prompt(self.active_sheet, event.initial):
            return
        try:
            if self.data_group == STRENGTH:
                self.edit_angle(event.row, event.column, event.initial)
            else:
                self.edit_cell(event.row, event.column, event.initial)
        except SassError as exc:
            self.complain(str(exc))
        self._after_edit_request(self.active_sheet)

    def edit_cell(self, row: int, column: int, initial: str = "") -> None:
        """Prompt for a data cell (column 0-5: value, percentile of x, y, z)."""
        group = self.data_group
        axis, is_percentile = column // 2, bool(column % 2)
        self.figure.check_cell(group, row, axis)
        state = self.figure.groups[group]
        value, percentile = state.cell(row, axis)
        name = f"{state.rows[row].label} {AXES[axis]}"
        if is_percentile:
            current = format_percentile(percentile)
            prompt = f"{name} percentile [{current}]:"
        else:
            shown = convert(value, GROUP_UNITS[group][0], state.unit)
            current = format_value(shown, state.unit)
            prompt = f"{name} value [{current} {DISPLAY[state.unit]}]:"
        self.ask(
            prompt, lambda text: self._edit_cell(group, row, axis, is_percentile, text), initial
        )

    def _edit_cell(self, group: str, row: int, axis: int, is_percentile: bool, text: str) -> None:
        state = self.figure.groups[group]
        name = f"{state.rows[row].label} {AXES[axis]}"
        if not text.strip():
            self.say(f"{name} unchanged.")
            return
        if is_percentile:
            self.session.set_cell_percentile(group, row, axis, parse_percentile(text))
        else:
            typed = parse_quantity(text, state.unit)
            self.session.set_value(
                group, row, axis, convert(typed, state.unit, GROUP_UNITS[group][0])
            )
        state = self.figure.groups[group]
        source = state.source
        assert source is not None  # a loaded group has its population
        canonical = GROUP_UNITS[group][0]
        value, percentile = state.cell(row, axis)
        shown = convert(value, canonical, state.unit)
        stats = source.cell(self.figure.gender, row, axis)
        if not has_spread(*stats):
            flat = convert(stats[1], canonical, state.unit)
            where = (
                f"no percentile: the population's 5th, 50th and 95th are all "
                f"{format_value(flat, state.unit)} {DISPLAY[state.unit]}"
            )
        elif math.isnan(percentile):
            where = "no percentile: the population's statistics give none for this value"
        else:
            where = f"{format_percentile(percentile)} percentile"
        said = f"{name} = {format_value(shown, state.unit)} {DISPLAY[state.unit]} ({where})."
        kind = "info"
        if (
            has_spread(*stats)
            and not math.isnan(percentile)
            and not MIN_PERCENTILE <= percentile <= MAX_PERCENTILE
        ):
            low, high = (convert(v, canonical, state.unit) for v in plausible_range(*stats))
            said += " " + _outside(
                format_value(low, state.unit), format_value(high, state.unit), DISPLAY[state.unit]
            )
            kind = "warning"
        if group == GIRTH and self.sass_app.figure_work.not_in_humanoid(state.rows[row].name, axis):
            # The figure view does not move: say why, and where the value goes.
            said += (
                " It goes to a .fig; the figure view and Export HAnim stand the joints "
                "at the stature's landmarks."
            )
        self.message_line.show(said, kind)

    def edit_angle(self, row: int, column: int, initial: str = "") -> None:
        """Prompt for a joint angle of the strength page (column 0-6)."""
        sheet = self.session.strength_sheet
        if sheet is None:
            self.complain(self.strength_error)
            return
        name = f"{sheet.side} {MOTIONS[row].label.lower()}, {JOINT_AXIS_LABELS[column].lower()}"
        current = format_angle(sheet.angles[row, column])
        self.ask(
            f"{name} angle [{current} deg]:",
            lambda text: self._edit_angle(row, column, text),
            initial,
        )

    def _edit_angle(self, row: int, column: int, text: str) -> None:
        axis = JOINT_AXIS_LABELS[column].lower()
        if not text.strip():
            self.say(f"{MOTIONS[row].label} {axis} unchanged.")
            return
        result = self.session.set_angle(row, column, text)
        self.say(
            f"{result.side.capitalize()} {result.label.lower()} at {axis} "
            f"{format_angle(result.angles[column])} deg: "
            f"{format_strength(result.value)} {result.unit} ({result.source})."
        )

    # --- editing the global data --------------------------------------------------------
    def on_global_panel_edit_requested(self, event: GlobalPanel.EditRequested) -> None:
        event.stop()
        if self._pass_to_prompt(self.query_one(GlobalPanel), event.initial):
            return
        self.edit_global(event.field, event.initial)
        self._after_edit_request(self.query_one(GlobalPanel))

    def edit_global(self, field: str, initial: str = "") -> None:
        if field == "population":
            self.complain("The population is read from the population file; it cannot be edited.")
            return
        if field == "group_percentile" and self.data_group == STRENGTH:
            if self.session.strength_sheet is None:
                self.complain(self.strength_error)
                return
        current = global_text(self.figure, self.data_group, field, self.strength_percentile)
        hint = GLOBAL_HINTS.get(field, f"percentile of every {GROUP_TITLES[self.data_group]} row")
        stats = self.figure.global_stats
        if field in ("mass", "stature", "mass_percentile", "stature_percentile") and stats:
            hint += f"; of {stats.title}"  # whose stature and mass the percentiles are
        label = field.replace("_", " ").capitalize()
        self.ask(
            f"{label} ({hint}) [{current}]:", lambda text: self._edit_global(field, text), initial
        )

    def _edit_global(self, field: str, text: str) -> None:
        label = field.replace("_", " ").capitalize()
        if not text.strip():
            self.say(f"{label} unchanged.")
            return
        session = self.session
        strength = session.strength_sheet
        if field == "figure_type":
            session.set_figure_type(text)
        elif field == "gender":
            session.set_gender(text)
        elif field == "mass":
            session.set_mass(parse_quantity(text, "kg"))
        elif field == "stature":
            session.set_stature(parse_quantity(text, "cm"))
        elif field == "mass_percentile":
            session.set_mass_percentile(parse_percentile(text))
        elif field == "stature_percentile":
            session.set_stature_percentile(parse_percentile(text))
        elif field == "group_percentile" and self.data_group == STRENGTH and strength is not None:
            strength.set_percentile(parse_percentile(text))
        elif field == "group_percentile":
            session.set_group_percentile(self.data_group, parse_percentile(text))
        elif field == "motion_speed":
            session.set_strength_parameter(field, parse_quantity(text, "deg/s"))
        elif field in ("training_level", "fatigue_level"):
            try:
                number = float(text)
            except ValueError:
                raise AnswerError(
                    f"{label.lower()} must be a number, got {text.strip()!r}"
                ) from None
            session.set_strength_parameter(field, number)
        else:
            session.set_strength_parameter(field, text)
        shown = global_text(self.figure, self.data_group, field, self.strength_percentile)
        message = f"{label} = {shown}."
        warning = self._implausible(field) or self._without_effect(field)
        if field == "gender":
            message += " Every group reloaded for this gender."
        elif warning:
            message += f" {warning}"
        elif field in STRENGTH_PARAMETERS and strength is None:
            message += " It changes strength only (strength data is not loaded)."
        elif field in STRENGTH_PARAMETERS:
            message += " Strength values recomputed."
        self.message_line.show(message, "warning" if warning else "info")

    def _implausible(self, field: str) -> str:
        """A typed mass or stature beyond the population's 0.5th-99.5th
        percentile: accepted, and the range said ("" when inside)."""
        outside = self.figure.implausible_range(field)
        if outside is None:
            return ""
        low, high = outside
        return _outside(f"{low:.1f}", f"{high:.1f}", "kg" if field == "mass" else "cm")

    def _without_effect(self, field: str) -> str:
        """A strength setting that changes nothing as the figure stands: a
        motion speed for isometric strength (a held posture has no speed;
        model/strength/strength.py strength_type_factor)."""
        figure = self.figure
        speed_ignored = figure.strength_type == "isometric" and figure.motion_speed != 0
        if field in ("motion_speed", "strength_type") and speed_ignored:
            return (
                f"Motion speed {figure.motion_speed:g} deg/s has no effect on isometric "
                "strength (it applies to isokinetic and isotonic strength)."
            )
        return ""


def _outside(low: str, high: str, unit: str) -> str:
    return (
        f"Warning: outside the population's 0.5th-99.5th percentile range, "
        f"{low}-{high} {unit}; accepted."
    )
