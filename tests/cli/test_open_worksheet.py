"""`sass --open FILE`: a file that is not a worksheet is refused in one line
naming the file and what was expected, before the TUI starts."""

from __future__ import annotations

from sass_tui.cli import main


def test_open_refuses_a_file_that_is_not_a_worksheet(tmp_path, capsys):
    path = tmp_path / "girth.dat"
    path.write_text("C a population file\nT MALE\n")
    assert main(["--open", str(path)]) == 2
    error = capsys.readouterr().err
    assert error == f"sass: error: {path}:1: not a sass worksheet (JSON: Expecting value)\n"


def test_open_refuses_a_missing_file(tmp_path, capsys):
    assert main(["--open", str(tmp_path / "none.json")]) == 2
    error = capsys.readouterr().err.strip()
    assert error.startswith("sass: error: ") and "none.json" in error
    assert "\n" not in error


def test_open_is_in_the_help(capsys):
    try:
        main(["--help"])
    except SystemExit:
        pass
    assert "--open FILE" in capsys.readouterr().out
