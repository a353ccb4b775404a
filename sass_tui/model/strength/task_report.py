"""What `sass task` says: its answer (model/strength/task.py) as text and as
JSON, with the low back and the balance.  No Textual import here."""

from __future__ import annotations

import numpy as np

from sass_tui.model.strength.low_back import LowBack, limit_words
from sass_tui.model.strength.reba import ASSUMED as REBA_ASSUMED
from sass_tui.model.strength.rula import ASSUMED as RULA_ASSUMED
from sass_tui.model.strength.statics import Balance
from sass_tui.model.strength.task import UNCOVERED, HandLoad, TaskAnswer

MOMENT_DECIMALS = 1  # N-m: segment masses and lengths carry three figures
PERCENT_DECIMALS = 1
FORCE_DECIMALS = 0  # N of the low back: the model's assumptions are coarser
PLACE_DECIMALS = 3  # m


def _round(value: float, decimals: int) -> float:
    return round(float(value), decimals) + 0.0  # no -0.0


def load_json(load: HandLoad) -> dict[str, object]:
    return {
        "side": load.side,
        "force_N": round(load.force, 1),
        "mass_kg": None if load.mass is None else _round(load.mass, 2),
        "direction": [_round(x, 4) for x in load.direction],
        "exerted_by": "the hand, on the object",
    }


def low_back_json(back: LowBack | None) -> dict[str, object] | None:
    if back is None:
        return None
    return {
        "moment_N_m": _round(back.moment[0], MOMENT_DECIMALS),
        "moment_trunk_axes_N_m": [_round(x, MOMENT_DECIMALS) for x in back.moment],
        "compression_N": _round(back.compression, FORCE_DECIMALS),
        "shear_N": _round(back.shear, FORCE_DECIMALS),
        "muscle_N": _round(back.muscle, FORCE_DECIMALS),
        "limits": back.limits,
        "notes": list(back.notes),
    }


def balance_json(stance: Balance | None, lean: float | None) -> dict[str, object]:
    if stance is None:
        return {"stable": None, "seated": True}
    return {
        "stable": stance.stable,
        "reason": stance.reason or None,
        "center_of_mass_m": [_round(x, PLACE_DECIMALS) for x in stance.center_of_mass],
        "center_of_pressure_m": [_round(x, PLACE_DECIMALS) for x in stance.center_of_pressure],
        "margin_m": _round(stance.margin, PLACE_DECIMALS) if np.isfinite(stance.margin) else None,
        "feet_N": {
            side: [_round(x, MOMENT_DECIMALS) for x in force]
            for side, (_, force) in stance.feet.items()
        },
        "feet_on_floor": list(stance.bearing),
        "lean_deg": None if lean is None else _round(lean, 1),
    }


def task_json(answer: TaskAnswer, posture: list[str]) -> dict[str, object]:
    def triple(v: tuple[float, float, float]) -> list[float]:
        return [_round(x, MOMENT_DECIMALS) for x in v]

    return {
        "posture": posture,
        "loads": [load_json(load) for load in answer.loads],
        "figure": answer.figure_words,
        "moments_N_m": [
            {
                "joint": m.joint,
                "moment": triple(m.moment),
                "size": round(m.size, MOMENT_DECIMALS),
                "from_loads": triple(m.from_loads),
                "covered_by": m.covered_by,
            }
            for m in answer.moments
        ],
        "capable": [
            {
                "what": c.what,
                "motion": c.motion,
                "demand": round(c.demand, MOMENT_DECIMALS),
                "unit": c.unit,
                "percent": {k: round(v, PERCENT_DECIMALS) for k, v in c.percent.items()},
                "source": c.source,
                "passive": c.passive,
                "extrapolated": c.extrapolated or None,
            }
            for c in answer.capabilities
        ],
        "limiting": {
            p: None if (c := answer.limiting(p)) is None else c.what for p in answer.populations
        },
        "low_back": low_back_json(answer.low_back),
        "balance": balance_json(answer.stance, answer.lean),
        "out_of_balance": answer.unstable,
        "rula": [
            {
                "side": r.side,
                "score": r.score,
                "action_level": r.action_level,
                "posture_a": r.posture_a,
                "posture_b": r.posture_b,
                "upper_arm": r.upper_arm,
                "lower_arm": r.lower_arm,
                "wrist": r.wrist,
                "wrist_twist": r.wrist_twist,
                "neck": r.neck,
                "trunk": r.trunk,
                "legs": r.legs,
                "force_a": r.force_a,
                "force_b": r.force_b,
                "assumed": RULA_ASSUMED,
                "source": "McAtamney & Corlett 1993",
            }
            for r in answer.rula
        ],
        "reba": [
            {
                "side": r.side,
                "score": r.score,
                "action_level": r.action_level,
                "score_a": r.score_a,
                "score_b": r.score_b,
                "trunk": r.trunk,
                "neck": r.neck,
                "legs": r.legs,
                "load": r.load,
                "upper_arm": r.upper_arm,
                "lower_arm": r.lower_arm,
                "wrist": r.wrist,
                "assumed": REBA_ASSUMED,
                "source": "Hignett & McAtamney 2000",
            }
            for r in answer.reba
        ],
        "not_covered": [m.joint for m in answer.moments if m.covered_by == UNCOVERED],
        "notes": answer.notes,
        "cautions": answer.cautions,
    }


def _load_words(load: HandLoad) -> str:
    held = f" ({load.mass:g} kg held)" if load.mass is not None else ""
    way = ", ".join(f"{x:.2f}" for x in load.direction)
    return f"{load.side} hand exerts {load.force:.1f} N along ({way}){held}"


def task_text(answer: TaskAnswer, posture: list[str]) -> list[str]:
    loads = "; ".join(_load_words(load) for load in answer.loads) or "none (body weight only)"
    lines = [
        f"Task: posture {' '.join(posture) or 'standing'}; the hands' forces: {loads}",
        f"Moments (N-m, HAnim axes: x left, y up, z forward) on {answer.figure_words}:",
        f"  {'joint':<16} {'x':>8} {'y':>8} {'z':>8} {'size':>8} {'loads':>8}  covered by",
    ]
    for m in answer.moments:
        x, y, z = m.moment
        lines.append(
            f"  {m.joint:<16} {x:>8.1f} {y:>8.1f} {z:>8.1f} {m.size:>8.1f} "
            f"{float(np.linalg.norm(m.from_loads)):>8.1f}  {m.covered_by}"
        )
    lines += _low_back_lines(answer.low_back)
    lines += _balance_lines(answer.stance)
    lines += [
        f"RULA (McAtamney & Corlett 1993), {r.side} arm: {r.score} (action level "
        f"{r.action_level}; A {r.posture_a}, B {r.posture_b})"
        for r in answer.rula
    ]
    if answer.rula:
        lines.append(f"  RULA assumes: {RULA_ASSUMED}")
    lines += [
        f"REBA (Hignett & McAtamney 2000), {r.side} arm: {r.score} (action level "
        f"{r.action_level}; A {r.score_a}, B {r.score_b})"
        for r in answer.reba
    ]
    if answer.reba:
        lines.append(f"  REBA assumes: {REBA_ASSUMED}")
    # a column as wide as its population's name (a target's are long), 20 at least
    width = max([20, *(len(p) + 2 for p in answer.populations)])
    heads = "".join(f"{p:>{width}}" for p in answer.populations)
    rows = [
        (c, f"{c.what}: {c.motion.replace('_', ' ')} {c.demand:.1f} {c.unit}")
        for c in answer.capabilities
    ]
    # the widest row sets the column (a passive joint's words are long)
    label = max([46, *(len(what) + 1 for _, what in rows)])
    lines += ["", f"Percent capable{'':<{label - 13}}{heads}"]
    for c, what in rows:
        cells = "".join(
            f"{c.percent[p]:>{width - 2}.1f} %" if p in c.percent else f"{'-':>{width}}"
            for p in answer.populations
        )
        lines.append(f"  {what:<{label}}{cells}")
        if c.extrapolated:
            lines.append(f"    {c.what}: {c.extrapolated}")
    for p in answer.populations:
        if p in answer.unstable:
            lines.append(f"out of balance for {p}: {answer.unstable[p]}; not scored")
            continue
        worst = answer.limiting(p)
        if worst is not None:
            lines.append(f"limiting for {p}: {worst.what} ({worst.percent[p]:.1f} % capable)")
    uncovered = [m.joint for m in answer.moments if m.covered_by == UNCOVERED]
    lines.append(f"not covered: {', '.join(uncovered)}: {UNCOVERED}")
    sources = sorted({c.source.split(";")[0] for c in answer.capabilities})
    lines.append(f"sources: {'; '.join(sources)}")
    lines += [f"note: {n}" for n in answer.notes]
    lines += [f"caution: {c}" for c in answer.cautions]
    return lines


def _low_back_lines(back: LowBack | None) -> list[str]:
    if back is None:
        return []
    passed = [f"{words}: {'within' if ok else 'ABOVE'}" for words, ok in back.limits.items()]
    return [
        f"Low back (L5/S1): moment {back.moment[0]:.1f} N-m, compression "
        f"{back.compression:.0f} N, shear {back.shear:.0f} N (muscle {back.muscle:.0f} N)",
        f"  {'; '.join(passed)}",
        f"  limits: {', '.join(limit_words())}",
        *(f"  {note}" for note in back.notes),
    ]


def _balance_lines(stance: Balance | None) -> list[str]:
    if stance is None:
        return ["Balance: seated, not assessed"]
    cop = stance.center_of_pressure
    feet = ", ".join(
        f"{side} {force[1]:.0f} N" + ("" if side in stance.bearing else " (off the floor)")
        for side, (_, force) in stance.feet.items()
    )
    state = "in balance" if stance.stable else f"OUT OF BALANCE: {stance.reason}"
    return [
        f"Balance: {state}; centre of pressure x {cop[0]:.3f} z {cop[2]:.3f} m, "
        f"margin {stance.margin * 100:.1f} cm; the floor under the feet: {feet or 'none'}"
    ]
