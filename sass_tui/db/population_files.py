"""Writing a selection's population (db/population.py) as files: the girth
file where the user asked, the center-of-mass file beside it as
NAME-cmass.dat.  One code path for `sass population` and the query screen's
Make Population."""

from __future__ import annotations

from pathlib import Path

from sass_tui.db.population import SelectionPopulation
from sass_tui.model.atomic import write_files_atomic
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GLOBAL
from sass_tui.model.popfile import render_population_file


def cmass_path(girth_path: Path) -> Path:
    return girth_path.with_name(f"{girth_path.stem}-cmass{girth_path.suffix or '.dat'}")


def global_path(girth_path: Path) -> Path:
    """A weighted population's stature and mass (`sass fig --global`)."""
    return girth_path.with_name(f"{girth_path.stem}-global{girth_path.suffix or '.dat'}")


def write_population_files(result: SelectionPopulation, target: Path) -> dict[str, Path]:
    """Write each group the population has, all or none (a full disk once left
    a new girth file beside an old center-of-mass file); returns group -> the
    file written."""
    paths = {GIRTH: target, CENTER_OF_MASS: cmass_path(target), GLOBAL: global_path(target)}
    written = {group: paths[group] for group in result.groups}
    write_files_atomic(
        {written[group]: render_population_file(data) for group, data in result.groups.items()}
    )
    return written
