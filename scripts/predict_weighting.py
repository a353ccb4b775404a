"""What weighting would change in `sass predict --virtual nhanes-2017-2020`
(docs/target-populations.md, "Predicting from virtual people").

    python scripts/predict_weighting.py

Over the published NHANES 2017-March 2020 adults (20+, with a height and a
weight; ../shared/data/nhanes, read here, not through sass), per gender:
least squares of
- mass on stature: the one relation of the virtual people that is NHANES's
  own (every other measure is drawn from sass's regression on the soldiers,
  given stature and mass), predicted at the weighted 5th / 50th / 95th
  stature, unweighted and weighted by WTMECPRP;
- hip circumference (BMXHIP) on stature and mass, a measured relation,
  predicted at the weighted medians, both ways;
and Kish's effective sample size of the weights, the share of the sample a
weighted fit keeps.
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import numpy.typing as npt

ROOT = Path(__file__).resolve().parent.parent
PUBLISHED = ROOT.parent / "shared" / "data" / "nhanes" / "nhanes_p_demo_bmx_2020.csv"
GENDERS = (("female", "2"), ("male", "1"))

Array = npt.NDArray[np.float64]


def adults(code: str) -> dict[str, Array]:
    lines = [
        line
        for line in PUBLISHED.read_text(encoding="utf-8").splitlines()
        if not line.startswith("#")
    ]
    rows = [
        r
        for r in csv.DictReader(lines)
        if r["RIAGENDR"] == code
        and r["RIDAGEYR"] != "NA"
        and float(r["RIDAGEYR"]) >= 20
        and r["BMXHT"] != "NA"
        and r["BMXWT"] != "NA"
    ]
    return {
        c: np.array([np.nan if r[c] == "NA" else float(r[c]) for r in rows])
        for c in ("BMXHT", "BMXWT", "BMXHIP", "WTMECPRP")
    }


def least_squares(x: Array, y: Array, w: Array) -> Array:
    """Coefficients (intercept first) of y on the columns of x, weights w."""
    design = np.column_stack([np.ones(len(x)), x])
    root = np.sqrt(w)[:, None]
    coef, *_ = np.linalg.lstsq(design * root, y * root[:, 0], rcond=None)
    return np.asarray(coef, dtype=np.float64)


def weighted_quantile(v: Array, w: Array, q: float) -> float:
    order = np.argsort(v)
    share = np.cumsum(w[order]) / w.sum()
    return float(v[order][np.searchsorted(share, q)])


def main() -> None:
    for gender, code in GENDERS:
        d = adults(code)
        w = d["WTMECPRP"]
        kish = w.sum() ** 2 / (w**2).sum()
        print(
            f"{gender}: {len(w)} adults; Kish effective n {kish:.0f} ({100 * kish / len(w):.0f} %)"
        )
        ones = np.ones(len(w))
        flat = least_squares(d["BMXHT"], d["BMXWT"], ones)
        survey = least_squares(d["BMXHT"], d["BMXWT"], w)
        for q in (0.05, 0.50, 0.95):
            s = weighted_quantile(d["BMXHT"], w, q)
            a, b = flat[0] + flat[1] * s, survey[0] + survey[1] * s
            print(f"  mass at stature {s:.1f} cm: unweighted {a:.1f} kg, weighted {b:.1f} kg")
        keep = ~np.isnan(d["BMXHIP"])
        x = np.column_stack([d["BMXHT"], d["BMXWT"]])[keep]
        at = np.array([1.0, *(weighted_quantile(c, w[keep], 0.5) for c in x.T)])
        flat = least_squares(x, d["BMXHIP"][keep], ones[keep])
        survey = least_squares(x, d["BMXHIP"][keep], w[keep])
        print(
            f"  hip at the medians ({at[1]:.1f} cm, {at[2]:.1f} kg): unweighted "
            f"{at @ flat:.1f} cm, weighted {at @ survey:.1f} cm"
        )


if __name__ == "__main__":
    main()
