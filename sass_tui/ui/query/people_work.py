"""What the spreadsheet and the app do with the database's people: the query
screen, the selected list's count and people, a person's figure and own
strength (report §12.4), the Family screen and Predict's model.

A module of its own because all of it brings the database package (and
Predict the prediction model, numpy), which neither the first screen nor
its next frame imports (sass_tui/startup.py): the app reaches it in one
place (`SassApp.people_work`), when a command first needs the database.
"""

from __future__ import annotations

from pathlib import Path

from sass_tui.db.engine.database import Database
from sass_tui.db.people.individual import Individual, strength_measurements
from sass_tui.db.people.individual import person_figure as figure_of
from sass_tui.db.query.lists import SELECTED_LIST, QueryLists
from sass_tui.model.body.figure import Figure
from sass_tui.model.population.prediction import Predictor, split_known
from sass_tui.model.strength.strength import StrengthData, person_strength_data
from sass_tui.ui.query.family_screen import FamilyScreen
from sass_tui.ui.query.query_screen import QueryScreen


def open_predictor_at(db_path: str | Path | None) -> Predictor:
    """The predictor of the database the query screen uses (the default one
    when no --db was given); run in a worker."""
    db = Database.open(db_path)
    try:
        return db.predictor()
    finally:
        db.close()


class PeopleWork:
    """The work on the database's people; holds nothing."""

    def query_screen(self, lists: QueryLists | None, db_path: str | Path | None) -> QueryScreen:
        return QueryScreen(lists, db_path)

    def selected_count(self, lists: QueryLists) -> int:
        return lists.count(SELECTED_LIST)

    def person_figure(self, individual: Individual, population: Figure) -> Figure:
        """The figure of a person of the database (report §12.4)."""
        return figure_of(individual, population)

    def own_strength(self, individual: Individual, person: Figure, name: str) -> StrengthData | str:
        """The person's own strength experiments, at the person's own
        conditions (the global panel's), or why there are none."""
        measurements = strength_measurements(individual)
        if not measurements:
            return (
                f"{person.person} has no strength experiments in the database: "
                "no strength is shown for them."
            )
        conditions = (
            person.strength_type,
            person.motion_speed,
            person.training_level,
            person.fatigue_level,
        )
        return person_strength_data(name, person.gender, measurements, conditions)

    def family_screen(self, db_path: str | Path | None, gender: str) -> FamilyScreen:
        return FamilyScreen(db_path, gender)

    def open_predictor(self, db_path: str | Path | None) -> Predictor:
        return open_predictor_at(db_path)

    def split_known(self, text: str) -> list[tuple[str, str]]:
        """Predict's answer split into (name, value) pairs."""
        return split_known(text)
