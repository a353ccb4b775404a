"""`sass fig` warns about the files the user named, not about the shipped
ones it loaded by default: appendix L.1's rules tie a center-of-mass file to
the girth of its own population (both the report's, or both the user's)."""

from __future__ import annotations

import shutil
from statistics import NormalDist

from sass_tui.cli import main
from sass_tui.model import datasets


def test_a_shipped_file_passed_alone_warns_only_about_itself(tmp_path, capsys):
    cmass = datasets.path("cmass.dat")
    assert main(["fig", "--cmass", str(cmass), "-o", str(tmp_path / "A.fig")]) == 0
    err = capsys.readouterr().err
    assert f"{cmass}:44: Right Upper Leg z" in err  # the report's own misprint, in the file named
    assert "girth.dat" not in err.replace("(docs/model.md", "")


def test_a_copy_of_the_reports_girth_beside_the_shipped_center_of_mass_is_not_checked(
    tmp_path, capsys
):
    """The user's girth with the report's center of mass: two populations, so
    no L.1 warning naming datasets/cmass.dat, which the user did not pass."""
    mine = tmp_path / "mine.dat"
    shutil.copy(datasets.path("girth.dat"), mine)
    assert main(["fig", "--girth", str(mine), "-o", str(tmp_path / "B.fig")]) == 0
    err = capsys.readouterr().err
    assert "cmass.dat" not in err and "appendix L.1" not in err
    assert f"{mine}:45: Lower Torso z" in err  # its own cross-gender warning stays
    # both the user's: the rules apply again
    theirs = tmp_path / "theirs-cmass.dat"
    shutil.copy(datasets.path("cmass.dat"), theirs)
    main(["fig", "--girth", str(mine), "--cmass", str(theirs), "-o", str(tmp_path / "C.fig")])
    assert "appendix L.1's foot rule" in capsys.readouterr().err


def test_a_mass_or_stature_beyond_the_population_is_accepted_with_a_warning(tmp_path, capsys):
    """As the spreadsheet warns of a typed one (ui/spreadsheet/spreadsheet_edit.py): beyond
    the 0.5th-99.5th percentile of datasets/global.dat, each side of the 50th
    spread as its 5th or 95th says (male mass 62.6 / 82.2 / 107.6 kg)."""
    z = NormalDist().inv_cdf(0.995) / NormalDist().inv_cdf(0.95)
    low, high = 82.2 - (82.2 - 62.6) * z, 82.2 + (107.6 - 82.2) * z
    out = tmp_path / "heavy.fig"
    assert main(["fig", "--mass", "300", "-o", str(out)]) == 0
    err = capsys.readouterr().err
    assert err.count("warning:") == 1 and out.is_file()
    assert (
        f"--mass 300: outside the male population's 0.5th-99.5th percentile range, "
        f"{low:.1f}-{high:.1f} kg; accepted"
    ) in err
    assert main(["fig", "--mass", "80kg", "--stature", "175cm", "-o", str(out)]) == 0
    assert "warning" not in capsys.readouterr().err
    assert main(["export", "hanim", "--stature", "7ft", "-o", str(tmp_path / "tall.x3d")]) == 0
    assert "--stature 7ft: outside the male population's" in capsys.readouterr().err
