"""The query screen's sort (any column, either way, no value last) and jump
(to an id or a name) on the lists' TEMP tables, on both engines."""

from __future__ import annotations

import math

import pytest

from sass_tui.db.people.individual import person_record
from sass_tui.db.query.lists import QUERY_LIST, SELECTED_LIST, SORT_COLUMNS, QueryLists

QUERY = "gender = female AND stature > 170 cm"


def whole_list(lists: QueryLists, which: str, sort=None) -> list[dict]:
    rows, first = [], 0
    while page := lists.page(which, first, 50, sort):
        rows += page
        first += 50
    return rows


def key_of(value):
    return (value is None or (isinstance(value, float) and math.isnan(value)), value)


@pytest.mark.parametrize("column", sorted(SORT_COLUMNS))
def test_a_list_sorted_by_any_column_either_way(engine_db, column):
    lists = QueryLists(engine_db)
    total = lists.run(QUERY)
    assert total > 25
    unsorted = whole_list(lists, QUERY_LIST)
    for descending in (False, True):
        shown = whole_list(lists, QUERY_LIST, (column, descending))
        assert sorted(r["id"] for r in shown) == sorted(r["id"] for r in unsorted)
        present = [r[column] for r in shown if r[column] is not None]
        assert present == sorted(present, reverse=descending), column
        # People with no value come last, in the list's own order.
        missing = [r["id"] for r in shown if r[column] is None]
        assert [r["id"] for r in shown[len(present) :]] == missing == sorted(missing)


def test_the_tallest_first_is_the_tallest_of_the_list(engine_db):
    lists = QueryLists(engine_db)
    lists.run(QUERY)
    everyone = whole_list(lists, QUERY_LIST)
    tallest = max(r["stature"] for r in everyone)
    assert lists.page(QUERY_LIST, 0, 1, ("stature", True))[0]["stature"] == tallest


def test_jump_to_an_id_a_name_in_any_case_or_its_start(engine_db):
    lists = QueryLists(engine_db)
    lists.run(QUERY)
    sort = ("mass", False)
    shown = whole_list(lists, QUERY_LIST, sort)
    person = shown[37]
    assert lists.position(QUERY_LIST, str(person["id"]), sort) == 37
    assert lists.position(QUERY_LIST, person["name"].upper(), sort) == 37
    assert lists.position(QUERY_LIST, f"  {person['name'].lower()}  ", sort) == 37
    # The start of a name: the first person in the order shown whose name starts so.
    start = person["name"][:6]
    first = next(i for i, r in enumerate(shown) if r["name"].lower().startswith(start.lower()))
    assert lists.position(QUERY_LIST, start, sort) == first
    assert lists.position(QUERY_LIST, "nobody of that name", sort) is None
    assert lists.position(QUERY_LIST, "50%", sort) is None  # % is a character, not a wildcard
    assert lists.position(SELECTED_LIST, str(person["id"])) is None


def test_the_person_record_is_what_sass_person_shows(engine_db):
    lists = QueryLists(engine_db)
    lists.run(QUERY)
    person = lists.page(QUERY_LIST, 0, 1)[0]
    record = lists.person_record(person["id"])
    assert record == person_record(engine_db, person["id"])
    assert record["name"] == person["name"] and record["measures"]
