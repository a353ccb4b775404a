"""The shipped target and virtual population `nhanes-2017-2020`, made in a
database the first time a command names them (db/populations/virtual.py's
store_shipped); every verb and screen that reads a target's weights by name
reads them here."""

from __future__ import annotations

import sqlite3

from sass_tui.db.populations.targets import SHIPPED, TargetWeights, load_target, target_exists
from sass_tui.db.populations.virtual import store_shipped, within_range


def load_weights(
    conn: sqlite3.Connection, name: str, *, only_within_range: bool = False
) -> TargetWeights:
    """The stored target (or virtual population `virtual:NAME`) `name` and its
    weights (db/populations/targets.py's load_target); a shipped one not made yet is made
    first, on either engine.  `only_within_range` (`--within-range`): a
    virtual population without the people predicted beyond the real people
    (db/populations/virtual.py's within_range)."""
    if name in SHIPPED and not target_exists(conn, name):
        store_shipped(conn)
    weights = load_target(conn, name)
    return within_range(conn, weights) if only_within_range else weights
