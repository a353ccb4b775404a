"""A PostgreSQL server restarted under an open query screen: the next query
answers (the connection is opened again once, its lists made again), and a
server still gone is a message naming the address without its password.
The tests run a throwaway cluster (tests/_postgres.py's `cluster` fixture)."""

from __future__ import annotations

import pytest

from sass_tui.db.engine.schema import DatabaseError
from sass_tui.db.query.lists import QUERY_LIST, SELECTED_LIST, QueryLists

QUERY = "gender = female AND stature > 170 cm"


@pytest.fixture(scope="module")
def restarted_url(cluster, postgres_template) -> str:
    """A database after `sass db init`, with a password in its address (the
    throwaway cluster trusts every local connection and ignores it)."""
    url = cluster.create_database("restarted_lists", postgres_template)
    return url.replace("postgresql://sass@", "postgresql://sass:s3cret@")


@pytest.mark.slow
def test_the_first_query_after_a_restart_answers(cluster, restarted_url):
    lists = QueryLists.open(restarted_url)
    try:
        count, first = lists.run_first_page(QUERY, 25)
        assert count > 0 and len(first) == min(count, 25)
        lists.select_one(first[0]["id"])
        cluster.restart()
        # The query screen's Do Query: run and first page, in one transaction each.
        again, page = lists.run_first_page(QUERY, 25)
        # The selected person went with the old session: the query finds them again.
        assert again == count and page == first
        assert lists.count(SELECTED_LIST) == 0 and lists.page(SELECTED_LIST, 0, 5) == []
        # ... and the screen can say so, once.
        lost = lists.take_lost()
        assert lost is not None and "restarted" in lost
        assert f"the query list ({count - 1} people)" in lost
        assert "the selected list (1 person)" in lost
        assert lists.take_lost() is None
        lists.select_one(page[0]["id"])
        assert lists.count(SELECTED_LIST) == 1 and lists.count(QUERY_LIST) == count - 1
    finally:
        lists.close()


@pytest.mark.slow
def test_a_server_still_gone_is_a_message_without_the_password(cluster, restarted_url):
    lists = QueryLists.open(restarted_url)
    try:
        assert lists.run(QUERY) > 0
        cluster.stop()
        try:
            with pytest.raises(DatabaseError) as raised:
                lists.run_first_page(QUERY, 25)
        finally:
            cluster.start()
        message = str(raised.value)
        assert "s3cret" not in message and f"sass:***@127.0.0.1:{cluster.port}" in message
        assert "cannot reach the PostgreSQL server" in message
        # The server is back: the next query answers.
        assert lists.run(QUERY) > 0
    finally:
        lists.close()
