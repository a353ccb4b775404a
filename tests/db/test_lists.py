"""The query and selected lists (report §12.3.2) kept as TEMP tables."""

from __future__ import annotations

import pytest

from sass_tui.db.query.lists import QUERY_LIST, SELECTED_LIST, QueryLists
from sass_tui.db.query.query import QueryError, run_query

MALES = "gender = male"


def test_run_select_delete_and_a_new_query_keeps_the_selected(engine_db):
    lists = QueryLists(engine_db)
    males = run_query(engine_db, MALES).ids()
    assert lists.run(MALES) == len(males) == lists.count(QUERY_LIST)
    assert [r["id"] for r in lists.page(QUERY_LIST, 0, 25)] == males[:25]
    assert [r["id"] for r in lists.page(QUERY_LIST, 25, 25)] == males[25:50]
    assert lists.select_one(males[3]) and lists.select_one(males[0])
    assert not lists.select_one(males[3])  # already moved
    assert [r["id"] for r in lists.page(SELECTED_LIST, 0, 25)] == [males[3], males[0]]
    assert lists.selected_id(1) == males[0] and lists.selected_id(2) is None
    assert lists.delete_one(QUERY_LIST, males[1])
    assert lists.count(QUERY_LIST) == len(males) - 3
    # A new query replaces the query list; the selected people are not found again.
    stature = run_query(engine_db, "stature > 0").ids()
    assert lists.run("stature > 0") == len(stature) - 2
    assert lists.count(SELECTED_LIST) == 2
    moved = lists.select_all()
    assert moved == len(stature) - 2 and lists.count(QUERY_LIST) == 0
    assert lists.count(SELECTED_LIST) == len(stature)
    assert lists.selected_id(0) == males[3]  # selection order is kept


def test_a_bad_query_leaves_the_lists_as_they_were(engine_db):
    lists = QueryLists(engine_db)
    found = lists.run(MALES)
    with pytest.raises(QueryError, match="column"):
        lists.run("gender = maybe")
    assert lists.count(QUERY_LIST) == found and lists.last_query == MALES
    assert len(lists.page(QUERY_LIST, 0, 5)) == 5
