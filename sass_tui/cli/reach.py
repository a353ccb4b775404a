"""`sass reach`: where a figure's hands can go (model/body/reach.py, docs/reach.md).

sass reach --gender female --percentile 5
sass reach --person 'ANSUR II M 10037' --format json
sass reach --gender male --point 40,140,60 --hand both
sass reach --point '0.5,1.3,0.4 m' --virtual nhanes-2017-2020
sass reach --gender female -o reach.glb --with-body
sass reach --gender male --known stature=175cm --known mass=80kg
"""

from __future__ import annotations

import argparse
import json
import sys
from typing import TYPE_CHECKING, Any

import numpy as np

from sass_tui.cli.common.figure_from_options import figure_from_args
from sass_tui.cli.common.options import SubParsers, add_figure_options, file_name, print_warnings
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.reach import (
    REACH_MEASURES,
    SIDES,
    Envelope,
    ReachError,
    envelope,
    linkage_of,
    own_travel,
    parse_point,
    point_verdict,
    reach_measures,
)
from sass_tui.model.files.gltf import check_path, write_gltf
from sass_tui.model.files.paths import user_path
from sass_tui.model.files.reach_gltf import render_reach_gltf

if TYPE_CHECKING:
    from sass_tui.model.population.prediction import Estimate

HAND_CHOICES = ("right", "left", "both")


def register(commands: SubParsers) -> None:
    reach = commands.add_parser(
        "reach",
        help="where the figure's hands can go: reach measures, a point, an envelope",
        description="Each hand's reachable volume from the figure's HAnim arm (shoulder, "
        "elbow, wrist) over its joint limits, the survey's reach measures (thumbtipreach, "
        "overheadfingertipreachsitting, span) from the same linkage, whether a point is "
        "reached (and by how much it is missed), the share of a target or virtual "
        "population reaching it, and the envelope as glTF (docs/reach.md).",
    )
    add_figure_options(reach)
    reach.add_argument(
        "--known",
        metavar="NAME=VALUE",
        action="append",
        default=[],
        help="a predicted person (sass predict's --known, with --gender): e.g. "
        "stature=175cm, mass=80kg, measure.handlength=19cm (repeat for more); the arm "
        "from their predicted measurements",
    )
    reach.add_argument(
        "--hand", choices=HAND_CHOICES, default="right", help="which hand (default right)"
    )
    reach.add_argument(
        "--hand-point",
        choices=("fingertip", "grip"),
        default="fingertip",
        help="the hand's point for the envelope and --point: the middle fingertip "
        "(default) or the grip centre",
    )
    reach.add_argument(
        "--seated",
        action="store_true",
        help="seated: the origin on the seat below the hips' midpoint",
    )
    reach.add_argument(
        "--trunk", action="store_true", help="the trunk bends, leans and twists within its limits"
    )
    reach.add_argument(
        "--point",
        metavar="X,Y,Z",
        help="a point in the body's frame (+X left, +Y up, +Z forward; cm unless a unit "
        "follows, e.g. '0.4,1.3,0.6 m'; a negative X: --point -20,130,60): reached, or missed "
        "by how much",
    )
    reach.add_argument(
        "-o",
        "--output",
        metavar="FILE.glb",
        type=file_name,
        help="write the envelope(s) as glTF: FILE.glb or FILE.gltf (+ .bin)",
    )
    reach.add_argument(
        "--with-body", action="store_true", help="with -o: the standing body beside the envelope"
    )
    reach.add_argument("--format", choices=("text", "json"), default="text", help="output form")
    reach.set_defaults(func=run)


def _sides(hand: str) -> tuple[str, ...]:
    return SIDES if hand == "both" else (hand,)


# A point typed without a unit whose every coordinate is under this many cm is
# most likely metres (a hand reaching the floor between the feet is rare).
METRES_LIKELY_CM = 3.0


def metres_hint(text: str, point: np.ndarray) -> str | None:
    """A note when --point was typed without a unit and reads as a point within
    a few cm of the floor between the feet: metres were probably meant."""
    if any(ch.isalpha() or ch in "\"'" for ch in text):
        return None
    if float(np.abs(point).max()) * 100 >= METRES_LIKELY_CM:
        return None
    return (
        f"sass reach: note: --point {text.strip()} is read in cm (no unit typed); "
        f"metres are written '{text.strip()} m'"
    )


def run(args: argparse.Namespace) -> int:
    try:
        point = parse_point(args.point) if args.point is not None else None
    except ReachError as exc:  # the model's words name no option (the TUI asks for a point too)
        raise ReachError(f"--point {exc}") from None
    hint = None if point is None else metres_hint(args.point, point)
    if hint is not None:
        print(hint, file=sys.stderr)
    output = None
    if args.output is not None:
        output = check_path(user_path(args.output))
    elif args.with_body:
        raise ReachError("--with-body goes with -o FILE.glb")
    if args.with_body and args.seated:
        raise ReachError("the body is written standing: leave out --seated or --with-body")
    # With --point, --target and --virtual count who of their people reach it
    # (each person's own linkage); without, they size the figure as for sass fig.
    shares = point is not None and (args.target is not None or args.virtual is not None)
    if args.known:
        _check_known(args)
    if shares or args.known:
        # deferred: cli.reach_people (the db package) — off sass reach (sass_tui/startup.py)
        from sass_tui.cli import reach_people

        if shares and point is not None:
            answer: dict[str, Any] = {"point": reach_people.population_shares(args, point)}
            _print(args, answer, None)
            return 0
        figure, regression = reach_people.predicted_figure(args)
    else:
        figure, warnings = figure_from_args(args)
        print_warnings(warnings)
    envelopes: list[Envelope] = []
    answer = _figure_answer(args, figure, point, envelopes)
    if args.known:
        _add_regression(answer, regression)
    if output is not None:
        body = figure if args.with_body else None
        asset = render_reach_gltf(envelopes, f"{_who(figure)} reach", body)
        answer["written"] = [str(path) for path in write_gltf(asset, output)]
    _print(args, answer, figure)
    return 0


# The figure options a predicted person (--known) does not go with: the
# prediction gives the stature, mass, girths and centres of mass itself.
NOT_WITH_KNOWN = (
    ("--person", "person"),
    ("--target", "target"),
    ("--virtual", "virtual"),
    ("--girth", "girth"),
    ("--jntlmt", "jntlmt"),
    ("--cmass", "cmass"),
    ("--global", "global_file"),
    ("--stature", "stature"),
    ("--mass", "mass"),
    ("--stature-percentile", "stature_percentile"),
    ("--mass-percentile", "mass_percentile"),
    ("--girth-percentile", "girth_percentile"),
    ("--joint-limit-percentile", "joint_limit_percentile"),
    ("--cmass-percentile", "cmass_percentile"),
)


def _check_known(args: argparse.Namespace) -> None:
    given = [option for option, name in NOT_WITH_KNOWN if getattr(args, name) is not None]
    if args.percentile != 50.0:  # the joint ranges are the gender's default figure's
        given.insert(0, "--percentile")
    if given:
        raise ReachError(
            f"--known predicts the person (sass predict): leave out {', '.join(given)}; "
            "a known stature or mass is --known stature=… / mass=…"
        )
    if args.gender is None:
        raise ReachError(
            "--known needs --gender male|female: the people the prediction learns from"
        )


def _who(figure: Figure) -> str:
    if figure.person:
        return str(figure.person)
    return f"{figure.gender} {figure.stature_percentile:.0f}th percentile"


def _figure_answer(
    args: argparse.Namespace, figure: Figure, point: np.ndarray | None, out: list[Envelope]
) -> dict[str, Any]:
    """The figure's reach measures (its right arm, as the survey measures)
    and, for each hand asked, its envelope and the point's verdict."""
    model = linkage_of(figure, "right")
    own = own_travel(model, figure.landmarks or {})
    modelled = reach_measures(model)
    values = reach_measures(own)
    answer: dict[str, Any] = {"figure": _who(figure)}
    for name in REACH_MEASURES:
        entry = {
            "value": round(float(values[name][0]), 1),
            "unit": "cm",
            "source": own.sources[name],
        }
        if own.sources[name] == "measured":
            entry["model"] = round(float(modelled[name][0]), 1)
        answer[name] = entry
    verdicts = []
    for side in _sides(args.hand):
        linkage = own if side == "right" else own_travel(linkage_of(figure, side), figure.landmarks)
        env = envelope(linkage, args.hand_point, args.seated, args.trunk)
        out.append(env)
        if point is not None:
            verdicts.append((side, point_verdict(env, point)))
    if point is not None:
        reached = [side for side, v in verdicts if v.reached]
        answer["point"] = {
            "value": [round(float(v) * 100, 1) for v in point],
            "unit": "cm",
            "frame": _frame(args.seated),
            "handPoint": args.hand_point,
            "reached": bool(reached),
            "hands": reached,
            "miss": {
                "value": 0.0 if reached else round(min(v.miss for _, v in verdicts) * 100, 1),
                "unit": "cm",
            },
        }
    else:
        answer["point"] = None
    return answer


def _add_regression(answer: dict[str, Any], regression: dict[str, Estimate]) -> None:
    """A predicted person's reach is the model's, from their predicted arm
    (a known reach measure is theirs): said so, with `sass predict`'s own
    estimate of the measure beside it."""
    answer["basis"] = (
        "the arm placed by the measurements sass predict gives; each reach measure "
        "the model's from that arm unless known"
    )
    for name in REACH_MEASURES:
        entry = answer[name]
        if entry["source"] == "measured":
            entry["source"] = "known"
            entry.pop("model", None)
        estimate = regression.get(name)
        if estimate is not None and not estimate.known:
            entry["predicted"] = {
                "value": round(estimate.value, 1),
                "low": round(estimate.low, 1),
                "high": round(estimate.high, 1),
                "unit": "cm",
            }


def _frame(seated: bool) -> str:
    if seated:
        return "seated: origin on the seat below the hips' midpoint, +Y up, +Z forward, +X left"
    return "standing: origin on the floor between the feet, +Y up, +Z forward, +X left"


def _print(args: argparse.Namespace, answer: dict[str, Any], figure: Figure | None) -> None:
    if args.format == "json":
        print(json.dumps(answer))
        return
    if figure is not None:
        pose = "seated" if args.seated else "standing"
        trunk = "trunk free" if args.trunk else "trunk fixed"
        print(f"reach: {answer['figure']} ({pose}, {trunk})")
        if "basis" in answer:
            print(f"  {answer['basis']}")
        for name in REACH_MEASURES:
            entry = answer[name]
            how = entry["source"]
            if "model" in entry:
                how += f"; the model from their other measurements {entry['model']:.1f} cm"
            if how == "model" and "basis" in answer:
                how = "model, from the predicted arm"
            if "predicted" in entry:
                p = entry["predicted"]
                how += (
                    f"; sass predict's regression {p['value']:.1f} cm, "
                    f"90 % {p['low']:.1f}-{p['high']:.1f}"
                )
            print(f"  {name:<31} {entry['value']:6.1f} cm  ({how})")
    point = answer.get("point")
    if point is not None:
        where = "(" + ", ".join(f"{v:g}" for v in point["value"]) + ") cm"
        if "shares" in point:
            print(f"{where}, {point['frame']}: the {point['handPoint']} reaches it for")
            for who, share in point["shares"].items():
                print(f"  {who:<24} {share:5.1f} %")
        elif point["reached"]:
            hands = " and ".join(point["hands"])
            print(f"{where}: reached by the {hands} {point['handPoint']}")
        else:
            print(f"{where}: missed by {point['miss']['value']:.1f} cm")
    for path in answer.get("written", []):
        print(f"wrote {path}")
