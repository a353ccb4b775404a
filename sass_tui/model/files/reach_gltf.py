"""The reach envelopes (model/body/reach.py) as glTF 2.0: one closed,
see-through mesh per hand in the body's frame (metres, +Y up, +Z forward,
+X the body's left), alone or beside the figure's skinned body
(model/files/gltf.py's render_gltf, standing).  `sass reach -o FILE.glb`."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from sass_tui.model.body.body_surface import vertex_normals
from sass_tui.model.files.gltf import (
    ARRAY_BUFFER,
    ELEMENT_ARRAY_BUFFER,
    FLOAT,
    UNSIGNED_INT,
    GltfDocument,
    GltfError,
    Packer,
    linear,
    render_gltf,
    sass_version,
)

if TYPE_CHECKING:
    from sass_tui.model.body.figure import Figure
    from sass_tui.model.body.reach import Envelope

# Each hand's colour (sRGB) and how opaque the envelope is drawn.
_COLOURS = {"right": (0.85, 0.35, 0.25), "left": (0.25, 0.45, 0.85)}
_ALPHA = 0.35


def render_reach_gltf(
    envelopes: list[Envelope], name: str, figure: Figure | None = None
) -> GltfDocument:
    """The envelopes as meshes; with `figure`, beside its standing body."""
    if figure is not None and any(env.seated for env in envelopes):
        raise GltfError("the body is written standing: leave out --seated or --with-body")
    if figure is None:
        packer = Packer()
        document: dict[str, Any] = {
            "asset": {"version": "2.0", "generator": f"sass {sass_version()} (sass reach)"},
            "scene": 0,
            "scenes": [{"name": name, "nodes": []}],
            "nodes": [],
            "meshes": [],
            "materials": [],
        }
    else:
        body = render_gltf(figure)
        packer = Packer(body)
        document = dict(body.document)
        document["scenes"] = [dict(scene) for scene in body.document["scenes"]]
        document["scenes"][0]["nodes"] = list(document["scenes"][0]["nodes"])
        document["nodes"] = list(body.document["nodes"])
        document["meshes"] = list(body.document["meshes"])
        document["materials"] = list(body.document["materials"])
    for env in envelopes:
        vertices, triangles = env.mesh()
        positions = vertices.astype(np.float32)
        normals = vertex_normals(vertices, triangles).astype(np.float32)
        material = len(document["materials"])
        colour = [linear(c) for c in _COLOURS[env.side]]
        document["materials"].append(
            {
                "name": f"{env.side}_reach",
                "pbrMetallicRoughness": {
                    "baseColorFactor": [*colour, _ALPHA],
                    "metallicFactor": 0.0,
                    "roughnessFactor": 0.9,
                },
                "alphaMode": "BLEND",
            }
        )
        mesh = {
            "name": f"{env.side}_{env.point}_reach",
            "primitives": [
                {
                    "attributes": {
                        "POSITION": packer.add(positions, "VEC3", FLOAT, ARRAY_BUFFER, bounds=True),
                        "NORMAL": packer.add(normals, "VEC3", FLOAT, ARRAY_BUFFER),
                    },
                    "indices": packer.add(
                        triangles.reshape(-1), "SCALAR", UNSIGNED_INT, ELEMENT_ARRAY_BUFFER
                    ),
                    "material": material,
                    "mode": 4,
                }
            ],
        }
        document["scenes"][0]["nodes"].append(len(document["nodes"]))
        document["nodes"].append(
            {
                "name": f"{env.side}_{env.point}_reach",
                "mesh": len(document["meshes"]),
                "extras": {
                    "reach": {
                        "hand": env.side,
                        "point": env.point,
                        "seated": env.seated,
                        "trunk": env.trunk,
                        "shoulder": [round(float(v), 6) for v in env.centre],
                        "frame": "the seat below the hips' midpoint"
                        if env.seated
                        else "the floor between the feet",
                    }
                },
            }
        )
        document["meshes"].append(mesh)
    document["accessors"] = packer.accessors
    document["bufferViews"] = packer.views
    return GltfDocument(name, document, bytes(packer.data))
