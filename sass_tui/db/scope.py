"""Real people by default: which people a query reaches.

The default database holds the 6,068 real people of ANSUR II and 200
synthetic demonstration people (`source = synthetic`, docs/data-sources.md),
who exist only to show the strength, joint-limit and center-of-mass columns
ANSUR II did not measure.  A count, a list, a population, a fit or a
prediction must not mix them into an answer about real people, so a query
that names no `source` term reaches only the people whose source is not
`synthetic`; any `source` term (`source = synthetic`, `source != ansur2`)
leaves the choice to the query.

`real_only` is the one place that scope is added; `db/query.py`'s
`compile_query` calls it with whether the query named `source`.  When the
scope leaves nobody, `query.demonstration_hint` says how many demonstration
people the query would reach, and the query that reaches them
(`demonstration_query`).
"""

from __future__ import annotations

DEMONSTRATION_SOURCE = "synthetic"
# source is NOT NULL (db/schema.py) and the default database stores the label
# in lower case, so a plain comparison: the column copy of db/accelerator.py
# answers it (it leaves a comparison without regard to case to SQLite).
_REAL_ONLY = "p.source != ?"


def real_only(
    where: str, params: tuple[object, ...], names_source: bool
) -> tuple[str, tuple[object, ...]]:
    """`where` limited to real people, unless the query named a `source` term."""
    if names_source:
        return where, params
    return f"{where} AND {_REAL_ONLY}", (*params, DEMONSTRATION_SOURCE)


def demonstration_query(text: str) -> str:
    """The query that reaches the demonstration people `text` would select."""
    return f"({text}) AND source = {DEMONSTRATION_SOURCE}"
