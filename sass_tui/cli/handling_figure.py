"""`sass handling` from the figure: the hands' H and V for a posture of a sass
figure (joint angles as `sass task` takes them, or a posture file), each
sex's figure at --percentile, or a real person's (--person).  A module of its
own: it brings numpy and the figure's humanoid, which typed numbers go
without."""

from __future__ import annotations

import argparse

from sass_tui.cli.common.person_option import named_person_record, person_figure
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import parse_angles, pose_figure, read_posture_file
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS
from sass_tui.model.session import Session
from sass_tui.model.strength.hand_position import body_h_v, posture_h_v
from sass_tui.model.strength.liberty_mutual import HandlingError


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
