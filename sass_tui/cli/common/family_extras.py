"""What `sass family` needs only for an option: a target's weights (`--target`,
`--virtual`: db/populations/shipped.py, which brings db/populations/targets.py)
and the glTF writer (`--gltf`: model/files/gltf.py, which brings
importlib.metadata).  The verb imports this module only when one of them is
given, so its start-up row (sass_tui/startup.py) keeps both off its path."""

from __future__ import annotations

from sass_tui.db.populations.shipped import load_weights
from sass_tui.model.files.gltf import export_gltf

__all__ = ["export_gltf", "load_weights"]
