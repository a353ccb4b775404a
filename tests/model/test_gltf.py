"""glTF 2.0 export (`sass export gltf`, model/files/gltf.py), checked from outside:
the Khronos glTF-Validator (npm `gltf-validator`, node/package.json), and the
files read back with pygltflib against the HAnim export of the same figure
and against the ANSUR II CSV."""

from __future__ import annotations

import csv
import json
import math
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from _built_once import copy_database_file
from _gltf_files import khronos_validator
from _paths import ROOT
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.cli import main

pygltflib = pytest.importorskip("pygltflib")

LOA1_JOINTS = 18  # ISO 19774-1, 4.8.5: the joints of LOA-1
PERCENTILES = [(g, p) for g in ("male", "female") for p in (1, 50, 99)]


@pytest.fixture(scope="module")
def validator():
    return khronos_validator()


@pytest.fixture(scope="module")
def people(tmp_path_factory, ansur_dir, shipped_db_file):
    """The default database (which holds ANSUR II) and ten of its people, five
    men and five women spread through the CSV files, with their CSV rows."""
    folder = tmp_path_factory.mktemp("gltf-people")
    db = folder / "sass.db"
    copy_database_file(shipped_db_file, db)  # what `sass db init` builds
    chosen = []
    for gender, letter in (("MALE", "M"), ("FEMALE", "F")):
        with open(ansur_dir / f"ANSUR_II_{gender}_Public.csv", encoding="latin-1") as handle:
            rows = [{k.lower(): v for k, v in row.items()} for row in csv.DictReader(handle)]
        for row in rows[:: len(rows) // 5][:5]:
            chosen.append((f"ANSUR II {letter} {row['subjectid']}", row))
    return db, chosen


def _export(tmp_path: Path, name: str, *options: str) -> Path:
    out = tmp_path / name
    assert main(["export", "gltf", "-o", str(out), *options]) == 0
    return out


def _figure_options(gender: str, percentile: float) -> list[str]:
    return ["--gender", gender, "--percentile", f"{percentile:g}"]


# --- an independent reader --------------------------------------------------------


class Read:
    """A glTF file read back with pygltflib; world transforms and skinning
    computed here from the spec (2.0, 3.5.3 and 3.7.3), not by sass."""

    def __init__(self, path: Path) -> None:
        self.gltf = pygltflib.GLTF2().load(str(path))
        if path.suffix == ".gltf":  # the buffer's file, named by a URI (spec 3.6.1.1)
            from urllib.parse import unquote

            self.blob = (path.parent / unquote(self.gltf.buffers[0].uri)).read_bytes()
        else:
            self.blob = self.gltf.binary_blob()
        self.names = [node.name for node in self.gltf.nodes]
        self.parent = {}
        for i, node in enumerate(self.gltf.nodes):
            for child in node.children or []:
                self.parent[child] = i

    def accessor(self, index: int) -> np.ndarray:
        acc = self.gltf.accessors[index]
        view = self.gltf.bufferViews[acc.bufferView]
        dtype = {5126: "<f4", 5121: "u1", 5123: "<u2", 5125: "<u4"}[acc.componentType]
        width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4, "MAT4": 16}[acc.type]
        start = (view.byteOffset or 0) + (acc.byteOffset or 0)
        data = np.frombuffer(self.blob, dtype, acc.count * width, start)
        return data.reshape(acc.count, width) if width > 1 else data

    def local(self, i: int, rotations: dict[int, np.ndarray] | None = None) -> np.ndarray:
        node = self.gltf.nodes[i]
        m = np.eye(4)
        x, y, z, w = node.rotation or [0, 0, 0, 1]
        if rotations and i in rotations:
            x, y, z, w = rotations[i]
        m[:3, :3] = [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
        m[:3, 3] = node.translation or [0, 0, 0]
        return m

    def world(self, i: int, rotations: dict[int, np.ndarray] | None = None) -> np.ndarray:
        m = self.local(i, rotations)
        while i in self.parent:
            i = self.parent[i]
            m = self.local(i, rotations) @ m
        return m

    def joint_positions(self) -> dict[str, np.ndarray]:
        skin = self.gltf.skins[0]
        return {self.names[j]: self.world(j)[:3, 3] for j in skin.joints}

    @property
    def primitive(self):
        return self.gltf.meshes[0].primitives[0]

    def positions(self) -> np.ndarray:
        return self.accessor(self.primitive.attributes.POSITION).astype(float)

    def skinned(self, rotations: dict[int, np.ndarray] | None = None) -> np.ndarray:
        """Linear blend skinning (spec 3.7.3.3) with the nodes' transforms."""
        skin = self.gltf.skins[0]
        ibm = self.accessor(skin.inverseBindMatrices).reshape(-1, 4, 4).transpose(0, 2, 1)
        joint_matrices = np.array(
            [self.world(j, rotations) @ ibm[k] for k, j in enumerate(skin.joints)]
        )
        p = self.positions()
        homogeneous = np.hstack([p, np.ones((len(p), 1))])
        joints = self.accessor(self.primitive.attributes.JOINTS_0)
        weights = self.accessor(self.primitive.attributes.WEIGHTS_0).astype(float)
        out = np.zeros_like(homogeneous)
        for slot in range(4):
            moved = np.einsum("nij,nj->ni", joint_matrices[joints[:, slot]], homogeneous)
            out += weights[:, slot, None] * moved
        return out[:, :3]

    def segment_masses(self) -> dict[str, float]:
        return {
            node.extras["segment"]: node.extras["mass"]
            for node in self.gltf.nodes
            if node.extras and node.extras.get("hanim") == "joint"
        }

    @property
    def figure(self) -> dict:
        return self.gltf.scenes[0].extras


def _hanim_centers(path: Path) -> dict[str, np.ndarray]:
    """Joint centres of an X3D HAnim humanoid, read from the XML."""
    root = ET.parse(path).getroot()
    return {
        joint.get("name"): np.array([float(v) for v in joint.get("center").split()])
        for joint in root.iter("HAnimJoint")
        if joint.get("name")
    }


# --- the validator ----------------------------------------------------------------


def test_percentile_figures_pass_the_khronos_validator(tmp_path, validator):
    files = [_export(tmp_path, f"{g}{p}.glb", *_figure_options(g, p)) for g, p in PERCENTILES]
    files.append(_export(tmp_path, "male50.gltf", "--gender", "male"))
    files.append(_export(tmp_path, "seated.glb", "--gender", "female", "--pose", "seated"))
    reports = validator(files)
    assert len(reports) == len(files)
    for report in reports:
        assert (report["numErrors"], report["numWarnings"]) == (0, 0), report


@pytest.mark.slow
def test_ansur_people_pass_the_validator_and_match_their_hanim_export(tmp_path, validator, people):
    """Ten ANSUR II people: 0 errors and 0 warnings; read back, the mesh is
    the person's stature tall (CSV, mm) within 5 mm, the body the person's
    mass (CSV), and every joint where the HAnim export of the same person
    puts it, within 1 mm."""
    db, chosen = people
    files = []
    for name, row in chosen:
        stem = name.replace(" ", "_")
        glb = _export(tmp_path, f"{stem}.glb", "--db", str(db), "--person", name)
        x3d = tmp_path / f"{stem}.x3d"
        assert main(["export", "hanim", "--db", str(db), "--person", name, "-o", str(x3d)]) == 0
        files.append(glb)
        read = Read(glb)
        p = read.positions()
        assert abs(p[:, 1].max() - p[:, 1].min() - float(row["stature"]) / 1000) <= 0.005
        assert sum(read.segment_masses().values()) == pytest.approx(
            float(row["weightkg"]) / 10, abs=0.01
        )
        hanim = _hanim_centers(x3d)
        joints = read.joint_positions()
        assert sorted(joints) == sorted(hanim)
        for joint, centre in hanim.items():
            assert np.abs(joints[joint] - centre).max() <= 0.001, (name, joint)
        assert read.figure["person"] == name
    for report in validator(files):
        assert (report["numErrors"], report["numWarnings"]) == (0, 0), report


# --- read back --------------------------------------------------------------------


@pytest.fixture(scope="module")
def male50(tmp_path_factory):
    out = tmp_path_factory.mktemp("gltf") / "male50.glb"
    assert main(["export", "gltf", "-o", str(out)]) == 0
    x3d = out.with_suffix(".x3d")
    assert main(["export", "hanim", "-o", str(x3d)]) == 0
    return Read(out), x3d


def test_skeleton_is_the_hanim_loa1_joints_at_the_hanim_centres(male50):
    read, x3d = male50
    hanim = _hanim_centers(x3d)
    skin = read.gltf.skins[0]
    assert len(skin.joints) == LOA1_JOINTS == len(hanim)
    assert [read.names[j] for j in skin.joints] == list(hanim)  # the X3D's order
    for joint, centre in read.joint_positions().items():
        assert np.abs(centre - hanim[joint]).max() <= 0.001
    # the skinned mesh node is a root of the scene (spec 3.7.3: its own
    # transform is not used), the skeleton's root the other one
    scene = read.gltf.scenes[0]
    assert [read.names[i] for i in scene.nodes] == ["humanoid_root", "male_50_body"]


def test_sites_are_empty_nodes_at_the_hanim_sites(male50):
    read, x3d = male50
    root = ET.parse(x3d).getroot()
    sites = {
        s.get("name"): np.array([float(v) for v in s.get("translation").split()])
        for s in root.iter("HAnimSite")
        if s.get("name")
    }
    assert len(sites) == 10
    for name, where in sites.items():
        i = read.names.index(name)
        node = read.gltf.nodes[i]
        assert node.mesh is None and not node.children
        assert np.abs(read.world(i)[:3, 3] - where).max() <= 0.001, name


def test_mesh_is_the_stature_tall_standing_on_the_floor(male50):
    read, _ = male50
    from sass_tui.model.body.figure import Figure

    stature = Figure.default("male").stature / 100
    p = read.positions()
    assert p[:, 1].min() == pytest.approx(0.0, abs=0.001)
    assert p[:, 1].max() == pytest.approx(stature, abs=0.005)
    assert read.figure["stature"]["m"] == pytest.approx(stature, abs=0.0005)
    # the bind pose is the rest pose: skinning with the nodes moves nothing
    assert np.abs(read.skinned() - p).max() < 1e-5
    # +Z forward: the toes are in front of the heels
    toes = read.world(read.names.index("l_metatarsophalangeal_2"))[2, 3]
    heel = read.world(read.names.index("l_calcaneus_posterior_pt"))[2, 3]
    assert toes > 0.1 > -0.02 > heel


def test_segment_masses_and_centres_are_the_hanim_export(male50):
    read, x3d = male50
    root = ET.parse(x3d).getroot()
    hanim = {
        s.get("name"): (
            float(s.get("mass")),
            np.array([float(v) for v in s.get("centerOfMass").split()]),
        )
        for s in root.iter("HAnimSegment")
        if s.get("name")
    }
    from sass_tui.model.body.figure import Figure

    assert sum(read.segment_masses().values()) == pytest.approx(
        Figure.default("male").mass, abs=0.005
    )
    for i in read.gltf.skins[0].joints:
        extras = read.gltf.nodes[i].extras
        mass, centre = hanim[extras["segment"]]
        assert extras["mass"] == pytest.approx(mass, abs=1e-4)
        world = read.world(i) @ np.append(extras["centerOfMass"], 1.0)
        assert np.abs(world[:3] - centre).max() <= 0.001


def test_figure_extras_say_who_and_where_from(male50):
    read, _ = male50
    extras = read.figure
    assert extras["population"] and extras["gender"] == "male" and extras["person"] is None
    assert extras["girthPercentile"] == 50 == extras["jointLimitPercentile"]
    assert extras["mass"]["percentile"] == pytest.approx(50, abs=0.1)
    assert extras["provenance"]["segmentMasses"].startswith("de Leva (1996)")
    assert extras["generator"].startswith("sass ")
    assert read.gltf.asset.generator.startswith("sass ")


def test_weights_bend_the_segment_the_joint_carries(male50):
    """Each vertex's heaviest joint is the segment it lies in: turning the left
    knee moves the left shank and foot, nothing above the left thigh, nothing
    of the other leg, and the shank turns about the knee."""
    read, _ = male50
    knee = read.names.index("l_knee")
    p = read.positions()
    weights = read.accessor(read.primitive.attributes.WEIGHTS_0).astype(float)
    assert np.allclose(weights.sum(axis=1), 1.0, atol=1e-6)
    angle = math.pi / 2
    bent = read.skinned({knee: np.array([math.sin(angle / 2), 0, 0, math.cos(angle / 2)])})
    moved = np.linalg.norm(bent - p, axis=1) > 1e-4
    knee_at = read.world(knee)[:3, 3]
    hip_at = read.world(read.names.index("l_hip"))[:3, 3]
    assert moved.sum() > 500
    assert (p[moved, 0] > 0).all()  # only the left side (+X)
    assert p[moved, 1].max() < hip_at[1]  # nothing above the hip
    well_below = p[:, 1] < knee_at[1] - 0.1
    on_left_leg = well_below & (np.abs(p[:, 0] - knee_at[0]) < 0.1)
    assert moved[on_left_leg].all()
    # the ankle's vertices swing back behind the knee, as far as the shank is long
    ankle = read.world(read.names.index("l_talocrural"))[:3, 3]
    near_ankle = on_left_leg & (np.linalg.norm(p - ankle, axis=1) < 0.03)
    swung = bent[near_ankle] - knee_at
    assert np.all(swung[:, 2] < -0.8 * (knee_at[1] - ankle[1]))


def test_gltf_and_bin_hold_the_glb_s_content(tmp_path):
    glb = _export(tmp_path, "one.glb", "--gender", "female")
    text = _export(tmp_path, "two words.gltf", "--gender", "female")
    assert (tmp_path / "two words.bin").is_file()
    document = json.loads(text.read_text(encoding="utf-8"))
    assert document["buffers"][0]["uri"] == "two%20words.bin"
    a, b = Read(glb), Read(text)
    assert np.array_equal(a.positions(), b.positions())
    assert a.joint_positions().keys() == b.joint_positions().keys()


def test_seated_pose_bends_hips_and_knees_90_degrees_feet_on_the_floor(tmp_path):
    out = _export(
        tmp_path, "seated.glb", "--gender", "female", "--percentile", "5", "--pose", "seated"
    )
    read = Read(out)
    at = {name: read.world(read.names.index(name))[:3, 3] for name in read.names[:18]}
    for side in ("l", "r"):
        hip, knee, ankle = at[f"{side}_hip"], at[f"{side}_knee"], at[f"{side}_talocrural"]
        thigh, shank = knee - hip, ankle - knee
        assert thigh[2] > 0.3 and abs(thigh[1]) < 1e-6  # forward, level
        assert abs(shank[2]) < 1e-6 and shank[1] < -0.3  # straight down
        # within the joint's limits: the flexion about the limit frame's y
        for joint in (f"{side}_hip", f"{side}_knee"):
            extras = read.gltf.nodes[read.names.index(joint)].extras
            assert extras["llimit"][1] <= math.pi / 2 <= extras["ulimit"][1]
    skinned = read.skinned()
    assert skinned[:, 1].min() == pytest.approx(0.0, abs=0.02)  # soles on the floor
    assert read.figure["pose"] == "seated"


def test_predict_writes_a_glb_of_the_predicted_person(tmp_path, validator, capsys, shipped_db_file):
    out = tmp_path / "P.glb"
    db = tmp_path / "p.db"
    copy_database_file(shipped_db_file, db)  # what `sass db init` builds
    args = ["--db", str(db), "predict", "--gender", "male", "--known", "stature=175.5cm"]
    assert main([*args, "--known", "mass=82.2kg", "-o", str(out)]) == 0
    read = Read(out)
    p = read.positions()
    assert p[:, 1].max() - p[:, 1].min() == pytest.approx(1.755, abs=0.005)
    assert sum(read.segment_masses().values()) == pytest.approx(82.2, abs=0.01)
    [report] = validator([out])
    assert (report["numErrors"], report["numWarnings"]) == (0, 0), report


# --- refusals ---------------------------------------------------------------------


def test_other_suffixes_are_refused_before_anything_is_written(tmp_path, capsys):
    assert main(["export", "gltf", "-o", str(tmp_path / "body.obj")]) != 0
    assert "ends in .glb (binary) or .gltf" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_a_figure_that_cannot_bend_90_degrees_is_not_seated(tmp_path):
    from sass_tui.model.body.figure import Figure
    from sass_tui.model.files.gltf import GltfError, export_gltf
    from sass_tui.model.names import JOINT_LIMITS, row_index

    figure = Figure.default("male")
    figure.set_value(JOINT_LIMITS, row_index(JOINT_LIMITS, "left_knee_ul"), 1, 80.0)
    out = tmp_path / "seated.glb"
    with pytest.raises(GltfError, match=r"l_knee flexes 0 to 80 degrees"):
        export_gltf(figure, out, "seated")
    assert not out.exists()
    assert export_gltf(figure, out, "standing") == [out]


@settings(max_examples=12, deadline=None)
@given(
    gender=st.sampled_from(["male", "female"]),
    percentile=st.floats(0.5, 99.5),
)
def test_any_percentile_figure_is_its_stature_tall_with_normal_weights(gender, percentile):
    from sass_tui.model.body.body_surface import body_mesh, figure_surface
    from sass_tui.model.body.figure import Figure
    from sass_tui.model.body.hanim import build_humanoid
    from sass_tui.model.files.gltf import render_gltf

    figure = Figure.default(gender)
    for group in figure.groups:
        figure.set_group_percentile(group, percentile)
    figure.set_mass_percentile(percentile)
    figure.set_stature_percentile(percentile)
    humanoid = build_humanoid(figure)
    mesh = body_mesh(humanoid, figure_surface(figure, humanoid))
    assert mesh.positions[:, 1].min() == pytest.approx(0.0, abs=1e-6)
    assert mesh.positions[:, 1].max() == pytest.approx(figure.stature / 100, abs=0.005)
    assert np.allclose(mesh.weights.sum(axis=1, dtype=np.float32), 1.0, atol=1e-6)
    assert (mesh.joints < LOA1_JOINTS).all() and (mesh.weights >= 0).all()
    assert np.allclose(np.linalg.norm(mesh.normals, axis=1), 1.0, atol=1e-5)
    # front faces counter-clockwise seen from outside (glTF 3.7.2.1): every
    # closed solid encloses a positive volume, its normals point the same way
    a, b, c = (mesh.positions[mesh.triangles[:, i]].astype(float) for i in range(3))
    assert np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6 > 0.02  # m^3
    face = np.cross(b - a, c - a)
    vertex = mesh.normals[mesh.triangles].sum(axis=1)
    assert (np.einsum("ij,ij->i", face, vertex) >= 0).all()
    glb = render_gltf(figure).glb()
    assert glb[:4] == b"glTF" and len(glb) % 4 == 0


@given(st.text(max_size=12))
def test_a_pose_answer_is_a_pose_or_a_clear_refusal(text):
    from sass_tui.model.files.gltf import POSES, GltfError, pose_of

    try:
        pose = pose_of(text)
    except GltfError as exc:
        assert "expected standing or seated" in str(exc)
        assert text.strip() and not any(p.startswith(text.strip().lower()) for p in POSES)
    else:
        assert pose in POSES
        assert pose.startswith(text.strip().lower())


@given(st.text(min_size=1, max_size=30).filter(lambda t: "\0" not in t))
def test_a_file_name_is_glb_or_gltf_or_refused_by_name(text):
    from pathlib import PurePath

    from sass_tui.model.files.gltf import GltfError, check_path

    try:
        path = check_path(text)
    except GltfError as exc:
        assert "a glTF file name ends in .glb (binary) or .gltf (+ .bin)" in str(exc)
        assert PurePath(text).suffix.lower() not in (".glb", ".gltf")
    else:
        assert path.suffix.lower() in (".glb", ".gltf")


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("chromium") is None, reason="Debian's chromium is not installed")
def test_the_picture_script_renders_both_figures(tmp_path):
    """scripts/gltf_pictures.py (docs/gltf-figures.png): three.js loads both
    exported .glb files and Chromium's screenshot is the page's size and not
    blank (a white 800 x 900 PNG is about 3 KiB; two lit bodies far more)."""
    import struct
    import sys

    if not (ROOT / "node" / "node_modules" / "three").is_dir():
        pytest.skip("three.js is not installed: npm ci --prefix node")
    out = tmp_path / "figures.png"
    done = subprocess.run(
        [sys.executable, str(ROOT / "scripts" / "gltf_pictures.py"), str(out)],
        capture_output=True,
        text=True,
        timeout=180,
    )
    assert done.returncode == 0, done.stderr
    data = out.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert struct.unpack(">II", data[16:24]) == (800, 900)
    assert len(data) > 40_000


def test_figure_options_reach_the_body(tmp_path, capsys):
    """The options of sass fig: a mass and stature of one's own, another
    girth percentile (the note export hanim prints), the figure type."""
    out = _export(
        tmp_path,
        "tall.glb",
        *("--mass", "210 lb", "--stature", "190", "--girth-percentile", "95"),
        *("--figure-type", "polybody"),
    )
    err = capsys.readouterr().err
    assert err.startswith("note: The humanoid's joints stand at its stature's landmarks")
    read = Read(out)
    p = read.positions()
    assert p[:, 1].max() - p[:, 1].min() == pytest.approx(1.90, abs=0.005)
    assert sum(read.segment_masses().values()) == pytest.approx(210 * 0.45359237, abs=0.01)
    assert read.figure["girthPercentile"] == 95 and read.figure["figureType"] == "polybody"


def test_only_the_export_imports_the_gltf_writer(tmp_path):
    """sass fig and export hanim never load model/files/gltf.py; export gltf loads
    neither Textual nor the query parser (lark) nor pint (no unit typed)."""
    import sys

    def imported(argv: list[str]) -> set[str]:
        code = (
            "import sys\nfrom sass_tui.cli import main\n"
            f"assert main({argv!r}) == 0\n"
            "names = ('sass_tui.model.files.gltf', 'textual', 'lark', 'pint')\n"
            "print('imported:' + ','.join(m for m in names if m in sys.modules))\n"
        )
        done = subprocess.run(
            [sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path, timeout=120
        )
        assert done.returncode == 0, done.stderr
        last = done.stdout.strip().splitlines()[-1].removeprefix("imported:")
        return set(filter(None, last.split(",")))

    assert imported(["fig", "-o", "X.fig"]) == set()
    assert imported(["export", "hanim", "-o", "X.x3d"]) == set()
    assert imported(["export", "gltf", "-o", "X.glb"]) == {"sass_tui.model.files.gltf"}


def test_a_file_that_cannot_be_written_is_named_and_nothing_is_left(tmp_path, capsys):
    missing = tmp_path / "no such folder" / "body.gltf"
    assert main(["export", "gltf", "-o", str(missing)]) != 0
    err = capsys.readouterr().err
    assert f"cannot write {missing.with_suffix('.bin')}: no such directory" in err
    assert "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.slow
def test_the_seated_body_bends_smoothly_without_tearing(tmp_path):
    """Seated (hips and knees at 90 degrees), skinned here from the file: no
    edge of the surface stretches to more than three times its standing
    length or shrinks below 15 % of it (smooth weights across each joint), and the
    surface stays in one piece per part (the same triangles)."""
    out = _export(tmp_path, "seated.glb", "--gender", "male", "--pose", "seated")
    read = Read(out)
    rest, bent = read.positions(), read.skinned()
    triangles = read.accessor(read.primitive.indices).reshape(-1, 3).astype(np.int64)
    edges = np.vstack([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    before = np.linalg.norm(rest[edges[:, 0]] - rest[edges[:, 1]], axis=1)
    after = np.linalg.norm(bent[edges[:, 0]] - bent[edges[:, 1]], axis=1)
    ratio = after / before
    assert ratio.max() < 3.0 and ratio.min() > 0.15, (ratio.min(), ratio.max())
