"""The 93 measurements of the ANSUR II public survey (Gordon et al. 2014).

Names are the survey's own column names, lower case.  The published files
give lengths in mm, `weightkg` in 0.1 kg and `interpupillarybreadth` in
0.1 mm; sass stores and shows every one in its canonical unit (cm or kg).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Final

MEASURES: Final[tuple[str, ...]] = (
    "abdominalextensiondepthsitting",
    "acromialheight",
    "acromionradialelength",
    "anklecircumference",
    "axillaheight",
    "balloffootcircumference",
    "balloffootlength",
    "biacromialbreadth",
    "bicepscircumferenceflexed",
    "bicristalbreadth",
    "bideltoidbreadth",
    "bimalleolarbreadth",
    "bitragionchinarc",
    "bitragionsubmandibulararc",
    "bizygomaticbreadth",
    "buttockcircumference",
    "buttockdepth",
    "buttockheight",
    "buttockkneelength",
    "buttockpopliteallength",
    "calfcircumference",
    "cervicaleheight",
    "chestbreadth",
    "chestcircumference",
    "chestdepth",
    "chestheight",
    "crotchheight",
    "crotchlengthomphalion",
    "crotchlengthposterioromphalion",
    "earbreadth",
    "earlength",
    "earprotrusion",
    "elbowrestheight",
    "eyeheightsitting",
    "footbreadthhorizontal",
    "footlength",
    "forearmcenterofgriplength",
    "forearmcircumferenceflexed",
    "forearmforearmbreadth",
    "forearmhandlength",
    "functionalleglength",
    "handbreadth",
    "handcircumference",
    "handlength",
    "headbreadth",
    "headcircumference",
    "headlength",
    "heelanklecircumference",
    "heelbreadth",
    "hipbreadth",
    "hipbreadthsitting",
    "iliocristaleheight",
    "interpupillarybreadth",
    "interscyei",
    "interscyeii",
    "kneeheightmidpatella",
    "kneeheightsitting",
    "lateralfemoralepicondyleheight",
    "lateralmalleolusheight",
    "lowerthighcircumference",
    "mentonsellionlength",
    "neckcircumference",
    "neckcircumferencebase",
    "overheadfingertipreachsitting",
    "palmlength",
    "poplitealheight",
    "radialestylionlength",
    "shouldercircumference",
    "shoulderelbowlength",
    "shoulderlength",
    "sittingheight",
    "sleevelengthspinewrist",
    "sleeveoutseam",
    "span",
    "stature",
    "suprasternaleheight",
    "tenthribheight",
    "thighcircumference",
    "thighclearance",
    "thumbtipreach",
    "tibialheight",
    "tragiontopofhead",
    "trochanterionheight",
    "verticaltrunkcircumferenceusa",
    "waistbacklength",
    "waistbreadth",
    "waistcircumference",
    "waistdepth",
    "waistfrontlengthsitting",
    "waistheightomphalion",
    "weightkg",
    "wristcircumference",
    "wristheight",
)

# Canonical unit of each measurement.
MEASURE_UNITS: Final[dict[str, str]] = {
    name: ("kg" if name == "weightkg" else "cm") for name in MEASURES
}

# Multiply a value as published by this to get it in its canonical unit.
PUBLISHED_TO_CANONICAL: Final[dict[str, float]] = {
    name: {"weightkg": 0.1, "interpupillarybreadth": 0.01}.get(name, 0.1) for name in MEASURES
}


def suggest(name: str, limit: int = 3, names: Sequence[str] = MEASURES) -> list[str]:
    """The `names` (default: the measurements') close to `name`, for a "did
    you mean" after a typo."""
    # deferred: difflib — off sass query, sass query --count, sass person … (sass_tui/startup.py)
    import difflib

    return difflib.get_close_matches(name.lower(), names, n=limit, cutoff=0.6)
