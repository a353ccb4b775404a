"""Where the shipped data sets live (`datasets/` at the top of the repository,
copied into the package as `sass_tui/datasets/` when a wheel is built), and
the shipped JSON tables read from there.

In os.path, not pathlib: the lifting equations' verbs (`sass niosh`,
`sass handling`) read their tables through here, and pathlib brings fnmatch,
urllib.parse and ipaddress (~4 ms of a command that runs in ~30 ms).
model/datasets.py gives the same directory as a Path for everything else.
"""

from __future__ import annotations

import json
import os
from functools import cache
from typing import Any

_PACKAGE = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))


def directory() -> str:
    """The shipped data sets' directory (the one holding girth.dat)."""
    for candidate in (
        os.path.join(_PACKAGE, "datasets"),
        os.path.join(os.path.dirname(_PACKAGE), "datasets"),
    ):
        if os.path.isfile(os.path.join(candidate, "girth.dat")):
            return candidate
    raise FileNotFoundError("the sass data sets (girth.dat, ...) are not installed")


@cache
def json_table(name: str) -> dict[str, Any]:
    """A shipped JSON data set (an object), read once: the NIOSH lifting
    equation's and the Liberty Mutual equations' tables."""
    with open(os.path.join(directory(), name), encoding="utf-8") as file:
        loaded: dict[str, Any] = json.load(file)
    return loaded
