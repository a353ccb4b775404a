"""Query DB on the query screen finds its people through the column copy
(db/query/accelerator.py) when the copy can answer: the same count and list as
SQLite, driven by key presses."""

from __future__ import annotations

import pytest
from _screen import message, settle
from test_query_screen import SIZE, choose, open_query_screen, summary

from sass_tui.db.engine.schema import connect
from sass_tui.db.query import accelerator, copy_file
from sass_tui.db.query.lists import QUERY_LIST
from sass_tui.db.query.query import compile_query
from sass_tui.ui.query.query_screen import COMPLETE

QUERY = "gender = female AND stature > 165 cm"


@pytest.mark.slow
def test_query_db_list_comes_from_the_column_copy(drive, app_at, db, monkeypatch, tmp_path):
    monkeypatch.setattr(accelerator, "MIN_PEOPLE", 0)  # the copy answers on any size
    monkeypatch.setattr(copy_file, "BACKGROUND", False)
    monkeypatch.setattr(copy_file, "CACHE_DIR", tmp_path / "columns")
    monkeypatch.setattr(copy_file, "OPEN_COPIES", {})
    answered = []
    answer = accelerator.answer_in_transaction
    monkeypatch.setattr(
        accelerator,
        "answer_in_transaction",
        lambda *a, **k: (lambda r: answered.append(r) or r)(answer(*a, **k)),
    )
    compiled = compile_query(QUERY)
    with connect(db) as conn:
        expected = [
            r[0]
            for r in conn.execute(
                f"SELECT p.id_num FROM {compiled.from_clause()} WHERE {compiled.where} "
                "ORDER BY p.id_num",
                compiled.params,
            )
        ]
    assert expected

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            await pilot.press("d", "b")
            await choose(pilot, "Global Information")
            await choose(pilot, "Gender")
            await choose(pilot, "Male")
            await pilot.press("e")  # the query as text on the message line
            # The text is offered selected: End keeps it, to edit its end.
            await pilot.press("end", *["backspace"] * 4, *QUERY[len("gender = ") :], "enter")
            await choose(pilot, "Done")
            await settle(pilot)
            assert message(app) == f"{COMPLETE} {len(expected)} people found."
            assert f"Total Data in Query List: {len(expected)}" in summary(app)
            listed = [row["id"] for row in screen.lists.page(QUERY_LIST, 0, len(expected) + 1)]
            assert listed == expected

    drive(scenario())
    assert answered and answered[-1] == expected  # the copy found them
