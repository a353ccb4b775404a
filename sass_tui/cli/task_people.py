"""`sass task --person`, `--target` and `--virtual`: the task for people of
the database (a real person at their own size; a target's or a virtual
population's people, each scaled to their own size, weighted).

A module of its own because these bring the db package and numpy's
statistics (cli/common/person_option.py, db/populations/task_people.py), which `sass task` for
women and men goes without (the `sass task` row of sass_tui/startup.py).
"""

from __future__ import annotations

import argparse
from collections.abc import Callable

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import weighting_name
from sass_tui.cli.common.person_option import named_person_record, person_figure
from sass_tui.db.populations.task_people import group_words, weighted_people
from sass_tui.model.body.figure import Figure
from sass_tui.model.strength.task import (
    Reference,
    TaskAnswer,
    TaskError,
    assess_populations,
    assess_task,
)

# The verb's figure of a gender, at --mass and --stature (cli/task.py).
FigureOf = Callable[[argparse.Namespace, str], Figure]


def people_answer(args: argparse.Namespace, angles, loads, figure_of: FigureOf) -> TaskAnswer:
    """The task for --person, or for the people of --target or --virtual."""
    if args.person is not None:
        return assess_task(_person_references(args, figure_of), angles, loads, args.seated)
    return _weighted_answer(args, angles, loads, figure_of)


def _refuse_own_body(args: argparse.Namespace, who: str) -> None:
    given = [
        option
        for option, value in (
            ("--mass", args.mass),
            ("--stature", args.stature),
            ("--age", args.age),
        )
        if value is not None
    ]
    if given:
        raise TaskError(f"{who} takes each person's own body; leave out {', '.join(given)}")


def _person_references(args: argparse.Namespace, figure_of: FigureOf) -> list[Reference]:
    _refuse_own_body(args, "--person")
    record = named_person_record(args)
    figure = person_figure(args, figure_of(args, str(record["gender"])))
    age = record["age"]
    return [Reference(str(figure.person), figure, None if age is None else float(age))]  # type: ignore[arg-type]


def _weighted_answer(args: argparse.Namespace, angles, loads, figure_of: FigureOf) -> TaskAnswer:
    """A target's (or virtual population's) people, each scaled to their own
    size from their gender's figure, weighted: each gender and, for a target
    of both, everyone together."""
    name = weighting_name(args)
    assert name is not None  # --target or --virtual was given
    _refuse_own_body(args, "--virtual" if args.virtual is not None else "--target")
    conn = open_db(args)
    try:
        target, people = weighted_people(conn, name)
    finally:
        conn.close()
    groups = [(figure_of(args, group.gender), group) for group in people]
    return assess_populations(groups, angles, loads, group_words(target, None), args.seated)
