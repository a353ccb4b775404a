"""Where the shipped data sets live: `datasets/` at the top of the repository,
copied into the package as `sass_tui/datasets/` when a wheel is built."""

from __future__ import annotations

from pathlib import Path

from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS

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
