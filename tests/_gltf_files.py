"""glTF files read from outside sass: the Khronos glTF-Validator (npm
`gltf-validator`, node/package.json, run by node/validate.js) and a reader
of a .glb's accessors with pygltflib (a module of its own: several test
folders read glTF)."""

from __future__ import annotations

import json
import shutil
import subprocess
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from _paths import ROOT

VALIDATE = ROOT / "node" / "validate.js"
VALIDATOR = ROOT / "node" / "node_modules" / "gltf-validator"


def khronos_validator() -> Callable[[list[Path]], list[dict]]:
    """validate(files) -> one report a file ({"numErrors", "numWarnings", ...});
    the test is skipped, saying why, without node or the validator."""
    node = shutil.which("node")
    if node is None or not VALIDATOR.is_dir():
        pytest.skip("the glTF-Validator needs Debian's nodejs and `npm ci --prefix node`")

    def validate(files: list[Path]) -> list[dict]:
        done = subprocess.run(
            [node, str(VALIDATE), *map(str, files)], capture_output=True, text=True, timeout=300
        )
        assert done.returncode in (0, 1), done.stderr
        return [json.loads(line) for line in done.stdout.splitlines()]

    return validate


def accessor(gltf: Any, blob: bytes, index: int) -> np.ndarray:
    """Accessor `index` of a .glb (float, unsigned short or int; scalars or
    3-vectors) as numpy, read from the binary chunk as the spec lays it out."""
    acc = gltf.accessors[index]
    view = gltf.bufferViews[acc.bufferView]
    dtype = {5126: "<f4", 5123: "<u2", 5125: "<u4"}[acc.componentType]
    width = {"SCALAR": 1, "VEC3": 3}[acc.type]
    start = (view.byteOffset or 0) + (acc.byteOffset or 0)
    data = np.frombuffer(blob, dtype, acc.count * width, start)
    return data.reshape(acc.count, width) if width > 1 else data
