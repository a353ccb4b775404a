"""A served session's file names (model/files/paths.py's `inside`): whatever is
typed, the path given back lies inside the working directory, or the name is
refused with a message saying why."""

from __future__ import annotations

import os

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.files.paths import PathError, inside, regular_file, user_path


@pytest.fixture
def workdir(tmp_path):
    work = tmp_path / "work"
    (work / "sub").mkdir(parents=True)
    (tmp_path / "outside").mkdir()
    (work / "out").symlink_to(tmp_path / "outside")
    (work / "sub" / "up").symlink_to("../..")  # a link back out, relative
    (work / "sub" / "here").symlink_to("..")  # a link that stays inside
    (work / "loop").symlink_to("loop")
    return work


def test_plain_names_land_inside(workdir):
    assert inside(workdir, "a.fig") == workdir.resolve() / "a.fig"
    assert inside(workdir, "sub/a.fig") == workdir.resolve() / "sub" / "a.fig"
    assert inside(workdir, "sub/here/a.fig") == workdir.resolve() / "a.fig"
    assert user_path("a.fig", workdir) == workdir.resolve() / "a.fig"
    assert user_path("a.fig") == type(workdir)("a.fig")  # no workdir: the user's own


@pytest.mark.parametrize(
    "name, why",
    [
        ("../x.fig", "'..' is refused"),
        ("sub/../../x.fig", "'..' is refused"),
        ("/tmp/x.fig", "not an absolute or ~ path"),
        ("~/x.fig", "not an absolute or ~ path"),
        ("~root/x.fig", "not an absolute or ~ path"),
        ("out/x.fig", "a symbolic link leads out of"),
        ("sub/up/x.fig", "a symbolic link leads out of"),
        ("loop/x.fig", "cannot follow its links"),
        ("  ", "no file name given"),
    ],
)
def test_names_that_would_leave_are_refused(workdir, name, why):
    with pytest.raises(PathError, match=why):
        inside(workdir, name)


def test_a_file_outside_is_not_read_through_a_link(workdir, tmp_path):
    (tmp_path / "outside" / "secret.dat").write_text("T MALE\n")
    with pytest.raises(PathError, match="leads out of"):
        regular_file("out/secret.dat", workdir)


NAME_PARTS = st.sampled_from(["a", "b.fig", "..", ".", "sub", "out", "up", "here", "~", ""])


@settings(max_examples=300, deadline=None)
@given(parts=st.lists(NAME_PARTS, min_size=1, max_size=6), lead=st.sampled_from(["", "/", "~"]))
def test_whatever_is_typed_stays_inside_or_is_refused(tmp_path_factory, parts, lead):
    work = tmp_path_factory.getbasetemp() / "inside-property" / "work"
    if not work.exists():
        (work / "sub").mkdir(parents=True)
        (work.parent / "outside").mkdir()
        (work / "out").symlink_to(work.parent / "outside")
        (work / "sub" / "up").symlink_to("../..")
        (work / "sub" / "here").symlink_to("..")
    name = lead + "/".join(parts)
    try:
        path = inside(work, name)
    except PathError as exc:
        assert str(exc)  # a message, never a traceback
        return
    root = work.resolve()
    assert os.path.commonpath([root, path]) == str(root), (name, path)
