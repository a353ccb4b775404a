"""The options that put the hands where a sass figure's posture puts them
(joint angles as `sass task` takes them, `--posture FILE`, `--percentile`,
`--person`), shared by `sass niosh` and `sass handling`, and the one way to
reach the code that poses the figure: cli/handling_people.py, which brings
numpy, the figure's humanoid and the db package that typed numbers go
without."""

from __future__ import annotations

import argparse
from types import ModuleType

from sass_tui.cli.common.options import add_db_option, file_name, percentile


def add_figure_hands_options(parser: argparse.ArgumentParser, lift_words: str) -> None:
    parser.add_argument(
        "angles",
        nargs="*",
        metavar="JOINT=ANGLE",
        help=f"a posture of the figure (as `sass task`): the hands' H "
        f"and V are taken from it ({lift_words})",
    )
    parser.add_argument(
        "--posture",
        metavar="FILE",
        type=file_name,
        help="a posture file (JSON joint centres, `sass task`'s)",
    )
    parser.add_argument(
        "--percentile",
        type=percentile,
        default=50.0,
        help="the figure's percentile for a posture (default 50)",
    )
    add_db_option(parser)


def from_figure(args: argparse.Namespace) -> bool:
    """Whether the hands come from a figure (a posture or a person is given)."""
    return bool(args.angles) or args.posture is not None or args.person is not None


def refuse_typed_hands(args: argparse.Namespace, error: type[Exception]) -> None:
    """With the hands taken from a figure, --h and --v typed as well are
    refused; a word that is no JOINT=ANGLE is named first, since it alone may
    have made a posture of the command (`--load 10 kg` leaves `kg` behind)."""
    typed = [option for option, value in (("--h", args.h), ("--v", args.v)) if value is not None]
    if typed:
        posed_people().parse_angles(args.angles)
        raise error(f"the posture gives H and V; leave out {', '.join(typed)}")


def posed_people() -> ModuleType:
    """cli/handling_people.py: a posture's figures and a population's weights."""
    # deferred: cli.handling_people (numpy, the figure, the db package) — off sass handling, sass niosh (sass_tui/startup.py)
    from sass_tui.cli import handling_people

    return handling_people
