"""The population picker: the sheet made a population's figure in one step
(`P` on the spreadsheet or the query screen).

Its choices: the shipped virtual U.S. civilians and every other target
population in the database (`sass target`), the real survey's people (ANSUR
II soldiers), and the last query's people.  The choice's people make the
population files, weighted to the target when one was chosen, written beside
the database (`populations/`), and loaded as Make Population loads them
(query_population.py); the spreadsheet then shows that population's figure."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.widgets import OptionList
from textual.widgets.option_list import Option

from sass_tui.db.query.lists import QueryLists, people_of, target_names, target_people
from sass_tui.db.query.scope import VIRTUAL_PREFIX
from sass_tui.ui.pop_up import PopUpScreen

SURVEY_QUERY = "source = ansur2"


@dataclass(frozen=True)
class PopulationChoice:
    label: str  # as the picker shows it
    title: str  # the population file's title
    target: str | None  # weighted to this target (or virtual population)
    query: str | None  # else these people (a query's)

    def people(self, lists: QueryLists) -> tuple[int, ...]:
        """The choice's people (in a worker: a target may be made first)."""
        if self.target is not None:
            return lists.read(target_people, self.target)
        assert self.query is not None
        return lists.read(people_of, self.query)

    def file_name(self) -> str:
        """A file name for its girth population (the others go beside it)."""
        slug = re.sub(r"[^a-z0-9]+", "-", (self.target or self.label).lower()).strip("-")
        return f"{slug or 'population'}.dat"


def population_choices(target_names: list[str], last_query: str | None) -> list[PopulationChoice]:
    """The virtual populations first (U.S. civilians), then the targets, the
    survey, and the last query's people when there is a last query."""
    virtual = [name for name in target_names if name.startswith(VIRTUAL_PREFIX)]
    real = [name for name in target_names if not name.startswith(VIRTUAL_PREFIX)]
    choices = [
        PopulationChoice(
            f"{name.removeprefix(VIRTUAL_PREFIX)}: virtual U.S. civilians",
            f"VIRTUAL people of {name.removeprefix(VIRTUAL_PREFIX)}, weighted",
            name,
            None,
        )
        for name in virtual
    ]
    choices += [
        PopulationChoice(
            f"{name}: ANSUR II weighted to the target", f"weighted to target {name}", name, None
        )
        for name in real
    ]
    choices.append(
        PopulationChoice("ANSUR II soldiers: the real survey", "ANSUR II", None, SURVEY_QUERY)
    )
    if last_query:
        choices.append(
            PopulationChoice(f"The last query: {last_query}", last_query, None, last_query)
        )
    return choices


class PopulationPicker(PopUpScreen[PopulationChoice | None]):
    DEFAULT_CSS = """
    PopulationPicker { align: center middle; background: transparent; }
    PopulationPicker > #population-popup { width: 60; max-height: 80%; }
    """
    BINDINGS = [Binding("escape", "dismiss(None)", "Cancel")]

    def __init__(self, choices: list[PopulationChoice]) -> None:
        super().__init__()
        self.choices = choices

    def compose(self) -> ComposeResult:
        with Vertical(id="population-popup", classes="pop-up-menu") as popup:
            popup.border_title = "Population of the sheet"
            yield OptionList(
                *(Option(c.label, id=f"population-{i}") for i, c in enumerate(self.choices)),
                id="population-menu",
            )

    def on_option_list_option_selected(self, event: OptionList.OptionSelected) -> None:
        event.stop()
        if self.app.screen is self:  # not again for an Enter typed twice at once
            self.dismiss(self.choices[event.option_index])


def read_choices(lists: QueryLists) -> list[PopulationChoice]:
    """The picker's choices, from the database (a short read); OSError or a
    database error when it cannot be read."""
    return population_choices(lists.read(target_names), lists.last_query)


def population_path(database: Path, choice: PopulationChoice) -> Path:
    """Where a picked population's files go: beside the database file."""
    return database.parent / "populations" / choice.file_name()
