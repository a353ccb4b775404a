"""The figure `add_figure_options` (cli/common/options.py) describes, built through
a Session as the TUI builds it: `sass fig` and `sass export`."""

from __future__ import annotations

import argparse
from types import ModuleType

from sass_tui.cli.common.options import weighting_name
from sass_tui.model.body.figure import Figure, FigureError
from sass_tui.model.files.popfile import PopulationData, read_global_beside, read_population_file
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GLOBAL, JOINT_LIMITS
from sass_tui.model.session import Session
from sass_tui.model.units import parse_quantity


def figure_from_args(args: argparse.Namespace) -> tuple[Figure, list[str]]:
    """Build the figure the options describe, through a Session as the TUI
    does (each edit checked the same way); returns it and the load warnings."""
    weighting = weighting_name(args)
    db_side: ModuleType | None = None
    if args.person is not None or weighting is not None:
        # deferred: cli.person_option (the db package, numpy) — off sass fig, sass export hanim, sass export gltf (sass_tui/startup.py)
        from sass_tui.cli.common import person_option as db_side
    if weighting is not None:
        given = [
            o
            for o, v in (
                ("--person", args.person),
                ("--girth", args.girth),
                ("--jntlmt", args.jntlmt),
                ("--cmass", args.cmass),
                ("--global", args.global_file),
            )
            if v
        ]
        if given:
            raise FigureError(
                f"--{'virtual' if args.virtual else 'target'} sizes the figure from its people; "
                f"leave out {', '.join(given)}"
            )
    if args.person is not None:
        given = [o for o, v in (("--mass", args.mass), ("--stature", args.stature)) if v]
        given += [o for o, v in (("--gender", args.gender),) if v]
        if given:
            raise FigureError(f"--person takes the person's own {', '.join(given)}; leave it out")
    files = {
        group: read_population_file(option, group)
        for group, option in (
            (GIRTH, args.girth),
            (JOINT_LIMITS, args.jntlmt),
            (CENTER_OF_MASS, args.cmass),
        )
        if option
    }
    weighted = None
    if db_side is not None and weighting is not None:
        weighted = db_side.weighted_groups(args, weighting)
        files = {g: weighted[g] for g in (GIRTH, CENTER_OF_MASS) if g in weighted}
    gender = args.gender
    if gender is None and args.person is None and files:
        # A population of one gender (e.g. `sass population` over women) sizes that gender.
        held = set.intersection(*(set(data.sections) for data in files.values()))
        gender = held.pop() if len(held) == 1 else None
    session = Session(Figure.default(gender or "male"))
    warnings: list[str] = []
    for group, data in files.items():
        session.load_group(group, data)
        warnings += [w for w in data.warnings if w not in warnings]
    # The people's own stature and mass `sass population` wrote beside its girth file.
    stature_and_mass: PopulationData | None
    if weighted is not None:
        stature_and_mass = weighted.get(GLOBAL)
    elif args.global_file:
        stature_and_mass = read_population_file(args.global_file, GLOBAL)
    else:
        beside = read_global_beside(args.girth) if args.girth else None
        # a gender the girth file lacks is said by the girth's own error
        stature_and_mass = beside if beside and beside.has(session.figure.gender) else None
    if stature_and_mass is not None:
        session.load_global(stature_and_mass)
        warnings += [w for w in stature_and_mass.warnings if w not in warnings]
    for group, option in (
        (GIRTH, args.girth_percentile),
        (JOINT_LIMITS, args.joint_limit_percentile),
        (CENTER_OF_MASS, args.cmass_percentile),
    ):
        session.set_group_percentile(group, option if option is not None else args.percentile)
    if args.mass is not None:
        session.set_mass(parse_quantity(args.mass, "kg"))
    else:
        session.set_mass_percentile(args.mass_percentile or args.percentile)
    if args.stature is not None:
        session.set_stature(parse_quantity(args.stature, "cm"))
    else:
        session.set_stature_percentile(args.stature_percentile or args.percentile)
    session.set_figure_type(args.figure_type)
    # A warning is about a file the user named: the shipped girth.dat's misprints
    # are not news to one who passed only the shipped cmass.dat.
    named = {data.path for data in files.values()}
    if stature_and_mass is not None:
        named.add(stature_and_mass.path)
    warnings = [w for w in warnings if w.split(":", 1)[0] in named]
    for name, option, unit in (("mass", args.mass, "kg"), ("stature", args.stature, "cm")):
        outside = session.figure.implausible_range(name) if option is not None else None
        if outside is not None:  # as the spreadsheet says of a typed one
            warnings.append(
                f"--{name} {option}: outside the {session.figure.gender} population's "
                f"0.5th-99.5th percentile range, {outside[0]:.1f}-{outside[1]:.1f} {unit}; "
                "accepted"
            )
    if db_side is not None and args.person is not None:
        return db_side.person_figure(args, session.figure), warnings
    return session.figure, warnings
