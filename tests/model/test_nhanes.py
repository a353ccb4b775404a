"""The shipped NHANES file (datasets/nhanes/, docs/data-sources.md) is what
scripts/make_nhanes.py makes from the published file, and holds the numbers
the CDC's file gives, read here straight from ../shared/data/nhanes/."""

from __future__ import annotations

import csv
import gzip
import io
import runpy

import numpy as np

from sass_tui.model import datasets
from tests._paths import NHANES_CSV, ROOT, nhanes_lines, shared_file


def published_rows() -> list[dict[str, str]]:
    lines = nhanes_lines()
    return list(csv.DictReader(lines))


def test_the_script_regenerates_the_shipped_file_byte_for_byte(tmp_path):
    script = runpy.run_path(str(ROOT / "scripts" / "make_nhanes.py"))
    script["main"]([str(shared_file(NHANES_CSV)), str(tmp_path / "out.csv.gz")])
    # The CSV inside, byte for byte: the compressed bytes depend on the zlib
    # Python was built with (3.11's and 3.13's differ here).
    made = gzip.decompress((tmp_path / "out.csv.gz").read_bytes())
    assert made == gzip.decompress(datasets.path(datasets.NHANES).read_bytes())


def test_the_shipped_file_holds_every_adult_with_the_published_values():
    shipped = list(csv.DictReader(io.StringIO(datasets.shipped_text(datasets.NHANES))))
    adults = [r for r in published_rows() if r["RIDAGEYR"] != "NA" and float(r["RIDAGEYR"]) >= 20]
    assert len(shipped) == len(adults) == 8544
    by_seqn = {r["SEQN"]: r for r in adults}
    for row in shipped:
        source = by_seqn[row["seqn"]]
        assert row["gender"] == {"1": "male", "2": "female"}[source["RIAGENDR"]]
        assert row["stature[cm]"] == ("" if source["BMXHT"] == "NA" else source["BMXHT"])
        assert row["mass[kg]"] == ("" if source["BMXWT"] == "NA" else source["BMXWT"])
        assert row["WTMECPRP"] == source["WTMECPRP"]
    assert len(datasets.path(datasets.NHANES).read_bytes()) < 2_000_000
    assert gzip.decompress(datasets.path(datasets.NHANES).read_bytes()).startswith(b"seqn,gender")


def test_weighted_mass_of_the_women_is_the_issues_figure():
    """73.7 kg at the 50th and 120.8 kg at the 95th (NHANES's own weights),
    by cumulative weight over the published file."""
    women = [
        r
        for r in published_rows()
        if r["RIAGENDR"] == "2"
        and r["RIDAGEYR"] != "NA"
        and float(r["RIDAGEYR"]) >= 20
        and r["BMXWT"] != "NA"
    ]
    mass = np.array([float(r["BMXWT"]) for r in women])
    weight = np.array([float(r["WTMECPRP"]) for r in women])
    order = np.argsort(mass)
    cumulative = np.cumsum(weight[order]) / weight.sum()
    p50, p95 = (mass[order][np.searchsorted(cumulative, q)] for q in (0.50, 0.95))
    assert (p50, p95) == (73.7, 120.8)
