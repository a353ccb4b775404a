"""Writing a selection's population (db/populations/population.py) as files: the girth
file where the user asked, the center-of-mass file beside it as
NAME-cmass.dat, the people's own stature and mass as NAME-global.dat.  One code path for `sass population` and the query screen's
Make Population."""

from __future__ import annotations

from pathlib import Path

from sass_tui.db.populations.population import SelectionPopulation
from sass_tui.model.files.atomic import write_files_atomic
from sass_tui.model.files.popfile import cmass_path, global_path, render_population_file
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GLOBAL

__all__ = ["cmass_path", "global_path", "write_population_files"]


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
