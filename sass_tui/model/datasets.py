"""Where the shipped data sets live: `datasets/` at the top of the repository,
copied into the package as `sass_tui/datasets/` when a wheel is built."""

from __future__ import annotations

import gzip
import json
from functools import cache
from pathlib import Path
from typing import Any

from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS

# NHANES 2017-March 2020, the adults (scripts/make_nhanes.py, docs/data-sources.md).
NHANES = "nhanes/nhanes_2017_2020_adults.csv.gz"
NHANES_NAME = "nhanes-2017-2020"  # the shipped sample, target and virtual population
NHANES_WEIGHT = "WTMECPRP"  # its examination sample weight column
FILES = {GIRTH: "girth.dat", JOINT_LIMITS: "jntlmt.dat", CENTER_OF_MASS: "cmass.dat"}
# The shipped population a group's Input Data takes by name: the report's
# NASA crewmember trainees (the files above).
SHIPPED_POPULATION = "nasa"

_PACKAGE = Path(__file__).resolve().parent.parent


def directory() -> Path:
    for candidate in (_PACKAGE / "datasets", _PACKAGE.parent / "datasets"):
        if (candidate / "girth.dat").is_file():
            return candidate
    raise FileNotFoundError("the sass data sets (girth.dat, ...) are not installed")


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
    return (gzip.decompress(data) if name.endswith(".gz") else data).decode("utf-8")


def is_shipped(file: str | Path) -> bool:
    """Whether `file` names one of the shipped data sets (the report's)."""
    return bool(str(file)) and Path(file).resolve().parent == directory().resolve()


@cache
def json_table(name: str) -> dict[str, Any]:
    """A shipped JSON data set (an object), read once: the NIOSH lifting
    equation's and the Liberty Mutual equations' tables."""
    loaded: dict[str, Any] = json.loads(path(name).read_text(encoding="utf-8"))
    return loaded
