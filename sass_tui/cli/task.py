"""`sass task`: can the people a product is for do it?  A posture, the loads
on the hands and a population -> the static moments at the wrists, elbows,
shoulders, trunk, hips, knees and ankles, and the percent capable where a
published model covers the joint (the Arm Force Field for each loaded hand,
Anderson et al. 2007 for hips, knees and ankles), the limiting one named
(model/strength/task.py, docs/strength.md "A task").

    sass task shoulder_y=60 elbow_y=30 --right-load 100N
    sass task trunk_y=30 hip_y=60 shoulder_y=60 --left-load "10 kg" --right-load "10 kg"
    sass task shoulder_y=90 elbow_y=0 --right-load 40N --right-direction forward
    sass task hands=40cm,30cm --left-load "10 kg" --right-load "10 kg"
    sass task trunk_y=20 hip_y=90 --seated
    sass task shoulder_y=90 elbow_y=0 --right-load "15 lbf" --person "ANSUR II F 10037"
    sass task shoulder_y=90 --right-load 50N --target nasa-women
    sass task shoulder_y=90 --right-load 50N --virtual nhanes-2017-2020
"""

from __future__ import annotations

import argparse
import json

from sass_tui.cli.common.options import SubParsers, add_db_option, add_virtual_option
from sass_tui.model.body.figure import Figure
from sass_tui.model.strength.hands_at import (
    hands_at_json,
    hands_at_note,
    posture_of,
    split_posture,
)
from sass_tui.model.strength.published_strength import GENDER_WORDS
from sass_tui.model.strength.task import Reference, TaskError, assess_task, load_of
from sass_tui.model.strength.task_report import task_json, task_text
from sass_tui.model.units import parse_quantity
from sass_tui.model.vocabulary import GENDERS

LOAD_HELP = (
    "the force the {side} hand exerts on the object, e.g. 60N or '15 lbf' (N without a "
    "unit), or a mass held, e.g. '10 kg' (its weight, exerted up)"
)
DIRECTION_HELP = (
    "the direction the {side} hand exerts its force: up (default: a weight held), down, "
    "forward (a push), back (a pull), left, right or X,Y,Z on HAnim's axes"
)


def register(commands: SubParsers) -> None:
    task = commands.add_parser(
        "task",
        help="a task's joint moments and the percent capable of doing it",
        description="The static moments of a posture, standing on the floor or seated, "
        "with the forces the hands exert, from the figure's own segment masses and the "
        "floor's force under each foot; the low back's L5/S1 compression and shear against "
        "the NIOSH and Gallagher & Marras limits; the balance over the feet; and the share "
        "of women and men (or a person, or a target population) able to exert them where a "
        "published model covers the joint: the Arm Force Field (La Delfa & Potvin 2017) for "
        "each hand, Anderson et al. 2007 for hips, knees and ankles (a joint at the end of "
        "its range carries its moment passively).  A posture that would tip is said to, not "
        "scored.  A target or virtual population's people are each scaled to their own "
        "stature and mass and weighted: each gender and everyone (docs/task.md).",
    )
    task.add_argument(
        "angles",
        nargs="*",
        metavar="JOINT=ANGLE",
        help="the posture: shoulder_x/y/z, elbow_y, wrist_x/y/z, hip_y, knee_y, ankle_y "
        "(deg; both sides, or left_/right_ before the joint), trunk_x (bend right), trunk_y "
        "(flexion), trunk_z (twist left), neck_x (bend right), neck_y (flexion), neck_z "
        "(rotation right); hands=H,V (e.g. hands=40cm,30cm, cm without a unit): where the "
        "hands grasp, H ahead of the ankles and V above the floor (the NIOSH manual's H and "
        "V), each figure stooping to it, its own hip_y and shoulder_y found (hands=H,V,squat: "
        "squatting, knee_y and ankle_y found too); standing upright if none",
    )
    task.add_argument(
        "--seated",
        action="store_true",
        help="seated: the pelvis on a seat, which carries the legs (no leg joint, no balance)",
    )
    for side in ("left", "right"):
        task.add_argument(f"--{side}-load", metavar="FORCE", help=LOAD_HELP.format(side=side))
        task.add_argument(
            f"--{side}-direction",
            metavar="DIRECTION",
            help=DIRECTION_HELP.format(side=side),
        )
    who = task.add_mutually_exclusive_group()
    who.add_argument("--gender", choices=GENDERS, help="one gender (default: women and men)")
    who.add_argument("--person", metavar="ID", help="a real person of the database (id or name)")
    who.add_argument(
        "--target",
        metavar="NAME",
        help="a target population (sass target): its people, each scaled to their own size, "
        "weighted",
    )
    add_virtual_option(who)
    task.add_argument("--age", type=float, help="years, picks Anderson et al. 2007's age group")
    task.add_argument("--mass", help="the figure's body mass, e.g. 70 or '154 lb' (kg)")
    task.add_argument("--stature", help="the figure's stature, e.g. 165 or '65 in' (cm)")
    task.add_argument("--format", choices=("text", "json"), default="text", help="output form")
    add_db_option(task)
    task.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    angles, goal = split_posture(args.angles, args.seated)
    for side in ("left", "right"):
        if getattr(args, f"{side}_load") is None and getattr(args, f"{side}_direction"):
            raise TaskError(f"--{side}-direction without --{side}-load: give the force too")
    loads = [
        load_of(
            side, text, direction, load_name=f"--{side}-load", direction_name=f"--{side}-direction"
        )
        for side, text, direction in (
            ("left", args.left_load, args.left_direction),
            ("right", args.right_load, args.right_direction),
        )
        if text is not None
    ]
    posture = posture_of(angles, goal, loads)
    if args.person is None and args.target is None and args.virtual is None:
        genders = [args.gender] if args.gender else ["female", "male"]
        references = [Reference(GENDER_WORDS[g], _figure(args, g), args.age) for g in genders]
        answer = assess_task(references, posture, loads, args.seated)
    else:
        # deferred: cli.task_people (the db package, numpy) — off sass task (sass_tui/startup.py)
        from sass_tui.cli.task_people import people_answer

        answer = people_answer(args, posture, loads, _figure)
    if goal is not None:
        answer.notes.insert(0, hands_at_note(goal, answer.postures))
    if args.format == "json":
        shown = task_json(answer, args.angles)
        if goal is not None:
            shown["hands_at"] = hands_at_json(goal, answer.postures)
        print(json.dumps(shown))
    else:
        for line in task_text(answer, args.angles):
            print(line)
    return 0


def _figure(args: argparse.Namespace, gender: str) -> Figure:
    figure = Figure.default(gender)
    if args.mass is not None:
        figure.set_mass(parse_quantity(args.mass, "kg"))
    if args.stature is not None:
        figure.set_stature(parse_quantity(args.stature, "cm"))
    return figure
