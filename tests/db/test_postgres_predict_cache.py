"""`sass predict` on PostgreSQL keeps its fit in the user's cache directory:
the second command loads it instead of fitting, an import (other people)
changes its key and the next command fits again, and the file's name comes
from the server, port, database and user, never the password.  The tests
run a throwaway cluster (tests/_postgres.py's `cluster` fixture)."""

from __future__ import annotations

import pytest

import sass_tui.db.populations.predict as predict_module
from sass_tui.cli import main
from sass_tui.db.engine.database import Database
from sass_tui.db.populations.predict import data_key, server_cache_path

PREDICT = ["predict", "--gender", "male", "--known", "stature=180cm", "--known", "mass=85kg"]


@pytest.fixture()
def private_cache(tmp_path, monkeypatch):
    """The user's cache directory (platformdirs reads $XDG_CACHE_HOME), here."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    return tmp_path / "cache" / "sass" / "predict"


@pytest.fixture()
def fits(monkeypatch) -> list[str]:
    """The keys of the fits made (db/populations/predict.py's fit_predictor, still run)."""
    made: list[str] = []
    fit = predict_module.fit_predictor

    def counted(conn, key="", population=predict_module.DEFAULT_POPULATION):
        made.append(key)
        return fit(conn, key, population)

    monkeypatch.setattr(predict_module, "fit_predictor", counted)
    return made


def key_of(url: str) -> str:
    db = Database.open(url)
    try:
        with db.connection() as conn:
            return data_key(conn)
    finally:
        db.close()


@pytest.mark.slow
def test_the_second_predict_loads_the_cache_and_an_import_refits(
    cluster, postgres_template, private_cache, fits, ansur_dir, capsys
):
    url = cluster.create_database("predict_cache", postgres_template)  # after `sass db init`
    url = url.replace("postgresql://sass@", "postgresql://sass:s3cret@")
    capsys.readouterr()
    before = key_of(url)

    assert main([*PREDICT, "--db", url]) == 0
    first = capsys.readouterr().out
    assert len(fits) == 1
    (cached,) = private_cache.iterdir()
    assert "s3cret" not in str(cached) and cached.name.endswith(".predict.npz")
    written = cached.stat().st_mtime_ns

    assert main([*PREDICT, "--db", url]) == 0
    assert capsys.readouterr().out == first  # the same numbers, from the cache
    assert len(fits) == 1 and cached.stat().st_mtime_ns == written

    # Other people: the key changes, the next command fits again on them.
    female = ansur_dir / "ANSUR_II_FEMALE_Public.csv"
    assert main(["db", "import-ansur", "--source", "desk", str(female), "--db", url]) == 0
    capsys.readouterr()
    assert key_of(url) != before
    assert main([*PREDICT, "--db", url]) == 0
    capsys.readouterr()
    assert len(fits) == 2 and fits[1] != fits[0]
    assert list(private_cache.iterdir()) == [cached]  # the same file, the new fit
    assert cached.stat().st_mtime_ns != written


def test_the_cache_file_is_named_without_the_password(cluster, private_cache):
    """Two passwords for one role and database: one cache file, whose name
    holds neither (the connection's own host, port, database and user)."""
    url = cluster.url()
    paths = set()
    for password in ("s3cret", "other"):
        db = Database.open(
            url.replace("postgresql://sass@", f"postgresql://sass:{password}@"), create=True
        )
        try:
            with db.connection() as conn:
                identity = conn.identity()
                paths.add(predict_module.cache_path(conn))
        finally:
            db.close()
        assert password not in identity and f":{cluster.port}/postgres" in identity
    (path,) = paths
    assert path == server_cache_path(identity) and path.parent == private_cache
    assert "s3cret" not in str(path) and "other" not in str(path)
    # Another database of the same server is another file.
    other = cluster.create_database("predict_other")
    db = Database.open(other, create=True)
    try:
        with db.connection() as conn:
            assert predict_module.cache_path(conn) != path
    finally:
        db.close()


def test_the_key_takes_any_finite_value_and_sees_a_change(cluster):
    """A flat file's girth may hold any finite number: the key's integer sums
    (db/engine/dialect.py's total) neither overflow on 1e200 nor miss an edit of
    0.1 mm."""
    import psycopg

    url = cluster.create_database("predict_key")
    Database.open(url, create=True).close()
    with psycopg.connect(url, autocommit=True) as raw:
        raw.execute(
            "INSERT INTO person (id_num, name, gender, stature, mass, source) "
            "VALUES (1, 'a', 'male', 180.0, 80.0, 'lab')"
        )
        raw.execute(
            "INSERT INTO girth (id_num, seg_name, thickness, width, length, mass) "
            "VALUES (1, 'head', 1e200, -1e200, 20.0, NULL)"
        )
    keys = [key_of(url), key_of(url)]
    assert keys[0] == keys[1]
    with psycopg.connect(url, autocommit=True) as raw:
        raw.execute("UPDATE girth SET length = 20.01")
    assert key_of(url) != keys[0]
