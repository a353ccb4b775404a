"""Appendix L.1's center-of-mass rules are defined once (model/body/appendix_l.py)
and are the report's own: its formulas, read from the report's text here, give
the same numbers; no other module of sass writes their constants."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import sass_tui
from sass_tui.model.body import appendix_l, hanim
from sass_tui.model.body.appendix_l import foot_center, lower_leg_center, toes_implied
from sass_tui.model.files import popfile

PACKAGE = Path(sass_tui.__file__).parent


def test_the_rules_are_the_reports(report_lines):
    text = "\n".join(report_lines)
    foot = re.search(
        r"anklebone = \$([\d.]+) \* \(\\text\{footx\} \+ \\text\{toesx\}\) - ([\d.]+) \* ", text
    )
    leg = re.search(r"from knee = \$([\d.]+) \* \\text\{lowlegz\}", text)
    assert foot is not None and leg is not None
    fraction, heel = float(foot.group(1)), float(foot.group(2))
    # a 24 cm foot whose toes are 6 cm; a 40 cm lower leg
    assert foot_center(24.0, 6.0) == pytest.approx(fraction * (24 + 6) - heel * 24)
    assert toes_implied(foot_center(24.0, 6.0), 24.0) == pytest.approx(6.0)
    assert lower_leg_center(40.0) == pytest.approx(float(leg.group(1)) * 40)


def test_heel_behind_ankle_is_defined_once():
    """The HAnim/glTF foot and the population-file check share one constant."""
    assert hanim.HEEL_BEHIND_ANKLE is appendix_l.HEEL_BEHIND_ANKLE
    definitions = [
        f"{path.relative_to(PACKAGE)}:{n}"
        for path in sorted(PACKAGE.rglob("*.py"))
        for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
        if re.match(r"\s*(HEEL_BEHIND_ANKLE|FOOT_FRACTION|LOWER_LEG_FRACTION)\s*[:=]", line)
        or re.search(r"(?<![\d.])0\.2516(?!\d)", line.split("#", 1)[0])
    ]
    assert len(definitions) == 3 and all(
        d.startswith("model/body/appendix_l.py") for d in definitions
    ), definitions
    assert popfile.HEEL_BEHIND_ANKLE is appendix_l.HEEL_BEHIND_ANKLE
