"""Every example of docs/query-language.md runs: each ```query block is
compiled and counted on both engines, each ```sh command is run through
`sass`, each ```text error is what sass says, and each count the page
states ("finds N people") is the database's and a direct count over the
published ANSUR II CSV's."""

from __future__ import annotations

import csv
import re
import shlex
from pathlib import Path

import pytest

from sass_tui.cli import main
from sass_tui.db.query.query import run_query
from sass_tui.db.query.query_grammar import GRAMMAR

DOC = Path(__file__).resolve().parents[2] / "docs" / "query-language.md"
FILES = {"male": "ANSUR_II_MALE_Public.csv", "female": "ANSUR_II_FEMALE_Public.csv"}
BLOCK = re.compile(r"```(\w+)\n(.*?)```(?:\n\nfinds (\d+) people)?", re.DOTALL)
SIX_FT_TWO_IN_MM = 74 * 25.4

# The same selections over the CSV, written from the survey's own columns
# (stature and sittingheight in mm, Age in years); a stated count without one
# here fails.
ORACLES = {
    "gender = female AND stature > 175 cm": lambda r: (
        r["gender"] == "female" and int(r["stature"]) > 1750
    ),
    "stature BETWEEN 160 cm AND 180 cm": lambda r: 1600 <= int(r["stature"]) <= 1800,
    "handedness = left": lambda r: r["WritingPreference"] == "Left hand",
    "stature > 6 ft 2 in": lambda r: int(r["stature"]) > SIX_FT_TWO_IN_MM,
    "NOT branch = 'Combat Arms'": lambda r: r["Branch"] != "Combat Arms",
    "gender = male AND NOT age BETWEEN 40 AND 60": lambda r: (
        r["gender"] == "male" and not 40 <= int(r["Age"]) <= 60
    ),
    "measure.sittingheight > 95 cm AND branch = 'Combat Arms'": lambda r: (
        int(r["sittingheight"]) > 950 and r["Branch"] == "Combat Arms"
    ),
}


def blocks(kind: str) -> list[tuple[str, int | None]]:
    found = []
    for match in BLOCK.finditer(DOC.read_text(encoding="utf-8")):
        if match.group(1) == kind:
            stated = match.group(3)
            found.append((match.group(2).strip(), None if stated is None else int(stated)))
    return found


QUERIES = blocks("query")


@pytest.fixture(scope="module")
def survey(ansur_dir) -> list[dict[str, str]]:
    rows = []
    for gender, name in FILES.items():
        with (ansur_dir / name).open(encoding="utf-8-sig", errors="replace") as handle:
            rows += [{**r, "gender": gender} for r in csv.DictReader(handle)]
    return rows


def test_the_page_has_its_examples():
    assert len(QUERIES) >= 10
    assert sum(stated is not None for _, stated in QUERIES) == len(ORACLES)


@pytest.mark.parametrize(("text", "stated"), QUERIES, ids=[q for q, _ in QUERIES])
def test_every_query_example_runs_and_its_count_is_the_csvs(engine_db, survey, text, stated):
    found = run_query(engine_db, text).count()
    if stated is None:
        return
    expected = sum(1 for row in survey if ORACLES[text](row))
    assert found == stated == expected


def test_every_command_example_runs(shared_target, capsys):
    commands = blocks("sh")
    errors = [text for text, _ in blocks("text") if text.startswith("sass query: error:")]
    assert commands and errors
    said_errors = []
    for command, _ in commands:
        argv = shlex.split(command)
        assert argv[0] == "sass"
        status = main([argv[1], "--db", shared_target, *argv[2:]])
        said = capsys.readouterr()
        if status:
            said_errors.append(said.err.splitlines()[0])
        else:
            assert said.out
    assert said_errors == errors


def test_the_field_count_the_page_states_is_sass_querys(capsys):
    assert main(["query", "--fields"]) == 0
    last = capsys.readouterr().out.splitlines()[-1]
    assert f"every field ({last.split()[0]} of them)" in DOC.read_text(encoding="utf-8")


def test_the_grammar_on_the_page_names_every_rule_of_the_parser():
    page = DOC.read_text(encoding="utf-8")
    for line in GRAMMAR.splitlines():
        rule = line.lstrip("?").split(":")[0].strip()
        if line[:1].isalpha() or line.startswith("?"):
            if rule.islower():
                assert f"\n{rule} " in page or f"\n{rule}:" in page, rule
