"""The shipped target and virtual population `nhanes-2017-2020`: every verb
and screen that reads a target's weights by name reads them here.

A read never writes: `sass db init` makes the shipped pair; where they are
not stored (dropped with `sass target --drop`, or a database built before
they shipped or by imports alone) a verb that reads them says so and how to
make them again, instead of making them (8,381 virtual people, 9 s, a
write under `--read-only`)."""

from __future__ import annotations

import sqlite3

from sass_tui.db.populations.targets import (
    SHIPPED,
    TargetWeights,
    UnknownTargetError,
    load_target,
    target_exists,
    within_range,
)
from sass_tui.db.query.scope import VIRTUAL_PREFIX
from sass_tui.model.datasets import NHANES_NAME, NHANES_WEIGHT

# The command that makes the shipped pair again as `sass db init` does
# (db/populations/virtual.py's make_shipped: both genders, by stature and
# mass, NHANES's examination weights, within the people's range).
REMAKE = (
    f"sass target {NHANES_NAME} --sample {NHANES_NAME} --weight {NHANES_WEIGHT} "
    "--within-range --virtual --force"
)


def not_stored(name: str) -> str:
    """What to say of a shipped target this database does not hold."""
    kind = "virtual population" if name.startswith(VIRTUAL_PREFIX) else "target"
    return (
        f"the shipped {kind} {name.removeprefix(VIRTUAL_PREFIX)!r} is not in this database "
        f"(dropped, or the database was built without it); `sass db init` or `{REMAKE}` "
        "makes it again"
    )


def load_weights(
    conn: sqlite3.Connection, name: str, *, only_within_range: bool = False
) -> TargetWeights:
    """The stored target (or virtual population `virtual:NAME`) `name` and its
    weights (db/populations/targets.py's load_target); a shipped one not stored
    is reported, never made here.  `only_within_range` (`--within-range`): a
    virtual population without the people predicted beyond the real people
    (db/populations/virtual.py's within_range)."""
    if name in SHIPPED and not target_exists(conn, name):
        raise UnknownTargetError(not_stored(name), where=name)
    weights = load_target(conn, name)
    return within_range(conn, weights) if only_within_range else weights
