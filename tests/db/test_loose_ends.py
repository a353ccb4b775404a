"""Small command-line promises: `--mix` with one gender completes the other,
`--version` prints to standard output, and no reader opens what is not a
regular file (a FIFO or /dev/zero would block or never end).  The mix runs on
both engines (tests/db/conftest.py); the readers' files are SQLite files."""

from __future__ import annotations

import json
import os

import pytest
from _built_once import copy_database_file
from hypothesis import assume, given
from hypothesis import strategies as st

from sass_tui.cli import main
from sass_tui.cli.fit import mix_argument
from sass_tui.db.populations.fit import FitError, check_mix


def test_one_gender_of_the_mix_leaves_the_rest_to_the_other():
    assert check_mix({"male": 0.8}) == pytest.approx({"male": 0.8, "female": 0.2})
    assert check_mix({"female": 0.25}) == pytest.approx({"female": 0.25, "male": 0.75})
    assert check_mix({"female": 1.0}) == {"female": 1.0}  # no rest: the women alone
    with pytest.raises(FitError, match=r"male=1.5 alone is a share from 0 to 1"):
        check_mix({"male": 1.5})


@given(st.floats(0, 1e308), st.floats(0, 1e308))
def test_a_mix_of_any_two_weights_is_their_shares(male, female):
    """The shares are the weights' proportions, whatever their size: 1e308
    and 1e308 added up to infinity, and the weighted share was printed '-'."""
    assume(max(male, female) > 0)
    shares = check_mix(mix_argument(f"male={male!r},female={female!r}"))
    assert sum(shares.values()) == pytest.approx(1.0)
    largest = max(male, female)
    assert shares["male"] * (female / largest) == pytest.approx(
        shares["female"] * (male / largest), abs=1e-12
    )


def test_a_gender_given_twice_in_the_mix_is_refused(capsys):
    with pytest.raises(SystemExit):
        main(["fit", "--mix", "male=1,male=2", "stature <= 190 cm"])
    # it said "male=2 alone is a share from 0 to 1"
    assert "argument --mix: 'male=2': male is given twice" in capsys.readouterr().err


def test_fit_mix_male_alone_is_male_and_female_together(shared_target, capsys):
    # on both engines (tests/db/conftest.py)
    limits = "stature <= 185 cm AND mass <= 100 kg"
    base = ["fit", "--db", shared_target, "--format", "json"]
    assert main([*base, "--mix", "male=0.8", limits]) == 0
    alone = json.loads(capsys.readouterr().out)
    assert main([*base, "--mix", "male=0.8,female=0.2", limits]) == 0
    both = json.loads(capsys.readouterr().out)
    assert alone == both
    assert alone["mix"] == pytest.approx({"male": 0.8, "female": 0.2})
    assert main([*base, "--mix", "female=2", limits]) == 2
    assert "a share from 0 to 1" in capsys.readouterr().err


def test_version_goes_to_standard_output(capsys):
    with pytest.raises(SystemExit) as done:
        main(["--version"])
    assert done.value.code == 0
    said = capsys.readouterr()
    assert said.out.startswith("sass ") and said.err == ""


@pytest.fixture()
def fifo(tmp_path):
    path = tmp_path / "pipe.dat"
    os.mkfifo(path)
    return str(path)


@pytest.mark.parametrize("special", ["/dev/zero", "fifo"])
@pytest.mark.parametrize(
    "argv",
    [
        ["fig", "-o", "{out}", "--girth", "{f}"],
        ["fig", "-o", "{out}", "--cmass", "{f}"],
        ["fig", "-o", "{out}", "--jntlmt", "{f}"],
        ["fig", "-o", "{out}", "--strength", "{f}"],
        ["db", "import-ansur", "--db", "{db}", "{f}"],
        [
            "db",
            "import-flat",
            "--db",
            "{db}",
            "--person",
            "{f}",
            "--girth",
            "{f}",
            "--jntlmt",
            "{f}",
            "--cmass",
            "{f}",
        ],  # fmt: skip
        ["predict", "--db", "{db}", "--gender", "male", "--input", "{f}", "--output", "{out}"],
        ["population", "--db", "{db}", "--ids", "{f}", "-o", "{out}"],
    ],
    ids=["girth", "cmass", "jntlmt", "strength", "import-ansur", "import-flat", "predict", "ids"],
)
def test_no_reader_opens_what_is_not_a_regular_file(
    argv, special, fifo, default_db_file, tmp_path, capsys
):
    name = fifo if special == "fifo" else special
    out = tmp_path / "out.x"
    db = tmp_path / "s.db"
    if argv[0] in ("predict", "population"):
        copy_database_file(default_db_file, db)
    args = [a.format(f=name, out=out, db=db) for a in argv]
    assert main(args) == 2
    said = capsys.readouterr().err
    assert "not a regular file" in said and name in said and "Traceback" not in said
    assert not out.exists()
