"""`sass niosh --tasks FILE`: a multi-task job, each task's FIRWL, STRWL,
FILI and STLI and the composite lifting index (the NIOSH manual's section
2.4; model/strength/niosh.py).  A module of its own: the job file's reader
(csv, the file checks) is not on the path of one lift."""

from __future__ import annotations

import argparse
import json
from typing import Any

from sass_tui.cli.niosh import index_text, number
from sass_tui.model.files.paths import LARGEST_TEXT_FILE, read_user_text
from sass_tui.model.strength.niosh import (
    CompositeAnswer,
    Form,
    NioshError,
    composite_lifting_index,
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
                "firwl": {"value": number(task.firwl, 3), "unit": of.load_unit},
                "strwl": {"value": number(task.strwl, 3), "unit": of.load_unit},
                "fili": number(task.fili),
                "stli": number(task.stli),
            }
            for task in answer.tasks
        ],
        "increments": [number(step) for step in answer.increments],
        "composite_lifting_index": number(answer.cli),
        "source": source(),
    }


def job_text(answer: CompositeAnswer, of: Form, duration: str) -> list[str]:
    lines = [
        f"Multi-task job ({'metric form' if of.name == 'metric' else 'U.S. form'}, "
        f"{duration} duration), tasks by decreasing STLI:",
        f"{'#':>3} {'task':20} {'F/min':>7} {'FIRWL':>9} {'STRWL':>9} {'FILI':>7} {'STLI':>7}",
    ]
    for i, task in enumerate(answer.tasks, 1):
        lines.append(
            f"{i:>3} {printable(task.name)[:20]:20} {task.f:>7.2f} {task.firwl:>9.2f} {task.strwl:>9.2f} "
            f"{index_text(task.fili):>7} {index_text(task.stli):>7}"
        )
    lines.append(
        f"Composite lifting index: {index_text(answer.cli)} (FIRWL, STRWL in {of.load_unit})"
    )
    lines.append(f"Source: {source()}")
    return lines
