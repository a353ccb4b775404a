"""`sass population`: the population files of the people a query selects,
their statures the 5th/50th/95th percentiles of the ANSUR II CSV read directly."""

from __future__ import annotations

import re

import numpy as np

from sass_tui.cli import main
from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.names import CENTER_OF_MASS, GIRTH


def test_the_womens_files_carry_their_own_stature_percentiles(
    people_db, ansur_stature_cm, tmp_path, capsys
):
    out = tmp_path / "F.dat"
    argv = ["--db", str(people_db), "population", "--query", "gender = female", "-o", str(out)]
    assert main(argv) == 0
    assert "from 1986 women selected by: gender = female" in capsys.readouterr().out
    assert (tmp_path / "F-cmass.dat").is_file()
    text = out.read_text(encoding="utf-8")
    # The comment says which statures scaled the cells the people lack.
    found = re.search(r"the people's stature ([\d.]+)/([\d.]+)/([\d.]+) cm", text)
    assert found, text[:500]
    expected = np.percentile(ansur_stature_cm["female"], [5, 50, 95])
    assert np.allclose([float(v) for v in found.groups()], expected, atol=0.051)
    # The files read back as population files (report figure 7) of women.
    assert list(read_population_file(out, GIRTH).sections) == ["female"]
    assert list(read_population_file(tmp_path / "F-cmass.dat", CENTER_OF_MASS).sections) == [
        "female"
    ]


def test_a_query_that_selects_nobody_writes_nothing(people_db, tmp_path, capsys):
    out = tmp_path / "N.dat"
    argv = ["--db", str(people_db), "population", "--query", "stature > 300 cm", "-o", str(out)]
    assert main(argv) == 2
    assert capsys.readouterr().err.startswith("sass population: error:")
    assert list(tmp_path.glob("N*")) == []
