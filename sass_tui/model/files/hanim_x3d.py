"""The HAnim humanoid (model/body/hanim.py) written as an ISO/IEC 19774 X3D 4.0
XML document (docs/hanim.md).  No Textual import: the CLI and the TUI both
call export_hanim().
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from sass_tui.model.body.body_surface import SKIN, BodyMesh, body_mesh, figure_surface
from sass_tui.model.body.hanim import LOA1, HAnimError, Humanoid, Site, build_humanoid
from sass_tui.model.files.atomic import write_text_atomic
from sass_tui.model.names import GIRTH
from sass_tui.model.text import xml_safe

if TYPE_CHECKING:
    from sass_tui.model.body.figure import Figure

HANIM_VERSION = "2.0"
LOA = 1  # clause 4.8.5: the 18 joints of figure 4.4


def _num(value: float) -> str:
    if not math.isfinite(value):
        raise HAnimError(f"cannot write the humanoid: a value is {value}, not a number")
    text = f"{value:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _vec(values: Iterable[float]) -> str:
    return " ".join(_num(v) for v in values)


def _mfstring(values: list[str]) -> str:
    return " ".join('"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"' for v in values)


def humanoid_element(humanoid: Humanoid, gender: str, mesh: BodyMesh | None = None) -> ET.Element:
    """The HAnimHumanoid node.  DEF names follow the HAnim convention the x3d
    package checks: the humanoid's name, '_', the node's name ('male_50_l_hip');
    humanoids with different names can share a scene.  With the body's `mesh`
    (model/body/body_surface.py, the glTF body's) the humanoid wears it as its skin
    (ISO/IEC 19774-1 clause 6.3: skinCoord, skinNormal, skin, and each joint's
    skinCoordIndex and skinCoordWeight); without it, each segment holds the
    boxes and ellipsoids of its solids."""
    prefix = f"{humanoid.name}_"
    # skeletalConfiguration is "BASIC" (clause 4.8.2) through the field's X3D 4.0
    # default: X3D's canonical XML form leaves defaults out, and Debian's
    # view3dscene 4.2, which predates the field, warns when it is written.
    root = ET.Element(
        "HAnimHumanoid",
        {
            "DEF": humanoid.name,
            "name": humanoid.name,
            "version": HANIM_VERSION,
            "loa": str(LOA),
            "info": _mfstring(humanoid.info),
        },
    )
    appearance_def = f"{prefix}skin_appearance"
    joints: dict[str, ET.Element] = {}
    first_shape = True
    sites_by_segment: dict[str, list[Site]] = {}
    for site in humanoid.sites:
        sites_by_segment.setdefault(site.segment, []).append(site)
    skin = _skin_of_joints(mesh) if mesh is not None else {}
    for number, (joint, segment_name, parent) in enumerate(LOA1):
        attrs = {"DEF": f"{prefix}{joint}", "name": joint, "center": _vec(humanoid.centers[joint])}
        if parent is None:
            attrs["containerField"] = "skeleton"
        if number in skin:
            attrs["skinCoordIndex"], attrs["skinCoordWeight"] = skin[number]
        limits = humanoid.limits.get(joint)
        if limits is not None:
            attrs["limitOrientation"] = _vec(limits.orientation)
            attrs["ulimit"] = _vec(limits.upper)
            attrs["llimit"] = _vec(limits.lower)
        element = ET.SubElement(root if parent is None else joints[parent], "HAnimJoint", attrs)
        joints[joint] = element
        segment = humanoid.segments[segment_name]
        seg = ET.SubElement(
            element,
            "HAnimSegment",
            {
                "DEF": f"{prefix}{segment_name}",
                "name": segment_name,
                "mass": _num(segment.mass),
                "centerOfMass": _vec(segment.center_of_mass),
                "momentsOfInertia": _vec(segment.inertia.ravel()),
            },
        )
        for kind, centre, size in segment.shapes if mesh is None else ():
            if kind == "ellipsoid":
                transform = ET.SubElement(
                    seg, "Transform", {"translation": _vec(centre), "scale": _vec(size / 2)}
                )
                geometry = ("Sphere", {"radius": "1"})
            else:
                transform = ET.SubElement(seg, "Transform", {"translation": _vec(centre)})
                geometry = ("Box", {"size": _vec(size)})
            shape = ET.SubElement(transform, "Shape")
            if first_shape:
                appearance = ET.SubElement(shape, "Appearance", {"DEF": appearance_def})
                ET.SubElement(
                    appearance, "Material", {"diffuseColor": SKIN.get(gender, SKIN["male"])}
                )
                first_shape = False
            else:
                ET.SubElement(shape, "Appearance", {"USE": appearance_def})
            ET.SubElement(shape, geometry[0], geometry[1])
        for site in sites_by_segment.get(segment_name, []):
            ET.SubElement(
                seg,
                "HAnimSite",
                {
                    "DEF": f"{prefix}{site.name}",
                    "name": site.name,
                    "translation": _vec(site.translation),
                    "rotation": _vec(site.rotation),
                },
            )
    if mesh is not None:
        _add_skin(root, mesh, prefix, SKIN.get(gender, SKIN["male"]))
    for joint, _, _ in LOA1:
        ET.SubElement(root, "HAnimJoint", {"USE": f"{prefix}{joint}", "containerField": "joints"})
    for _, segment_name, _ in LOA1:
        ET.SubElement(
            root, "HAnimSegment", {"USE": f"{prefix}{segment_name}", "containerField": "segments"}
        )
    for site in humanoid.sites:
        ET.SubElement(root, "HAnimSite", {"USE": f"{prefix}{site.name}", "containerField": "sites"})
    return root


def _numbers(values: np.ndarray, decimals: int) -> str:
    """Many numbers at once (the skin's coordinates), `decimals` after the point."""
    if not np.isfinite(values).all():
        raise HAnimError("cannot write the humanoid: a skin coordinate is not a number")
    # a value that prints as zero is written 0, never "-0.0000": the skin's
    # midline points lie within 1e-12 m of x = 0 on either side
    printed_zero = np.abs(values) < 0.5 * 10.0**-decimals
    numbers = np.where(printed_zero, 0.0, values).ravel().tolist()
    # one %-format over the whole list: half the time of formatting each number
    return " ".join([f"%.{decimals}f"] * len(numbers)) % tuple(numbers)


def _integers(values: np.ndarray) -> str:
    """Many whole numbers at once (the skin's triangles and each joint's
    vertices): one %-format over the list, ~half the time of str() on each."""
    numbers = values.ravel().tolist()
    return ("%d " * len(numbers))[:-1] % tuple(numbers)


def _skin_of_joints(mesh: BodyMesh) -> dict[int, tuple[str, str]]:
    """Per joint (LOA1 order): the skin's vertices it moves and their weights."""
    out: dict[int, tuple[str, str]] = {}
    for joint in range(len(LOA1)):
        rows, slots = np.nonzero((mesh.joints == joint) & (mesh.weights > 0))
        if len(rows):
            order = np.argsort(rows, kind="stable")
            weights = mesh.weights[rows[order], slots[order]].astype(float)
            out[joint] = (_integers(rows[order]), _numbers(weights, 5))
    return out


def _add_skin(root: ET.Element, mesh: BodyMesh, prefix: str, colour: str) -> None:
    """The skin's coordinates and normals (bound to the joints through their
    skinCoordIndex), and the one Shape drawing them."""
    coord, normal = f"{prefix}skin_coord", f"{prefix}skin_normal"
    ET.SubElement(
        root,
        "Coordinate",
        {"DEF": coord, "containerField": "skinCoord", "point": _numbers(mesh.positions, 5)},
    )
    ET.SubElement(
        root,
        "Normal",
        {"DEF": normal, "containerField": "skinNormal", "vector": _numbers(mesh.normals, 4)},
    )
    shape = ET.SubElement(root, "Shape", {"containerField": "skin"})
    appearance = ET.SubElement(shape, "Appearance", {"DEF": f"{prefix}skin_appearance"})
    ET.SubElement(appearance, "Material", {"diffuseColor": colour})
    triangles = ET.SubElement(
        shape,
        "IndexedTriangleSet",
        {"index": _integers(mesh.triangles), "solid": "true"},
    )
    ET.SubElement(triangles, "Coordinate", {"USE": coord})
    ET.SubElement(triangles, "Normal", {"USE": normal})


def scene_document(humanoids: list[tuple[ET.Element, float]], title: str, height: float) -> str:
    """An X3D 4.0 document holding humanoids side by side (x offsets in metres)."""
    x3d = ET.Element(
        "X3D",
        {
            "profile": "Immersive",
            "version": "4.0",
            "xmlns:xsd": "http://www.w3.org/2001/XMLSchema-instance",
            "xsd:noNamespaceSchemaLocation": "https://www.web3d.org/specifications/x3d-4.0.xsd",
        },
    )
    head = ET.SubElement(x3d, "head")
    ET.SubElement(head, "component", {"name": "HAnim", "level": "1"})
    ET.SubElement(head, "meta", {"name": "title", "content": title})
    ET.SubElement(head, "meta", {"name": "generator", "content": "sass export hanim"})
    ET.SubElement(
        head,
        "meta",
        {
            "name": "reference",
            "content": "ISO/IEC 19774-1:2019 HAnim, clause 4; SASS report, appendix D",
        },
    )
    scene = ET.SubElement(x3d, "Scene")
    ET.SubElement(scene, "WorldInfo", {"title": title})
    ET.SubElement(scene, "Background", {"skyColor": "1 1 1"})
    ET.SubElement(scene, "NavigationInfo", {"type": '"EXAMINE" "ANY"'})
    offsets = [x for _, x in humanoids]
    span = max(offsets) - min(offsets)
    middle = (max(offsets) + min(offsets)) / 2
    # far enough back that the tallest figure and the whole row fit a 45 degree view
    distance = 1.3 * max(height, span + 0.8)
    # turned a little to the humanoid's left: a straight front view hides the arms
    turn = 0.35
    ET.SubElement(
        scene,
        "Viewpoint",
        {
            "description": "front, three quarters",
            "position": _vec(
                (middle + distance * math.sin(turn), height / 2, distance * math.cos(turn))
            ),
            "orientation": _vec((0, 1, 0, turn)),
            "centerOfRotation": _vec((middle, height / 2, 0)),
        },
    )
    for element, x in humanoids:
        if x:
            transform = ET.SubElement(scene, "Transform", {"translation": _vec((x, 0, 0))})
            transform.append(element)
        else:
            scene.append(element)
    ET.indent(x3d)
    body = xml_safe(ET.tostring(x3d, encoding="unicode"))
    return (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<!DOCTYPE X3D PUBLIC "ISO//Web3D//DTD X3D 4.0//EN" '
        '"https://www.web3d.org/specifications/x3d-4.0.dtd">\n' + body + "\n"
    )


def figure_title(figure: Figure) -> str:
    if figure.person:
        return f"{figure.person} ({figure.gender}) - SASS HAnim humanoid"
    return (
        f"{figure.population}, {figure.gender}, girth percentile "
        f"{figure.groups[GIRTH].percentile:g} - SASS HAnim humanoid"
    )


def render_hanim(figure: Figure) -> str:
    """The figure's humanoid wearing its body (model/body/body_surface.py) as its skin."""
    humanoid = build_humanoid(figure)
    mesh = body_mesh(humanoid, figure_surface(figure, humanoid))
    height = float(humanoid.sites[0].translation[1])  # skull vertex
    return scene_document(
        [(humanoid_element(humanoid, figure.gender, mesh), 0.0)], figure_title(figure), height
    )


def export_hanim(figure: Figure, path: str | Path) -> Path:
    """Write the figure as an HAnim X3D file, atomically (the TUI's Export HAnim)."""
    text = render_hanim(figure)
    write_text_atomic(path, text)
    return Path(path)
