"""Query, Disp. Indv., Disp. More and Disp. Pop. on the anthropometric
spreadsheet (report §12.2.4, §12.4).

The query screen and the database are imported when first used, not when
`sass` starts: they cost ~60 ms of start-up that a user who never queries
should not pay.
"""

from __future__ import annotations

import re
from pathlib import Path

from sass_tui.model.figure import FigureError
from sass_tui.model.names import GROUPS
from sass_tui.ui.commands import COMMANDS


def _slug(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name).strip("_") or "person"


class QueryCommands:
    """Query, Disp. Indv., Disp. More and Disp. Pop. for SassApp (a mixin: the
    app keeps its own file small and these commands beside their screen)."""

    db_path: Path | None = None
    query_lists = None  # sass_tui.db.lists.QueryLists, opened by the query screen
    population_figure = None  # the population figure while a person is shown
    person_index = 0

    def check_action(self, action: str, parameters) -> bool | None:
        # The spreadsheet's commands do nothing on the query screen and its pop-ups.
        if getattr(self.screen, "blocks_app_commands", False) and action != "quit":
            return False
        spec = next((c for c in COMMANDS if c.action == action), None)
        if spec is not None and not spec.available(self):
            return False  # its slot shows the other command; the key does nothing
        return super().check_action(action, parameters)

    def action_query(self) -> None:
        from sass_tui.ui.query_screen import QueryScreen

        self.push_screen(QueryScreen(self.query_lists, self.db_path))

    def action_display_individual(self) -> None:
        self.show_person(0)

    def action_display_more(self) -> None:
        from sass_tui.db.lists import SELECTED_LIST
        from sass_tui.ui.query_screen import MoreMenu

        if self.population_figure is None:
            self.complain("Disp. Indv. first: Disp. More shows more of the selected list.")
            return

        def chosen(choice: str | None) -> None:
            if choice is None:
                self.say("Disp. More cancelled.")
            elif choice == "Nth Person":
                self.ask("Enter the number:", self._nth_person)
            else:
                total = self.query_lists.count(SELECTED_LIST)
                index = {
                    "First": 0,
                    "Last": total - 1,
                    "Previous": self.person_index - 1,
                    "Next": self.person_index + 1,
                }[choice]
                self.show_person(index)

        self.push_screen(MoreMenu(), chosen)

    def _nth_person(self, text: str) -> None:
        try:
            number = int(text.strip())
        except ValueError:
            raise ValueError(f"expected a whole number such as 3, got {text.strip()!r}") from None
        self.show_person(number - 1)

    def show_person(self, index: int) -> None:
        from sass_tui.db.individual import fetch_individual
        from sass_tui.db.lists import SELECTED_LIST
        from sass_tui.ui.query_screen import DB_ERRORS

        lists = self.query_lists
        total = lists.count(SELECTED_LIST) if lists else 0
        if total == 0:
            self.complain("The selected list is empty: Query, then Select One or Select All.")
            return
        if not 0 <= index < total:
            self.complain(f"There is no person {index + 1}: the selected list holds {total}.")
            return
        population = self.population_figure or self.figure
        try:
            with lists.lock:
                person = fetch_individual(lists.conn, lists.selected_id(index))
            figure = population.for_person(
                person.name,
                person.gender,
                {g: person.groups[g] for g in GROUPS},
                mass=person.mass,
                stature=person.stature,
                handedness=person.handedness if person.handedness in ("right", "left") else None,
                **{
                    k: person.strength.get(k)
                    for k in ("strength_type", "motion_speed", "training_level", "fatigue_level")
                },
            )
        except (FigureError, *DB_ERRORS) as exc:
            self.complain(f"Cannot display person {index + 1}: {exc}")
            return
        self.population_figure, self.figure, self.person_index = population, figure, index
        self.refresh_screen()
        self.say(f"Person {index + 1} of {total} in the selected list: {person.name}.")

    def action_display_population(self) -> None:
        if self.population_figure is None:
            self.say("The population is already shown.")
            return
        self.figure, self.population_figure = self.population_figure, None
        self.refresh_screen()
        self.say(f"Population {self.figure.population} displayed.")

    def person_fig_name(self) -> str:
        return f"{_slug(self.figure.person)}.fig"
