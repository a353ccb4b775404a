"""`sass reach --point P --target/--virtual NAME`: the share of a target's (or
virtual population's) people whose hand reaches the point, each person the
gender's figure scaled to their own stature (model/body/reach.py), weighted.

A module of its own because it brings the db package, which `sass reach`
for a figure goes without."""

from __future__ import annotations

import argparse
from typing import Any

import numpy as np

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import weighting_name
from sass_tui.db.populations.task_people import group_words, weighted_people
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import humanoid_stature
from sass_tui.model.body.reach import SIDES, envelope, linkage_of, share_reaching


def population_shares(args: argparse.Namespace, point: np.ndarray) -> dict[str, Any]:
    """The point's answer: the weighted percent reaching it, by gender and together."""
    name = weighting_name(args)
    assert name is not None  # --target or --virtual was given
    conn = open_db(args)
    try:
        target, people = weighted_people(conn, name)
    finally:
        conn.close()
    sides = SIDES if args.hand == "both" else (args.hand,)
    shares: dict[str, float] = {}
    total_reached = total = 0.0
    for group in people:
        figure = Figure.default(group.gender)
        envs = [
            envelope(linkage_of(figure, side), args.hand_point, args.seated, args.trunk)
            for side in sides
        ]
        stature = humanoid_stature(figure) / 100.0
        reached, weight = share_reaching(envs, stature, group.statures, group.weights, point)
        shares[group.words] = round(100.0 * reached / weight, 1)
        total_reached, total = total_reached + reached, total + weight
    if len(people) > 1:
        shares[group_words(target, None)] = round(100.0 * total_reached / total, 1)
    return {
        "value": [round(float(v) * 100, 1) for v in point],
        "unit": "cm",
        "frame": "seated, the seat below the hips' midpoint"
        if args.seated
        else "standing, the floor between the feet",
        "handPoint": args.hand_point,
        "hands": list(sides),
        "shares": shares,
        "note": target.words(),
    }
