"""Export HAnim and Export glTF from the spreadsheet: the file name asked for,
the figure shown rendered on the UI thread and written in a worker.

A module of its own, imported when an export is asked for: the X3D writer
(model/files/hanim_x3d.py) brings xml.etree, and the glTF export
(ui/spreadsheet/gltf_export.py) reads a person from the database; neither the first
screen nor its next frame imports them (sass_tui/startup.py).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from sass_tui.model.body.hanim import not_in_humanoid_note
from sass_tui.model.files.hanim_x3d import render_hanim
from sass_tui.ui.spreadsheet.gltf_export import ask_gltf_export
from sass_tui.ui.widgets.message_line import CANCELLED

if TYPE_CHECKING:
    from sass_tui.ui.spreadsheet.spreadsheet_files import FileCommands


def export_figure(screen: FileCommands, kind: str) -> None:
    """Export the figure shown: `kind` "hanim" (an X3D humanoid) or "gltf" (.glb)."""
    if kind == "gltf":
        ask_gltf_export(screen, screen.figure, screen._default_name(".glb"))
    else:
        screen.converse(_export_hanim(screen))


async def _export_hanim(screen: FileCommands) -> None:
    """Export HAnim's questions: the file name, and y/N before a file is
    replaced."""
    default = screen._default_name(".x3d")
    name = await screen.answer_to(f"HAnim file name [{default}]:", complete=screen.complete_file)
    if name is None:
        screen.say(CANCELLED)
        return
    path = screen.sass_app.user_path(name.strip() or default)
    figure = screen.figure
    text = render_hanim(figure)  # on the UI thread: see FileCommands._write_figure
    done = f"Exported the HAnim humanoid to {path}.{not_in_humanoid_note(figure)}"
    if await screen._may_write(path):
        screen.write_text(path, text, done)
