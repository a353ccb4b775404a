"""`sass stats`'s arguments (cli/stats.py): the percentile list parser, and
bad input refused in one line before the database is read."""

from __future__ import annotations

import argparse

import pytest
from hypothesis import given
from hypothesis import strategies as st

from sass_tui.cli import main
from sass_tui.cli.stats import percentile_list


@given(
    st.lists(
        st.floats(min_value=0.01, max_value=99.99, allow_nan=False), min_size=1, max_size=8
    ).map(lambda xs: list(dict.fromkeys(round(x, 2) for x in xs)))
)
def test_a_percentile_list_reads_back(values):
    assert percentile_list(",".join(f"{v:g}" for v in values)) == tuple(values)


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("5,fifty", "'fifty': expected a percentile"),
        ("0,50", "'0': a percentile must be over 0 and under 100"),
        ("50,100", "'100': a percentile must be over 0 and under 100"),
        ("5,5", "'5' is listed twice"),
    ],
)
def test_a_bad_percentile_list(text, said):
    with pytest.raises(argparse.ArgumentTypeError, match=said):
        percentile_list(text)


@pytest.mark.parametrize(
    ("argv", "said"),
    [
        (["stats", "sittinghieght"], "unknown measurement 'sittinghieght'"),
        (["stats", "--target", "a", "--virtual", "b"], "give --target NAME or --virtual NAME"),
        (["stats", "--unit", "furlongs"], "--unit"),
        (["stats", "--unit", "deg"], "expected a unit of length (cm, mm, in) or mass"),
        (["stats", "--query", "stature >> 3"], "--query"),
    ],
)
def test_bad_input_is_one_line(shipped_db_file, capsys, argv, said):
    assert main(["--db", str(shipped_db_file), *argv]) != 0
    err = capsys.readouterr().err
    assert said in err and "Traceback" not in err
