"""The UI tests' apps: `app_at(size, db=True)` runs a SassApp at a terminal
size on a private copy of the shipped database; `new_app(...)` makes one for
`snap_compare`, which runs it itself."""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import AsyncIterator, Callable
from pathlib import Path

import pytest
import textual._wait
import textual.screen
from _built_once import copy_database_file
from textual._styles_cache import StylesCache
from textual.css.stylesheet import Stylesheet
from textual.filter import ANSIToTruecolor
from textual.pilot import Pilot
from textual.widgets import Input
from textual_canvas import Canvas

from sass_tui.model.body.figure import Figure
from sass_tui.ui.app import SassApp


@pytest.fixture(autouse=True, scope="session")
def quick_idle_check():
    """The Pilot waits after every key press and pause until the app is idle:
    it sleeps SLEEP_GRANULARITY (20 ms) at a time until a sleep passes with
    under 1 ms of CPU.  A key costs ~4 ms of CPU here, so the UI tests spent
    most of their time asleep: 50 keys typed into a prompt took 4.8 s, 2.2 s
    with 5 ms sleeps (load 11 on the 2 cores).  Still the same test of
    idleness, 1 ms of CPU in a sleep.  Textual's private module: setattr
    raises if the name moves, failing every UI test at once."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(textual._wait, "SLEEP_GRANULARITY", 1 / 200)
        yield


@pytest.fixture(autouse=True, scope="session")
def css_parsed_once():
    """Textual parses every widget class's DEFAULT_CSS and the app's .tcss
    files again for each app (its cache, Stylesheet._parse_cache, lives and
    dies with the app's stylesheet), and the UI tests start hundreds of apps:
    the same text with the same theme variables gives the same rules, so the
    test process parses each once.  A SassApp started, given five keys and
    closed: 0.128 s of CPU instead of 0.141 s (20 apps, three runs each way,
    at few_frames' rate).  The rules are read, never
    changed, once parsed (Textual's own cache hands the same list out again).
    Textual's private method: setattr raises if the name moves."""
    parse_rules = Stylesheet._parse_rules
    parsed: dict[tuple, list] = {}

    def parsed_once(self, css, read_from, is_default_rules=False, tie_breaker=0, scope=""):
        key = (
            css,
            read_from,
            is_default_rules,
            tie_breaker,
            scope,
            tuple(sorted(self._variables.items())),
        )
        if key not in parsed:
            parsed[key] = parse_rules(self, css, read_from, is_default_rules, tie_breaker, scope)
        return parsed[key]

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(Stylesheet, "_parse_rules", parsed_once)
        yield


@pytest.fixture(autouse=True)
def no_widget_kept_by_a_cache():
    """Three caches keyed on the object their method is called on keep what
    an app drew alive after the app has closed: `StylesCache.get_inner_outer`
    (Textual: a widget's cache of drawn lines), `ANSIToTruecolor.truecolor_style`
    (Textual: an app's colour filter) and `Canvas._segment_of` (textual-canvas:
    the figure view's canvas, with its widget), up to 1,024, 1,024 and 128 of
    them.  A test process kept 160,000-185,000 objects of closed apps that
    way, and every full collection of the garbage collector went through them
    again.  Emptied after each test, 54,000-63,000 objects are left, and
    tests/ui with `-n 3` takes 104-105 s of CPU instead of 112-114 s.  An
    app's drawing is the same with a cold cache; the caches fill
    again as it draws.  Their private names: an attribute that moves raises,
    failing every UI test at once."""
    yield
    StylesCache.get_inner_outer.cache_clear()
    ANSIToTruecolor.truecolor_style.cache_clear()
    Canvas._segment_of.cache_clear()


# A frame every quarter second: see few_frames.
FRAME_PERIOD_S = 1 / 4


@pytest.fixture(autouse=True)
def few_frames(request, monkeypatch):
    """Textual draws a screen's changes up to 60 times a second
    (textual.screen.UPDATE_PERIOD, the screen's update timer), but in a test
    nobody looks at the frames in between: the Pilot draws the screen itself
    after each key press and pause (Pilot.pause calls the timer's
    `_on_timer_update`), and the tests read the app's state or that screen.
    At 4 frames a second, 70 UI tests run one after another took 28.3 s of CPU
    instead of 35.3 s (60 frames; 10 frames: 30.5 s).  The snapshot tests keep
    Textual's 60: pytest-textual-snapshot takes its picture one pause after the
    keys, and a footer recomposed by that pause is drawn only on the next
    frame (tests/ui/test_query_snapshots.py's More Menu lost its footer at 4).
    Textual's private module constant: setattr raises if the name moves."""
    if "snap_compare" not in request.fixturenames:
        monkeypatch.setattr(textual.screen, "UPDATE_PERIOD", FRAME_PERIOD_S)


@pytest.fixture(autouse=True)
def no_cursor_blink(monkeypatch):
    """A steady cursor: snapshots must not depend on when the blink timer fired."""
    monkeypatch.setattr(Input.__dict__["cursor_blink"], "_default", False)


@pytest.fixture(autouse=True)
def own_config_dir(tmp_path_factory, monkeypatch):
    """Never the user's remembered theme (snapshots), nor write to it."""
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path_factory.mktemp("config")))


@pytest.fixture
def drive():
    """Run an async Pilot scenario from a plain test (no asyncio plugin needed)."""
    return asyncio.run


@pytest.fixture
def db(shipped_db_file, tmp_path):
    """A private copy: Input DB and the lists must not leak between tests."""
    path = tmp_path / "sass.db"
    copy_database_file(shipped_db_file, path)
    return path


@pytest.fixture
def new_app(request) -> Callable[..., SassApp]:
    """`new_app(figure=None, db=False, strength_path=None)`: a SassApp as `sass`
    makes it.  `db=True`: on this test's private copy of the shipped database
    (the `db` fixture, copied only when asked for); a path or a PostgreSQL
    address: that database;
    False: the session's default database ($SASS_DB, tests/conftest.py), for
    tests that never open the query screen."""

    def make(
        figure: Figure | None = None,
        *,
        db: bool | Path | str = False,
        strength_path: Path | None = None,
    ) -> SassApp:
        db_path = request.getfixturevalue("db") if db is True else (db or None)
        return SassApp(figure, db_path=db_path, strength_path=strength_path)

    return make


@pytest.fixture
def app_at(new_app):
    """`async with app_at((80, 24), db=True) as (app, pilot):` the app running
    headless at that terminal size (`new_app`'s arguments after the size)."""

    @contextlib.asynccontextmanager
    async def run(size: tuple[int, int], *args, **kwargs) -> AsyncIterator[tuple[SassApp, Pilot]]:
        app = new_app(*args, **kwargs)
        async with app.run_test(size=size) as pilot:
            yield app, pilot

    return run
