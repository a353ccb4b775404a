"""The Liberty Mutual manual materials handling equations (Potvin, Ciriello,
Snook, Maynard & Brogmus 2021, *Ergonomics* 64(8):955-970,
doi:10.1080/00140139.2021.1891297), which replace the tables of Snook &
Ciriello (1991).

For lift, lower, push and pull (initial and sustained) and carry, women and
men: the maximum acceptable load of the 50th percentile of the sex

    MAL = RL x (a scale factor of each of H, VRM, DV, F)     lift, lower
    MAL = RL x (a scale factor of each of V, DH, F)          push, pull, carry

(kg; kgf for push and pull), each factor a polynomial of the variable or of
its natural log, with a coefficient of variation: the load a share p accepts
is MAL (1 - z_p CV), and the share who accept a load L is
Phi((1 - L/MAL) / CV) (the paper's section 3.4).  The coefficients and the
input ranges the paper states are data, datasets/liberty_mutual.json.  Plain
floats (math.erf), no numpy: `sass handling` starts in the time of a bare
Python.
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

from sass_tui.model import shipped
from sass_tui.model.errors import SassError

DATA_FILE = "liberty_mutual.json"
TASKS = ("lift", "lower", "push", "pull", "carry")
SEXES = ("female", "male")
VARIANTS = {"push": ("initial", "sustained"), "pull": ("initial", "sustained")}
HANDLES = ("handles", "poor", "none")
# The shares the answers give the load for (the paper's 75 %; 90 %, the
# Liberty Mutual tables' design goal for women).
SHARES = (75.0, 90.0)


class HandlingError(ValueError, SassError):
    """A handling task outside what the equations take."""

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        # the message leads with where (file:line), as the CLI prints only the message
        SassError.__init__(self, f"{where}: {message}" if where else message, where=where)


def table() -> dict[str, Any]:
    """datasets/liberty_mutual.json, read once."""
    return shipped.json_table(DATA_FILE)


def source() -> str:
    return str(table()["source"])


def variants(task: str) -> tuple[str, ...]:
    """("initial", "sustained") for push and pull, ("",) otherwise."""
    return VARIANTS.get(task, ("",))


def equation(task: str, variant: str, sex: str) -> dict[str, Any]:
    for row in table()["equations"]:
        if (row["task"], row["variant"], row["sex"]) == (task, variant, sex):
            return dict(row)
    raise HandlingError(f"no Liberty Mutual equation for {task} {variant} {sex}".replace("  ", " "))


def scale_factor(factor: dict[str, Any], value: float) -> float:
    """constant + sum(sign x^power / divisor), x the value or its natural log."""
    if factor["log"]:
        if value <= 0:
            raise HandlingError(f"{factor['of']} {value:g} must be above 0 (its log is taken)")
        value = math.log(value)
    total = float(factor["constant"])
    for term in factor["terms"]:
        total += term["sign"] * value ** term["power"] / term["divisor"]
    return total


class Inputs(NamedTuple):
    """A task's variables in metres and actions per minute: for lift and lower
    h (hand distance), v (the middle of the vertical range, VRM) and d (the
    vertical distance, DV); for push, pull and carry v (hand height) and d
    (the horizontal distance, DH)."""

    task: str
    v: float
    d: float
    f: float
    h: float | None = None
    handles: str = "handles"  # lift and lower: the coupling scale factor's


def _variables(inputs: Inputs) -> dict[str, float]:
    if inputs.task in ("lift", "lower"):
        if inputs.h is None:
            raise HandlingError(f"{inputs.task} needs the hand distance H (--h)")
        return {"H": inputs.h, "VRM": inputs.v, "DV": inputs.d, "F": inputs.f}
    return {"V": inputs.v, "DH": inputs.d, "F": inputs.f}


def out_of_range(inputs: Inputs, sex: str) -> list[str]:
    """The paper's ranges `inputs` break for `sex` (empty: none); the answer
    refuses them ("must range from ... to ...", journal pp. 962-964)."""
    ranges = table()["ranges"][inputs.task]
    values = _variables(inputs)
    broken = []
    for name, value in values.items():
        bounds = ranges.get(name)
        if bounds is None:
            continue
        low, high = bounds[sex] if isinstance(bounds, dict) else bounds
        if not low <= value <= high:
            if name == "F":  # the paper's least frequency, one a day, is 1/480 per minute
                day = " (one a day)" if math.isclose(low * 480, 1, rel_tol=1e-3) else ""
                broken.append(f"F {value:g} per minute outside {low:.3g}{day}-{high:g} per minute")
            else:
                broken.append(f"{name} {value:g} m outside {low:g}-{high:g} m")
    if inputs.task in ("lift", "lower"):
        reach = ranges["arm_reach"][sex]
        top = inputs.v + inputs.d / 2
        if top > reach:
            broken.append(
                f"the hands' highest point VRM + DV/2 = {top:.3g} m above the arm reach "
                f"{reach:g} m of the 50th percentile {sex}"
            )
    velocity = inputs.d * inputs.f
    if velocity > ranges["velocity"]:
        broken.append(
            f"mean velocity D x F = {velocity:.3g} m/min above {ranges['velocity']:g} m/min"
        )
    return broken


def cautions(inputs: Inputs, sex: str) -> list[str]:
    """Section 4.3's cautions (the answer is given, flagged)."""
    ranges = table()["ranges"][inputs.task]
    caution = ranges["caution_velocity"].get(sex)
    velocity = inputs.d * inputs.f
    said = []
    if caution is not None and velocity > caution:
        said.append(
            f"mean velocity {velocity:.3g} m/min above ~{caution:g} m/min for "
            f"{'women' if sex == 'female' else 'men'}: use with caution, "
            "a physiological criterion may limit the load (the paper, section 4.3)"
        )
    if inputs.task in ("lift", "lower") and inputs.handles != "handles":
        said.append(
            f"no handles or poor ones: the coupling scale factor "
            f"{table()['coupling'][inputs.handles]:g} applied (section 4.3)"
        )
    return said


class Acceptable(NamedTuple):
    """One equation's answer for one sex (and, for push and pull, one variant)."""

    task: str
    variant: str  # "" | "initial" | "sustained"
    sex: str
    factors: dict[str, float]  # RL, then each scale factor
    cv: float
    refused: list[str]  # the ranges broken: no answer then
    inputs: Inputs
    notes: list[str]  # the paper's cautions that apply (the answer stands)

    @property
    def words(self) -> str:
        """The inputs as the paper names them."""
        i = self.inputs
        if i.task in ("lift", "lower"):
            said = f"H {i.h:.3g} m, VRM {i.v:.3g} m, DV {i.d:.3g} m"
        else:
            said = f"V {i.v:.3g} m, DH {i.d:.3g} m"
        return f"{said}, F {i.f:.3g}/min"

    @property
    def mal(self) -> float:
        """The maximum acceptable load of the 50th percentile."""
        product = 1.0
        for value in self.factors.values():
            product *= value
        return product

    def load_for(self, percent: float) -> float:
        """The load `percent` % of the sex accept: MAL (1 - z CV)."""
        return self.mal * (1.0 - normal_quantile(percent / 100.0) * self.cv)

    def percent_capable(self, load: float) -> float:
        """The percentage who accept `load`: 100 Phi((1 - load/MAL) / CV)."""
        if self.mal <= 0:
            return 0.0 if load > 0 else 100.0
        return 100.0 * normal_cdf((1.0 - load / self.mal) / self.cv)


def acceptable(inputs: Inputs, variant: str, sex: str) -> Acceptable:
    """The equation of `inputs.task`, `variant` and `sex` on `inputs`."""
    if inputs.task not in TASKS:
        raise HandlingError(f"unknown task {inputs.task!r} (expected {', '.join(TASKS)})")
    if inputs.handles not in HANDLES:
        raise HandlingError(f"unknown handles {inputs.handles!r} (expected {', '.join(HANDLES)})")
    row = equation(inputs.task, variant, sex)
    refused = out_of_range(inputs, sex)
    factors = {"RL": float(row["RL"])}
    if not refused:
        values = _variables(inputs)
        for name, factor in row["factors"].items():
            factors[name] = scale_factor(factor, values[factor["of"]])
        if inputs.task in ("lift", "lower") and inputs.handles != "handles":
            factors["coupling"] = float(table()["coupling"][inputs.handles])
    return Acceptable(
        inputs.task,
        variant,
        sex,
        factors,
        float(row["CV"]),
        refused,
        inputs,
        [] if refused else cautions(inputs, sex),
    )


def normal_cdf(z: float) -> float:
    return 0.5 * (1.0 + math.erf(z / math.sqrt(2.0)))


def normal_quantile(p: float) -> float:
    """Phi^-1(p) by bisection on erf (to 1e-12; statistics.NormalDist would
    cost the verb its import)."""
    if not 0.0 < p < 1.0:
        raise HandlingError(f"a share {p:g} must lie strictly between 0 and 1")
    low, high = -40.0, 40.0
    while high - low > 1e-12:
        middle = (low + high) / 2.0
        if normal_cdf(middle) < p:
            low = middle
        else:
            high = middle
    return (low + high) / 2.0


def mixed_percent(percents: dict[str, float], weights: dict[str, float]) -> float:
    """The weighted mix of each sex's percent capable (a population's people of
    each gender weighted by their survey weights)."""
    total = sum(weights[sex] for sex in percents)
    if total <= 0:
        raise HandlingError("the population's people weigh nothing")
    return sum(percents[sex] * weights[sex] for sex in percents) / total
