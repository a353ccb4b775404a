"""sass converts every unit by its table (model/units.py BASE_FACTORS), never
by pint: every unit it stores or shows is in the table, and a name outside it
is refused with a message."""

from __future__ import annotations

import pytest

from sass_tui.db.query import query
from sass_tui.model.units import BASE_FACTORS, DISPLAY, GROUP_UNITS, UnitError, convert


def test_every_unit_sass_stores_or_shows_is_in_the_table():
    stored = {unit for units in GROUP_UNITS.values() for unit in units}
    stored |= set(DISPLAY)
    stored |= {field[2] for field in query._GLOBAL_FIELDS.values() if field[2]}
    stored |= {unit for unit in query.MEASURE_UNITS.values() if unit}
    stored |= {group[2] for group in query._GROUPS.values() if group[2]}
    assert stored <= set(BASE_FACTORS), stored - set(BASE_FACTORS)


@pytest.mark.parametrize("pair", [("cm", "furlong"), ("furlong", "cm")])
def test_a_unit_outside_the_table_is_refused(pair):
    with pytest.raises(UnitError, match="unknown unit 'furlong'"):
        convert(1.0, *pair)
