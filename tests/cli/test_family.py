"""`sass family`: a manikin family over ANSUR II men, its center the men's
means computed from the CSV file directly."""

from __future__ import annotations

import csv
import json
import os

import numpy as np
import pytest

from sass_tui.cli import main


@pytest.mark.slow
def test_the_center_manikin_is_the_mens_mean(people_db, ansur_dir, tmp_path, capsys):
    out = tmp_path / "family"
    argv = ["--db", str(people_db), "family", "--gender", "male"]
    assert main([*argv, "--measures", "stature,mass", "-o", str(out)]) == 0
    capsys.readouterr()
    family = json.loads((out / "family.json").read_text(encoding="utf-8"))
    men = list(csv.DictReader((ansur_dir / "ANSUR_II_MALE_Public.csv").open(encoding="latin-1")))
    (center,) = (m for m in family["manikins"] if m["name"] == "center")
    assert center["values"]["stature"] == pytest.approx(
        np.mean([float(r["stature"]) for r in men]) / 10, abs=1e-3
    )  # mm in the CSV
    # fitted with log mass (the default space): the center is the geometric mean
    assert center["values"]["mass"] == pytest.approx(
        np.exp(np.mean([np.log(float(r["weightkg"]) / 10) for r in men])), abs=1e-3
    )  # the CSV's weightkg is in tenths of a kg
    assert family["space"] == "log mass"
    assert family["coverage"]["people"] == len(men)
    for manikin in family["manikins"]:
        assert all((out / name).is_file() for name in manikin["files"])


@pytest.mark.slow
def test_a_distributed_family_adds_an_inner_shell(people_db, tmp_path, capsys):
    names = {}
    for kind in ("boundary", "distributed"):
        out = tmp_path / kind
        argv = ["--db", str(people_db), "family", "--gender", "female", "--kind", kind]
        assert main([*argv, "--measures", "stature,mass", "-o", str(out)]) == 0
        family = json.loads((out / "family.json").read_text(encoding="utf-8"))
        names[kind] = {m["name"] for m in family["manikins"]}
    inner = names["distributed"] - names["boundary"]
    assert inner and all(name.endswith("_inner") for name in inner)
    assert {name.removesuffix("_inner") for name in inner} <= names["boundary"]
    capsys.readouterr()


@pytest.mark.parametrize(
    ("output", "says"),
    [("taken", "cannot write {out}: it is a file, not a directory"),
     ("taken/family", "cannot write {out}: not a directory: {taken}")],
)  # fmt: skip
def test_an_output_folder_a_file_stands_in_is_refused_by_name(
    people_db, tmp_path, capsys, output, says
):
    """mkdir's own words were "[Errno 17] File exists: 'taken'"."""
    taken = tmp_path / "taken"
    taken.write_text("a file the user keeps\n")
    out = tmp_path / output
    argv = ["--db", str(people_db), "family", "--gender", "female"]
    assert main([*argv, "--measures", "stature,mass", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert says.format(out=out, taken=taken) in err and "Errno" not in err, err
    assert taken.read_text() == "a file the user keeps\n"


def test_an_output_folder_a_fifo_stands_in_is_named_for_what_it_is(people_db, tmp_path, capsys):
    # it was called "a file"
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    argv = ["--db", str(people_db), "family", "--gender", "female", "--measures", "stature,mass"]
    assert main([*argv, "-o", str(fifo)]) == 2
    assert (
        f"cannot write {fifo}: it is a FIFO (named pipe), not a directory"
        in capsys.readouterr().err
    )
