"""The spreadsheet's file commands (report §12.2.4): Input Data, Create
Figure, Export HAnim and glTF.  Files are read and written in workers that
get an immutable input (a path, the rendered text)."""

from __future__ import annotations

from pathlib import Path

from textual import work

from sass_tui.model.datasets import SHIPPED_POPULATION, shipped_population
from sass_tui.model.errors import SassError, reason_text
from sass_tui.model.files.atomic import OutputFileError, check_target, write_text_atomic
from sass_tui.model.files.popfile import read_global_beside, read_population_file
from sass_tui.model.names import (
    GIRTH,
    GROUP_TITLES,
    STRENGTH,
)
from sass_tui.model.strength.published_grip import GRIP_DATA_SET, table_words
from sass_tui.model.strength.published_strength import DATA_SET, EXAMPLE_DATA_SET
from sass_tui.ui.base import WorkerSaid
from sass_tui.ui.spreadsheet.spreadsheet_base import (
    AnswerError,
    PopulationRead,
    SheetScreenBase,
    StrengthRead,
)
from sass_tui.ui.widgets.message_line import CANCELLED

# The strength data sets Input Data takes by name on the strength page
# (docs/strength.md): model/strength/published_strength.py's EXAMPLE_DATA_SET and
# DATA_SET, model/strength/published_grip.py's GRIP_DATA_SET, which the first screen
# does not import.
STRENGTH_DATA_SETS = ("example", "anderson2007", "hfds2003")


class FileCommands(SheetScreenBase):
    # --- Input Data -----------------------------------------------------------------
    def action_input_data(self) -> None:
        """Read a population (or strength) file into the group shown."""
        if self.data_group == STRENGTH:
            names: tuple[str, ...] = STRENGTH_DATA_SETS
            prompt = f"Strength data file: (Tab completes; or a data set: {', '.join(names)})"
        else:
            names = (SHIPPED_POPULATION,)
            prompt = (
                f"{GROUP_TITLES[self.data_group]} population file: "
                f"(Tab completes; or the shipped data set: {SHIPPED_POPULATION})"
            )

        def complete(text: str) -> list[str]:
            typed = text.strip().lower()
            shipped = [name for name in names if typed and name.startswith(typed)]
            return shipped + self.complete_file(text)

        self.ask(prompt, self._input_data_from, complete=complete)

    def _input_data_from(self, text: str) -> None:
        if not text.strip():
            self.say("No file given; nothing loaded.")
            return
        if self.data_group == STRENGTH and self._strength_data_set(text.strip().lower()):
            return
        shipped = shipped_population(text, self.data_group)
        if shipped is not None:
            self.say(f"Reading the shipped data set {text.strip().lower()} ({shipped.name}) ...")
            self.read_data_file(shipped, self.data_group)
            return
        # Refused here, before any worker opens it: a FIFO would block it forever.
        path = self.sass_app.regular_file(text.strip())
        self.say(f"Reading {text.strip()} ...")
        self.read_data_file(path, self.data_group)

    def _strength_data_set(self, name: str) -> bool:
        """A strength data set named instead of a file (docs/strength.md): the
        example data read again, Anderson et al. 2007's curves shown, or HFDS
        2003's grip forces said (forces: the strength page shows joint torques)."""
        if name == EXAMPLE_DATA_SET:
            path = self.sass_app.figure_work.example_strength_path()
            self.say(f"Reading the example data ({path.name}) ...")
            self.read_data_file(path, STRENGTH)
            return True
        if name == DATA_SET:
            self.action_strength_curve()
            return True
        if name == GRIP_DATA_SET:
            self.say(f"{table_words()} (forces, not on this page: sass strength hand_grip).")
            return True
        return False

    @work(thread=True, exclusive=True, group="input-data", exit_on_error=False)
    def read_data_file(self, path: Path, group: str) -> None:
        """Input Data: read in a worker; a file that fails changes nothing."""
        what = "strength data" if group == STRENGTH else GROUP_TITLES[group]
        try:
            if group == STRENGTH:
                strength = self.sass_app.figure_work.read_strength_file(path)
                self.post_message(StrengthRead(strength))
            else:
                data = read_population_file(path, group)
                beside = read_global_beside(path) if group == GIRTH else None
                self.post_message(PopulationRead(group, data, beside))
        except SassError as exc:
            self.post_message(WorkerSaid(f"{exc}; {what} unchanged.", "error"))
        except OSError as exc:
            self.post_message(WorkerSaid(f"{path}: {reason_text(exc)}; {what} unchanged.", "error"))

    def on_strength_read(self, event: StrengthRead) -> None:
        data = event.data
        self.session.load_strength(data)
        self._say_loaded("strength", data.path, data.title)

    def on_population_read(self, event: PopulationRead) -> None:
        group, data = event.group, event.data
        gender = self.figure.gender
        if not data.has(gender):
            self.complain(
                f"{data.path}: no 'T {gender.upper()}' section for this {gender} "
                f"figure; {GROUP_TITLES[group]} unchanged."
            )
            return
        beside = event.stature_and_mass
        if beside is not None and not beside.has(gender):
            beside = None  # a gender the girth file has and its stature file lacks
        try:
            self.session.load_group(group, data, beside)
        except SassError as exc:
            self.complain(f"{exc}; {GROUP_TITLES[group]} unchanged.")
            return
        title, figure = data.title, self.figure
        if beside is not None:
            title += (
                f"; Stature {figure.stature:.1f} cm and Mass {figure.mass:.1f} kg are the "
                f"people's own, from {Path(beside.path).name} beside it"
            )
        elif group == GIRTH and figure.global_stats and figure.global_stats.title != data.title:
            title += f"; Stature and Mass stay those of {figure.global_stats.title}"
        self._say_loaded(GROUP_TITLES[group], data.path, title)

    def _say_loaded(self, what: str, path: str, title: str) -> None:
        """A file just loaded (Input Data): the screen redrawn, what was
        loaded said, then the file's warnings one by one."""
        self._warning_index = 0
        self.refresh_screen()
        self.say(f"Loaded {what} from {path} ({title}).")
        if self.session.warnings:
            self._show_warning()

    # --- Create Figure --------------------------------------------------------------
    def _default_name(self, suffix: str) -> str:
        """Create Figure's and the exports' file name: the person's shown,
        else the figure's gender and girth percentile (MALE50.FIG)."""
        return self.sass_app.figure_work.file_name(self.figure, suffix)

    def action_create_figure(self) -> None:
        """Write the figure shown as a .fig file."""
        missing = self.figure.missing_groups()
        if missing:
            self.complain(
                f"Cannot create a figure: {', '.join(missing)} not loaded for {self.figure.gender}."
            )
            return
        self.converse(self._create_figure())

    async def _create_figure(self) -> None:
        """Create Figure's questions: the file name, whether to include
        strength (when it is loaded), and y/N before a file is replaced."""
        default = self._default_name(".fig")
        name = await self.answer_to(f"Figure file name [{default}]:", complete=self.complete_file)
        if name is None:
            self.say(CANCELLED)
            return
        path = self.sass_app.user_path(name.strip() or default)
        sections: list = []
        example = ""
        strength = self.session.strength_sheet
        if strength is not None:
            answer = await self.answer_to(
                "Include strength in the figure? (Y/n; 'example' adds the invented arm data)"
            )
            if answer is None:
                self.say(CANCELLED)
                return
            word = answer.strip().lower()
            if word in ("", "y", "yes", "example"):
                figure_work = self.sass_app.figure_work
                sections, example = figure_work.fig_strength(self.figure, strength, word)
            elif word not in ("n", "no"):
                raise AnswerError(
                    f"expected y, n or example, got {answer.strip()!r}; nothing written"
                )
        if await self._may_write(path):
            self._write_figure(path, sections, example)

    async def _may_write(self, path: Path) -> bool:
        """A new file may be written; an existing one only after the user says
        y; what cannot be written (a directory) is refused before asking."""
        if not path.exists():
            return True
        try:
            check_target(path)
        except OutputFileError as exc:
            self.complain(f"{exc}; nothing written")
            return False
        answer = await self.answer_to(f"{path} exists. Overwrite it? (y/N)")
        if answer is None:
            self.say(CANCELLED)
            return False
        if answer.strip().lower() in ("y", "yes"):
            return True
        self.say(f"Not written; {path} kept as it was.")
        return False

    def _write_figure(self, path: Path, sections: list, said: str = "") -> None:
        """Rendered here, on the UI thread: the worker gets the text, never the
        figure the user may be editing meanwhile."""
        text, note = self.sass_app.figure_work.fig_text(self.figure, sections)
        self.write_text(path, text, f"Wrote {path}.{note}{said}")

    @work(thread=True, group="write", exit_on_error=False)
    def write_text(self, path: Path, text: str, done: str) -> None:
        try:
            write_text_atomic(path, text)
        except (SassError, OSError) as exc:
            self.post_message(WorkerSaid(f"{path}: cannot write: {reason_text(exc)}", "error"))
            return
        self.post_message(WorkerSaid(done))

    # --- Export HAnim, Export glTF ------------------------------------------------------
    def action_export_hanim(self) -> None:
        """Write the figure shown as an HAnim X3D humanoid."""
        self._export("hanim")

    def action_export_gltf(self) -> None:
        """Write the figure shown as a glTF 2.0 body (.glb)."""
        self._export("gltf")

    def _export(self, kind: str) -> None:
        # deferred: ui.exports (model.hanim_x3d, xml.etree, the db package) — off the first screen, the first screen's next frame (sass_tui/startup.py)
        from sass_tui.ui.spreadsheet.exports import export_figure

        export_figure(self, kind)
