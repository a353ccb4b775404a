"""`sass niosh`: the Revised NIOSH Lifting Equation (Waters et al. 1994,
DHHS (NIOSH) Pub. 94-110): the recommended weight limit, each multiplier
with the manual's limits it applied, and the lifting index of a load, at the
origin and (when the load must be placed) the destination; or, for a
multi-task job (`--tasks FILE`), each task's FIRWL, STRWL, FILI and STLI and
the composite lifting index (cli/niosh_job.py; model/strength/niosh.py,
docs/manual-handling.md).

    sass niosh --h 40cm --v 60cm --d 80cm --a 30 --f 2 --duration moderate --load 12kg
    sass niosh --h 10in --v 22in --dest-h 20in --dest-v 59in --f 3 --load 26lb
    sass niosh --tasks job.csv --duration long
"""

from __future__ import annotations

import argparse
import json
import math
from typing import Any

from sass_tui.cli.common.figure_hands import (
    add_figure_hands_options,
    from_figure,
    posed_people,
    refuse_typed_hands,
)
from sass_tui.cli.common.options import SubParsers, file_name
from sass_tui.model.strength import niosh_input
from sass_tui.model.strength.niosh import (
    COUPLINGS,
    DURATIONS,
    Form,
    Lift,
    LiftAnswer,
    Limit,
    NioshError,
    Point,
    assess_lift,
    index_words,
    json_number,
    lifting_index,
    source,
    special_frequency,
)
from sass_tui.model.units import convert
from sass_tui.model.vocabulary import GENDERS

LENGTH_HELP = "{what}, e.g. 40cm or 16in (inches: the manual's U.S. form, LC 51 lb; else metric)"
ORDER = ("LC", "HM", "VM", "DM", "AM", "FM", "CM")


def register(commands: SubParsers) -> None:
    niosh = commands.add_parser(
        "niosh",
        help="the Revised NIOSH Lifting Equation: recommended weight limit and lifting index",
        description="RWL = LC x HM x VM x DM x AM x FM x CM and LI = load / RWL, as the "
        "Applications Manual for the Revised NIOSH Lifting Equation (Waters, Putz-Anderson & "
        "Garg 1994, DHHS (NIOSH) Pub. 94-110) gives them, every limit of the manual applied "
        "and named.  Metric lengths use the metric form (LC 23 kg), inches the U.S. "
        "customary form (LC 51 lb).  With --dest-h and --dest-v (significant control at the "
        "destination) the RWL is also found there and the lower one rates the lift.",
    )
    niosh.add_argument("--h", metavar="LEN", help=LENGTH_HELP.format(what="H at the origin"))
    niosh.add_argument("--v", metavar="LEN", help=LENGTH_HELP.format(what="V at the origin"))
    niosh.add_argument(
        "--d",
        metavar="LEN",
        help="vertical travel distance D (default: |V at the destination - V at the origin|)",
    )
    niosh.add_argument("--a", metavar="DEG", default="0", help="asymmetry angle (deg, default 0)")
    niosh.add_argument(
        "--f", metavar="N", help="lifts per minute, or N/h, N/s (below 0.2/min counts as 0.2)"
    )
    niosh.add_argument(
        "--lifting-minutes",
        metavar="M",
        type=float,
        help="the special frequency adjustment: lifting only M of a 15-minute sample, "
        "F = lifts per minute x M / 15 (the manual's section 1.3.5)",
    )
    niosh.add_argument(
        "--duration",
        choices=DURATIONS,
        default="long",
        help="work duration: short (<= 1 h), moderate (<= 2 h), long (<= 8 h; default)",
    )
    niosh.add_argument(
        "--coupling", choices=COUPLINGS, default="fair", help="hand coupling (default fair)"
    )
    niosh.add_argument("--load", metavar="MASS", help="the load, e.g. 12kg or '26 lb'")
    niosh.add_argument("--dest-h", metavar="LEN", help="H at the destination")
    niosh.add_argument("--dest-v", metavar="LEN", help="V at the destination")
    niosh.add_argument("--dest-a", metavar="DEG", help="asymmetry at the destination (default --a)")
    niosh.add_argument(
        "--dest-coupling",
        choices=COUPLINGS,
        help="coupling at the destination (default --coupling)",
    )
    niosh.add_argument(
        "--tasks",
        type=file_name,
        metavar="FILE",
        help="a multi-task job, FILE.json or FILE.csv (columns name, load, load_max, h, v, d, "
        "a, f, coupling, dest_h, dest_v, dest_a, dest_coupling): the composite lifting index",
    )
    add_figure_hands_options(niosh, "as the origin of the lift")
    who = niosh.add_mutually_exclusive_group()
    who.add_argument(
        "--gender", choices=GENDERS, help="the figure's gender for a posture (default male)"
    )
    who.add_argument("--person", metavar="ID", help="a real person's figure for the posture")
    niosh.add_argument("--format", choices=("text", "json"), default="text", help="output form")
    niosh.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if args.tasks is not None:
        # deferred: cli.niosh_job (pathlib, csv, the job file's reader) — off sass niosh (sass_tui/startup.py)
        from sass_tui.cli.niosh_job import run_job

        return run_job(args)
    answer = assess_lift(single_lift(args))
    if args.format == "json":
        print(json.dumps(lift_json(answer)))
    else:
        for line in lift_text(answer):
            print(line)
    return 0


def single_lift(args: argparse.Namespace) -> Lift:
    """The lift the options describe."""
    if args.f is None:
        raise NioshError("a lift needs --f (or --tasks FILE)")
    of = niosh_input.form_of((args.h, args.v, args.d, args.dest_h, args.dest_v))
    h, v = _origin(args, of)
    dest_v = None if args.dest_v is None else niosh_input.length(args.dest_v, of)
    f = niosh_input.frequency(args.f)
    if args.lifting_minutes is not None:
        f = special_frequency(f, args.lifting_minutes)
    origin = Point(h, v, niosh_input.angle(args.a), args.coupling)
    destination = None
    if args.dest_h is not None or dest_v is not None:
        if args.dest_h is None or dest_v is None:
            raise NioshError("a destination needs both --dest-h and --dest-v")
        destination = Point(
            niosh_input.length(args.dest_h, of),
            dest_v,
            origin.a if args.dest_a is None else niosh_input.angle(args.dest_a),
            args.dest_coupling or args.coupling,
        )
    load = None if args.load is None else niosh_input.load(args.load, of)
    d = niosh_input.travel(args.d, v, dest_v, of)
    return Lift(of, origin, d, f, args.duration, load, destination)


def _origin(args: argparse.Namespace, of: Form) -> tuple[float, float]:
    """H and V at the origin: typed, or where the figure's posture puts the hands."""
    if not from_figure(args):
        for option, value in (("--h", args.h), ("--v", args.v)):
            if value is None:
                raise NioshError(f"a lift needs {option}, a posture or --tasks FILE")
        return niosh_input.length(args.h, of), niosh_input.length(args.v, of)
    refuse_typed_hands(args, NioshError)
    hands = posed_people().hands_of(args, [args.gender or "male"])
    h, v = next(iter(hands.values()))
    return convert(h, "m", of.length_unit), convert(v, "m", of.length_unit)


def _end_json(end: Limit, of: Form, load: float | None) -> dict[str, Any]:
    return {
        "rwl": {"value": json_number(end.rwl, 3), "unit": of.load_unit},
        "lifting_index": json_number(lifting_index(load, end.rwl)),
        "multipliers": {name: json_number(end.multipliers[name].value) for name in ORDER},
        "limits": end.limits,
    }


def lift_json(answer: LiftAnswer) -> dict[str, Any]:
    lift = answer.lift
    of = lift.of
    return {
        "form": of.name,
        "origin": _end_json(answer.origin, of, lift.load),
        "destination": None
        if answer.destination is None
        else _end_json(answer.destination, of, lift.load),
        "rwl": {"value": json_number(answer.rwl, 3), "unit": of.load_unit},
        "lifting_index": json_number(lifting_index(lift.load, answer.rwl)),
        "load": None if lift.load is None else {"value": lift.load, "unit": of.load_unit},
        "inputs": {
            "h": lift.origin.h,
            "v": lift.origin.v,
            "d": lift.d,
            "a": lift.origin.a,
            "f": lift.f,
            "duration": lift.duration,
            "coupling": lift.origin.coupling,
            "length_unit": of.length_unit,
        },
        "source": source(),
    }


def lift_text(answer: LiftAnswer) -> list[str]:
    lift, of = answer.lift, answer.lift.of
    ends = [("origin", answer.origin)]
    if answer.destination is not None:
        ends.append(("destination", answer.destination))
    form_words = "metric form, cm and kg" if of.name == "metric" else "U.S. form, in and lb"
    lines = [
        f"Revised NIOSH Lifting Equation ({form_words}): H {lift.origin.h:.4g}, V "
        f"{lift.origin.v:.4g}, D {lift.d:.4g} {of.length_unit}, A {lift.origin.a:g} deg, "
        f"F {lift.f:g}/min, {lift.duration} duration, {lift.origin.coupling} coupling",
        f"{'':12}" + "".join(f"{name:>13}" for name, _ in ends),
    ]
    for key in ORDER:
        lines.append(
            f"{key:12}" + "".join(f"{end.multipliers[key].value:>13.3f}" for _, end in ends)
        )
    lines.append(f"{'RWL ' + of.load_unit:12}" + "".join(f"{end.rwl:>13.2f}" for _, end in ends))
    if lift.load is not None:
        lines.append(
            f"{'LI':12}"
            + "".join(f"{index_words(lifting_index(lift.load, end.rwl)):>13}" for _, end in ends)
        )
        index = lifting_index(lift.load, answer.rwl)
        lines.append(
            f"Lifting index of {lift.load:g} {of.load_unit}: {index_words(index)} "
            + (
                "(the RWL is 0: a limit below leaves no load acceptable at this place)"
                if index is not None and math.isinf(index)
                else "(above 1: an increased risk of lifting-related low back pain for some workers)"
            )
        )
    for name, end in ends:
        for limit in end.limits:
            lines.append(f"Limit ({name}): {limit}")
    lines.append(f"Source: {source()}")
    return lines
