"""Input DB takes an ANSUR II format file too (the "ANSUR import" of
the TUI): given as the Person file, it is recognised by its header, imported
under the source label asked for, with the progress bar, and Escape rolls it
back."""

from __future__ import annotations

import gzip

import pytest
from _screen import message, settle
from test_query_screen import open_query_screen
from test_work_progress import HeldWork, _answer, _state

from sass_tui.db.engine.schema import connect
from sass_tui.db.people.ansur import looks_like_ansur
from sass_tui.db.people.default_people import shipped_ansur_files
from sass_tui.ui.progress import WorkBar

SIZE = (120, 40)


def _female_survey() -> list[str]:
    female = next(p for p in shipped_ansur_files() if "FEMALE" in p.name)
    with gzip.open(female, "rt", encoding="utf-8") as stream:
        return stream.read().splitlines()


def _small_survey(path, people: int) -> list[int]:
    """The survey's header and its first `people` women, renumbered so they are
    new people; returns their ids."""
    header, *rows = _female_survey()
    ids = [900_000 + k for k in range(people)]
    lines = [header] + [f"{i}," + row.split(",", 1)[1] for i, row in zip(ids, rows)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return ids


def test_the_header_tells_a_survey_file_from_a_person_file(tmp_path):
    survey = tmp_path / "mine.csv"
    _small_survey(survey, 3)
    person = tmp_path / "person.dat"
    person.write_text("1 Jane female 60 165 right\n", encoding="utf-8")
    assert looks_like_ansur(survey)
    assert all(looks_like_ansur(p) for p in shipped_ansur_files())  # gzip, any case
    assert not looks_like_ansur(person)
    assert not looks_like_ansur(tmp_path / "missing.csv")


@pytest.mark.slow
def test_input_db_imports_an_ansur_file_under_the_label_asked_for(drive, app_at, db, tmp_path):
    survey = tmp_path / "fieldstudy.csv"
    ids = _small_survey(survey, 30)

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            await open_query_screen(pilot)
            await pilot.press("i")
            await _answer(pilot, survey)
            await settle(pilot)
            assert "ANSUR II format file. Source label [fieldstudy]:" in message(app)
            await pilot.press("enter")  # the file's name
            await settle(pilot)
            assert message(app) == "Loaded 30 people into the database."

    drive(scenario())
    with connect(db) as conn:
        stored = conn.execute(
            "SELECT name FROM person WHERE source = 'fieldstudy' ORDER BY id_num"
        ).fetchall()
    assert [row[0] for row in stored] == [f"fieldstudy F {i}" for i in ids]


@pytest.mark.slow
def test_escape_rolls_an_ansur_import_back(drive, app_at, db, tmp_path, monkeypatch):
    male = next(p for p in shipped_ansur_files() if "FEMALE" not in p.name)
    before = _state(db)
    held = HeldWork(monkeypatch, "ANSUR import")

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            bar = screen.query_one(WorkBar)
            await pilot.press("i")
            await _answer(pilot, male)
            await settle(pilot)
            await _answer(pilot, "men again")
            await held.until_shown(pilot, bar)
            done, total = held.reports[-1]
            assert 0 < done < total
            assert bar.text == f"ANSUR import {done:,}/{total:,}"
            await pilot.press("escape")
            held.gate.set()
            await settle(pilot)
            assert message(app) == "Input DB cancelled; the database is unchanged."

    drive(scenario())
    assert _state(db) == before
