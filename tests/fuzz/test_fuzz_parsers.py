"""Fuzzing in the suite: every parser, a modest budget each.

Each input is a mutated seed file or random text (tests/fuzz/fuzz_targets.py);
the parser must return or raise SassError/OSError, never another exception.
A watchdog ends the run (with every thread's traceback) if one input takes
longer than WATCHDOG seconds: a hang fails the suite instead of stalling it.
scripts/fuzz.py runs the same targets for longer, each input in a worker
process under a time limit.
"""

from __future__ import annotations

import faulthandler
import random

import pytest
from _built_once import copy_database_file
from fuzz_targets import DATABASES, KNOWN_ELSEWHERE, TARGET_MAKERS, outcome, target
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

WATCHDOG = 60.0
# About 30 s for the whole folder on one core (flat and fig cost ~10 ms an input).
EXAMPLES = {"population": 100, "strength": 200, "fig": 120, "query": 200, "flat": 100,
            "ansur": 120, "units": 300, "ids": 300, "anderson2007": 150,
            "strength_limit": 300, "hfds2003": 150,
            "population_file": 40, "strength_file": 40, "ids_file": 40,
            # a colleague's worksheet and sample, a posture file, two verbs run whole:
            # ~300 each in CI, as docs/reliability.md says (about 8 s of CPU together,
            # with the default database's build)
            "worksheet": 300, "sample": 300, "arm_force": 300, "stats": 300, "task": 300}  # fmt: skip


@pytest.fixture(autouse=True, scope="module")
def _the_runs_default_database(shipped_db_file, tmp_path_factory):
    """The query target and the verbs read a copy of the run's default
    database rather than building their own (~2 s of CPU)."""
    copy = tmp_path_factory.mktemp("fuzz") / "sass.db"
    copy_database_file(shipped_db_file, copy)
    DATABASES.use_default_file(copy)


def check(name: str, value: object) -> str:
    faulthandler.dump_traceback_later(WATCHDOG, exit=True)
    try:
        return outcome(name, value)
    except KNOWN_ELSEWHERE.get(name, ()):
        return "known"
    finally:
        faulthandler.cancel_dump_traceback_later()


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(TARGET_MAKERS))
def test_every_parser_survives_its_fuzz_inputs(name):
    target(name)  # build the seeds (and for queries the database) outside the examples

    @settings(
        max_examples=EXAMPLES[name],
        deadline=None,
        derandomize=True,
        database=None,
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
    )
    @given(st.randoms(use_true_random=False))
    def run(rng: random.Random) -> None:
        check(name, target(name).generate(rng))

    run()


@pytest.mark.parametrize("name", sorted(TARGET_MAKERS))
def test_every_seed_parses(name):
    # The fuzzer starts from valid files: each seed must be accepted as it is.
    for seed in target(name).seeds:
        assert check(name, seed) == "ok", seed


@given(st.text(max_size=200))
@settings(max_examples=100, deadline=None, derandomize=True, database=None)
def test_arbitrary_text_in_every_text_parser(text):
    for name in ("population", "strength", "fig", "query", "ansur", "units"):
        check(name, text)


DIGITS = "1" * 200_000 + "x"
LONG_NUMBERS = {
    "population": f"C t\nT MALE\n{DIGITS} 1 1 1 1 1 1 1 1 /* Bottom head */\n",
    "strength": f"P t\nG MALE\nL RIGHT\n{DIGITS} 45 0 90 0 0 0 17 50 /* shoulder abduction */\n",
    "fig": f'botheadx = {DIGITS}cm;\nfigure ["body.fig"] ("skinny.a");\n',
    "query": f"stature > {DIGITS}",
    "units": DIGITS,
}


@pytest.mark.parametrize("name", sorted(LONG_NUMBERS))
def test_a_long_run_of_digits_does_not_stall_a_parser(name):
    # 200,000 digits then a letter: the number patterns backtracked through
    # every split of the digits (20 s at 20,000 digits in popfile.py, growing
    # with the square); the watchdog in check() ends a stalled run.
    assert check(name, LONG_NUMBERS[name]) == "error"
