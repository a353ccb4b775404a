"""`sass niosh --tasks FILE`: a multi-task job (the Applications Manual's
section 2.4): each task's FIRWL, STRWL, FILI and STLI, in the order of
decreasing STLI, and the composite lifting index.  Apart from cli/niosh.py
because only a job reads a file: the file reader (model/files/paths.py,
with pathlib) and the job file's parser (model/strength/niosh_tasks.py,
with csv) would cost a single lift ~4 ms of start-up."""

from __future__ import annotations

import argparse
import json
from typing import Any

from sass_tui.model.files.paths import LARGEST_TEXT_FILE, read_user_text
from sass_tui.model.strength.niosh import (
    CompositeAnswer,
    Form,
    NioshError,
    composite_lifting_index,
    index_words,
    json_number,
    source,
    task_indices,
)
from sass_tui.model.strength.niosh_tasks import read_tasks
from sass_tui.model.text import printable


def run_job(args: argparse.Namespace) -> int:
    given = [
        option
        for option, value in (
            ("--h", args.h),
            ("--v", args.v),
            ("--d", args.d),
            ("--f", args.f),
            ("--load", args.load),
            ("--dest-h", args.dest_h),
            ("--dest-v", args.dest_v),
            ("--dest-a", args.dest_a),
            ("--dest-coupling", args.dest_coupling),
            ("--lifting-minutes", args.lifting_minutes),
            # a posture's hands were passed over without a word
            ("JOINT=ANGLE", args.angles or None),
            ("--posture", args.posture),
            ("--person", args.person),
            ("--gender", args.gender),
        )
        if value is not None
    ]
    if given:
        raise NioshError(f"--tasks takes each task from its file; leave out {', '.join(given)}")
    path, text = read_user_text(args.tasks, kind="a job file", largest=LARGEST_TEXT_FILE)
    of, lifts = read_tasks(text, str(path), args.duration)
    answer = composite_lifting_index(
        [task_indices(name, lift) for name, lift in lifts], args.duration, of
    )
    if args.format == "json":
        print(json.dumps(job_json(answer, of, args.duration)))
    else:
        for line in job_text(answer, of, args.duration):
            print(line)
    return 0


def job_json(answer: CompositeAnswer, of: Form, duration: str) -> dict[str, Any]:
    return {
        "form": of.name,
        "duration": duration,
        "tasks": [
            {
                "name": task.name,
                "frequency": task.f,
                "firwl": {"value": json_number(task.firwl, 3), "unit": of.load_unit},
                "strwl": {"value": json_number(task.strwl, 3), "unit": of.load_unit},
                "fili": json_number(task.fili),
                "stli": json_number(task.stli),
                "limits": list(task.limits),
            }
            for task in answer.tasks
        ],
        "increments": [json_number(step) for step in answer.increments],
        "composite_lifting_index": json_number(answer.cli),
        "source": source(),
    }


def job_text(answer: CompositeAnswer, of: Form, duration: str) -> list[str]:
    lines = [
        f"Multi-task job ({'metric form' if of.name == 'metric' else 'U.S. form'}, "
        f"{duration} duration), tasks by decreasing STLI:",
        f"{'#':>3} {'task':20} {'F/min':>7} {'FIRWL':>9} {'STRWL':>9} {'FILI':>9} {'STLI':>9}",
    ]
    for i, task in enumerate(answer.tasks, 1):
        lines.append(
            f"{i:>3} {printable(task.name)[:20]:20} {task.f:>7.2f} {task.firwl:>9.2f} {task.strwl:>9.2f} "
            f"{index_words(task.fili):>9} {index_words(task.stli):>9}"
        )
    for task in answer.tasks:
        lines += [f"Limit (task {printable(task.name)}): {limit}" for limit in task.limits]
    lines.append(
        f"Composite lifting index: {index_words(answer.cli)} (FIRWL, STRWL in {of.load_unit})"
    )
    lines.append(f"Source: {source()}")
    return lines
