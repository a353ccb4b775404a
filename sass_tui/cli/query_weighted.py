"""`sass query --count --target NAME` (or --virtual NAME): the count weighted
to a target population.  Its own module because the stored weights
(db/populations/shipped.py, db/populations/targets.py, with numpy) are what `sass query` without a
target keeps off its start-up path (sass_tui/startup.py)."""

from __future__ import annotations

from sass_tui.db.populations.shipped import load_weights
from sass_tui.db.populations.targets import weighted_count
from sass_tui.db.query.query import compile_query
from sass_tui.model.population.targets import TargetError


def answer_weighted(count: bool, conn, query, name: str) -> None:  # query: CompiledQuery
    """`--target`/`--virtual` weight a count: print it, or refuse a listing."""
    if not count:
        raise TargetError("--target and --virtual weight a count: give --count too")
    print_weighted_count(conn, query, name)


def print_weighted_count(conn, query, name: str) -> None:  # query: db.query.CompiledQuery
    """The raw count, and beside it the target's weighted count and share."""
    weights = load_weights(conn, name)
    if weights.target.is_virtual:  # its virtual people, whom a query reaches only by name
        query = compile_query(f"({query.text}) AND {weights.target.population}")
    counted = weighted_count(conn, query, weights)
    target = counted.target
    if target.is_virtual:
        print(
            f"{counted.count}\nweighted: {counted.weighted:.1f} of {counted.total:.0f} "
            f"({counted.percent:.1f} %) of the {target.words()}"
        )
        return
    print(
        f"{counted.count}\nweighted: {counted.weighted:.1f} of {counted.total:.0f} "
        f"({counted.percent:.1f} %) of target {target.name} ({target.gender}, weighted by "
        f"{', '.join(target.fields)} to {target.sample}; {counted.in_target} of the "
        f"{counted.count} people are the target's)"
    )
