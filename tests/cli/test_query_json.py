"""`sass query --format json` streams: a chunk of rows at a time, the count
last, so its memory does not grow with the people listed (every row and the
whole text held at once took 224 MB at 200,000 people, against 43 MB for
CSV)."""

from __future__ import annotations

import contextlib
import io
import json
import tracemalloc

from sass_tui.cli import main


def _listed(argv: list[str], capsys) -> tuple[str, int]:
    """What `sass ARGV` printed, and the most memory Python held meanwhile."""
    tracemalloc.start()
    try:
        assert main(argv) == 0
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    return capsys.readouterr().out, peak


def test_json_lists_every_person_once_with_the_count(shipped_db_file, capsys):
    out, _ = _listed(
        ["--db", str(shipped_db_file), "query", "--format", "json", "mass > 0"], capsys
    )
    listed = json.loads(out)
    csv_out, _ = _listed(
        ["--db", str(shipped_db_file), "query", "--format", "csv", "mass > 0"], capsys
    )
    ids = [int(line.split(",", 1)[0]) for line in io.StringIO(csv_out).readlines()[1:]]
    assert listed["count"] == len(listed["persons"]) == len(ids) > 6000
    assert [p["id"] for p in listed["persons"]] == ids
    empty, _ = _listed(
        ["--db", str(shipped_db_file), "query", "--format", "json", "mass > 900 kg"], capsys
    )
    assert json.loads(empty) == {"persons": [], "count": 0}


def _peak_writing(db, query: str, listing) -> int:
    """The most memory Python held while `sass query --format json` wrote
    to a file (not captured in memory); the first run warms imports and caches."""
    argv = ["--db", str(db), "query", "--format", "json", query]
    for _ in range(2):
        with listing.open("w") as out, contextlib.redirect_stdout(out):
            tracemalloc.start()
            try:
                assert main(argv) == 0
                _, peak = tracemalloc.get_traced_memory()
            finally:
                tracemalloc.stop()
    return peak


def test_json_holds_a_chunk_of_people_not_all_of_them(shipped_db_file, tmp_path):
    """Three times the people, about the same memory: a chunk's worth (the
    whole listing held at once was over five times the text's size)."""
    listing = tmp_path / "people.json"
    women = _peak_writing(shipped_db_file, "gender = female", listing)
    assert 1900 < json.loads(listing.read_text())["count"] < 2100
    everyone = _peak_writing(shipped_db_file, "mass > 0", listing)
    size = listing.stat().st_size
    assert json.loads(listing.read_text())["count"] > 6000
    print(
        f"{size:,} bytes of JSON written holding at most {everyone:,} bytes ({women:,} for women)"
    )
    assert everyone < size
    assert everyone < 1.5 * women
