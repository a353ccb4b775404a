"""What the strength page's Task panel (ui/spreadsheet/task_panel.py) reads and writes
as text: the posture from the strength page's row, the people typed in its
cell, a hand's load, and the answer's rows.  No widget here."""

from __future__ import annotations

import math

from sass_tui.model.strength.hands_at import postures_words
from sass_tui.model.strength.task import UNCOVERED, HandLoad, TaskAnswer, TaskError
from sass_tui.model.vocabulary import JOINT_AXES

# The people a task is for: the figure's gender (default), the figure shown
# with its own size, the standard figure of one gender or of both; or the
# people of a target or virtual population by name (`target NAME`,
# `virtual NAME`), each scaled to their own size and weighted.
PEOPLE = ("gender", "figure", "women", "men", "women and men")
WEIGHTED = ("target", "virtual")
JOINT_ORDER = ("hand", "elbow", "shoulder", "hip", "knee", "ankle")


def strength_posture(side: str, angles: list[float]) -> tuple[str, ...]:
    """The strength page's angles of one row as a posture of that side's arm."""
    return tuple(
        f"{side}_{axis}={degrees:g}"
        for axis, degrees in zip(JOINT_AXES, angles)
        if not math.isnan(degrees)
    )


def posture_words(posture: tuple[str, ...]) -> str:
    """`right_shoulder_x=30 ...` -> `right arm shoulder 30 45 0, elbow 90, wrist 0 0 0 deg`."""
    if not posture:
        return "standing"
    side = posture[0].partition("_")[0]
    values = {
        item.partition("=")[0].removeprefix(f"{side}_"): item.partition("=")[2] for item in posture
    }
    joints = []
    for joint in ("shoulder", "elbow", "wrist"):
        shown = [values[axis] for axis in JOINT_AXES if axis.startswith(joint) and axis in values]
        if shown:
            joints.append(f"{joint} {' '.join(shown)}")
    return f"{side} arm {', '.join(joints)} deg"


def parse_people(text: str) -> str:
    words = " ".join(text.split())
    kind, _, name = words.partition(" ")
    if kind.lower() in WEIGHTED and name:
        return f"{kind.lower()} {name}"
    if words.lower() not in PEOPLE:
        raise TaskError(
            f"people {text.strip()!r}: expected one of {', '.join(PEOPLE)}, "
            "target NAME or virtual NAME"
        )
    return words.lower()


def load_words(load: HandLoad | None) -> str:
    if load is None:
        return "none"
    x, y, z = (float(v) for v in load.direction)
    named = {(0.0, -1.0, 0.0): "down", (0.0, 1.0, 0.0): "up", (0.0, 0.0, 1.0): "forward"}
    named |= {(0.0, 0.0, -1.0): "back", (1.0, 0.0, 0.0): "left", (-1.0, 0.0, 0.0): "right"}
    way = named.get((round(x, 4) + 0.0, round(y, 4) + 0.0, round(z, 4) + 0.0))
    return f"{load.force:g} N {way or f'{x:.2f},{y:.2f},{z:.2f}'}"


def _shared_words(names: list[str]) -> str:
    """The first words every name of several starts with: `VIRTUAL` of
    `VIRTUAL men`, `VIRTUAL women`."""
    if len(names) < 2:
        return ""
    shared: list[str] = []
    for words in zip(*(name.split() for name in names)):
        if len(set(words)) > 1:
            break
        shared.append(words[0])
    return " ".join(shared)


def answer_lines(answer: TaskAnswer) -> list[str]:
    """The answer in the panel's rows: each loaded hand and each elbow,
    shoulder, hip, knee and ankle with its moment and percent capable."""
    table, notes = answer_parts(answer)
    return table + notes


def answer_parts(answer: TaskAnswer) -> tuple[list[str], list[str]]:
    """The answer's table (a row per hand and joint, the trunk's) and its
    notes (the balance, scores and moments no model covers; the limiting),
    which the panel wraps at its width and always shows whole."""
    people = answer.populations
    # the words the columns share (VIRTUAL, a target's name) once, in the header
    shared = _shared_words(people)
    heads = "".join(f"{p[len(shared) :].strip()[:12]:>13}" for p in people)
    exert = f"to exert ({shared})" if shared else "to exert"
    lines = [f"{'Joint':<15}{'N-m':>6}{'loads':>6}  {exert[:30]:<30}{heads}"]
    capable = {c.what: c for c in answer.capabilities}
    moments = {m.joint: m for m in answer.moments}
    for side in ("left", "right"):
        for word in JOINT_ORDER:
            what = f"{side} {word}"
            moment, found = moments.get(what), capable.get(what)
            if moment is None and found is None:
                continue  # a hand without a load
            size = f"{moment.size:6.1f}" if moment is not None else f"{'':6}"
            loads = f"{math.hypot(*moment.from_loads):6.1f}" if moment is not None else f"{'':6}"
            if found is None:
                demand, cells = "the arm, at the hand", ""
            else:
                motion = "against the load" if found.unit == "N" else found.motion
                demand = f"{motion.replace('_', ' ')} {found.demand:.1f} {found.unit}"
                cells = "".join(
                    f"{found.percent[p]:>11.1f} %" if p in found.percent else f"{'-':>13}"
                    for p in people
                )
            lines.append(f"{what:<15}{size}{loads}  {demand[:30]:<30}{cells}")
    limiting = []
    for p in people:
        worst = answer.limiting(p)
        if worst is not None:
            limiting.append(f"{p} {worst.what} {worst.percent[p]:.1f} %")
    back = answer.low_back
    if back is not None:
        lines.append(
            f"{'trunk (L5/S1)':<15}{back.moment[0]:6.1f}  compression {back.compression:.0f} N, "
            f"shear {back.shear:.0f} N" + ("" if all(back.limits.values()) else ": above a limit")
        )
    stance = answer.stance
    if stance is not None and not stance.stable:
        limiting = [f"{p} out of balance" for p in answer.unstable]
    balance = "seated" if stance is None else "in balance" if stance.stable else "OUT OF BALANCE"
    scores = " ".join(f"{r.side[0]} {r.score}" for r in answer.rula)
    rebas = " ".join(f"{r.side[0]} {r.score}" for r in answer.reba)
    uncovered = [f"{m.joint} {m.size:.1f}" for m in answer.moments if m.covered_by == UNCOVERED]
    # a model answering outside what it was fitted on says so (sass task gives why)
    outside = [c.what for c in answer.capabilities if c.extrapolated]
    notes = [
        f"Balance: {balance}; RULA {scores}; REBA {rebas}; not covered (N-m): "
        f"{', '.join(uncovered)}",
        f"Limiting: {'; '.join(limiting)}"
        + (f"; extrapolated (outside the fitted data): {', '.join(outside)}" if outside else ""),
    ]
    if answer.cautions:
        notes.append(f"Cautions: {'; '.join(answer.cautions)}")
    if answer.postures:  # hands=H,V: the stoop or squat each figure found
        squat = "knee_y" in answer.solved_axes
        notes.append(
            f"{'Squat' if squat else 'Stoop'} to the hands' place: "
            + postures_words(answer.solved_axes, answer.postures, between=" ")
        )
    return lines, notes
