"""`sass handling` for people: the hands' H and V for a posture of a sass
figure (joint angles as `sass task` takes them, or a posture file), each
sex's figure at --percentile or a real person's (--person); and for
--target and --virtual the share of a population's people who accept a
load, each gender's percent capable (the Liberty Mutual equations depend on
the sex only) mixed by the population's weights of its women and men, read
as `sass task --target/--virtual` reads them (db/populations/task_people.py).
A module of its own: it brings numpy, the figure's humanoid and the db
package, which `sass handling` on typed numbers goes without."""

from __future__ import annotations

import argparse
from typing import Any

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import weighting_name
from sass_tui.cli.common.person_option import named_person_record, person_figure
from sass_tui.db.populations.task_people import group_words, weighted_people
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import parse_angles, pose_figure, read_posture_file
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS
from sass_tui.model.session import Session
from sass_tui.model.strength.hand_position import body_h_v, posture_h_v
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


def figure_at(gender: str, percentile: float) -> Figure:
    """The gender's default figure with every group, mass and stature at `percentile`
    (as `sass fig --percentile` builds it)."""
    session = Session(Figure.default(gender))
    for group in (GIRTH, JOINT_LIMITS, CENTER_OF_MASS):
        session.set_group_percentile(group, percentile)
    session.set_mass_percentile(percentile)
    session.set_stature_percentile(percentile)
    return session.figure


def hands_of(args: argparse.Namespace, sexes: list[str]) -> dict[str, tuple[float, float]]:
    """Each sex's (H, V) in metres: from the posture file, or the figure posed."""
    if args.posture is not None:
        if args.angles:
            raise HandlingError("give joint angles or --posture, not both")
        h_v = posture_h_v(read_posture_file(args.posture))
        return {sex: h_v for sex in sexes}
    angles = parse_angles(args.angles)
    if args.person is not None:
        gender = str(named_person_record(args)["gender"])
        figure = person_figure(args, figure_at(gender, args.percentile))
        return {gender: body_h_v(pose_figure(figure, angles))}
    return {sex: body_h_v(pose_figure(figure_at(sex, args.percentile), angles)) for sex in sexes}
