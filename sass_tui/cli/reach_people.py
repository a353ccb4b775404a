"""`sass reach --point P --target/--virtual NAME`: the share of a target's (or
virtual population's) people whose hand reaches the point, each with their
own shoulder and arm (their own measurements: a virtual person's are
predicted from their stature and mass) and the gender's figure's joint
ranges (model/body/reach.py own_arms_reaching), weighted.

`sass reach --gender G --known NAME=VALUE ...`: the person `sass predict`
predicts from the known values (db/populations/predict.py, the same fitted
regression), as a figure whose landmarks are the predicted measurements
(the arm's, the shoulder's, the sitting height) that place a real person's
arm; their reach measures withheld, so the reach is the model's from those.

A module of its own because it brings the db package, which `sass reach`
for a figure goes without."""

from __future__ import annotations

import argparse
from typing import Any

import numpy as np

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import weighting_name
from sass_tui.db.populations.predict import open_predictor
from sass_tui.db.populations.task_people import group_words, weighted_values
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.landmarks import LANDMARK_MEASURES
from sass_tui.model.body.reach import (
    LINKAGE_MEASURES,
    REACH_MEASURES,
    SIDES,
    envelope,
    linkage_from_measures,
    linkage_of,
    own_arms_reaching,
)
from sass_tui.model.population.prediction import Estimate, split_known

# The query language's names of the measurements an arm is built from.
FIELDS = ["stature", *(f"measure.{name}" for name in LINKAGE_MEASURES if name != "stature")]


def population_shares(args: argparse.Namespace, point: np.ndarray) -> dict[str, Any]:
    """The point's answer: the weighted percent reaching it, by gender and together."""
    name = weighting_name(args)
    assert name is not None  # --target or --virtual was given
    conn = open_db(args)
    try:
        target, groups = weighted_values(conn, name, FIELDS)
    finally:
        conn.close()
    sides = SIDES if args.hand == "both" else (args.hand,)
    shares: dict[str, float] = {}
    total_reached = total = 0.0
    left_out = 0
    for gender, values, weights in groups:
        figure = Figure.default(gender)
        measures = dict(zip(LINKAGE_MEASURES, values.matrix.T, strict=True))
        figure_arms, arms = [], []
        for side in sides:
            linkage = linkage_of(figure, side)
            figure_arms.append(
                (envelope(linkage, args.hand_point, args.seated, args.trunk), linkage)
            )
            arms.append(linkage_from_measures(gender, measures, linkage.limits, side))
        reached, weight, missing = own_arms_reaching(figure_arms, arms, weights, point)
        shares[group_words(target, gender)] = round(100.0 * reached / weight, 1)
        total_reached, total, left_out = total_reached + reached, total + weight, left_out + missing
    if len(groups) > 1:
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
        "leftOut": left_out,
        "note": target.words(),
    }


def predicted_figure(args: argparse.Namespace) -> tuple[Figure, dict[str, Estimate]]:
    """The person `sass predict --gender G --known ...` predicts, as its
    `-o` figure (Prediction.figure), with their predicted (or known)
    measurements as the landmarks a real person's arm is placed by; a
    reach measure only when it was known.  Also the regression's own
    estimate of each reach measure (cm, with its 90 % interval)."""
    pairs = [pair for item in args.known for pair in split_known(item)]
    conn = open_db(args)
    try:
        predictor = open_predictor(conn)
    finally:
        conn.close()
    known = predictor.parse_known(args.gender, pairs)
    prediction = predictor.predict(args.gender, known)
    figure = prediction.figure(Figure.default(args.gender))
    landmarks = {}
    for name in LANDMARK_MEASURES:
        field_name = "stature" if name == "stature" else f"measure.{name}"
        estimate = prediction.values.get(field_name)
        if estimate is None or (name in REACH_MEASURES and not estimate.known):
            continue
        landmarks[name] = estimate.value
    figure.landmarks = landmarks
    regression = {
        name: estimate
        for name in REACH_MEASURES
        if (estimate := prediction.values.get(f"measure.{name}")) is not None
    }
    return figure, regression
