"""Export glTF (t): a figure as a skinned glTF 2.0 body (model/files/gltf.py).

One path for both screens that offer it: the spreadsheet exports the figure
shown (the population's, or the person displayed), the query screen the
person under the list's cursor, measured against the spreadsheet's
population as Disp. Indv. does (report §12.4).  The prompts are Export
HAnim's: the file name (the person's, else MALE50.glb), the pose, and y/N
before a file is replaced.  The asset is made here, on the UI thread, from
the figure as it is when the name is given; the worker only writes the
bytes (architecture.md, Workers).
"""

from __future__ import annotations

from collections.abc import Callable
from contextlib import AbstractContextManager
from pathlib import Path
from typing import TYPE_CHECKING

from sass_tui.db.people.individual import person_figure
from sass_tui.db.query.lists import DB_ERRORS
from sass_tui.model.body.hanim import build_humanoid, not_in_humanoid_note
from sass_tui.model.errors import SassError, reason_text
from sass_tui.model.files.atomic import OutputFileError, check_target
from sass_tui.model.files.gltf import POSES, bin_path, check_path, pose_of, render_gltf, write_gltf
from sass_tui.ui.base import WorkerSaid
from sass_tui.ui.widgets.message_line import CANCELLED

if TYPE_CHECKING:
    from sass_tui.model.body.figure import Figure
    from sass_tui.model.files.gltf import GltfDocument
    from sass_tui.ui.base import SassScreen


def ask_gltf_export(screen: SassScreen, figure: Figure, default: str) -> None:
    """Ask for the file name and the pose, then write `figure` as glTF."""
    screen.converse(_export(screen, figure, default))


async def _export(screen: SassScreen, figure: Figure, default: str) -> None:
    """Export glTF's questions: the file name, the pose, and y/N before a
    file is replaced."""
    name = await screen.answer_to(f"glTF file name (.glb, or .gltf + .bin) [{default}]:")
    if name is None:
        screen.say(CANCELLED)
        return
    # A served session's file stays in its working directory (SassApp.user_path).
    name = name.strip() or default
    path = check_path(screen.sass_app.user_path(name))  # refused before the next prompt
    answer = await screen.answer_to(f"Pose: {' or '.join(POSES)} [{POSES[0]}]:")
    if answer is None:
        screen.say(CANCELLED)
        return
    pose = pose_of(answer)
    asset = render_gltf(figure, pose)
    files = [path] if path.suffix.lower() == ".glb" else [path, bin_path(path)]
    done = (
        f"Exported the {pose} glTF body to {' and '.join(map(str, files))}."
        f"{not_in_humanoid_note(figure)}"
    )
    try:
        for file in files:  # a directory is refused before it is offered for overwrite
            if file.exists():
                check_target(file)
    except OutputFileError as exc:
        screen.complain(f"{exc}; nothing written")
        return
    existing = " and ".join(str(f) for f in files if f.exists())
    if existing:
        answer = await screen.answer_to(f"{existing} exists. Overwrite? (y/N)")
        if answer is None:
            screen.say(CANCELLED)
            return
        if answer.strip().lower() not in ("y", "yes"):
            screen.say(f"Not written; {existing} kept as it was.")
            return
    _write(screen, asset, path, done)


def _write(screen: SassScreen, asset: GltfDocument, path: Path, done: str) -> None:
    def write() -> None:
        try:
            write_gltf(asset, path)
        except (SassError, OSError) as exc:
            screen.post_message(WorkerSaid(f"{path}: cannot write: {reason_text(exc)}", "error"))
            return
        screen.post_message(WorkerSaid(done))

    screen.run_worker(write, thread=True, group="write", exit_on_error=False)


def export_list_person(
    screen: SassScreen, database: Callable[[], AbstractContextManager], row: dict | None
) -> None:
    """The query screen's Export glTF: the person of the list row `row`, read
    through the screen's `database()` (which refuses while a query runs)."""
    if row is None:
        screen.say("The list is empty: no person to export.")
        return
    with database() as lists:
        try:
            person = lists.fetch_person(row["id"])
        except DB_ERRORS as exc:
            screen.complain(f"Cannot read {row['name']} from the database: {exc}")
            return
    figure = person_figure(person, screen.sass_app.session.population)
    # the humanoid's name is the person's, as a file name ('ANSUR_II_M_10037')
    ask_gltf_export(screen, figure, f"{build_humanoid(figure).name}.glb")
