"""A fit test's result as the text table `sass fit` prints and the query
screen's Fit Test shows (one formatting for both)."""

from __future__ import annotations

from sass_tui.db.populations.fit import FitResult


def _percent(value: float | None) -> str:
    return "-" if value is None else f"{value:.1f} %"


def outside_line(shares: dict[str, float]) -> str:
    """What of a target the weighted people cannot reach, beside its accommodated share."""
    each = ", ".join(
        f"{100 * share:.1f} % beyond every person's {f}" for f, share in shares.items()
    )
    return (
        f"outside: {each}; the weighted people cannot stand for them, and the target's "
        "share is of the rest"
    )


def format_table(result: FitResult) -> str:
    lines = [
        f"Design limits: {' AND '.join(result.limits)}",
        f"Population: {result.population} ({result.population_size} people)",
    ]
    if result.not_measured:
        lines.append(
            f"Not measured for {result.not_measured} people (lacking a limited value): "
            "left out of every share"
        )
    lines += ["", f"{'':<10} {'people':>7} {'fit':>7} {'accommodated':>13} {'naive':>9}"]
    for share in result.genders.values():
        lines.append(
            f"{share.gender:<10} {share.n:>7} {share.fit:>7} {_percent(share.percent):>13} "
            f"{_percent(share.naive_percent):>9}"
        )
    mix = ", ".join(f"{g} {100 * w:.0f} %" for g, w in result.mix.items())
    lines.append(
        f"{'weighted':<10} {'':>7} {'':>7} {_percent(result.weighted_percent):>13} "
        f"{_percent(result.naive_percent):>9}   ({mix})"
    )
    if result.target is not None:
        lines.append(
            f"{'target':<10} {'':>7} {'':>7} {_percent(result.target.percent):>13} "
            f"{'':>9}   (weighted: {result.target.words})"
        )
        if result.target.outside_share:
            lines.append(outside_line(result.target.outside_share))
        if result.target.virtual:
            lines.append(
                "VIRTUAL people: each gender's accommodated share is weighted by their "
                "survey's weights; people and fit are counts"
            )
    lines += [
        "",
        "naive = the product of each limit's own share (what univariate percentiles suggest)",
    ]
    if any(limit.endswith("(predicted)") for limit in result.limits):
        lines.append(
            "a (predicted) strength limit: each person's probability of meeting it, so fit "
            "and excluded are expected numbers of people (docs/strength.md)"
        )
    lines.append("")
    width = max(len("limit"), *(len(b.limit) for b in result.by_limit))
    lines.append(
        f"{'limit':<{width}} {'excluded':>9} {'only limit':>11} {'not measured':>13}"
        + "".join(f" {g + ' share':>13}" for g in result.genders)
    )
    for b in result.by_limit:
        lines.append(
            f"{b.limit:<{width}} {b.excluded:>9} {b.only_limit:>11} {b.not_measured:>13}"
            + "".join(f" {_percent(b.percent.get(g)):>13}" for g in result.genders)
        )
    if result.failing is not None:
        lines += ["", f"{len(result.failing)} people fail a limit:"]
        for person in result.failing:
            lines.append(
                f"{person.id:>7}  {person.name:<20.20} {person.gender:<6} "
                + "; ".join(person.limits)
            )
    return "\n".join(lines) + "\n"
