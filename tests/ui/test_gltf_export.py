"""Export glTF (t) on the spreadsheet (the figure shown) and on the query
screen (the person under the list's cursor), by key presses; the files read
back with pygltflib."""

from __future__ import annotations

import pytest
from _screen import message, settle
from textual import events

from sass_tui.db.engine.schema import connect
from sass_tui.db.people.individual import fetch_individual
from sass_tui.ui.query.query_popup import QueryPopup
from sass_tui.ui.query.query_screen import COMPLETE, QueryScreen

pygltflib = pytest.importorskip("pygltflib")

SIZE = (120, 40)


async def answer(pilot, text: str) -> None:
    pilot.app.screen.query_one("#answer").post_message(events.Paste(text))
    await pilot.pause()
    await pilot.press("enter")


def read_back(path):
    gltf = pygltflib.GLTF2().load(str(path))
    return gltf.scenes[0].extras, [gltf.nodes[j].name for j in gltf.skins[0].joints]


def test_spreadsheet_exports_the_figure_shown(app_at, drive, db, tmp_path):
    out = tmp_path / "body.glb"

    async def scenario():
        async with app_at(SIZE, db=db) as (app, pilot):
            await pilot.press("G")
            assert "glTF file name (.glb, or .gltf + .bin) [MALE50.glb]:" in message(app)
            await answer(pilot, str(out))
            assert "Pose: standing or seated [standing]:" in message(app)
            await pilot.press("s", "e", "a", "t", "e", "d", "enter")
            await settle(pilot)
            assert message(app) == f"Exported the seated glTF body to {out}."
            extras, joints = read_back(out)
            assert extras["pose"] == "seated" and extras["gender"] == "male"
            assert extras["mass"]["kg"] == pytest.approx(app.session.figure.mass, abs=0.01)
            assert len(joints) == 18 and joints[0] == "humanoid_root"
            # an existing file is kept unless the user says y
            before = out.read_bytes()
            await pilot.press("G")
            await answer(pilot, str(out))
            await pilot.press("enter")  # standing
            assert f"{out} exists. Overwrite? (y/N)" in message(app)
            await pilot.press("enter")
            assert message(app) == f"Not written; {out} kept as it was."
            assert out.read_bytes() == before
            # a name that is not glTF's is refused at once, nothing written
            await pilot.press("G")
            await answer(pilot, str(tmp_path / "body.obj"))
            assert "ends in .glb (binary) or .gltf" in message(app)
            assert sorted(p.name for p in tmp_path.iterdir()) == [
                "body.glb",
                "sass.db",
                "sass.db.predict.npz",
            ]

    drive(scenario())


@pytest.mark.slow
def test_query_screen_exports_the_highlighted_person(app_at, drive, db, tmp_path):
    out = tmp_path / "person.gltf"

    async def scenario():
        async with app_at(SIZE, db=db) as (app, pilot):
            await pilot.press("d")
            await settle(pilot)
            screen = app.screen
            assert isinstance(screen, QueryScreen)
            await pilot.press("G")
            assert message(app) == "The list is empty: no person to export."
            await pilot.press("d", "b")
            for label in ("Global Information", "Gender", "Female", "Done"):
                popup = app.screen.query_one(QueryPopup)
                options = popup.query_one("#popup-options")
                labels = [
                    str(options.get_option_at_index(i).prompt) for i in range(options.option_count)
                ]
                await pilot.press(*["down"] * labels.index(label), "enter")
            await settle(pilot)
            assert message(app).startswith(COMPLETE)
            await pilot.press("down")  # the second person of the list
            row = screen.sheet.highlighted
            await pilot.press("G")
            name = row["name"].replace(" ", "_")
            assert f"[{name}.glb]:" in message(app)
            await answer(pilot, str(out))
            await pilot.press("enter")
            await settle(pilot)
            bin_file = out.with_suffix(".bin")
            assert message(app) == f"Exported the standing glTF body to {out} and {bin_file}."
            extras, joints = read_back(out)
            with connect(db) as conn:
                person = fetch_individual(conn, row["id"])
            assert extras["person"] == person.name == row["name"]
            assert extras["gender"] == "female"
            assert extras["mass"]["kg"] == pytest.approx(person.mass, abs=0.01)
            assert len(joints) == 18

    drive(scenario())
