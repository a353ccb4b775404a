"""A manikin family's files (model/population/accommodation.py builds the family): a
.fig and an HAnim .x3d per manikin, and family.json.

A module of its own because the X3D writer brings xml.etree, which the
family's arithmetic goes without: `sass fit` builds families to count their
coverage and writes none (the `sass fit` row of sass_tui/startup.py).
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

from sass_tui.model.body.figure import Figure
from sass_tui.model.files.atomic import make_directory, write_text_atomic
from sass_tui.model.files.figfile import write_fig
from sass_tui.model.files.hanim_x3d import export_hanim
from sass_tui.model.population.accommodation import Family


def write_family(
    family: Family,
    directory: str | Path,
    population: Figure,
    gltf: Callable[[Figure, Path], object] | None = None,
) -> Family:
    """Write a .fig and an .x3d per manikin (with `gltf`, model/files/gltf.py's
    export_gltf, a .glb too: the caller imports it, `sass family` only for
    --gltf) and
    family.json into `directory` (each file atomically); returns the family
    with each manikin's files.  A family of both genders sizes each manikin
    against its own gender's population figure."""
    out = make_directory(directory)
    manikins = []
    for manikin in family.manikins:
        own = manikin.prediction.gender
        figure = manikin.figure(population if population.gender == own else Figure.default(own))
        if family.target is not None:  # every file of a weighted family says so
            figure.person = f"{figure.person}, weighted to target {family.target['name']}"
        stem = f"{family.gender}_{manikin.name}"
        write_fig(figure, out / f"{stem}.fig")
        export_hanim(figure, out / f"{stem}.x3d")
        files = [f"{stem}.fig", f"{stem}.x3d"]
        if gltf is not None:
            gltf(figure, out / f"{stem}.glb")
            files.append(f"{stem}.glb")
        manikins.append(replace(manikin, files=tuple(files)))
    written = replace(family, manikins=tuple(manikins))
    text = json.dumps(written.to_json(), indent=1, allow_nan=False) + "\n"
    write_text_atomic(out / "family.json", text)
    return written
