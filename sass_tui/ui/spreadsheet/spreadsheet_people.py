"""The spreadsheet's commands for the people of the database and the other
screens (report §12.2.4, §12.4): Query, Disp. Indv./More/Pop., Family,
Predict and its interval, See figure."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from textual import work

from sass_tui.model.body.figure import Figure
from sass_tui.model.errors import SassError
from sass_tui.model.names import (
    AXES,
    CENTER_OF_MASS,
    GIRTH,
    GROUP_TITLES,
)
from sass_tui.model.units import convert
from sass_tui.ui.base import WorkerSaid
from sass_tui.ui.spreadsheet.more_menu import MoreMenu
from sass_tui.ui.spreadsheet.predict import (
    KNOWN_PROMPT,
    KnownSuggester,
    PredictorOpened,
    interval_text,
)
from sass_tui.ui.spreadsheet.spreadsheet_base import (
    AnswerError,
    SheetScreenBase,
)
from sass_tui.ui.widgets.message_line import CANCELLED

if TYPE_CHECKING:  # numpy-heavy: imported when first used, after the first screen
    from sass_tui.model.strength.strength import StrengthData


class PeopleCommands(SheetScreenBase):
    # --- Query, Disp. Indv., Disp. More, Disp. Pop. (§12.2.4, §12.4) ----------------------
    def action_query(self) -> None:
        """Open the database query spreadsheet."""
        self.sass_app.open_query_screen()

    def action_population(self) -> None:
        """Population: U.S. civilians (virtual), a target, ANSUR II or a query, as the sheet's figure."""
        if self.session.person is not None:
            self.say(self.why_not("query") or "Disp. Pop. (o) first.")
            return
        self.sass_app.open_query_screen()
        opened = self.app.screen
        when_ready = getattr(opened, "run_when_ready", None)
        if when_ready is not None:
            when_ready("pick_population")  # once the database is open (built on first use)

    def action_see_figure(self) -> None:
        """Open the figure view: the figure drawn front and side, to scale."""
        self.sass_app.open_figure_screen()

    def action_display_individual(self) -> None:
        """Show the first person of the selected list."""
        self.show_person(0)

    def action_display_more(self) -> None:
        """Show another person of the selected list (first, next, Nth ...)."""
        if self.session.person is None:
            self.complain("Disp. Indv. first: Disp. More shows more of the selected list.")
            return
        self.converse(self._display_more())

    async def _display_more(self) -> None:
        """The More Menu's choice; for Nth Person, the number."""
        choice = await self.choose(MoreMenu())
        if choice is None:
            self.say("Disp. More cancelled.")
            return
        total = self.sass_app.selected_count()
        if choice == "Nth Person":
            text = await self.answer_to("Enter the number:")
            if text is None:
                self.say(CANCELLED)
                return
            try:
                index = int(text.strip()) - 1
            except ValueError:
                raise AnswerError(
                    f"expected a whole number such as 3, got {text.strip()!r}"
                ) from None
        else:
            index = {
                "First": 0,
                "Last": total - 1,
                "Previous": self.session.person_index - 1,
                "Next": self.session.person_index + 1,
            }[choice]
        self.show_person(index)

    def show_person(self, index: int) -> None:
        total = self.sass_app.selected_count()
        if total == 0:
            self.complain("The selected list is empty: Query, then Select One or Select All.")
            return
        if not 0 <= index < total:
            self.complain(f"There is no person {index + 1}: the selected list holds {total}.")
            return
        try:
            person = self.sass_app.person_figure(index, self.session.population)
        except (SassError, OSError) as exc:
            self.complain(f"Cannot display person {index + 1}: {exc}")
            return
        self.session.show_person(person, index, self._own_strength(index, person))
        self.refresh_screen()
        self.say(f"Person {index + 1} of {total} in the selected list: {person.person}.")

    def _own_strength(self, index: int, person: Figure) -> StrengthData | str:
        """The person's own strength experiments, or why there are none."""
        try:
            individual = self.sass_app.selected_individual(index)
        except (SassError, OSError) as exc:
            return f"{person.person}: strength not read ({exc})."
        name = person.person or f"person {index + 1}"  # a person's figure is always named
        return self.sass_app.people_work.own_strength(individual, person, name)

    def action_display_population(self) -> None:
        """Go back to the population figure."""
        self.prediction = None
        if self.session.person is None:
            self.say("The population is already shown.")
            return
        self.session.show_population()
        self.refresh_screen()
        self.say(f"Population {self.figure.population} displayed.")

    # --- Family ----------------------------------------------------------------
    def action_family(self) -> None:
        """Build a manikin family covering the population."""
        app = self.sass_app
        app.push_screen(app.people_work.family_screen(app.db_path, self.session.population.gender))

    # --- Predict ---------------------------------------------------------------
    def action_predict(self) -> None:
        """Predict a whole figure from a few known measurements."""
        if self._predictor is not None:
            self._ask_known()
            return
        self.say("Opening the prediction model (fitting it the first time takes a second) ...")
        self.open_predictor(self.sass_app.db_path)

    @work(thread=True, exclusive=True, group="predictor", exit_on_error=False)
    def open_predictor(self, db_path: str | Path | None) -> None:
        try:
            self.post_message(PredictorOpened(self.sass_app.people_work.open_predictor(db_path)))
        except (SassError, OSError) as exc:
            self.post_message(WorkerSaid(f"Cannot open the prediction model: {exc}", "error"))

    def on_predictor_opened(self, event: PredictorOpened) -> None:
        self._predictor = event.predictor
        self._ask_known()

    def _ask_known(self) -> None:
        predictor = self._predictor
        if predictor is None:
            return  # asked only once the model is open
        gender = self.session.population.gender
        try:
            fields = predictor.fields(gender)
        except SassError as exc:  # no people of this gender in the database
            self.complain(f"Cannot predict: {exc}")
            return
        self.converse(self._predict(gender, fields))

    async def _predict(self, gender: str, fields: tuple[str, ...]) -> None:
        """Predict's question: the known values, with the model's field names
        suggested while typing."""
        answer = self.message_line.answer
        answer.suggester = KnownSuggester(fields)
        try:
            text = await self.answer_to(KNOWN_PROMPT.format(gender=gender))
        finally:
            answer.suggester = None
        if text is None:
            self.say("Predict cancelled; nothing changed.")
            return
        self._predict_from(text)

    def _predict_from(self, text: str) -> None:
        if not text.strip():
            self.say("No known values given; nothing predicted.")
            return
        gender = self.session.population.gender
        predictor = self._predictor
        if predictor is None:
            return  # asked only once the model is open
        known = predictor.parse_known(gender, self.sass_app.people_work.split_known(text))
        prediction = predictor.predict(gender, known, nearest=1)
        figure = prediction.figure(self.session.population)
        self.session.show_person(figure, -1)
        self.prediction = (prediction, figure)
        self.refresh_screen()
        nearest = (
            f" Nearest real person: {prediction.nearest[0].name}." if prediction.nearest else ""
        )
        self.say(
            f"Figure {prediction.label()}.{nearest} a: a cell's 90 % interval; "
            "o: back to the population."
        )

    def action_interval(self) -> None:
        """Show the 90 % interval of the predicted cell under the cursor."""
        if self.prediction is None or self.session.person is not self.prediction[1]:
            self.complain(self.why_not("interval") or "Predict (k) first.")
            return
        group = self.data_group
        if group not in (GIRTH, CENTER_OF_MASS):
            self.say(
                f"{GROUP_TITLES[group]} is not predicted: it is the population's at the "
                "group percentile."
            )
            return
        sheet = self.sheet
        state = self.figure.groups[group]
        axis = sheet.cursor_column // 2
        field = f"{group}.{state.rows[sheet.cursor_row].name}.{AXES[axis]}"
        self.say(interval_text(self.prediction[0], field, state.unit, convert))
