"""`sass fig`: the body description file a command writes, named as the
report names them (section 5: MALE50.FIG, PBMALE50.FIG for the polybody)."""

from __future__ import annotations

import pytest

from sass_tui.cli import main
from sass_tui.model.files.fig_reader import read_fig


def test_the_default_names_are_the_reports(report_lines, tmp_path, monkeypatch, capsys):
    report = "\n".join(report_lines)
    monkeypatch.chdir(tmp_path)
    for argv, name in (
        ([], "MALE50.FIG"),
        (["--figure-type", "polybody"], "PBMALE50.FIG"),
    ):
        assert name in report  # the convention is the report's, not sass's invention
        assert main(["fig", *argv]) == 0
        assert capsys.readouterr().out.strip().endswith(f"wrote {name}")
        assert (tmp_path / name).is_file()


def test_a_percentile_and_a_stature_are_written_as_given(tmp_path, capsys):
    out = tmp_path / "TALL.fig"
    argv = ["fig", "--gender", "female", "--stature", "70 in", "--no-strength", "-o", str(out)]
    assert main(argv) == 0
    text = out.read_text(encoding="utf-8")
    # 70 in = 177.8 cm exactly (1 in = 2.54 cm), in the file's header comment.
    assert "; female; figure type skinny */" in text and "stature 177.8 cm (" in text
    assert read_fig(out).variables, "the file reads back"
    capsys.readouterr()


def test_an_option_out_of_range_is_refused(tmp_path, capsys):
    with pytest.raises(SystemExit) as stop:  # argparse's own error, status 2
        main(["fig", "--percentile", "100", "-o", str(tmp_path / "X.fig")])
    assert stop.value.code == 2
    assert "percentile" in capsys.readouterr().err
    assert not (tmp_path / "X.fig").exists()
