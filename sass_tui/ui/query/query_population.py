"""The query screen's commands that use the selected list or the last query
whole: Make Population, Fit Test, the target population."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from textual import work

from sass_tui.db.engine.addresses import is_url
from sass_tui.db.engine.database import configured_target
from sass_tui.db.engine.schema import default_db_path
from sass_tui.db.populations.fit import DEFAULT_POPULATION
from sass_tui.db.populations.population import people_words
from sass_tui.db.populations.population_files import write_population_files
from sass_tui.db.progress import Steps
from sass_tui.db.query.lists import DB_ERRORS, QueryLists
from sass_tui.model.errors import error_text
from sass_tui.model.names import GLOBAL, GROUP_TITLES
from sass_tui.ui.progress import Work
from sass_tui.ui.query.fit_screen import FitScreen
from sass_tui.ui.query.population_picker import (
    PopulationChoice,
    PopulationPicker,
    population_path,
    read_choices,
)
from sass_tui.ui.query.query_base import WAIT, Busy, QueryScreenBase
from sass_tui.ui.query.query_messages import PopulationMade
from sass_tui.ui.query.stats_screen import StatsScreen
from sass_tui.ui.query.target_picker import pick_target, weighted_words
from sass_tui.ui.widgets import MessageLine


class PopulationCommands(QueryScreenBase):
    def action_choose_target(self) -> None:
        """Pick a target population: counts, Fit Test and Make Population weighted to it."""
        lists = self.ready_lists()
        if lists is not None:
            self.converse(self._choose_target(lists))

    async def _choose_target(self, lists: QueryLists) -> None:
        name = await pick_target(self, lists, self.target)
        if name is None:
            return
        self.target = name or None
        self.say(
            f"Target {name}: query counts, Fit Test and Make Population are weighted to it."
            if name
            else "No target: the people unweighted."
        )

    # --- Make Population ----------------------------------------------------
    def action_make_population(self) -> None:
        """Write and load population files made of the selected list's people
        (Select One / Select All), not the last query's."""
        if self.running:
            self.say(WAIT)
            return
        try:
            with self._database() as lists:
                ids = lists.selected_ids()
        except Busy as exc:
            self.say(str(exc))
            return
        if not ids:
            self.say(
                "Make Population uses the selected list, which is empty: "
                "Select One (s) or Select All (a) people of a query first."
            )
            return

        def answer(text: str) -> None:
            name = text.strip()
            if not name:
                self.say("Make Population cancelled: no file name given.")
                return
            path = self.sass_app.user_path(name)
            work = self.begin_work("Make Population")
            self.say(f"Making the population of {len(ids):,} selected people (Esc cancels)...")
            sources = " OR ".join(f"({q})" for q in self.selected_from) or "selection"
            title = f"Population of {len(ids):,} selected from {sources}"
            self.make_population(self.lists, tuple(ids), path, title, work, self.target)

        self.ask(
            f"Population of the {len(ids):,} selected people: file name "
            "(girth; the center-of-mass file goes beside it):",
            answer,
            on_cancel=lambda: self.say("Make Population cancelled."),
        )

    @work(thread=True, exclusive=True, group="query-db", exit_on_error=False)
    def make_population(
        self,
        lists: QueryLists,
        ids: tuple[int, ...],
        target: Path,
        title: str,
        work: Work,
        weighted_to: str | None = None,
    ) -> None:
        try:
            if weighted_to:
                title += weighted_words(weighted_to)
            result = lists.population_of(ids, title, work.report, work.cancel, target=weighted_to)
            Steps(cancel=work.cancel, what="making the population").check()  # last chance
            paths = write_population_files(result, target)
        except DB_ERRORS as exc:
            self.post_message(PopulationMade(error=error_text(exc)))
            return
        self.post_message(PopulationMade(result, paths))

    def on_population_made(self, event: PopulationMade) -> None:
        event.stop()
        if self.end_work() and event.error:
            self.say("Make Population cancelled: nothing written or loaded.")
            return
        if event.error:
            self.complain(f"Make Population: nothing written or loaded: {event.error}")
            return
        session = self.sass_app.session
        if session.person is not None:
            session.show_population()  # the population is what the next figure is sized from
        genders = list(event.result.counts)
        if len(genders) == 1 and session.population.gender != genders[0]:
            session.set_gender(genders[0])  # the only gender the population has
        for group, data in event.result.groups.items():
            if group == GLOBAL:  # the people's own stature and mass
                session.load_global(replace(data, path=str(event.paths[group])))
            else:
                session.load_group(group, replace(data, path=str(event.paths[group])))
        files = ", ".join(
            f"{GROUP_TITLES[group].lower()} {path}" for group, path in event.paths.items()
        )
        figure = session.population
        said = (
            f"Population of {people_words(event.result.counts)} written ({files}) and loaded: "
            f"Stature {figure.stature:.1f} cm and Mass {figure.mass:.1f} kg are theirs "
            f"(percentiles {figure.stature_percentile:g} and {figure.mass_percentile:g}); "
            "Create Figure now sizes this subpopulation; joint limits and strength keep "
            "the loaded population."
        )
        if self._back_after_population:  # the picker: the sheet shows its figure
            self._back_after_population = False
            self.app.pop_screen()
            refresh = getattr(self.app.screen, "refresh_screen", None)
            if refresh is not None:
                refresh()
            self.app.screen.query_one(MessageLine).say(said)
            return
        self.say(said)

    # --- the population picker: the sheet a population's figure in one step -----
    # After the population is loaded, back to the spreadsheet (set by the picker).
    _back_after_population = False

    def action_pick_population(self) -> None:
        """Population: U.S. civilians (virtual), a target, ANSUR II or the last query, as the sheet's figure."""
        if self.running:
            self.say(WAIT)
            return
        lists = self.ready_lists()
        if lists is not None:
            self.converse(self._pick_population(lists))

    async def _pick_population(self, lists: QueryLists) -> None:
        try:
            choices = read_choices(lists)
        except DB_ERRORS as exc:
            self.complain(f"Cannot read the populations: {exc}")
            return
        choice = await self.choose(PopulationPicker(choices))
        if choice is None:
            self.say("Population unchanged.")
            return
        self._make_picked(lists, choice)

    def _make_picked(self, lists: QueryLists, choice: PopulationChoice) -> None:
        app = self.sass_app
        database = configured_target(self.db_path) or default_db_path()
        if app.workdir is not None or is_url(str(database)):
            path = app.user_path(choice.file_name())  # a served session, or PostgreSQL
        else:
            path = population_path(Path(database), choice)
        work = self.begin_work("Population")
        self._back_after_population = True
        self.say(f"Making the population {choice.label} (Esc cancels)...")
        self.make_picked_population(lists, choice, path, work)

    @work(thread=True, exclusive=True, group="query-db", exit_on_error=False)
    def make_picked_population(
        self, lists: QueryLists, choice: PopulationChoice, path: Path, work: Work
    ) -> None:
        try:
            ids = choice.people(lists)
            if not ids:
                self.post_message(PopulationMade(error=f"{choice.label}: nobody in the database"))
                return
            result = lists.population_of(
                ids, choice.title, work.report, work.cancel, target=choice.target
            )
            Steps(cancel=work.cancel, what="making the population").check()
            path.parent.mkdir(parents=True, exist_ok=True)
            paths = write_population_files(result, path)
        except DB_ERRORS as exc:
            self.post_message(PopulationMade(error=error_text(exc)))
            return
        self.post_message(PopulationMade(result, paths))

    # --- Fit Test ------------------------------------------------------------
    def action_fit_test(self) -> None:
        """Test a population against the last query as design limits."""
        if self.running:
            self.say(WAIT)
            return
        lists = self.lists
        limits = lists.last_query if lists else None
        if lists is None or not limits:
            self.say("Fit Test uses the last query as design limits: run a query first.")
            return

        def answer(text: str) -> None:
            population = text.strip() or DEFAULT_POPULATION
            self.app.push_screen(FitScreen(lists, limits, population, self.target))

        self.ask(
            f"Population to test (Enter: {DEFAULT_POPULATION}):",
            answer,
            on_cancel=lambda: self.say("Fit Test cancelled."),
        )

    # --- Stats ---------------------------------------------------------------
    def action_stats(self) -> None:
        """The percentile table of the last query's people (weighted to the target)."""
        if self.running:
            self.say(WAIT)
            return
        if self.lists is None:
            self.say("The database is not open yet.")
            return
        self.app.push_screen(StatsScreen(self.lists, self.lists.last_query, self.target))
