"""Screen snapshots of the anthropometric spreadsheet (pytest-textual-snapshot).

The terminal size is fixed and the answer line's cursor does not blink, so
the SVGs only change when the screen does.  Update them with
`pytest tests/ui/test_spreadsheet_snapshots.py --snapshot-update`.
"""

from __future__ import annotations

# Tall enough for the report's 25-row page.
SIZE = (100, 37)


def test_start_screen(snap_compare, new_app):
    assert snap_compare(new_app(), terminal_size=SIZE)


def test_start_screen_80x24(snap_compare, new_app):
    assert snap_compare(new_app(), terminal_size=(80, 24))


def test_joint_limits_page_2(snap_compare, new_app):
    assert snap_compare(new_app(), press=["j", "n"], terminal_size=SIZE)


def test_center_of_mass_in_inches(snap_compare, new_app):
    assert snap_compare(new_app(), press=["m", "c"], terminal_size=SIZE)


def test_error_message(snap_compare, new_app):
    # A length typed in degrees into a girth cell.
    assert snap_compare(new_app(), press=[*"12deg", "enter"], terminal_size=SIZE)
