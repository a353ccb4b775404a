"""Flat files (report figure 12) of many generated people: an Input DB that
takes a while, for the progress and cancel tests."""

from __future__ import annotations

from pathlib import Path

from sass_tui.db.engine.schema import GIRTH_NAMES
from sass_tui.db.people.flatfile import FlatFiles

FIRST_ID = 900_000


def write_big_flat_files(directory: Path, people: int = 3000) -> FlatFiles:
    """person.db and girth.db for `people` people (ids from FIRST_ID); the
    joint-limit and center-of-mass files Input DB asks for are empty."""
    directory.mkdir(parents=True, exist_ok=True)
    person = directory / "person.db"
    girth = directory / "girth.db"
    with person.open("w") as out:
        for k in range(people):
            gender = "male" if k % 2 else "female"
            out.write(
                f"{FIRST_ID + k},BIG_{k:06d},{gender},{160 + k % 30}.00,{60 + k % 40}.00,"
                f"right,{20 + k % 30}.00,generated for the progress tests\n"
            )
    with girth.open("w") as out:
        for k in range(people):
            for r, name in enumerate(GIRTH_NAMES):
                out.write(
                    f"{FIRST_ID + k},{name.upper()},{10 + r % 7}.5,{11 + k % 5}.25,20.0,1.0\n"
                )
    joint_limits = directory / "jntlmt.db"
    center_of_mass = directory / "cmass.db"
    joint_limits.write_text("")
    center_of_mass.write_text("")
    return FlatFiles(
        person=person, girth=girth, joint_limits=joint_limits, center_of_mass=center_of_mass
    )
