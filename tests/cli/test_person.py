"""`sass fig --person` and `sass export hanim --person` write a real person's
figure headless; impossible sizes are refused."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from sass_tui.cli import main
from sass_tui.model.body.figure import Figure, FigureError
from sass_tui.model.files.fig_reader import read_fig


def test_fig_person_by_name_and_by_id(person_db, tmp_path, monkeypatch, capsys):
    db, rows = person_db
    first = rows[0]
    name = f"ANSUR II F {first['SubjectId']}"
    monkeypatch.chdir(tmp_path)
    assert main(["fig", "--db", str(db), "--person", name.lower()]) == 0
    out = tmp_path / f"{name.replace(' ', '_')}.fig"
    fig = read_fig(out)
    text = out.read_text()
    assert f"/* {name}; female;" in text
    # ANSUR II stature is in mm, weight in 0.1 kg
    assert f"stature {float(first['stature']) / 10:.1f} cm" in text
    assert f"mass {float(first['weightkg']) / 10:.2f} kg" in text
    assert "not measured for" in text and "joint limits values" in text
    # the same person by database id
    capsys.readouterr()
    import sqlite3

    with sqlite3.connect(db) as conn:
        (person_id,) = conn.execute("SELECT id_num FROM person WHERE name = ?", (name,)).fetchone()
    assert main(["fig", "--db", str(db), "--person", str(person_id), "-o", "by_id.fig"]) == 0
    assert read_fig(tmp_path / "by_id.fig").variables == fig.variables
    assert main(["export", "hanim", "--db", str(db), "--person", name, "-o", "p.x3d"]) == 0
    root = ET.parse(tmp_path / "p.x3d").getroot()
    humanoid = root.find(".//HAnimHumanoid")
    assert humanoid.get("name") == name.replace(" ", "_")


def test_person_options_that_contradict_are_refused(person_db, tmp_path, capsys):
    db, _ = person_db
    out = tmp_path / "x.fig"
    assert main(["fig", "--db", str(db), "--person", "nobody at all", "-o", str(out)]) == 2
    assert "no person with id or name 'nobody at all'" in capsys.readouterr().err
    assert main(["fig", "--db", str(db), "--person", "1", "--stature", "170", "-o", str(out)]) == 2
    assert "--person takes the person's own --stature" in capsys.readouterr().err
    assert not out.exists()


@pytest.mark.parametrize("stature", ["2", "49.9", "301", "-170", "0"])
def test_impossible_statures_are_refused(tmp_path, capsys, stature):
    out = tmp_path / "x.fig"
    assert main(["fig", f"--stature={stature}", "-o", str(out)]) == 2
    assert "not a human one; expected 50-300 cm" in capsys.readouterr().err
    assert not out.exists()


def test_possible_statures_and_sizes():
    figure = Figure.default("male")
    for cm in (50.0, 300.0, 175.0):
        figure.set_stature(cm)
        assert figure.stature == cm
    with pytest.raises(FigureError, match="mass must be positive"):
        figure.set_mass(0)
    with pytest.raises(FigureError, match="a segment size must be positive, got -1 cm"):
        figure.set_value("girth", 4, 2, -1.0)
    with pytest.raises(FigureError, match="a segment size must be positive, got 0 cm"):
        figure.set_value("girth", 4, 2, 0.0)
    before = figure.groups["girth"].values.copy()
    figure.set_value("girth", 4, 2, 30.0)
    assert figure.groups["girth"].values[4, 2] == 30.0 != before[4, 2]
    # center of mass offsets may be negative or zero
    figure.set_value("center_of_mass", 2, 0, -3.0)
