"""The Revised NIOSH Lifting Equation (Waters, Putz-Anderson & Garg 1994,
*Applications Manual for the Revised NIOSH Lifting Equation*, DHHS (NIOSH)
Publication 94-110, revised 2021; public domain).

    RWL = LC x HM x VM x DM x AM x FM x CM        LI = load / RWL

Each multiplier is a pure function of its variable and the form (metric: cm,
kg, LC 23 kg; U.S. customary: in, lb, LC 51 lb — the manual's two sets of
constants, which are not conversions of each other), and says which of the
manual's limits it applied (H below 25 cm counts as 25 cm, beyond 63 cm the
multiplier is 0, ...).  Table 5 (frequency) and Table 7 (coupling) are data,
datasets/niosh_lifting.json.  The multi-task procedure (section 2.4: FIRWL,
STRWL, FILI, STLI, the composite lifting index) is `composite_lifting_index`.
Plain floats, no numpy: `sass niosh` starts in the time of a bare Python.
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

from sass_tui.model import shipped
from sass_tui.model.errors import SassError

DATA_FILE = "niosh_lifting.json"
DURATIONS = ("short", "moderate", "long")
COUPLINGS = ("good", "fair", "poor")
FORMS = ("metric", "us")


class NioshError(ValueError, SassError):
    """A lifting task the equation cannot take (a negative distance, no frequency...)."""

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        # the message leads with where (file:line), as the CLI prints only the message
        SassError.__init__(self, f"{where}: {message}" if where else message, where=where)


class Multiplier(NamedTuple):
    value: float
    limit: str = ""  # the manual's limit that was applied, in words; "" none


class Form(NamedTuple):
    """One of the manual's two sets of constants."""

    name: str  # "metric" | "us"
    length_unit: str  # "cm" | "in"
    load_unit: str  # "kg" | "lb"
    load_constant: float
    h: dict[str, float]
    v: dict[str, float]
    d: dict[str, float]
    low: float  # Tables 5 and 7: V below this (75 cm, 30 in) is "low"


def table() -> dict[str, Any]:
    """datasets/niosh_lifting.json, read once."""
    return shipped.json_table(DATA_FILE)


def source() -> str:
    return str(table()["source"])


def form(name: str) -> Form:
    """The metric or the U.S. customary form."""
    if name not in FORMS:
        raise NioshError(f"unknown form {name!r} (expected metric or us)")
    f = table()["forms"][name]
    return Form(
        name, f["length_unit"], f["load_unit"], float(f["LC"]), f["HM"], f["VM"], f["DM"], f["low"]
    )


def _length(value: float, unit: str) -> str:
    return f"{value:g} {unit}"


def horizontal_multiplier(h: float, of: Form) -> Multiplier:
    """HM = 25/H (10/H): H below 25 cm (10 in) counts as 25 cm; beyond 63 cm (25 in), 0."""
    if h < 0:
        raise NioshError(f"H {h:g} {of.length_unit} is negative")
    least, most = of.h["min"], of.h["max"]
    if h > most:
        return Multiplier(
            0.0, f"H {_length(h, of.length_unit)} beyond {_length(most, of.length_unit)}: HM 0"
        )
    if h < least:
        return Multiplier(
            1.0,
            f"H {_length(h, of.length_unit)} below {_length(least, of.length_unit)}: "
            f"taken as {_length(least, of.length_unit)}",
        )
    return Multiplier(of.h["numerator"] / h)


def vertical_multiplier(v: float, of: Form) -> Multiplier:
    """VM = 1 - 0.003 |V - 75| (1 - 0.0075 |V - 30|); above 175 cm (70 in), 0."""
    if v < 0:
        raise NioshError(f"V {v:g} {of.length_unit} is below the floor")
    if v > of.v["max"]:
        return Multiplier(
            0.0,
            f"V {_length(v, of.length_unit)} above the reach of "
            f"{_length(of.v['max'], of.length_unit)}: VM 0",
        )
    return Multiplier(1.0 - of.v["per_unit"] * abs(v - of.v["optimum"]))


def distance_multiplier(d: float, of: Form) -> Multiplier:
    """DM = 0.82 + 4.5/D (0.82 + 1.8/D): D below 25 cm (10 in) counts as 25 cm;
    beyond 175 cm (70 in), 0."""
    if d < 0:
        raise NioshError(f"D {d:g} {of.length_unit} is negative")
    least, most = of.d["min"], of.d["max"]
    if d > most:
        return Multiplier(
            0.0, f"D {_length(d, of.length_unit)} beyond {_length(most, of.length_unit)}: DM 0"
        )
    limit = ""
    if d < least:
        limit = (
            f"D {_length(d, of.length_unit)} below {_length(least, of.length_unit)}: "
            f"taken as {_length(least, of.length_unit)}"
        )
        d = least
    return Multiplier(of.d["constant"] + of.d["numerator"] / d, limit)


def asymmetric_multiplier(a: float) -> Multiplier:
    """AM = 1 - 0.0032 A (A in degrees, either side); beyond 135 deg, 0."""
    data = table()["AM"]
    a = abs(a)
    if a > data["max"]:
        return Multiplier(0.0, f"A {a:g} deg beyond {data['max']:g} deg: AM 0")
    return Multiplier(1.0 - data["per_degree"] * a)


def frequency_multiplier(f: float, duration: str, v_origin: float, of: Form) -> Multiplier:
    """FM from Table 5: by lifts per minute, work duration and V at the origin
    (below 75 cm / 30 in or not), linear between the table's rows; F below 0.2
    counts as 0.2; above the last frequency the column allows, 0."""
    data = table()["FM"]
    if duration not in DURATIONS:
        raise NioshError(f"unknown duration {duration!r} (expected short, moderate or long)")
    if f < 0:
        raise NioshError(f"frequency {f:g} per minute is negative")
    column = data[duration]["low" if v_origin < of.low else "high"]
    rows: list[float] = data["frequencies"]
    limit = ""
    if f < data["minimum"]:
        limit = f"F {f:g}/min below {data['minimum']:g}: taken as {data['minimum']:g}"
        f = data["minimum"]
    allowed = max(rate for rate, fm in zip(rows, column, strict=True) if fm > 0)
    if f > allowed:
        where = "below" if v_origin < of.low else "at or above"
        return Multiplier(
            0.0,
            f"F {f:g}/min above the {allowed:g}/min Table 5 allows for {duration} work "
            f"with V {where} {_length(of.low, of.length_unit)}: FM 0",
        )
    for i in range(len(rows) - 1):
        if rows[i] <= f <= rows[i + 1]:
            share = (f - rows[i]) / (rows[i + 1] - rows[i])
            return Multiplier(column[i] + share * (column[i + 1] - column[i]), limit)
    return Multiplier(column[0], limit)  # f == 0.2 exactly, reached above


def coupling_multiplier(coupling: str, v: float, of: Form) -> Multiplier:
    """CM from Table 7: by coupling and V (below 75 cm / 30 in or not)."""
    data = table()["CM"]
    if coupling not in COUPLINGS:
        raise NioshError(f"unknown coupling {coupling!r} (expected good, fair or poor)")
    return Multiplier(float(data[coupling]["low" if v < of.low else "high"]))


def special_frequency(lifts_per_minute: float, minutes: float) -> float:
    """The manual's special frequency adjustment (section 1.3.5): lifting for
    `minutes` (< 15) of a 15-minute sample at `lifts_per_minute` counts as
    lifts_per_minute x minutes / 15 lifts per minute."""
    if not 0 < minutes <= 15:
        raise NioshError(f"minutes of lifting {minutes:g}: expected more than 0, at most 15")
    if lifts_per_minute > 15:
        raise NioshError(
            f"the special frequency adjustment needs at most 15 lifts per minute, "
            f"got {lifts_per_minute:g}"
        )
    return lifts_per_minute * minutes / 15.0


class Point(NamedTuple):
    """Where the hands are at the origin or the destination of the lift."""

    h: float
    v: float
    a: float = 0.0
    coupling: str = "fair"


class Lift(NamedTuple):
    """One lifting task, in its form's units."""

    of: Form
    origin: Point
    d: float  # vertical travel distance
    f: float  # lifts per minute
    duration: str
    load: float | None = None  # average load (form's load unit)
    destination: Point | None = None  # significant control at the destination
    load_max: float | None = None  # the heaviest load (FILI, multi-task); default `load`


class Limit(NamedTuple):
    """The RWL at one end of the lift, each multiplier with its limit."""

    multipliers: dict[str, Multiplier]  # LC, HM, VM, DM, AM, FM, CM

    @property
    def rwl(self) -> float:
        product = 1.0
        for m in self.multipliers.values():
            product *= m.value
        return product

    @property
    def frequency_independent(self) -> float:
        """FIRWL: the RWL with FM 1."""
        fm = self.multipliers["FM"].value
        return self.rwl / fm if fm > 0 else self._without("FM")

    def _without(self, name: str) -> float:
        product = 1.0
        for key, m in self.multipliers.items():
            if key != name:
                product *= m.value
        return product

    @property
    def limits(self) -> list[str]:
        return [m.limit for m in self.multipliers.values() if m.limit]


def limit_at(lift: Lift, point: Point) -> Limit:
    """The multipliers at `point` (FM by V at the origin, as the manual's p. 15 says;
    CM by V at the point, as its Example 4)."""
    of = lift.of
    return Limit(
        {
            "LC": Multiplier(of.load_constant),
            "HM": horizontal_multiplier(point.h, of),
            "VM": vertical_multiplier(point.v, of),
            "DM": distance_multiplier(lift.d, of),
            "AM": asymmetric_multiplier(point.a),
            "FM": frequency_multiplier(lift.f, lift.duration, lift.origin.v, of),
            "CM": coupling_multiplier(point.coupling, point.v, of),
        }
    )


def lifting_index(load: float | None, rwl: float) -> float | None:
    """LI = load / RWL; None without a load; infinity when the RWL is 0 (no load)."""
    if load is None:
        return None
    if rwl <= 0:
        return float("inf") if load > 0 else 0.0
    return load / rwl


def index_words(value: float | None) -> str:
    """A lifting index as sass prints it: two decimals, "-" without a load,
    "infinite" where the RWL is 0 (a limit of the manual, H beyond 63 cm, V
    beyond 175 cm, F beyond Table 5, leaves no load acceptable)."""
    if value is None:
        return "-"
    return "infinite" if math.isinf(value) else f"{value:.2f}"


def json_number(value: float | None, digits: int = 4) -> float | None:
    """A weight limit, index or multiplier as `sass niosh --format json` gives
    it: rounded, and null for no value (no load) or no limit (an RWL of 0
    gives LI infinity, which JSON cannot hold)."""
    if value is None or not math.isfinite(value):
        return None
    return round(value, digits)


class LiftAnswer(NamedTuple):
    lift: Lift
    origin: Limit
    destination: Limit | None

    @property
    def rwl(self) -> float:
        """The lower of the origin's and the destination's (the manual, p. 26)."""
        ends = [self.origin] + ([self.destination] if self.destination else [])
        return min(end.rwl for end in ends)

    @property
    def firwl(self) -> float:
        ends = [self.origin] + ([self.destination] if self.destination else [])
        return min(end.frequency_independent for end in ends)

    @property
    def limits(self) -> list[str]:
        """The limits applied at the origin, then those only the destination adds."""
        found = list(self.origin.limits)
        if self.destination is not None:
            found += [limit for limit in self.destination.limits if limit not in found]
        return found


def assess_lift(lift: Lift) -> LiftAnswer:
    destination = None if lift.destination is None else limit_at(lift, lift.destination)
    return LiftAnswer(lift, limit_at(lift, lift.origin), destination)


class TaskIndices(NamedTuple):
    """One task of a multi-task job (the manual's section 2.4)."""

    name: str
    f: float
    v_origin: float
    firwl: float
    strwl: float
    fili: float  # heaviest load / FIRWL
    stli: float  # average load / STRWL
    limits: tuple[str, ...] = ()  # the manual's limits applied, at either end


class CompositeAnswer(NamedTuple):
    tasks: list[TaskIndices]  # renumbered: greatest STLI first
    cli: float
    increments: list[float]  # each ΔLI, from task 2 on


def task_indices(name: str, lift: Lift) -> TaskIndices:
    if lift.load is None:
        raise NioshError(f"task {name}: a multi-task job needs each task's load")
    answer = assess_lift(lift)
    firwl, strwl = answer.firwl, answer.rwl
    heaviest = lift.load if lift.load_max is None else lift.load_max
    return TaskIndices(
        name,
        lift.f,
        lift.origin.v,
        firwl,
        strwl,
        _index(heaviest, firwl),
        _index(lift.load, strwl),
        tuple(answer.limits),
    )


def _index(load: float, limit: float) -> float:
    return load / limit if limit > 0 else float("inf")


def composite_lifting_index(tasks: list[TaskIndices], duration: str, of: Form) -> CompositeAnswer:
    """CLI = STLI_1 + sum over k >= 2 of FILI_k (1/FM_1..k - 1/FM_1..k-1), the
    tasks renumbered by decreasing STLI (ties: the higher frequency first), each
    FM from Table 5 at the sum of the frequencies of tasks 1..k (the manual,
    p. 28).  The V column: below 75 cm (30 in) when any of those tasks starts
    there, the more protective reading (the manual does not say which task's V)."""
    if not tasks:
        raise NioshError("a multi-task job needs at least one task")
    ordered = sorted(tasks, key=lambda t: (-t.stli, -t.f))
    cli = ordered[0].stli
    increments: list[float] = []
    total_f = ordered[0].f
    lowest_v = ordered[0].v_origin
    before = frequency_multiplier(total_f, duration, lowest_v, of).value
    for task in ordered[1:]:
        total_f += task.f
        lowest_v = min(lowest_v, task.v_origin)
        after = frequency_multiplier(total_f, duration, lowest_v, of).value
        # FM 0 (the summed frequency beyond Table 5): no load at all
        step = float("inf") if after <= 0 else task.fili * (1.0 / after - _inverse(before))
        increments.append(step)
        cli += step
        before = after
    return CompositeAnswer(ordered, cli, increments)


def _inverse(fm: float) -> float:
    return 1.0 / fm if fm > 0 else float("inf")
