"""A manikin family on screen: the gender, measures and coverage
asked on the message line, the family computed in a worker (`load_family`,
as `sass family` does), shown as a table and as a scatter plot of the first
two measures with the population's people and the manikins; `w` writes the
family's files with `write_family`.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from textual import work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal
from textual.message import Message
from textual.widgets import DataTable, Label
from textual_plotext import PlotextPlot

from sass_tui.db.engine.database import Database
from sass_tui.db.populations.family import family_and_scatter
from sass_tui.db.populations.fit import DEFAULT_POPULATION
from sass_tui.model.body.figure import Figure
from sass_tui.model.errors import SassError, error_text
from sass_tui.model.files.family_files import write_family
from sass_tui.model.population.measure_fields import measure_field
from sass_tui.model.vocabulary import GENDERS
from sass_tui.ui.base import SassScreen, WorkerSaid
from sass_tui.ui.footer import Footer
from sass_tui.ui.progress import Work, WorkBar, WorkProgressed
from sass_tui.ui.widgets import MessageLine
from sass_tui.ui.widgets.message_line import CANCELLED

if TYPE_CHECKING:  # numpy: imported when a family is written
    from sass_tui.model.population.accommodation import Family

DEFAULT_MEASURES = "stature,mass"
DEFAULT_COVERAGE = 90.0


class FamilyAnswerError(ValueError, SassError):
    """An answer to the family screen's questions that is not what was asked for."""


class FamilyBuilt(Message):
    def __init__(self, family, people_x, people_y) -> None:
        super().__init__()
        self.family = family
        self.people_x = people_x
        self.people_y = people_y


class FamilyFailed(Message):
    def __init__(self, text: str) -> None:
        super().__init__()
        self.text = text


def parse_measures(text: str) -> list[str]:
    names = [name.strip() for name in (text.strip() or DEFAULT_MEASURES).split(",")]
    names = [name for name in names if name]
    if not 2 <= len(names) <= 6:
        raise FamilyAnswerError(f"give 2 to 6 measurements separated by commas, not {len(names)}")

    for name in names:
        measure_field(name)  # a typo is said now, before the database is opened
    return names


def parse_coverage(text: str) -> float:
    cleaned = text.strip().rstrip("%").strip()
    try:
        value = float(cleaned) if cleaned else DEFAULT_COVERAGE
    except ValueError:
        raise FamilyAnswerError(f"expected a coverage such as 90, got {text.strip()!r}") from None
    if not 0 < value < 100:
        raise FamilyAnswerError(f"coverage {value:g} % is outside 0-100 %")
    return value


class FamilyScreen(SassScreen):
    """Table of the manikins and their nearest real people; scatter plot."""

    BINDINGS = [
        Binding("escape", "back", "Back"),
        Binding("w", "write", "Write files"),
        Binding("b", "build", "New family"),
    ]

    DEFAULT_CSS = """
    FamilyScreen #family-body { height: 1fr; }
    FamilyScreen #family-table { width: 1fr; }
    FamilyScreen #family-plot { width: 1fr; }
    """

    def __init__(self, db_path: str | Path | None, gender: str = "male") -> None:
        super().__init__(id="family")
        self.db_path = db_path
        self.default_gender = gender
        self.family: Family | None = None
        self.work: Work | None = None

    def compose(self) -> ComposeResult:
        yield Label("Manikin family", id="family-title")
        with Horizontal(id="family-body"):
            yield DataTable(id="family-table", cursor_type="row")
            yield PlotextPlot(id="family-plot")
        yield WorkBar(id="work")
        yield MessageLine(id="message-line")
        yield Footer(compact=True)

    def on_mount(self) -> None:
        self.action_build()

    def action_back(self) -> None:
        """Escape: cancel the family being built, else back to the spreadsheet."""
        if self.work is not None:
            if not self.work.cancel.is_set():
                self.work.cancel.set()
                self.query_one(WorkBar).cancelling()
                self.say("Cancelling the family ...")
            return
        self.app.pop_screen()

    def on_work_progressed(self, event: WorkProgressed) -> None:
        event.stop()
        self.query_one(WorkBar).show(event)

    def _end_work(self) -> bool:
        work, self.work = self.work, None
        self.query_one(WorkBar).stop()
        return work is not None and work.cancel.is_set()

    # --- the questions ------------------------------------------------------------
    def action_build(self) -> None:
        """Build a new family (coverage, number of manikins)."""
        self.converse(self._build_questions())

    async def _build_questions(self) -> None:
        """The family's questions in turn (gender, measures, coverage), then
        the build in a worker."""
        text = await self.answer_to(f"Gender ({' or '.join(GENDERS)}) [{self.default_gender}]:")
        if text is None:
            self.say(CANCELLED)
            return
        gender = text.strip().lower() or self.default_gender
        if gender not in GENDERS:
            raise FamilyAnswerError(f"expected {' or '.join(GENDERS)}, got {text.strip()!r}")
        text = await self.answer_to(f"Measures, 2 to 6 separated by commas [{DEFAULT_MEASURES}]:")
        if text is None:
            self.say(CANCELLED)
            return
        measures = parse_measures(text)
        text = await self.answer_to(f"Coverage in % [{DEFAULT_COVERAGE:g}]:")
        if text is None:
            self.say(CANCELLED)
            return
        coverage = parse_coverage(text)
        self.say(
            f"Building the {gender} family over {', '.join(measures)} at {coverage:g} % "
            "(the prediction model completes each manikin) ..."
        )
        self.work = Work(self, "Family")
        self.query_one(WorkBar).start(self.work)
        self.build_family(self.db_path, gender, tuple(measures), coverage, self.work)

    # --- the worker -------------------------------------------------------------------
    @work(thread=True, exclusive=True, group="family", exit_on_error=False)
    def build_family(
        self,
        db_path: str | Path | None,
        gender: str,
        measures: tuple[str, ...],
        coverage: float,
        work: Work,
    ) -> None:
        try:
            db = Database.open(db_path)
            try:
                family, people = family_and_scatter(
                    db,
                    gender,
                    measures,
                    coverage / 100.0,
                    "boundary",
                    DEFAULT_POPULATION,
                    progress=work.report,
                    cancel=work.cancel,
                )
            finally:
                db.close()
        except (SassError, OSError) as exc:
            self.post_message(FamilyFailed(f"Cannot build the family: {error_text(exc)}"))
            return
        matrix = people.matrix
        self.post_message(FamilyBuilt(family, list(matrix[:, 0]), list(matrix[:, 1])))

    def on_family_failed(self, event: FamilyFailed) -> None:
        if self._end_work():
            self.say("Family cancelled: nothing built or written.")
            return
        self.complain(event.text)

    def on_family_built(self, event: FamilyBuilt) -> None:
        self._end_work()  # built: a cancel that came too late changes nothing
        family = self.family = event.family
        table = self.query_one(DataTable)
        table.clear(columns=True)
        short = [f.removeprefix("measure.") for f in family.measures]
        table.add_columns("manikin", *short, "nearest person")
        for manikin in family.manikins:
            table.add_row(
                manikin.name,
                *(f"{manikin.values[f]:.1f}" for f in family.measures),
                f"{manikin.nearest.name} ({manikin.nearest.distance:.2f})",
            )
        x_name, y_name = family.measures[:2]
        plot = self.query_one(PlotextPlot).plt
        plot.clear_data()
        plot.clear_figure()
        plot.scatter(event.people_x, event.people_y, marker="dot", label="people")
        plot.scatter(
            [m.values[x_name] for m in family.manikins],
            [m.values[y_name] for m in family.manikins],
            marker="x",
            label="manikins",
        )
        plot.xlabel(short[0])
        plot.ylabel(short[1])
        self.query_one(PlotextPlot).refresh()
        coverage = family.coverage
        self.query_one("#family-title", Label).update(
            f"{family.gender} {family.kind} family over {', '.join(short)}: "
            f"{len(family.manikins)} manikins; {coverage.inside_percent:.1f} % of "
            f"{coverage.n} people inside (promised {coverage.promised_percent:g} %)"
        )
        self.say(f"{len(family.manikins)} manikins. w: write their files; b: another family.")

    # --- writing ---------------------------------------------------------------------
    def action_write(self) -> None:
        """Write each manikin's .fig and HAnim files."""
        family = self.family
        if family is None:
            self.complain("No family built yet: answer the questions first (b).")
            return
        default = f"family_{family.gender}"
        # The family offered now is the one written, even if another is built
        # while the directory is asked.
        self.ask(
            f"Directory for the family's files [{default}]:",
            lambda text: self._write_to(family, self.sass_app.user_path(text.strip() or default)),
        )

    def _write_to(self, family: Family, directory: Path) -> None:
        self.say(f"Writing the family's files to {directory} ...")
        self.write_family_files(family, directory)

    # a family of 13 manikins takes half a second to write: not on the screen's loop
    @work(thread=True, group="family-write", exit_on_error=False)
    def write_family_files(self, family: Family, directory: Path) -> None:
        try:
            written = write_family(family, directory, Figure.default(family.gender))
        except (SassError, OSError) as exc:
            self.post_message(WorkerSaid(error_text(exc), "error"))
            return
        self.post_message(
            WorkerSaid(
                f"Wrote {len(written.manikins)} manikins (.fig, .x3d) and family.json "
                f"to {directory}.",
                "info",
            )
        )
