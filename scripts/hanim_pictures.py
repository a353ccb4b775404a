"""Render docs/hanim-figures.png: the 5th percentile female, 50th and 95th
percentile male HAnim exports side by side in one X3D scene (as the report's
figures 15 and 16), screenshot by view3dscene under xvfb-run."""

from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path

from sass_tui.model.body.body_surface import body_mesh, figure_surface
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import build_humanoid
from sass_tui.model.files.hanim_x3d import humanoid_element, scene_document

ROW = (("female", 5.0), ("male", 50.0), ("male", 95.0))
SPACING = 0.75  # metres between the figures' origins


def figure_at(gender: str, percentile: float) -> Figure:
    figure = Figure.default(gender)
    for group in figure.groups:
        figure.set_group_percentile(group, percentile)
    figure.set_mass_percentile(percentile)
    figure.set_stature_percentile(percentile)
    return figure


def main(out: Path = Path(__file__).resolve().parents[1] / "docs" / "hanim-figures.png") -> int:
    elements, tallest = [], 0.0
    for i, (gender, percentile) in enumerate(ROW):
        figure = figure_at(gender, percentile)
        humanoid = build_humanoid(figure)
        tallest = max(tallest, float(humanoid.sites[0].translation[1]))
        # the humanoid in its skin, as sass export hanim writes it
        element = humanoid_element(
            humanoid, gender, body_mesh(humanoid, figure_surface(figure, humanoid))
        )
        elements.append((element, (i - 1) * SPACING))
    text = scene_document(elements, "SASS HAnim: 5th female, 50th male, 95th male", tallest)
    with tempfile.TemporaryDirectory() as tmp:
        scene = Path(tmp) / "row.x3d"
        scene.write_text(text, encoding="utf-8")
        subprocess.run(
            [
                "xvfb-run",
                "-a",
                "view3dscene",
                str(scene),
                "--geometry",
                "900x700",
                "--anti-alias",
                "4",
                "--screenshot",
                "0",
                str(out),
            ],
            check=True,
            cwd=tmp,
            capture_output=True,
        )
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
