"""glTF 2.0 export: the HAnim humanoid as a skinned, articulated body.

The geometry is `model/body/hanim.py`'s: `build_humanoid` places the joints, sizes
the segments and gives their masses, so a figure exported as glTF and as HAnim
agree joint by joint (one placement model; docs/gltf.md).  This module only
turns the `Humanoid` into glTF 2.0 (Khronos, ISO/IEC 12113): a skeleton of
nodes named with the ISO 19774 joint names, the HAnim sites as empty nodes,
and one skinned mesh: the body's surface lofted through the figure's own
measurements (model/body/body_surface.py; the HAnim skin is the same surface).  Written by hand with numpy, json and struct: glTF is a
JSON document and a little-endian binary buffer (glTF 2.0 spec, sections 3.6
"Binary data storage" and 4.4 "GLB file format").

Units and axes are glTF's (spec 3.4): metres, +Y up, +Z forward -- the HAnim
humanoid's own frame (ISO 19774-1, 4.8.2), so no coordinate changes.
"""

from __future__ import annotations

import json
import math
import struct
from dataclasses import dataclass
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import TYPE_CHECKING, Any
from urllib.parse import quote

import numpy as np

from sass_tui.model.body.body_surface import SKIN, body_mesh, figure_surface
from sass_tui.model.body.hanim import LOA1, build_humanoid
from sass_tui.model.errors import SassError
from sass_tui.model.files.atomic import write_bytes_atomic, write_files_atomic
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GROUPS, JOINT_LIMITS

if TYPE_CHECKING:
    from sass_tui.model.body.figure import Figure
    from sass_tui.model.body.hanim import Humanoid

POSES = ("standing", "seated")
SUFFIXES = (".glb", ".gltf")
# Seated (the brief's "hips and knees 90 degrees"): both flexions, each about
# its joint's SASS flexion axis (hanim._LIMIT_AXES: the hip's is -X, the
# knee's +X), checked against the figure's limits before it is written.
SEATED_FLEXION = math.pi / 2

# glTF component types and buffer-view targets (spec 5.1.3, 5.11.4)
FLOAT, _UNSIGNED_BYTE, _UNSIGNED_SHORT, UNSIGNED_INT = 5126, 5121, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
_GLB_MAGIC, _GLB_JSON, _GLB_BIN = 0x46546C67, 0x4E4F534A, 0x004E4942


class GltfError(ValueError, SassError):
    """The figure cannot be written as glTF."""


@dataclass(frozen=True)
class GltfDocument:
    """A glTF asset: its JSON document and its one binary buffer."""

    name: str
    document: dict[str, Any]
    buffer: bytes

    def glb(self) -> bytes:
        """The GLB container (spec 4.4): header, JSON chunk, BIN chunk."""
        document = dict(self.document)
        document["buffers"] = [{"byteLength": len(self.buffer)}]
        text = _json(document)
        text += b" " * (-len(text) % 4)  # the JSON chunk is padded with spaces
        data = self.buffer + b"\0" * (-len(self.buffer) % 4)
        length = 12 + 8 + len(text) + 8 + len(data)
        return (
            struct.pack("<III", _GLB_MAGIC, 2, length)
            + struct.pack("<II", len(text), _GLB_JSON)
            + text
            + struct.pack("<II", len(data), _GLB_BIN)
            + data
        )

    def gltf(self, bin_name: str) -> bytes:
        """The JSON document of a .gltf whose buffer is the file `bin_name` beside it."""
        document = dict(self.document)
        document["buffers"] = [{"byteLength": len(self.buffer), "uri": quote(bin_name)}]
        return _json(document)


def _json(document: dict[str, Any]) -> bytes:
    try:
        return json.dumps(document, separators=(",", ":"), allow_nan=False).encode("utf-8")
    except ValueError:
        raise GltfError("cannot write the glTF: a value is not a number") from None


# --- the file ------------------------------------------------------------------


def check_path(path: str | Path) -> Path:
    """The output path, refused unless it ends in .glb or .gltf."""
    path = Path(path)
    if path.suffix.lower() not in SUFFIXES:
        raise GltfError(f"{path}: a glTF file name ends in .glb (binary) or .gltf (+ .bin)")
    return path


def pose_of(answer: str) -> str:
    """The pose a typed answer names: empty is standing; any start of a
    pose's name (`s` is ambiguous and means standing, the default's)."""
    word = answer.strip().lower()
    if not word:
        return POSES[0]
    pose = next((p for p in POSES if p.startswith(word)), None)
    if pose is None:
        raise GltfError(f"expected standing or seated, got {answer.strip()!r}; nothing written")
    return pose


def bin_path(path: Path) -> Path:
    """Where a .gltf's buffer goes: NAME.bin beside NAME.gltf."""
    return path.with_suffix(".bin")


def write_gltf(asset: GltfDocument, path: str | Path) -> list[Path]:
    """Write `asset` to `path` atomically: one .glb, or a .gltf and its .bin
    (both or neither, the .bin renamed first, so the .gltf never names a buffer
    that is not there).
    Returns the files written."""
    path = check_path(path)
    if path.suffix.lower() == ".glb":
        write_bytes_atomic(path, asset.glb())
        return [path]
    buffer = bin_path(path)
    if buffer == path:  # pragma: no cover - check_path allows only .gltf here
        raise GltfError(f"{path}: the buffer would overwrite the document")
    write_files_atomic({buffer: asset.buffer, path: asset.gltf(buffer.name)})
    return [path, buffer]


def export_gltf(figure: Figure, path: str | Path, pose: str = "standing") -> list[Path]:
    """Write the figure as glTF 2.0 (`sass export gltf`, `sass predict -o P.glb`)."""
    check_path(path)
    return write_gltf(render_gltf(figure, pose), path)


# --- the document --------------------------------------------------------------


def render_gltf(figure: Figure, pose: str = "standing") -> GltfDocument:
    """The figure's humanoid (hanim.build_humanoid) as a glTF asset in `pose`."""
    if pose not in POSES:
        raise GltfError(f"pose {pose!r}: expected one of {', '.join(POSES)}")
    humanoid = build_humanoid(figure)
    joints = [joint for joint, _, _ in LOA1]
    parent_of = {joint: parent for joint, _, parent in LOA1}
    segment_of = {joint: segment for joint, segment, _ in LOA1}
    joint_of = {segment: joint for joint, segment, _ in LOA1}
    index = {joint: i for i, joint in enumerate(joints)}
    centers = {joint: np.asarray(humanoid.centers[joint], dtype=float) for joint in joints}
    rotations = _pose_rotations(humanoid, pose)

    nodes: list[dict[str, Any]] = []
    for joint in joints:
        parent = parent_of[joint]
        translation = centers[joint] - (centers[parent] if parent else 0.0)
        if parent is None and pose == "seated":
            # thighs level, shanks upright, feet flat where they stood: the
            # hips come down to the knees' height
            translation = translation.copy()
            translation[1] = centers["l_knee"][1]
        node: dict[str, Any] = {"name": joint, "translation": _floats(translation)}
        if joint in rotations:
            node["rotation"] = _floats(rotations[joint])
        node["extras"] = _joint_extras(humanoid, joint, segment_of[joint], centers[joint])
        nodes.append(node)
    children: dict[str, list[int]] = {joint: [] for joint in joints}
    for joint in joints:
        parent = parent_of[joint]
        if parent is not None:
            children[parent].append(index[joint])
    for site in humanoid.sites:
        joint = joint_of[site.segment]
        site_node: dict[str, Any] = {
            "name": site.name,
            "translation": _floats(np.asarray(site.translation) - centers[joint]),
            "extras": {"hanim": "site", "segment": site.segment},
        }
        if site.rotation[3] != 0.0:
            site_node["rotation"] = _floats(_quaternion(site.rotation[:3], site.rotation[3]))
        children[joint].append(len(nodes))
        nodes.append(site_node)
    for joint in joints:
        if children[joint]:
            nodes[index[joint]]["children"] = children[joint]

    surface = figure_surface(figure, humanoid)
    mesh = body_mesh(humanoid, surface)
    packer = Packer()
    inverse_bind = np.zeros((len(joints), 4, 4), dtype=np.float32)
    for i, joint in enumerate(joints):
        inverse_bind[i] = np.eye(4)
        inverse_bind[i, :3, 3] = -centers[joint]
    # glTF matrices are column-major (spec 3.6.2.4): the transpose, row by row
    ibm = packer.add(inverse_bind.transpose(0, 2, 1), "MAT4", FLOAT, None)
    position = packer.add(mesh.positions, "VEC3", FLOAT, ARRAY_BUFFER, bounds=True)
    normal = packer.add(mesh.normals, "VEC3", FLOAT, ARRAY_BUFFER)
    joint_slots = packer.add(mesh.joints, "VEC4", _UNSIGNED_BYTE, ARRAY_BUFFER)
    weights = packer.add(mesh.weights, "VEC4", FLOAT, ARRAY_BUFFER)
    wide = len(mesh.positions) > 65535
    indices = packer.add(
        mesh.triangles.reshape(-1),
        "SCALAR",
        UNSIGNED_INT if wide else _UNSIGNED_SHORT,
        ELEMENT_ARRAY_BUFFER,
    )
    body = len(nodes)
    nodes.append({"name": f"{humanoid.name}_body", "mesh": 0, "skin": 0})
    skin_colour = [float(v) for v in SKIN.get(figure.gender, SKIN["male"]).split()]
    document: dict[str, Any] = {
        "asset": {"version": "2.0", "generator": f"sass {sass_version()} (sass export gltf)"},
        "scene": 0,
        "scenes": [{"name": humanoid.name, "nodes": [index["humanoid_root"], body], "extras": {}}],
        "nodes": nodes,
        "skins": [
            {
                "name": f"{humanoid.name}_skeleton",
                "joints": list(range(len(joints))),
                "skeleton": index["humanoid_root"],
                "inverseBindMatrices": ibm,
            }
        ],
        "meshes": [
            {
                "name": f"{humanoid.name}_body",
                "primitives": [
                    {
                        "attributes": {
                            "POSITION": position,
                            "NORMAL": normal,
                            "JOINTS_0": joint_slots,
                            "WEIGHTS_0": weights,
                        },
                        "indices": indices,
                        "material": 0,
                        "mode": 4,
                    }
                ],
            }
        ],
        "materials": [
            {
                "name": "skin",
                "pbrMetallicRoughness": {
                    # glTF colour factors are linear; SKIN is sRGB as X3D writes it
                    "baseColorFactor": [*(linear(c) for c in skin_colour), 1.0],
                    "metallicFactor": 0.0,
                    "roughnessFactor": 0.8,
                },
            }
        ],
        "accessors": packer.accessors,
        "bufferViews": packer.views,
    }
    extras = figure_extras(figure, humanoid, pose)
    extras["provenance"]["bodySurface"] = (
        "lofted through the ANSUR II measurements below (docs/gltf.md, The surface)"
    )
    measures = surface.measures
    extras["bodyMeasures"] = {
        name: {"cm": _round(value), "source": measures.sources[name]}
        for name, value in measures.values.items()
    }
    document["scenes"][0]["extras"] = extras
    return GltfDocument(humanoid.name, document, bytes(packer.data))


def _pose_rotations(humanoid: Humanoid, pose: str) -> dict[str, np.ndarray]:
    """Node rotations (quaternions x, y, z, w) of the pose; none standing."""
    if pose == "standing":
        return {}
    out: dict[str, np.ndarray] = {}
    for joint in ("l_hip", "r_hip", "l_knee", "r_knee"):
        limits = humanoid.limits[joint]
        # about the limit frame's y, the joint's flexion axis (hanim._LIMIT_AXES)
        lower, upper = limits.lower[1], limits.upper[1]
        if not lower <= SEATED_FLEXION <= upper:
            raise GltfError(
                f"cannot seat the figure: {joint} flexes {math.degrees(lower):.0f} to "
                f"{math.degrees(upper):.0f} degrees ({limits.sass_joint} joint limits), "
                "not 90"
            )
        out[joint] = _quaternion(limits.frame[:, 1], SEATED_FLEXION)
    return out


def _joint_extras(
    humanoid: Humanoid, joint: str, segment_name: str, center: np.ndarray
) -> dict[str, Any]:
    """The joint's segment: mass (kg), centre of mass (m, in the joint node's
    frame, so it moves with the pose), inertia about it; the joint's limits."""
    segment = humanoid.segments[segment_name]
    extras: dict[str, Any] = {
        "hanim": "joint",
        "segment": segment_name,
        "mass": _round(segment.mass),
        "centerOfMass": _floats(np.asarray(segment.center_of_mass) - center),
        "momentsOfInertia": _floats(np.asarray(segment.inertia).ravel()),
    }
    limits = humanoid.limits.get(joint)
    if limits is not None:
        extras["limitOrientation"] = _floats(np.array(limits.orientation))
        extras["ulimit"] = _floats(np.array(limits.upper))
        extras["llimit"] = _floats(np.array(limits.lower))
    return extras


def figure_extras(figure: Figure, humanoid: Humanoid, pose: str) -> dict[str, Any]:
    """Who and what the figure is, and where its numbers come from."""
    groups = figure.groups

    def number(value: float) -> float | None:
        return None if math.isnan(value) else _round(value)

    vertex = next(site for site in humanoid.sites if site.name == "skull_vertex_pt")
    filled = 0
    if figure.person is not None:
        filled = sum(int(figure.output_values(group)[1].sum()) for group in GROUPS)
    extras: dict[str, Any] = {
        "person": figure.person,
        "population": figure.population,
        "gender": figure.gender,
        "girthPercentile": number(groups[GIRTH].percentile),
        "jointLimitPercentile": number(groups[JOINT_LIMITS].percentile),
        "centerOfMassPercentile": number(groups[CENTER_OF_MASS].percentile),
        "mass": {"kg": number(figure.output_mass()), "percentile": number(figure.mass_percentile)},
        "stature": {
            "m": _round(float(vertex.translation[1])),
            "percentile": number(figure.stature_percentile),
        },
        "figureType": figure.figure_type,
        "pose": pose,
        "valuesFromPopulation": filled,
        "hanimInfo": list(humanoid.info),
        "provenance": {
            "jointCenters": "ANSUR II landmark/stature ratios at the figure's stature "
            "(docs/hanim.md, Joint centres)",
            "segmentDimensions": "the person's own where measured, else the population's "
            "at the girth percentile (SASS girth group)",
            "segmentMasses": "de Leva (1996), J. Biomech. 29(9):1223-1230, table 4",
            "construction": "docs/gltf.md",
        },
        "generator": f"sass {sass_version()}",
    }
    return extras


def sass_version() -> str:
    try:
        return version("sass-tui")
    except PackageNotFoundError:
        return "unknown (not installed)"


# --- the mesh ------------------------------------------------------------------


# --- packing -------------------------------------------------------------------


class Packer:
    """One buffer, one buffer view per accessor, each view 4-byte aligned
    (spec 3.6.2.4: an accessor's offset is a multiple of its component size);
    `asset` given, its buffer, views and accessors go on."""

    _DTYPES = {FLOAT: "<f4", _UNSIGNED_BYTE: "u1", _UNSIGNED_SHORT: "<u2", UNSIGNED_INT: "<u4"}
    _WIDTH = {"SCALAR": 1, "VEC3": 3, "VEC4": 4, "MAT4": 16}

    def __init__(self, asset: GltfDocument | None = None) -> None:
        self.data = bytearray(asset.buffer if asset else b"")
        self.views: list[dict[str, Any]] = list(asset.document["bufferViews"]) if asset else []
        self.accessors: list[dict[str, Any]] = list(asset.document["accessors"]) if asset else []

    def add(
        self,
        values: np.ndarray,
        kind: str,
        component: int,
        target: int | None,
        bounds: bool = False,
    ) -> int:
        array = np.ascontiguousarray(values, dtype=self._DTYPES[component])
        if component == FLOAT and not np.isfinite(array).all():
            raise GltfError("cannot write the glTF: a coordinate is not a number")
        self.data += b"\0" * (-len(self.data) % 4)
        raw = array.tobytes()
        view: dict[str, Any] = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(raw)}
        if target is not None:
            view["target"] = target
        self.data += raw
        self.views.append(view)
        width = self._WIDTH[kind]
        accessor: dict[str, Any] = {
            "bufferView": len(self.views) - 1,
            "componentType": component,
            "count": array.size // width,
            "type": kind,
        }
        if bounds:
            flat = array.reshape(-1, width)
            accessor["min"] = [float(v) for v in flat.min(axis=0)]
            accessor["max"] = [float(v) for v in flat.max(axis=0)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1


# --- small helpers ---------------------------------------------------------------


def _round(value: float) -> float:
    return float(f"{value:.6g}") if abs(value) >= 1e-3 else round(float(value), 9)


def _floats(values: np.ndarray) -> list[float]:
    out = [round(float(v), 7) for v in np.asarray(values, dtype=float).ravel()]
    if not all(math.isfinite(v) for v in out):
        raise GltfError("cannot write the glTF: a value is not a number")
    return [0.0 if v == 0 else v for v in out]


def _quaternion(axis: Any, angle: float) -> np.ndarray:
    """glTF's rotation (x, y, z, w) of `angle` radians about `axis`."""
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    half = angle / 2
    q: np.ndarray = np.append(a * math.sin(half), math.cos(half))
    return q


def linear(srgb: float) -> float:
    """sRGB to linear (IEC 61966-2-1), for glTF's baseColorFactor."""
    linear = srgb / 12.92 if srgb <= 0.04045 else ((srgb + 0.055) / 1.055) ** 2.4
    return round(linear, 4)
