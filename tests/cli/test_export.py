"""`sass export`: an ISO/IEC 19774 HAnim humanoid in X3D XML, and a glTF 2.0
binary whose header is the one the glTF 2.0 specification (section 4.4.2) sets."""

from __future__ import annotations

import json
import struct
import xml.etree.ElementTree as ET

from sass_tui.cli import main


def test_hanim_writes_one_humanoid_in_an_x3d_document(tmp_path, capsys):
    out = tmp_path / "body.x3d"
    assert main(["export", "hanim", "--gender", "female", "-o", str(out)]) == 0
    capsys.readouterr()
    root = ET.parse(out).getroot()
    assert root.tag == "X3D"
    (humanoid,) = root.iter("HAnimHumanoid")
    assert humanoid.get("version") == "2.0"


def test_gltf_writes_a_glb_with_the_specifications_header(tmp_path, capsys):
    out = tmp_path / "body.glb"
    assert main(["export", "gltf", "-o", str(out)]) == 0
    capsys.readouterr()
    data = out.read_bytes()
    magic, version, length = struct.unpack_from("<4sII", data)
    assert (magic, version, length) == (b"glTF", 2, len(data))
    chunk_length, chunk_type = struct.unpack_from("<I4s", data, 12)
    assert chunk_type == b"JSON"
    document = json.loads(data[20 : 20 + chunk_length])
    assert document["asset"]["version"] == "2.0"
    assert document["skins"], "a skinned body"


def test_a_name_without_the_format_suffix_is_refused(tmp_path, capsys):
    assert main(["export", "gltf", "-o", str(tmp_path / "body.txt")]) == 2
    assert "sass export: error:" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []
