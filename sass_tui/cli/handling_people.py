"""`sass handling --target` and `--virtual`: the share of a population's
people who accept a load, each gender's percent capable (the Liberty Mutual
equations depend on the sex only) mixed by the population's weights of its
women and men, read as `sass task --target/--virtual` reads them
(db/populations/task_people.py).  A module of its own: it brings the db
package and numpy, which `sass handling` for women and men goes without."""

from __future__ import annotations

import argparse
from typing import Any

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import weighting_name
from sass_tui.db.populations.task_people import group_words, weighted_people
from sass_tui.model.strength.liberty_mutual import Acceptable, HandlingError, mixed_percent


def gender_weights(args: argparse.Namespace) -> tuple[str, dict[str, float]]:
    """The population's words and the total weight of each of its genders."""
    name = weighting_name(args)
    assert name is not None  # --target or --virtual was given
    conn = open_db(args)
    try:
        target, people = weighted_people(conn, name)
    finally:
        conn.close()
    return group_words(target, None), {group.gender: float(group.weights.sum()) for group in people}


def population_share(
    args: argparse.Namespace, answers: dict[str, dict[str, Acceptable]], load: float
) -> dict[str, Any]:
    """The population's percent capable of `load` (per variant for push and pull)."""
    words, weights = gender_weights(args)
    missing = [sex for sex in weights if sex not in answers]
    if missing:
        raise HandlingError(f"the population has {missing[0]} people: leave out --gender")
    shares: dict[str, float] = {}
    for variant in next(iter(answers.values())):
        percents = {}
        for sex in weights:
            found = answers[sex][variant]
            if found.refused:
                raise HandlingError(
                    f"no share of the population: the {sex} equation refuses the task "
                    f"({found.refused[0]})"
                )
            percents[sex] = found.percent_capable(load)
        shares[variant] = round(mixed_percent(percents, weights), 2)
    return {
        "name": words,
        "percent_capable": shares[""] if "" in shares else shares,
        "weights": weights,
    }
