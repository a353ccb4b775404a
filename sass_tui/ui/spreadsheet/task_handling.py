"""The Task panel's manual-handling line: the task it holds (the posture's
hands, the weight the hands hold up) as a lift, rated by the NIOSH
lifting equation (its lifting index) and the Liberty Mutual equations (the
share of women and of men who accept it), docs/manual-handling.md.  The
panel holds no distance, frequency or duration, so the line says what it
takes: the posture as the lift's origin and middle, D and DV 25 cm, one lift
every 5 minutes for NIOSH (F 0.2/min, long duration, fair coupling, A 0) and
one a minute for Liberty Mutual."""

from __future__ import annotations

from collections.abc import Iterable

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import Angles, pose_figure
from sass_tui.model.errors import SassError
from sass_tui.model.strength import liberty_mutual, niosh
from sass_tui.model.strength.hand_position import body_h_v
from sass_tui.model.strength.task import HandLoad
from sass_tui.model.units import STANDARD_GRAVITY


def lifted_kg(loads: Iterable[HandLoad]) -> float:
    """The mass the hands hold: the upward parts of the forces they exert
    (a force is what the hand exerts on the object), N / g."""
    return sum(max(0.0, float(load.vector[1])) for load in loads) / STANDARD_GRAVITY


def handling_line(figure: Figure, angles: Angles, loads: Iterable[HandLoad]) -> str:
    """One line: the lifting index and the percent of women and men who accept the lift."""
    kg = lifted_kg(loads)
    if kg <= 0:
        return "Lifting: no load held up (NIOSH, Liberty Mutual rate a lift)"
    try:
        h, v = body_h_v(pose_figure(figure, angles))
        metric = niosh.form("metric")
        lift = niosh.Lift(metric, niosh.Point(h * 100, v * 100), 25.0, 0.2, "long", kg)
        rwl = niosh.assess_lift(lift).rwl
        index = niosh.lifting_index(kg, rwl)
        said = [f"Lifting {kg:.1f} kg, hands H {h * 100:.0f} V {v * 100:.0f} cm: NIOSH LI "]
        said.append(niosh.index_words(index) + (" (RWL 0)" if rwl <= 0 else ""))
        inputs = liberty_mutual.Inputs("lift", v, 0.25, 1.0, h)
        shares = []
        for sex, word in (("female", "women"), ("male", "men")):
            found = liberty_mutual.acceptable(inputs, "", sex)
            share = "outside its ranges" if found.refused else f"{found.percent_capable(kg):.0f} %"
            shares.append(f"{word} {share}")
        said.append(f"; Liberty Mutual accepted by {', '.join(shares)}")
    except SassError as exc:
        return f"Lifting: {exc}"
    return "".join(said) + " (D 25 cm, 1 lift/5 min; LM 1/min)"
