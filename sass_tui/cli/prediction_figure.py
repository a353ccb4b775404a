"""`sass predict -o FILE`: the predicted person written as a figure.  Its own
module because the figure and its three writers are what `sass predict`
without -o keeps off its start-up path (sass_tui/startup.py)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from sass_tui.model.body.figure import Figure
from sass_tui.model.files.figfile import write_fig
from sass_tui.model.files.gltf import export_gltf
from sass_tui.model.files.hanim_x3d import export_hanim

if TYPE_CHECKING:
    from sass_tui.model.population.prediction import Prediction


def write_prediction_figure(prediction: Prediction, path: str) -> str:
    """The predicted person as a .fig file, an HAnim .x3d humanoid or a glTF
    body; cells the model has no value for come from the default population
    (the file says which)."""
    figure = prediction.figure(Figure.default(prediction.gender))
    if path.lower().endswith((".glb", ".gltf")):
        return ", ".join(str(p) for p in export_gltf(figure, path))
    if path.lower().endswith(".x3d"):
        return str(export_hanim(figure, path))
    return str(write_fig(figure, path))
