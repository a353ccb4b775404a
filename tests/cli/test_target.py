"""`sass target`: listing and dropping stored targets, and the options that
do not go together."""

from __future__ import annotations

import gzip

from sass_tui.cli import main, target_change
from sass_tui.db.populations.targets import SHIPPED


def test_a_new_database_lists_only_the_shipped_target_and_virtual_population(people_db, capsys):
    """`sass db init` made them: listed as stored, not as made on first use."""
    assert main(["--db", str(people_db), "target", "--list"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert [line.split()[0] for line in lines] == list(SHIPPED)
    assert "VIRTUAL population" in lines[1] and "first use" not in "".join(lines)


def test_dropping_a_target_that_is_not_stored_says_so(people_db, capsys):
    assert main(["--db", str(people_db), "target", "--drop", "nosuch"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("sass target: error:") and "nosuch" in err


def test_list_takes_no_other_argument(people_db, capsys):
    assert main(["--db", str(people_db), "target", "--list", "NAME"]) == 2
    assert "--list and --drop NAME take no other arguments" in capsys.readouterr().err


def test_a_sample_is_bounded_by_what_it_expands_to(people_db, tmp_path, monkeypatch, capsys):
    """A .csv.gz is read only as far as the largest sample: a 1 MB file held a
    1 GiB field.  (The bound made small here: the file need not be large.)"""
    monkeypatch.setattr(target_change, "LARGEST_PEOPLE_TABLE", 1000)
    bomb = tmp_path / "s.csv.gz"
    bomb.write_bytes(gzip.compress(b"stature,mass\n" + b"170,70\n" * 1000))
    plain = tmp_path / "s.csv"
    plain.write_bytes(b"stature,mass\n" + b"170,70\n" * 1000)
    for sample, says in ((bomb, "expands to more than"), (plain, "")):
        argv = ["--db", str(people_db), "target", "t", "--sample", str(sample), "--gender", "male"]
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert err.startswith("sass target: error:") and str(sample) in err and says in err
        assert len(err.splitlines()) == 1


def test_names_that_impersonate_a_virtual_population_are_refused(people_db, tmp_path, capsys):
    """`virtual:foo` named a target of real people that was then listed as
    VIRTUAL; `foo --virtual` replaced `virtual:foo` without --force."""
    sample = tmp_path / "s.csv"
    sample.write_text("stature,mass,gender\n170,70,male\n160,60,female\n")
    argv = ["--db", str(people_db), "target", "virtual:foo", "--sample", str(sample)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "'virtual:' begins the name of a virtual population" in err
    assert main(["--db", str(people_db), "target", "--list"]) == 0
    assert "virtual:foo" not in capsys.readouterr().out


def test_virtual_people_are_bounded_before_the_sample_is_read(
    people_db, tmp_path, monkeypatch, capsys
):
    monkeypatch.setattr(target_change, "MAX_VIRTUAL_PEOPLE", 2)
    sample = tmp_path / "s.csv"
    sample.write_text("stature,mass,gender\n170,70,male\n160,60,female\n\n165,65,female\n")
    argv = ["--db", str(people_db), "target", "foo", "--sample", str(sample), "--virtual"]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert f"{sample}: 3 rows; --virtual makes one person a row, at most 2" in err


def test_an_unknown_virtual_population_is_named_as_typed(people_db, capsys):
    """The `virtual:` prefix the user never typed stayed out of the message."""
    assert main(["--db", str(people_db), "stats", "--virtual", "nosuch"]) == 2
    err = capsys.readouterr().err
    assert (
        "no virtual population named 'nosuch'; the virtual populations are nhanes-2017-2020" in err
    )
    assert "virtual:" not in err
