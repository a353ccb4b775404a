"""People imported from a flat file whose source says it is synthetic (the
shipped datasets/db files: "SYNTHETIC (not a real person): drawn by …") are
demonstration people, out of every answer about real people, on both
engines, as the default database's are (db/query/scope.py, `source_label`)."""

from __future__ import annotations

from pathlib import Path

import pytest

from sass_tui.cli import main
from sass_tui.db.query.scope import DEMONSTRATION_SOURCE, source_label

ROOT = Path(__file__).resolve().parents[2]
SHIPPED = ROOT / "datasets" / "db"


@pytest.mark.parametrize(
    ("text", "label"),
    [
        ("SYNTHETIC (not a real person): drawn by scripts/make_default_db.py", "synthetic"),
        ("synthetic", "synthetic"),
        ("Synthetic: a classroom example", "synthetic"),
        ("ANSUR II 2012", "ANSUR II 2012"),
        ("synthetic-aperture radar crew survey", "synthetic-aperture radar crew survey"),
        ("lab survey, synthetic fabrics", "lab survey, synthetic fabrics"),
    ],
)
def test_a_source_is_the_demonstration_label_only_when_it_starts_with_synthetic(text, label):
    assert source_label(text) == label


def _count(target: str, query: str, capsys) -> int:
    assert main(["query", "--count", "--db", target, query]) == 0
    return int(capsys.readouterr().out.split()[0])


def test_the_shipped_flat_files_reimported_stay_out_of_real_answers(engine_target, capsys):
    men = [line for line in (SHIPPED / "person.db").read_text().splitlines() if ",male," in line]
    real_men = _count(engine_target, "gender = male", capsys)
    args = ["db", "import-flat", "--db", engine_target]
    for option in ("person", "girth", "jntlmt", "cmass"):
        args += [f"--{option}", str(SHIPPED / f"{option}.db")]
    assert main(args) == 0
    capsys.readouterr()
    assert _count(engine_target, "gender = male", capsys) == real_men == 4082
    synthetic_men = f"gender = male AND source = {DEMONSTRATION_SOURCE}"
    assert _count(engine_target, synthetic_men, capsys) == len(men) == 100
