"""`sass handling lift|lower|push|pull|carry`: the Liberty Mutual manual
materials handling equations (Potvin et al. 2021): the maximum acceptable
load of the 50th percentile woman and man, the loads 75 % and 90 % accept,
and the share who accept a given load (push and pull: initial and
sustained), each scale factor printed; with --target or --virtual, the
population's share, women and men mixed by the survey's weights
(model/strength/liberty_mutual.py, docs/manual-handling.md).

    sass handling lift --h 0.38 --v 1.03 --d 0.51 --f 1 --load 10kg
    sass handling pull --v 1.2m --d 20m --f 1 --load 200N
    sass handling lift --d 0.5 --f 1 --load 10kg shoulder_y=45 --gender female --percentile 5
    sass handling carry --v 0.9 --d 5 --f 0.5 --load 12kg --virtual nhanes-2017-2020
"""

from __future__ import annotations

import argparse
import json
from typing import Any

from sass_tui.cli.common.figure_hands import (
    add_figure_hands_options,
    from_figure,
    posed_people,
    refuse_typed_hands,
)
from sass_tui.cli.common.options import SubParsers, add_virtual_option
from sass_tui.model.strength.liberty_mutual import (
    HANDLES,
    SEXES,
    SHARES,
    TASKS,
    Acceptable,
    HandlingError,
    Inputs,
    acceptable,
    source,
    variants,
)
from sass_tui.model.units import BASE_FACTORS, UnitError, parse_quantity, per_minute, quantity_unit
from sass_tui.model.vocabulary import GENDERS

WORDS = {"female": "women", "male": "men"}


def register(commands: SubParsers) -> None:
    handling = commands.add_parser(
        "handling",
        help="Liberty Mutual equations: loads women and men accept to lift, lower, push, "
        "pull, carry",
        description="The Liberty Mutual manual materials handling equations (Potvin, Ciriello, "
        "Snook, Maynard & Brogmus 2021, Ergonomics 64(8):955-970): the maximum acceptable load "
        "of the 50th percentile woman and man, the loads 75 % and 90 % accept and the share "
        "who accept --load, each scale factor given.  Inputs outside the ranges the paper "
        "states are refused; its cautions are said.  The hands' H and V can come from a "
        "posture of a sass figure (joint angles as `sass task` takes them, or --posture).",
    )
    handling.add_argument("task", choices=TASKS, help="the kind of handling")
    handling.add_argument(
        "--h", metavar="LEN", help="lift, lower: hand distance from the ankles (m without a unit)"
    )
    handling.add_argument(
        "--v",
        metavar="LEN",
        help="lift, lower: the middle of the vertical range; push, pull, carry: the hands' "
        "height (m without a unit)",
    )
    handling.add_argument(
        "--d",
        metavar="LEN",
        help="lift, lower: the vertical distance; push, pull, carry: the distance moved (m)",
    )
    handling.add_argument(
        "--f", metavar="N", default="1", help="actions per minute, or N/h, N/s (default 1)"
    )
    handling.add_argument(
        "--load", metavar="LOAD", help="the load (kg, lb) or for push and pull the force (N, lbf)"
    )
    handling.add_argument(
        "--handles",
        choices=HANDLES,
        default="handles",
        help="lift, lower: handles (default), poor (poor handles or a slippery hold) or none",
    )
    add_figure_hands_options(handling, "for lift and lower, the posture at the middle of the lift")
    who = handling.add_mutually_exclusive_group()
    who.add_argument("--gender", choices=GENDERS, help="one gender (default: women and men)")
    who.add_argument("--person", metavar="ID", help="a real person's figure for the posture")
    who.add_argument(
        "--target",
        metavar="NAME",
        help="a target population: the share of its people who accept --load, women and men "
        "weighted",
    )
    add_virtual_option(who)
    handling.add_argument("--format", choices=("text", "json"), default="text", help="output form")
    handling.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    load = None if args.load is None else parse_load(args.load, args.task)
    answers = {sex: _answers(inputs, sex) for sex, inputs in task_inputs(args).items()}
    population = None
    if args.target is not None or args.virtual is not None:
        if load is None:
            raise HandlingError("--target and --virtual give the share who accept --load: give it")
        population = posed_people().population_share(args, answers, load)
    if args.format == "json":
        print(json.dumps(handling_json(args.task, answers, load, population)))
    else:
        for line in handling_text(args.task, answers, load, population):
            print(line)
    return 0


def parse_load(text: str, task: str) -> float:
    """The load in kg (kgf for push and pull: a force in N, lbf or kgf is converted)."""
    unit = quantity_unit(text)
    if unit is not None and BASE_FACTORS[unit][0] == "force":
        if task not in ("push", "pull"):
            raise HandlingError(f"--load {text}: {task} takes a mass (kg, lb), not a force")
        value = parse_quantity(text, "kgf")
    else:
        value = parse_quantity(text, "kg")
    if value < 0:
        raise HandlingError(f"--load {text} is negative")
    return value


def _length(text: str | None, option: str) -> float | None:
    if text is None:
        return None
    value = parse_quantity(text, "m")
    if value < 0:
        raise HandlingError(f"{option} {text} is negative")
    return value


def task_inputs(args: argparse.Namespace) -> dict[str, Inputs]:
    """Each sex's inputs: the typed ones, or H and V from each sex's figure."""
    d = _length(args.d, "--d")
    if d is None:
        raise HandlingError("give --d, the distance the load is moved")
    try:
        f = per_minute(args.f)
    except UnitError as exc:
        raise HandlingError(f"--f: {exc}") from None
    sexes = [args.gender] if args.gender else list(SEXES)
    if from_figure(args):
        refuse_typed_hands(args, HandlingError)
        out = {}
        for sex, (hand_h, hand_v) in posed_people().hands_of(args, sexes).items():
            out[sex] = Inputs(
                args.task,
                hand_v,
                d,
                f,
                hand_h if args.task in ("lift", "lower") else None,
                args.handles,
            )
        return out
    v = _length(args.v, "--v")
    h = _length(args.h, "--h")
    if v is None:
        raise HandlingError("give --v (or a posture)")
    if args.task in ("lift", "lower") and h is None:
        raise HandlingError(f"{args.task} needs --h, the hand distance (or a posture)")
    return {sex: Inputs(args.task, v, d, f, h, args.handles) for sex in sexes}


def _answers(inputs: Inputs, sex: str) -> dict[str, Acceptable]:
    return {variant: acceptable(inputs, variant, sex) for variant in variants(inputs.task)}


def _answer_json(found: Acceptable, load: float | None, unit: str) -> dict[str, Any]:
    if found.refused:
        return {"refused": found.refused}
    return {
        "mal": {"value": round(found.mal, 3), "unit": unit},
        "cv": found.cv,
        "percent_capable": None if load is None else round(found.percent_capable(load), 2),
        "load_for": {f"{share:g}": round(found.load_for(share), 3) for share in SHARES},
        "factors": {name: round(value, 5) for name, value in found.factors.items()},
    }


def handling_json(
    task: str,
    answers: dict[str, dict[str, Acceptable]],
    load: float | None,
    population: dict[str, Any] | None,
) -> dict[str, Any]:
    unit = "kgf" if task in ("push", "pull") else "kg"
    out: dict[str, Any] = {
        "task": task,
        "load": None if load is None else {"value": load, "unit": unit},
    }
    for sex, by_variant in answers.items():
        if "" in by_variant:
            out[sex] = _answer_json(by_variant[""], load, unit)
        else:
            out[sex] = {v: _answer_json(a, load, unit) for v, a in by_variant.items()}
        inputs = next(iter(by_variant.values())).inputs
        out[sex]["inputs"] = {"h": inputs.h, "v": inputs.v, "d": inputs.d, "f": inputs.f}
    notes = _notes(answers)
    if notes:
        out["cautions"] = notes
    if population is not None:
        out["population"] = population
    out["source"] = source()
    return out


def _notes(answers: dict[str, dict[str, Acceptable]]) -> list[str]:
    notes: list[str] = []
    for by_variant in answers.values():
        for found in by_variant.values():
            for note in found.notes:
                if note not in notes:
                    notes.append(note)
    return notes


def handling_text(
    task: str,
    answers: dict[str, dict[str, Acceptable]],
    load: float | None,
    population: dict[str, Any] | None,
) -> list[str]:
    unit = "kgf" if task in ("push", "pull") else "kg"
    columns = [
        (f"{WORDS[sex]}{' ' + variant if variant else ''}", found)
        for sex, by_variant in answers.items()
        for variant, found in by_variant.items()
    ]
    first = columns[0][1]
    lines = [f"Liberty Mutual {task} (Potvin et al. 2021): {first.words}"]
    for name, found in columns[1:]:
        if found.words != first.words:
            lines.append(f"  {name}: {found.words}")
    lines.append(f"{'':16}" + "".join(f"{name:>17}" for name, _ in columns))
    names = list(dict.fromkeys(n for _, found in columns for n in found.factors))
    for name in names:
        cells = [found.factors.get(name) for _, found in columns]
        lines.append(
            f"{name + ' factor' if name != 'RL' else 'RL ' + unit:16}"
            + "".join(f"{'' if c is None else f'{c:.4g}':>17}" for c in cells)
        )
    rows: list[tuple[str, Any]] = [
        (f"MAL 50 % {unit}", lambda a: f"{a.mal:.2f}"),
        *[
            (f"{share:g} % accept", lambda a, share=share: f"{a.load_for(share):.2f}")
            for share in SHARES
        ],
        ("CV", lambda a: f"{a.cv:.3f}"),
    ]
    if load is not None:
        rows.append((f"accept {load:.3g} {unit}", lambda a: f"{a.percent_capable(load):.1f} %"))
    for label, cell in rows:
        lines.append(
            f"{label:16}"
            + "".join(f"{'refused' if a.refused else cell(a):>17}" for _, a in columns)
        )
    for name, found in columns:
        for reason in found.refused:
            lines.append(f"Refused ({name}): {reason}")
    for note in _notes(answers):
        lines.append(f"Caution: {note}")
    if population is not None:
        share = population["percent_capable"]
        said = (
            f"{share:.1f} %"
            if not isinstance(share, dict)
            else ", ".join(f"{v} {p:.1f} %" for v, p in share.items())
        )
        lines.append(
            f"{population['name']}: {said} accept {load:.3g} {unit} (women and men weighted by "
            "the population's weights: "
            + ", ".join(f"{WORDS[g]} {w:.4g}" for g, w in population["weights"].items())
            + ")"
        )
    lines.append(f"Source: {source()}")
    return lines
