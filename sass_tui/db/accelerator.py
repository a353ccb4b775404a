"""A column copy of the queried fields, for counting queries on millions of people.

SQLite answers a count by visiting, for each person, one row of every query
table the query names: on 5,000,000 people the report's sample query takes
2-4 s that way.  Here each queried column (`person.gender`,
`q_girth_right_upper_arm.z`, ...) is copied once into a numpy array aligned
on the sorted person ids, and a compiled query's WHERE clause is evaluated
over those arrays: tens of milliseconds at 5,000,000 people
(docs/performance.md, "Database at scale").

The SQLite file stays the store of record; the copy may never disagree with it:

- The copy is keyed on the data version the SQLite file carries in its
  header, the change counter that SQLite bumps on every committed write in
  rollback-journal mode, together with the file's size, modification time
  and inode.  The key is read, the copy checked (or built) and the query
  evaluated while one read transaction holds SQLite's shared lock, so no
  writer can commit in between.  Any other key means the copy is dropped and
  rebuilt from SQLite.
- Whatever this module cannot prove equal, SQLite answers: a database in WAL
  mode (its header counter does not move on every write), a connection with
  its own transaction open, a query whose SQL is not a plain AND / OR of
  `alias.column OP ?` comparisons over tables keyed one row per person, a
  column holding a value of another type than the one declared, a text
  column with a collation.  `count` then returns None.
- The WHERE clause has no NOT, so SQL's unknown (a comparison with NULL) can
  be read as false: AND / OR of true / false / unknown is true exactly when
  it is true with every unknown read as false.  NULL is NaN here (a REAL
  column cannot hold NaN in SQLite) and `!=` excludes it explicitly.

Only databases with at least MIN_PEOPLE people use the copy (below that
SQLite is fast, and numpy need not be imported).  The copy lives in memory
for the process and on disk under $XDG_CACHE_HOME/sass/columns/ (one folder
per database file) for the next process.
"""

from __future__ import annotations

import os
import re
import sqlite3
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    from sass_tui.db.query import CompiledQuery

MIN_PEOPLE = 200_000
# A text column with more different values than this is left to SQLite.
MAX_WORDS = 200
# Where the copies live; None: $XDG_CACHE_HOME/sass/columns (~/.cache/sass/columns).
CACHE_DIR: Path | None = None

_COMPARISON = re.compile(r"([a-z_][a-z0-9_]*)\.([a-z_][a-z0-9_]*) (<=|>=|!=|<|>|=) \?")
_TOKEN = re.compile(r"\s*(?:(\()|(\))|(AND)\b|(OR)\b|" + _COMPARISON.pattern + ")")


class Unsupported(Exception):
    """The copy cannot answer this query or database provably alike: SQLite answers."""


# --- the WHERE clause ------------------------------------------------------


@dataclass(frozen=True)
class Comparison:
    table: str
    column: str
    op: str
    value: object


# A parsed WHERE: a Comparison, or ("AND" | "OR", [operands]).
Node = Any


def parse_where(where: str, params: tuple[object, ...], aliases: dict[str, str]) -> Node:
    """The compiled WHERE as a tree, or Unsupported for any other SQL."""
    tokens: list[tuple[str, Any]] = []
    pos = 0
    values = iter(params)
    while pos < len(where):
        if where[pos:].strip() == "":
            break
        m = _TOKEN.match(where, pos)
        if m is None:
            raise Unsupported(f"SQL not understood at {where[pos : pos + 20]!r}")
        pos = m.end()
        if m.group(1):
            tokens.append(("(", None))
        elif m.group(2):
            tokens.append((")", None))
        elif m.group(3):
            tokens.append(("AND", None))
        elif m.group(4):
            tokens.append(("OR", None))
        else:
            alias, column, op = m.group(5), m.group(6), m.group(7)
            if alias not in aliases:
                raise Unsupported(f"unknown alias {alias}")
            try:
                value = next(values)
            except StopIteration:
                raise Unsupported("fewer parameters than placeholders") from None
            tokens.append(("CMP", Comparison(aliases[alias], column, op, value)))
    if next(values, StopIteration) is not StopIteration:
        raise Unsupported("more parameters than placeholders")
    tree, rest = _expr(tokens, 0)
    if rest != len(tokens):
        raise Unsupported("trailing SQL")
    return tree


def _expr(tokens: list[tuple[str, Any]], i: int) -> tuple[Node, int]:
    return _chain(tokens, i, "OR", _term)


def _term(tokens: list[tuple[str, Any]], i: int) -> tuple[Node, int]:
    return _chain(tokens, i, "AND", _factor)


def _chain(tokens: list[tuple[str, Any]], i: int, word: str, operand: Any) -> tuple[Node, int]:
    first, i = operand(tokens, i)
    items = [first]
    while i < len(tokens) and tokens[i][0] == word:
        item, i = operand(tokens, i + 1)
        items.append(item)
    return (first if len(items) == 1 else (word, items)), i


def _factor(tokens: list[tuple[str, Any]], i: int) -> tuple[Node, int]:
    if i >= len(tokens):
        raise Unsupported("SQL ends early")
    kind, value = tokens[i]
    if kind == "CMP":
        return value, i + 1
    if kind == "(":
        node, i = _expr(tokens, i + 1)
        if i >= len(tokens) or tokens[i][0] != ")":
            raise Unsupported("unbalanced parentheses")
        return node, i + 1
    raise Unsupported(f"unexpected {kind}")


# --- the data version ------------------------------------------------------


def data_version(conn: sqlite3.Connection) -> tuple[int, ...]:
    """The key of the copy: header change counter, page count and schema cookie,
    with the file's size, mtime and inode.  Call inside a read transaction."""
    import struct

    path = database_path(conn)
    with open(path, "rb") as f:
        header = f.read(100)
        stat = os.fstat(f.fileno())
    if len(header) < 100 or not header.startswith(b"SQLite format 3\0"):
        raise Unsupported("no SQLite header")
    if header[18] != 1 or header[19] != 1:
        raise Unsupported("not in rollback-journal mode (WAL): the change counter may not move")
    counter, pages = struct.unpack(">II", header[24:32])
    (cookie,) = struct.unpack(">I", header[40:44])
    return (counter, pages, cookie, stat.st_size, stat.st_mtime_ns, stat.st_ino, stat.st_dev)


def database_path(conn: sqlite3.Connection) -> Path:
    for _seq, name, file in conn.execute("PRAGMA database_list"):
        if name == "main":
            if not file:
                raise Unsupported("an in-memory or temporary database")
            return Path(file)
    raise Unsupported("no main database")  # pragma: no cover - SQLite always has one


# --- the columns -----------------------------------------------------------


@dataclass
class TextColumn:
    codes: npt.NDArray[np.int32]  # index into words, -1 for NULL
    words: list[str]


class ColumnStore:
    """The copy of one database file at one data version."""

    def __init__(self, folder: Path, key: tuple[int, ...]):
        import hashlib
        import json
        import shutil

        # One folder per data version: files of two versions never mix.
        self.key = list(key)
        version = hashlib.sha256(json.dumps(self.key).encode()).hexdigest()[:16]
        self.folder = folder / version
        self.columns: dict[tuple[str, str], Any] = {}
        self.ids: npt.NDArray[np.int64] | None = None
        if not self.folder.exists():
            if folder.exists():  # copies of older versions are stale for good
                for old in folder.iterdir():
                    if old.name != version:
                        shutil.rmtree(old, ignore_errors=True)
            self.folder.mkdir(parents=True, exist_ok=True)
            _write_atomic(self.folder / "key.json", json.dumps(self.key).encode())

    def person_ids(self, conn: sqlite3.Connection) -> npt.NDArray[np.int64]:
        import numpy as np

        if self.ids is None:
            path = self.folder / "person.id_num.npy"
            ids = _load(path, np.int64, None)
            if ids is None:
                ids = _fetch_ints(conn, "SELECT id_num FROM person ORDER BY id_num")
                self._save(path, ids)
            self.ids = ids
        return self.ids

    def column(self, conn: sqlite3.Connection, table: str, column: str) -> Any:
        """The column as an array aligned on person_ids (a TextColumn for text):
        read from this version's folder if there (and whole), else built from SQLite."""
        import json

        import numpy as np

        key = (table, column)
        if key in self.columns:
            return self.columns[key]
        kind = _column_kind(conn, table, column)
        path = self.folder / f"{table}.{column}.npy"
        people = len(self.person_ids(conn))
        loaded: Any
        if kind == "real":
            loaded = _load(path, np.float64, people)
            if loaded is None:
                loaded = self._build_real(conn, table, column)
                self._save(path, loaded)
        else:
            words_path = self.folder / f"{table}.{column}.json"
            codes = _load(path, np.int32, people)
            try:
                words = json.loads(words_path.read_text()) if codes is not None else None
            except (OSError, ValueError):
                words = None
            if codes is not None and isinstance(words, list):
                loaded = TextColumn(codes, words)
            else:
                loaded = self._build_text(conn, table, column)
                self._save(path, loaded.codes)
                _write_atomic(words_path, json.dumps(loaded.words).encode())
        self.columns[key] = loaded
        return loaded

    def _positions(
        self, conn: sqlite3.Connection, ids: npt.NDArray[np.int64]
    ) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.bool_]]:
        """Where each id sits in the person ids, and which ids are people at all."""
        import numpy as np

        people = self.person_ids(conn)
        at = np.searchsorted(people, ids)
        at_clipped = np.minimum(at, len(people) - 1) if len(people) else at
        known = (at < len(people)) & (people[at_clipped] == ids) if len(people) else at < 0
        return at_clipped, known

    def _build_real(self, conn: sqlite3.Connection, table: str, column: str) -> Any:
        import numpy as np

        # Anything but a REAL value (text, a blob) becomes 'not real', which
        # float() refuses: such a column cannot be copied and SQLite answers.
        cursor = conn.execute(
            f"SELECT id_num, CASE typeof({column}) WHEN 'real' THEN {column} "
            f"ELSE 'not real' END FROM {table} WHERE {column} IS NOT NULL"
        )
        try:
            rows = _fetch_pairs(cursor, np.float64)
        except ValueError:
            raise Unsupported(f"{table}.{column} holds a value that is not REAL") from None
        out = np.full(len(self.person_ids(conn)), np.nan)
        at, known = self._positions(conn, rows["id"])
        out[at[known]] = rows["v"][known]
        return out

    def _build_text(self, conn: sqlite3.Connection, table: str, column: str) -> TextColumn:
        import numpy as np

        # The distinct words first, then each row's word number computed by
        # SQLite (a CASE over the words, with the column's own BINARY
        # comparison): no Python work per row.  A value that is not text
        # becomes -2 and refuses the copy.
        words = [
            w
            for (w,) in conn.execute(
                f"SELECT DISTINCT {column} FROM {table} WHERE typeof({column}) = 'text'"
            )
        ]
        if len(words) > MAX_WORDS:
            raise Unsupported(f"{table}.{column} has more than {MAX_WORDS} different values")
        cases = "".join(f" WHEN {column} = ? THEN {k}" for k in range(len(words)))
        cursor = conn.execute(
            f"SELECT id_num, CASE WHEN typeof({column}) <> 'text' THEN -2{cases} ELSE -3 END "
            f"FROM {table} WHERE {column} IS NOT NULL",
            words,
        )
        rows = _fetch_pairs(cursor, np.int32)
        if len(rows) and int(rows["v"].min()) < 0:
            raise Unsupported(f"{table}.{column} holds a value that is not TEXT")
        out = np.full(len(self.person_ids(conn)), -1, dtype=np.int32)
        at, known = self._positions(conn, rows["id"])
        out[at[known]] = rows["v"][known]
        return TextColumn(out, words)

    def _save(self, path: Path, array: Any) -> None:
        import numpy as np

        tmp = path.with_name(path.name + ".tmp.npy")
        np.save(tmp, array)
        os.replace(tmp, path)


def _load(path: Path, dtype: Any, length: int | None) -> Any:
    """A saved array of that type and length, or None (absent, damaged or other)."""
    import numpy as np

    try:
        array = np.load(path, mmap_mode="r")
    except (OSError, ValueError):
        return None
    if array.dtype != dtype or array.ndim != 1 or (length is not None and len(array) != length):
        return None
    return array


def _write_atomic(path: Path, data: bytes) -> None:
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_bytes(data)
    os.replace(tmp, path)


def _fetch_ints(conn: sqlite3.Connection, sql: str) -> Any:
    import numpy as np

    cursor = conn.execute(sql)
    chunks = []
    while rows := cursor.fetchmany(65536):
        chunks.append(np.fromiter((r[0] for r in rows), dtype=np.int64, count=len(rows)))
    return np.concatenate(chunks) if chunks else np.zeros(0, dtype=np.int64)


def _fetch_pairs(cursor: sqlite3.Cursor, value_type: Any) -> Any:
    import numpy as np

    dtype = np.dtype([("id", np.int64), ("v", value_type)])
    chunks = []
    while rows := cursor.fetchmany(65536):
        chunks.append(np.fromiter(rows, dtype=dtype, count=len(rows)))
    return np.concatenate(chunks) if chunks else np.zeros(0, dtype=dtype)


def _column_kind(conn: sqlite3.Connection, table: str, column: str) -> str:
    """'real' or 'text' from the declared type; Unsupported for anything else."""
    for _cid, name, declared, *_rest in conn.execute(f"PRAGMA table_info({table})"):
        if name == column:
            declared = declared.upper()
            if declared == "REAL":
                return "real"
            if declared == "TEXT":
                ddl = conn.execute(
                    "SELECT sql FROM sqlite_master WHERE type = 'table' AND name = ?", (table,)
                ).fetchone()[0]
                if "COLLATE" in ddl.upper():
                    raise Unsupported(f"{table} has a collation")
                return "text"
            raise Unsupported(f"{table}.{column} is declared {declared}")
    raise Unsupported(f"{table} has no column {column}")


def _one_row_per_person(conn: sqlite3.Connection, table: str) -> bool:
    """Whether id_num alone is the table's primary key (so the LEFT JOIN keeps one row a person)."""
    keys = [r[1] for r in conn.execute(f"PRAGMA table_info({table})") if r[5]]
    return keys == ["id_num"]


# --- evaluating --------------------------------------------------------------


def _evaluate(node: Node, store: ColumnStore, conn: sqlite3.Connection) -> Any:
    import numpy as np

    if not isinstance(node, Comparison):
        word, items = node
        result = _evaluate(items[0], store, conn)
        for item in items[1:]:
            other = _evaluate(item, store, conn)
            result = (result & other) if word == "AND" else (result | other)
        return result
    column = store.column(conn, node.table, node.column)
    op, value = node.op, node.value
    if isinstance(column, TextColumn):
        if not isinstance(value, str):
            raise Unsupported("a text column compared with a number")
        # SQLite's BINARY collation compares UTF-8 bytes: the order of code points.
        matches = np.array(
            [_compare(word, op, value) for word in column.words] + [False], dtype=bool
        )
        return matches[column.codes]  # code -1 (NULL) picks the final False
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise Unsupported("a number column compared with text")
    if isinstance(value, int) and abs(value) > 2**53:
        raise Unsupported("an integer a double cannot hold exactly")
    number = float(value)
    if op == "!=":
        return (column != number) & ~np.isnan(column)
    return {
        "<": np.less,
        ">": np.greater,
        "<=": np.less_equal,
        ">=": np.greater_equal,
        "=": np.equal,
    }[op](column, number)


def _compare(a: str, op: str, b: str) -> bool:
    if op == "=":
        return a == b
    if op == "!=":
        return a != b
    if op == "<":
        return a < b
    if op == ">":
        return a > b
    if op == "<=":
        return a <= b
    return a >= b


# --- the entry point ---------------------------------------------------------

_STORES: dict[Path, ColumnStore] = {}


def _cache_folder(path: Path) -> Path:
    import hashlib

    base = CACHE_DIR
    if base is None:
        xdg = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
        base = Path(xdg) / "sass" / "columns"
    digest = hashlib.sha256(str(path.resolve()).encode()).hexdigest()[:16]
    return base / digest


def _large_enough(conn: sqlite3.Connection) -> bool:
    # Two subqueries: SQLite reads a lone min() or max() off the B-tree's edge,
    # but scans the whole table for both in one SELECT.
    low, high = conn.execute(
        "SELECT (SELECT min(id_num) FROM person), (SELECT max(id_num) FROM person)"
    ).fetchone()
    return low is not None and high - low + 1 >= MIN_PEOPLE


def _matches(conn: sqlite3.Connection, compiled: CompiledQuery) -> tuple[Any, ColumnStore]:
    """The match mask over the sorted person ids (Unsupported: SQLite must
    answer).  Call inside a read transaction."""
    aliases = {"p": "person"} | {alias: table for alias, table in compiled.tables}
    expected = "person p" + "".join(
        f" LEFT JOIN {table} {alias} ON {alias}.id_num = p.id_num"
        for alias, table in compiled.tables
    )
    if compiled.from_clause() != expected:
        raise Unsupported("a join of another shape")
    for table in aliases.values():
        if table != "person" and not _one_row_per_person(conn, table):
            raise Unsupported(f"{table} is not one row per person")
    tree = parse_where(compiled.where, compiled.params, aliases)
    path = database_path(conn)
    key = data_version(conn)
    store = _STORES.get(path)
    if store is None or store.key != list(key):
        store = _STORES[path] = ColumnStore(_cache_folder(path), key)
    mask = _evaluate(tree, store, conn)
    return mask, store


def _answer(conn: sqlite3.Connection, compiled: CompiledQuery, ids: bool) -> Any:
    if conn.in_transaction or not _large_enough(conn):
        return None
    conn.execute("BEGIN")
    try:
        # The shared lock from this read holds off every writer until COMMIT.
        conn.execute("SELECT 1 FROM person LIMIT 1").fetchone()
        mask, store = _matches(conn, compiled)
        if ids:
            return store.person_ids(conn)[mask].tolist()
        return int(mask.sum())
    except (Unsupported, OSError, sqlite3.Error, ValueError):
        return None
    finally:
        conn.execute("COMMIT")


def count(conn: sqlite3.Connection, compiled: CompiledQuery) -> int | None:
    """How many people match, from the column copy; None when SQLite must answer."""
    result: int | None = _answer(conn, compiled, ids=False)
    return result


def ids(conn: sqlite3.Connection, compiled: CompiledQuery) -> list[int] | None:
    """The matching ids in ascending order, from the column copy; None when SQLite must answer."""
    result: list[int] | None = _answer(conn, compiled, ids=True)
    return result
