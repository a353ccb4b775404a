"""Where the shipped data sets live: `datasets/` at the top of the repository,
copied into the package as `sass_tui/datasets/` when a wheel is built."""

from __future__ import annotations

import zlib
from pathlib import Path

from sass_tui.model import shipped
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS

# NHANES 2017-March 2020, the adults (scripts/make_nhanes.py, docs/data-sources.md).
NHANES = "nhanes/nhanes_2017_2020_adults.csv.gz"
NHANES_NAME = "nhanes-2017-2020"  # the shipped sample, target and virtual population
NHANES_WEIGHT = "WTMECPRP"  # its examination sample weight column
FILES = {GIRTH: "girth.dat", JOINT_LIMITS: "jntlmt.dat", CENTER_OF_MASS: "cmass.dat"}
# The shipped population a group's Input Data takes by name: the report's
# NASA crewmember trainees (the files above).
SHIPPED_POPULATION = "nasa"


def directory() -> Path:
    """The shipped data sets' directory (model/shipped.py finds it)."""
    return Path(shipped.directory())


def path(name: str) -> Path:
    return directory() / name


def shipped_population(name: str, group: str) -> Path | None:
    """The shipped file of `group` that `name` names (Input Data); None: it
    names none."""
    if name.strip().lower() == SHIPPED_POPULATION and group in FILES:
        return path(FILES[group])
    return None


def shipped_text(name: str) -> str:
    """A shipped text data set (a `.gz` one decompressed)."""
    data = path(name).read_bytes()
    # zlib with a gzip header (wbits 16 + 15) is gzip.decompress for one member
    # without the gzip module's imports (struct, _compression: ~1 ms)
    return (zlib.decompress(data, 31) if name.endswith(".gz") else data).decode("utf-8")


def is_shipped(file: str | Path) -> bool:
    """Whether `file` names one of the shipped data sets (the report's)."""
    return bool(str(file)) and Path(file).resolve().parent == directory().resolve()
