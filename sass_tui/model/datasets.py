"""Where the shipped data sets live: `datasets/` at the top of the repository,
copied into the package as `sass_tui/datasets/` when a wheel is built."""

from __future__ import annotations

from pathlib import Path

from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS

FILES = {GIRTH: "girth.dat", JOINT_LIMITS: "jntlmt.dat", CENTER_OF_MASS: "cmass.dat"}

_PACKAGE = Path(__file__).resolve().parent.parent


def directory() -> Path:
    for candidate in (_PACKAGE / "datasets", _PACKAGE.parent / "datasets"):
        if (candidate / "girth.dat").is_file():
            return candidate
    raise FileNotFoundError("the sass data sets (girth.dat, ...) are not installed")


def path(name: str) -> Path:
    return directory() / name


def is_shipped(file: str | Path) -> bool:
    """Whether `file` names one of the shipped data sets (the report's)."""
    return bool(str(file)) and Path(file).resolve().parent == directory().resolve()
