"""An import's rows reach PostgreSQL in COPY's binary format (db/engine/postgres.py
`copy_rows` with the columns' types): each double as its own 8 bytes, text
without COPY's escapes, NULL as NULL; a value its column cannot hold is a
DatabaseError naming the table and row, the transaction rolled back."""

from __future__ import annotations

import pytest

pytest.importorskip("psycopg")

from sass_tui.db.engine.postgres import PostgresConnection
from sass_tui.db.engine.schema import DatabaseError

TYPES = ["bigint", "text", "double precision", "bytea"]
ROWS = [
    (1, "tab\there", 0.1 + 0.2, b"\x00\\N"),
    (2**62, "back\\slash\nnew line", -1.2345678901234567e-300, None),
    (3, None, None, b""),
    (-4, "ümlaut \\N", float("inf"), b"\xff"),
]


@pytest.fixture()
def table(cluster, request):
    conn = PostgresConnection(
        cluster.create_database(f"binary_{request.node.name[-20:]}".lower()), read_only=False
    )
    conn.execute("CREATE TABLE sample (i BIGINT, s TEXT, x DOUBLE PRECISION, b BYTEA)")
    yield conn
    conn.close()


def test_every_value_arrives_as_it_was_sent(table):
    with table.transaction():
        assert table.copy_rows("sample", ["i", "s", "x", "b"], iter(ROWS), TYPES) == len(ROWS)
    stored = table.execute("SELECT i, s, x, b FROM sample ORDER BY i").fetchall()
    expected = sorted(ROWS, key=lambda row: row[0])
    assert [(i, s, x, None if b is None else bytes(b)) for i, s, x, b in stored] == expected
    assert dict((i, x) for i, _s, x, _b in stored)[1] == 0.30000000000000004  # not 0.3


def test_the_text_format_stores_the_same(table):
    with table.transaction():
        table.copy_rows("sample", ["i", "s", "x", "b"], iter(ROWS))
    stored = table.execute("SELECT i, s, x, b FROM sample ORDER BY i").fetchall()
    assert [(i, s, x, None if b is None else bytes(b)) for i, s, x, b in stored] == sorted(
        ROWS, key=lambda row: row[0]
    )


@pytest.mark.parametrize("bad", [(1.5, "a", 1.0, None), (1, "a", "not a number", None)])
def test_a_value_its_column_cannot_hold_is_a_database_error(table, bad):
    with pytest.raises(DatabaseError) as raised:
        with table.transaction():
            table.copy_rows("sample", ["i", "s", "x", "b"], iter([ROWS[0], bad]), TYPES)
    said = str(raised.value)
    assert "row 2 of sample" in said and "nothing was stored" in said
    assert table.execute("SELECT count(*) FROM sample").fetchone()[0] == 0
