"""HAnim export (ISO/IEC 19774): structure, sizes, limits, masses, and a real X3D browser."""

from __future__ import annotations

import math
import shutil
import struct
import subprocess
import xml.etree.ElementTree as ET
import zlib

import numpy as np
import pytest

from sass_tui.cli import main
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import rotation_matrix
from sass_tui.model.files.figfile import FigureIncompleteError
from sass_tui.model.files.hanim_x3d import export_hanim
from sass_tui.model.names import JOINT_LIMITS, MASS_FRACTIONS, row_index

# ISO/IEC 19775-1 (X3D 4.0) HAnimHumanoid field defaults the export relies on.
X3D4_DEFAULTS = {"skeletalConfiguration": "BASIC"}

PARENTS = {  # clause 4.9.6.1, figure 4.10, written out independently of the module
    "humanoid_root": (None, "sacrum"),
    "sacroiliac": ("humanoid_root", "pelvis"),
    "l_hip": ("sacroiliac", "l_thigh"),
    "l_knee": ("l_hip", "l_calf"),
    "l_talocrural": ("l_knee", "l_talus"),
    "l_metatarsophalangeal_2": ("l_talocrural", "l_tarsal_proximal_phalanx_2"),
    "r_hip": ("sacroiliac", "r_thigh"),
    "r_knee": ("r_hip", "r_calf"),
    "r_talocrural": ("r_knee", "r_talus"),
    "r_metatarsophalangeal_2": ("r_talocrural", "r_tarsal_proximal_phalanx_2"),
    "vl5": ("humanoid_root", "l5"),
    "skullbase": ("vl5", "skull"),
    "l_shoulder": ("vl5", "l_upperarm"),
    "l_elbow": ("l_shoulder", "l_forearm"),
    "l_radiocarpal": ("l_elbow", "l_carpal"),
    "r_shoulder": ("vl5", "r_upperarm"),
    "r_elbow": ("r_shoulder", "r_forearm"),
    "r_radiocarpal": ("r_elbow", "r_carpal"),
}


def _floats(text: str) -> np.ndarray:
    return np.array([float(v) for v in text.split()])


def _export(tmp_path, name: str, gender: str, percentile: float):
    figure = Figure.default(gender)
    for group in figure.groups:
        figure.set_group_percentile(group, percentile)
    figure.set_mass_percentile(percentile)
    figure.set_stature_percentile(percentile)
    path = export_hanim(figure, tmp_path / name)
    return figure, path, ET.parse(path).getroot()


def _joints(root) -> dict[str, ET.Element]:
    return {j.get("name"): j for j in root.iter("HAnimJoint") if j.get("name")}


@pytest.fixture(scope="module")
def male50(tmp_path_factory):
    return _export(tmp_path_factory.mktemp("hanim"), "male50.x3d", "male", 50)


def test_loa1_hierarchy_names_and_parents(male50):
    _, _, root = male50
    (humanoid,) = root.iter("HAnimHumanoid")
    assert humanoid.get("version") == "2.0"
    # "BASIC" is the field's X3D 4.0 default; canonical X3D leaves it unwritten.
    assert humanoid.get("skeletalConfiguration", X3D4_DEFAULTS["skeletalConfiguration"]) == "BASIC"
    parents = {}
    for joint in root.iter("HAnimJoint"):
        for child in joint:
            if child.tag == "HAnimJoint" and child.get("name"):
                parents[child.get("name")] = joint.get("name")
    joints = _joints(root)
    assert set(joints) == set(PARENTS)
    skeleton = [c for c in humanoid if c.get("containerField") == "skeleton"]
    assert [j.get("name") for j in skeleton] == ["humanoid_root"]
    for name, (parent, segment) in PARENTS.items():
        assert parents.get(name) == parent, name
        segments = [c.get("name") for c in joints[name] if c.tag == "HAnimSegment"]
        assert segments == [segment], name


def test_every_joint_segment_and_site_is_listed(male50):
    _, _, root = male50
    (humanoid,) = root.iter("HAnimHumanoid")
    defs = {e.get("DEF"): e for e in root.iter() if e.get("DEF")}

    def listed(field):
        return {
            defs[e.get("USE")].get("name")
            for e in humanoid
            if e.get("containerField") == field and e.get("USE")
        }

    assert listed("joints") == set(PARENTS)
    assert listed("segments") == {segment for _, segment in PARENTS.values()}
    assert listed("sites") == {s.get("name") for s in root.iter("HAnimSite") if s.get("DEF")}
    assert {"skull_vertex_pt", "sellion_pt"} <= listed("sites")


def test_feet_on_the_ground_and_joints_at_the_landmarks(male50, ansur_dir):
    """Joint centres at the ANSUR II landmark/stature ratios times the figure's
    stature (recomputed here from the CSV), the skull vertex at the stature."""
    import runpy

    from _paths import ROOT

    figure, _, root = male50
    joints = _joints(root)
    script = runpy.run_path(str(ROOT / "scripts" / "hanim_landmarks.py"))
    fractions = script["landmark_fractions"](ansur_dir)["male"]
    stature = figure.stature / 100
    # the soles of the skin touch Y = 0, nothing is below it; its top is the vertex
    (coordinate,) = [c for c in root.iter("Coordinate") if c.get("point")]
    skin = _floats(coordinate.get("point")).reshape(-1, 3)
    assert skin[:, 1].min() == pytest.approx(0, abs=1e-5)
    assert skin[:, 1].max() == pytest.approx(stature, abs=1e-5)

    def height(joint):
        return _floats(joints[joint].get("center"))[1]

    assert height("r_talocrural") == pytest.approx(
        fractions["lateral_malleolus"] * stature, abs=1e-5
    )
    assert height("r_knee") == pytest.approx(fractions["femoral_epicondyle"] * stature, abs=1e-5)
    assert height("r_hip") == pytest.approx(fractions["trochanterion"] * stature, abs=1e-5)
    assert height("vl5") == pytest.approx(fractions["iliocristale"] * stature, abs=1e-5)
    # Rab et al. (2002): 17 % of the biacromial breadth (the stature's share) below the acromion
    breadth = script["biacromial_fractions"](ansur_dir)["male"] * stature
    assert height("r_shoulder") == pytest.approx(
        fractions["acromion"] * stature - 0.17 * breadth, abs=1e-5
    )
    assert height("skullbase") == pytest.approx(fractions["tragion"] * stature, abs=1e-5)
    sites = {s.get("name"): s for s in root.iter("HAnimSite") if s.get("name")}
    vertex = _floats(sites["skull_vertex_pt"].get("translation"))[1]
    assert vertex == pytest.approx(stature, abs=0.005)
    # the origin lies between the feet (4.8.2)
    feet = [_floats(joints[j].get("center")) for j in ("l_talocrural", "r_talocrural")]
    assert feet[0][0] == pytest.approx(-feet[1][0]) and feet[0][0] > 0  # +X is the left


def test_limits_in_radians_equal_the_joint_limit_group(male50):
    figure, _, root = male50
    joints = _joints(root)
    values = figure.groups[JOINT_LIMITS].values
    checked = 0
    for hanim, sass in (
        ("l_hip", "left_hip"),
        ("r_shoulder", "right_shoulder"),
        ("skullbase", "neck"),
        ("vl5", "waist"),
        ("l_radiocarpal", "left_wrist"),
        ("r_talocrural", "right_ankle"),
        ("l_knee", "left_knee"),
    ):
        upper = _floats(joints[hanim].get("ulimit"))
        lower = _floats(joints[hanim].get("llimit"))
        ul = values[row_index(JOINT_LIMITS, f"{sass}_ul")]
        ll = values[row_index(JOINT_LIMITS, f"{sass}_ll")]
        for axis in range(3):
            if math.isnan(ul[axis]):  # 999: no motion, the axis is locked
                assert upper[axis] == lower[axis] == 0
                continue
            exported = (upper[axis], lower[axis])
            as_is = (math.radians(ul[axis]), math.radians(ll[axis]))
            mirrored = (-as_is[1], -as_is[0])
            if axis < 2:  # x and y always keep SASS's sense
                assert exported == pytest.approx(as_is, abs=1e-5), (hanim, axis)
            else:
                assert exported == pytest.approx(as_is, abs=1e-5) or exported == pytest.approx(
                    mirrored, abs=1e-5
                ), (hanim, axis)
            checked += 1
    assert checked == 19


@pytest.mark.parametrize(
    "joint, sass, axis, probe, towards",
    [
        ("l_hip", "left_hip", 1, (0, -1, 0), (0, 0, 1)),  # flexion: the knee goes forward
        ("r_hip", "right_hip", 0, (0, -1, 0), (-1, 0, 0)),  # abduction: right leg to the right
        ("l_hip", "left_hip", 2, (0, 0, 1), (1, 0, 0)),  # lateral rotation: knee turns out
        ("r_knee", "right_knee", 1, (0, -1, 0), (0, 0, -1)),  # flexion: the shank goes back
        ("l_knee", "left_knee", 1, (0, -1, 0), (0, 0, -1)),
        ("r_elbow", "right_elbow", 1, (0, -1, 0), (0, 0, 1)),
        ("l_talocrural", "left_ankle", 0, (0, -1, 0), (-1, 0, 0)),  # supination: the sole turns in
        ("l_radiocarpal", "left_wrist", 1, (0, -1, 0), (-1, 0, 0)),  # flexion: towards the palm
        ("l_elbow", "left_elbow", 1, (0, -1, 0), (0, 0, 1)),  # flexion: the forearm comes forward
        ("l_shoulder", "left_shoulder", 0, (0, -1, 0), (1, 0, 0)),  # abduction: arm out to the left
        ("skullbase", "neck", 1, (0, 1, 0), (0, 0, 1)),  # flexion: the head nods forward
        ("skullbase", "neck", 2, (0, 0, 1), (-1, 0, 0)),  # rotation right: face turns right
        ("r_talocrural", "right_ankle", 1, (0, 0, 1), (0, 1, 0)),  # dorsiflexion: toes up
        ("vl5", "waist", 0, (0, 1, 0), (-1, 0, 0)),  # bend to the right
    ],
)
def test_limit_axes_move_the_body_the_way_sass_means(male50, joint, sass, axis, probe, towards):
    """Rotating by the exported limit that carries SASS's upper limit, about the
    limit frame's axis, moves the body part the way appendix G describes."""
    figure, _, root = male50
    element = _joints(root)[joint]
    orientation = _floats(element.get("limitOrientation"))
    frame = rotation_matrix(orientation[:3], orientation[3])
    ul = math.radians(
        figure.groups[JOINT_LIMITS].values[row_index(JOINT_LIMITS, f"{sass}_ul")][axis]
    )
    candidates = [
        v
        for v in (
            *_floats(element.get("ulimit"))[axis : axis + 1],
            *_floats(element.get("llimit"))[axis : axis + 1],
        )
        if abs(abs(v) - abs(ul)) < 1e-5
    ]
    assert candidates
    # the direction the probe starts to move in when the joint turns towards that limit
    starts = [math.copysign(1, v) * np.cross(frame[:, axis], probe) for v in candidates]
    assert any(np.dot(s, towards) > 0.9 for s in starts), (candidates, starts)
    # and the limit itself, applied, is a rotation of |SASS ul| about that axis
    moved = rotation_matrix(frame[:, axis], candidates[0]) @ np.array(probe, float)
    assert math.acos(np.clip(moved @ np.array(probe, float), -1, 1)) == pytest.approx(
        min(abs(ul), 2 * math.pi - abs(ul)), abs=1e-5
    )


def test_segment_masses_add_up_to_the_figure_mass(male50):
    figure, _, root = male50
    segments = [s for s in root.iter("HAnimSegment") if s.get("DEF")]
    total = sum(float(s.get("mass")) for s in segments)
    assert sum(f for _, f in MASS_FRACTIONS) == pytest.approx(1.0)
    assert total == pytest.approx(figure.mass, abs=1e-4)
    thigh = next(s for s in segments if s.get("name") == "l_thigh")
    inertia = _floats(thigh.get("momentsOfInertia")).reshape(3, 3)
    # a long thigh turns more easily about its own (vertical) axis
    assert inertia[1, 1] < inertia[0, 0] and inertia[1, 1] < inertia[2, 2]
    assert np.count_nonzero(inertia - np.diag(np.diag(inertia))) == 0
    # de Leva (1996) table 4: a man's thigh is 14.16 % of his mass, its centre
    # of mass 40.95 % of the way from the hip centre to the knee centre
    hip = _floats(_joints(root)["l_hip"].get("center"))
    knee = _floats(_joints(root)["l_knee"].get("center"))
    below = hip[1] - _floats(thigh.get("centerOfMass"))[1]
    assert below == pytest.approx(0.4095 * (hip[1] - knee[1]), abs=1e-6)
    assert float(thigh.get("mass")) == pytest.approx(0.1416 * figure.mass, abs=1e-4)


def test_the_fig_keeps_appendix_k_masses_the_humanoid_de_levas(male50, tmp_path):
    """The .fig stays as BODY.FIG builds it (appendix K: legs ~32 % of the
    mass); the humanoid's legs carry de Leva's ~40 %."""
    figure, _, root = male50
    fig = dict(figure.segment_masses())
    k_legs = sum(fig[f"{s}{p}mass"] for s in "lr" for p in ("upleg", "lowleg", "foot", "toes"))
    masses = {
        s.get("name"): float(s.get("mass")) for s in root.iter("HAnimSegment") if s.get("DEF")
    }
    legs = sum(masses[f"{s}_{p}"] for s in "lr" for p in ("thigh", "calf", "talus"))
    assert k_legs / figure.mass == pytest.approx(0.32, abs=0.02)
    assert legs / figure.mass == pytest.approx(2 * (14.16 + 4.33 + 1.37) / 100, abs=1e-4)


def test_fifth_female_is_smaller_than_ninety_fifth_male_everywhere(tmp_path):
    _, _, small = _export(tmp_path, "f05.x3d", "female", 5)
    _, _, large = _export(tmp_path, "m95.x3d", "male", 95)
    small_joints, large_joints = _joints(small), _joints(large)
    for name in PARENTS:
        low = _floats(small_joints[name].get("center"))[1]
        high = _floats(large_joints[name].get("center"))[1]
        assert low < high, name
    vertex = {
        r: next(s for s in t.iter("HAnimSite") if s.get("name") == "skull_vertex_pt")
        for r, t in (("s", small), ("l", large))
    }
    assert _floats(vertex["s"].get("translation"))[1] < _floats(vertex["l"].get("translation"))[1]


def test_incomplete_figure_is_refused_and_nothing_written(tmp_path):
    figure = Figure.default("male")
    figure.groups[JOINT_LIMITS].values = None
    target = tmp_path / "x.x3d"
    with pytest.raises(FigureIncompleteError, match="Joint Limits"):
        export_hanim(figure, target)
    assert list(tmp_path.iterdir()) == []


def test_cli_export_hanim(tmp_path, capsys):
    out = tmp_path / "FEMALE05.x3d"
    assert main(["export", "hanim", "--gender", "female", "--percentile", "5", "-o", str(out)]) == 0
    (humanoid,) = ET.parse(out).getroot().iter("HAnimHumanoid")
    info = humanoid.get("info")
    assert '"gender=female"' in info and '"girthPercentile=5"' in info
    assert "population=NASA Crewmember Trainees" in info
    capsys.readouterr()
    with pytest.raises(SystemExit):
        main(["export", "hanim", "--percentile", "120", "-o", str(tmp_path / "bad.x3d")])
    assert "outside 0.5-99.5" in capsys.readouterr().err
    assert not (tmp_path / "bad.x3d").exists()


# --- a real X3D browser -------------------------------------------------------

needs_view3dscene = pytest.mark.skipif(
    shutil.which("tovrmlx3d") is None, reason="view3dscene (Debian package) is not installed"
)


@needs_view3dscene
def test_view3dscene_parses_without_warnings(male50):
    _, path, _ = male50
    result = subprocess.run(["tovrmlx3d", str(path)], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    # Debian's view3dscene 4.2 predates X3D 4.0's HAnimHumanoid `loa` field,
    # which sass declares (clause 4.8.5): that one warning is the viewer's, and only it.
    known = 'Unknown X3D field name (unhandled X3D XML attribute) "loa" in node "HAnimHumanoid"'
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert [line for line in lines if known not in line] == []
    assert len(lines) <= 1
    assert "HAnimHumanoid" in result.stdout and "humanoid_root" in result.stdout


def _read_png(path) -> np.ndarray:
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat = 8, b""
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos : pos + 4])
        kind, body = data[pos + 4 : pos + 8], data[pos + 8 : pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0
        elif kind == b"IDAT":
            idat += body
    channels = 3 if colour == 2 else 4
    raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(height, width * channels + 1)
    image = np.zeros((height, width * channels), np.int32)
    prior = np.zeros(width * channels, np.int32)
    for y in range(height):
        kind, line = raw[y, 0], raw[y, 1:].astype(np.int32)
        if kind == 0:
            row = line
        elif kind == 1:
            row = np.cumsum(line.reshape(width, channels), axis=0).ravel() % 256
        elif kind == 2:
            row = (line + prior) % 256
        else:
            row = np.zeros_like(line)
            for x in range(line.size):
                left = row[x - channels] if x >= channels else 0
                up = prior[x]
                if kind == 3:
                    row[x] = (line[x] + (left + up) // 2) % 256
                else:
                    corner = prior[x - channels] if x >= channels else 0
                    p = left + up - corner
                    pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                    best = left if pa <= pb and pa <= pc else up if pb <= pc else corner
                    row[x] = (line[x] + best) % 256
        image[y] = prior = row
    return image.reshape(height, width, channels)[:, :, :3]


@needs_view3dscene
@pytest.mark.skipif(shutil.which("xvfb-run") is None, reason="xvfb-run is not installed")
def test_view3dscene_renders_a_figure(male50, tmp_path):
    _, path, _ = male50
    png = tmp_path / "male50.png"
    subprocess.run(
        [
            "xvfb-run",
            "-a",
            "view3dscene",
            str(path),
            "--geometry",
            "200x250",
            "--screenshot",
            "0",
            str(png),
        ],
        capture_output=True,
        timeout=120,
        check=True,
        cwd=tmp_path,
    )
    image = _read_png(png)
    background = image[0, 0]
    figure_pixels = np.any(image != background, axis=2)
    # a standing figure: a few per cent of the picture, taller than wide
    assert 0.02 < figure_pixels.mean() < 0.6
    rows, cols = np.nonzero(figure_pixels)
    assert np.ptp(rows) > 2 * np.ptp(cols)


def test_axis_angle_round_trips_every_axis_aligned_rotation():
    """The limit frames are axis permutations; several are half turns."""
    from itertools import permutations, product

    from sass_tui.model.body.hanim import axis_angle

    count = 0
    for order, signs in product(permutations(range(3)), product((1, -1), repeat=3)):
        matrix = np.zeros((3, 3))
        for column, (row, sign) in enumerate(zip(order, signs)):
            matrix[row, column] = sign
        if np.linalg.det(matrix) < 0:
            continue
        *axis, angle = axis_angle(matrix)
        assert rotation_matrix(axis, angle) == pytest.approx(matrix, abs=1e-9)
        count += 1
    assert count == 24


# --- the x3d package's checks, loa, DEF names ------------------------------------

_CONTAINER = {"Appearance": "appearance", "Material": "material", "Box": "geometry"}
_CONTAINER["Sphere"] = "geometry"
_CONTAINER.update({"IndexedTriangleSet": "geometry", "Coordinate": "coord", "Normal": "normal"})


def _x3d_value(kind: str, text: str):
    numbers = [float(v) for v in text.split()] if kind[2:] not in ("String", "Bool") else []
    if kind == "MFString":
        import shlex

        return shlex.split(text)
    if kind == "SFString":
        return text
    if kind == "SFInt32":
        return int(text)
    if kind in ("SFFloat", "SFDouble", "SFTime"):
        return numbers[0]
    if kind == "SFBool":
        return text == "true"
    if kind.startswith("SF"):
        return tuple(numbers)
    if kind in ("MFVec3f", "MFVec2f"):
        width = int(kind[-2])
        return [tuple(numbers[i : i + width]) for i in range(0, len(numbers), width)]
    return numbers


def _to_x3d(x3d, element):
    """An x3d package node for an X3D XML element; the package validates every
    field as it is set."""
    cls = getattr(x3d, element.tag)
    kinds = {f[0]: f[2].__name__ for f in cls.FIELD_DECLARATIONS()}
    kwargs = {}
    for name, text in element.attrib.items():
        if name == "containerField" or ":" in name:
            continue
        kwargs[name] = _x3d_value(kinds[name], text)
    for child in element:
        field = child.get("containerField") or _CONTAINER.get(child.tag, "children")
        node = _to_x3d(x3d, child)
        if kinds.get(field) == "SFNode":
            kwargs[field] = node
        else:
            kwargs.setdefault(field, []).append(node)
    return cls(**kwargs)


@pytest.fixture(scope="module")
def x3d_package():
    import contextlib
    import io

    pytest.importorskip("x3d")
    with contextlib.redirect_stdout(io.StringIO()):  # its greeting on import
        import x3d
    return x3d


@pytest.mark.parametrize("gender, percentile", [("male", 50), ("female", 5), ("male", 2.5)])
def test_the_x3d_package_checks_pass_with_no_diagnostic(tmp_path, x3d_package, gender, percentile):
    import contextlib
    import io

    _, _, root = _export(tmp_path, "h.x3d", gender, percentile)
    (humanoid_xml,) = root.iter("HAnimHumanoid")
    assert humanoid_xml.get("loa") == "1"
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed), contextlib.redirect_stderr(printed):
        humanoid = _to_x3d(x3d_package, humanoid_xml)
        checked = 0
        for element in root.iter():
            if (
                element.tag.startswith("HAnim")
                and element.get("DEF")
                and element.tag != "HAnimHumanoid"
            ):
                assert x3d_package.isValidHAnimDEF(
                    humanoid, element.get("DEF"), element.get("name"), forceEvaluation=True
                ), element.get("DEF")
                checked += 1
        humanoid.XML()
    assert checked == 18 + 18 + 10
    assert printed.getvalue() == ""
    assert humanoid.loa == 1


def test_def_names_are_the_humanoid_name_and_the_node_name(male50):
    _, _, root = male50
    (humanoid,) = root.iter("HAnimHumanoid")
    name = humanoid.get("name")
    assert name == "male_50"
    for element in root.iter():
        if element.tag in ("HAnimJoint", "HAnimSegment", "HAnimSite") and element.get("DEF"):
            assert element.get("DEF") == f"{name}_{element.get('name')}"


@pytest.mark.parametrize("gender, percentile", [("male", 50), ("female", 5)])
def test_a_percentile_figure_stands_where_its_body_stands(tmp_path, gender, percentile):
    """Skull vertex at the stature; whole-body centre of mass 54-58 % of it."""
    from sass_tui.model.body.hanim import build_humanoid

    figure, _, _ = _export(tmp_path, "h.x3d", gender, percentile)
    humanoid = build_humanoid(figure)
    stature = figure.stature / 100
    assert humanoid.sites[0].name == "skull_vertex_pt"
    assert abs(humanoid.sites[0].translation[1] - stature) <= 0.005
    mass = sum(s.mass for s in humanoid.segments.values())
    com = sum(s.mass * s.center_of_mass[1] for s in humanoid.segments.values()) / mass
    assert 0.54 <= com / stature <= 0.58


@pytest.fixture(scope="module")
def ansur_measurement(ansur_dir):
    import runpy

    from _paths import ROOT

    script = runpy.run_path(str(ROOT / "scripts" / "hanim_landmarks.py"))
    return script, script["measure"](200, ansur_dir)


def test_landmark_fractions_are_the_ansur_means(ansur_measurement, ansur_dir):
    from sass_tui.model.body.hanim import LANDMARK_FRACTIONS

    script, _ = ansur_measurement
    assert script["landmark_fractions"](ansur_dir) == LANDMARK_FRACTIONS


def test_ansur_people_from_the_database_stand_on_their_landmarks(ansur_measurement):
    """200 ANSUR II people (100 men, 100 women) imported, fetched and exported
    (as docs/hanim.md reports): every site their measurements place within
    1 mm of it on average, the acromions as far apart as their biacromial
    breadth, wrist, hip, knee and ankle at their landmarks."""
    _, result = ansur_measurement
    assert result["people"] == 200
    assert len(result["mae_mm"]) == 20
    for name, error in result["mae_mm"].items():
        assert error < 1.0, name


def test_every_ansur_person_has_a_real_bodys_center_of_mass(ansur_measurement):
    """Each of the 200 people's whole-body centre of mass is at 53-59 % of
    their stature (adults: ~55-57 % on average, each person's own proportions
    about it); appendix K's masses put it at 57.6-58.2."""
    _, result = ansur_measurement
    shares = result["com_shares"]
    assert len(shares) == 200
    assert all(0.53 <= share <= 0.59 for share in shares), (min(shares), max(shares))
    # the shipped percentile figures, as the script reports them
    script, _ = ansur_measurement
    for name, share in script["percentile_figures"]().items():
        assert 0.54 <= share <= 0.58, name


def test_sass_export_hanim_notes_girth_lengths_of_another_percentile(tmp_path, capsys):
    out = tmp_path / "X.x3d"
    assert main(["export", "hanim", "--girth-percentile", "95", "-o", str(out)]) == 0
    err = capsys.readouterr().err
    assert err == (
        "note: The humanoid's joints stand at its stature's landmarks (175.5 cm, percentile "
        "50.0; docs/hanim.md). A .fig (sass fig) has the neck, torso and leg lengths at the "
        "girth percentile (95.0); the humanoid does not.\n"
    )
    for same in (
        ["--percentile", "95"],
        ["--girth-percentile", "95", "--stature-percentile", "95"],
    ):
        assert main(["export", "hanim", *same, "-o", str(out)]) == 0
        assert capsys.readouterr().err == ""


@pytest.mark.slow
def test_the_segment_dimensions_the_humanoid_leaves_out_are_exactly_those_listed():
    # Every girth cell changed by 10 %: the ones in NOT_IN_HUMANOID leave the
    # export as it was (the joints stand at the stature's landmarks; LOA-1
    # has no clavicle or eye), every other one changes it.
    from sass_tui.model.body.hanim import NOT_IN_HUMANOID
    from sass_tui.model.files.hanim_x3d import render_hanim
    from sass_tui.model.names import GIRTH, ROWS

    before = render_hanim(Figure.default())
    unchanged = set()
    for row, spec in enumerate(ROWS[GIRTH]):
        for axis in range(3):
            figure = Figure.default()
            figure.set_value(GIRTH, row, axis, figure.groups[GIRTH].cell(row, axis)[0] * 1.1)
            if render_hanim(figure) == before:
                unchanged.add((spec.name, axis))
    assert unchanged == set(NOT_IN_HUMANOID)


def test_edits_the_humanoid_leaves_out_are_named():
    from sass_tui.model.body.hanim import edits_not_in_humanoid, not_in_humanoid_note
    from sass_tui.model.names import GIRTH

    figure = Figure.default()
    assert edits_not_in_humanoid(figure) == [] and not_in_humanoid_note(figure) == ""
    figure.set_value(GIRTH, row_index(GIRTH, "left_lower_leg"), 2, 40.0)
    figure.set_cell_percentile(GIRTH, row_index(GIRTH, "neck"), 2, 80.0)
    figure.set_value(GIRTH, row_index(GIRTH, "right_upper_leg"), 0, 17.0)  # used: not named
    assert edits_not_in_humanoid(figure) == ["Neck z", "Left Lower Leg z"]
    assert not_in_humanoid_note(figure).endswith(
        "A .fig (Create Figure) has Neck z, Left Lower Leg z as set here; the humanoid does not."
    )
    # The group percentile sets every cell again: no cell is left out then, but
    # the girth lengths are another percentile's than the stature's.
    figure.set_group_percentile(GIRTH, 60.0)
    assert edits_not_in_humanoid(figure) == []
    assert not_in_humanoid_note(figure) == (
        " The humanoid's joints stand at its stature's landmarks (175.5 cm, percentile 50.0; "
        "docs/hanim.md). A .fig (Create Figure) has the neck, torso and leg lengths at the "
        "girth percentile (60.0); the humanoid does not."
    )
    figure.set_value(GIRTH, row_index(GIRTH, "right_upper_leg"), 2, 50.0)
    assert "girth percentile (60.0) and Right Upper Leg z as set here;" in (
        not_in_humanoid_note(figure)
    )
    figure.set_stature_percentile(60.0)  # the stature's percentile: only the cell
    assert "girth percentile" not in not_in_humanoid_note(figure)
    assert "has Right Upper Leg z as set here;" in not_in_humanoid_note(figure)
    # A person's own lengths are theirs, not edits (docs/hanim.md measures them).
    groups = {g: np.array(s.values) for g, s in Figure.default().groups.items() if s.loaded}
    groups[GIRTH][row_index(GIRTH, "neck"), 2] = 9.0
    person = figure.for_person("P", "male", groups, stature=175.0)
    assert edits_not_in_humanoid(person) == []


@pytest.mark.slow
def test_the_skin_is_the_gltf_body_bound_to_the_same_joints(tmp_path):
    """The humanoid wears the glTF body's surface as its HAnim skin (clause
    6.3): the same vertices (read back from the .glb with pygltflib), every
    vertex's joint weights adding up to 1, and the joints that move a vertex
    those of its glTF JOINTS_0 slots."""
    pygltflib = pytest.importorskip("pygltflib")
    figure, _, root = _export(tmp_path, "skin.x3d", "female", 50)
    glb = tmp_path / "skin.glb"
    assert main(["export", "gltf", "--gender", "female", "-o", str(glb)]) == 0
    gltf = pygltflib.GLTF2().load(str(glb))
    blob = gltf.binary_blob()
    attributes = gltf.meshes[0].primitives[0].attributes

    def accessor(index, dtype, width):
        acc = gltf.accessors[index]
        start = gltf.bufferViews[acc.bufferView].byteOffset or 0
        return np.frombuffer(blob, dtype, acc.count * width, start).reshape(acc.count, width)

    positions = accessor(attributes.POSITION, "<f4", 3)
    slots = accessor(attributes.JOINTS_0, "u1", 4)
    (coordinate,) = [c for c in root.iter("Coordinate") if c.get("point")]
    skin = _floats(coordinate.get("point")).reshape(-1, 3)
    assert skin.shape == positions.shape
    assert np.abs(skin - positions).max() < 1e-5
    order = [j.get("name") for j in root.iter("HAnimJoint") if j.get("name")]
    weights = np.zeros((len(skin), len(order)))
    for number, joint in enumerate(order):
        element = _joints(root)[joint]
        if element.get("skinCoordIndex"):
            index = _floats(element.get("skinCoordIndex")).astype(int)
            weights[index, number] = _floats(element.get("skinCoordWeight"))
    assert np.allclose(weights.sum(axis=1), 1.0, atol=1e-4)
    gltf_names = [gltf.nodes[j].name for j in gltf.skins[0].joints]
    for vertex in range(0, len(skin), 97):
        moving = {order[j] for j in np.nonzero(weights[vertex] > 0)[0]}
        assert moving <= {gltf_names[j] for j in slots[vertex]}


def test_no_number_is_written_as_a_negative_zero():
    # The skin's midline points lie within 1e-12 m of x = 0, on either side as
    # the section solver happens to land: written "0.0000", never "-0.0000".
    from sass_tui.model.files.hanim_x3d import render_hanim

    words = render_hanim(Figure.default()).replace('"', " ").split()
    zeros = [w for w in words if w.lstrip("-").strip("0") == "."]
    assert zeros and not [w for w in zeros if w.startswith("-")]
