"""Render docs/gltf-figures.png: a 5th percentile woman and a 95th percentile
man (NASA crew data sets), exported by `sass export gltf`, side by side.

The page is three.js (node/package.json: `npm ci --prefix node`) loading
the two .glb files with its GLTFLoader, served on 127.0.0.1 only, and Debian's
headless Chromium takes the screenshot.  Run it to re-render the picture:

    python scripts/gltf_pictures.py [OUT.png]
"""

from __future__ import annotations

import functools
import http.server
import shutil
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

from hanim_pictures import figure_at  # the scripts' percentile figure (scripts/ is on the path)

from sass_tui.model.files.gltf import export_gltf

ROOT = Path(__file__).resolve().parents[1]
THREE = ROOT / "node" / "node_modules" / "three"
ROW = (("female", 5.0), ("male", 95.0))
SPACING = 0.8  # metres between the figures' origins
SIZE = (800, 900)
# The flags the project runs Chromium with: no GPU, nothing fetched but the page.
CHROMIUM_FLAGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--no-first-run",
)

PAGE = """<!doctype html>
<html><head><meta charset="utf-8"><style>html,body{margin:0;background:#fff}</style>
<script type="importmap">{"imports": {
  "three": "/three/build/three.module.js",
  "three/addons/": "/three/examples/jsm/"}}</script></head>
<body><script type="module">
import * as THREE from "three";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
const files = FILES;
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setSize(WIDTH, HEIGHT);
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xffffff);
scene.add(new THREE.HemisphereLight(0xffffff, 0x8d8d8d, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 2.2);
sun.position.set(2, 4, 5);
scene.add(sun);
const floor = new THREE.Mesh(new THREE.CircleGeometry(1.2, 64),
  new THREE.MeshStandardMaterial({ color: 0xdddddd }));
floor.rotation.x = -Math.PI / 2;
scene.add(floor);
const loader = new GLTFLoader();
let tallest = 0;
for (const [i, [url, x]] of files.entries()) {
  const gltf = await loader.loadAsync(url);
  gltf.scene.position.x = x;
  scene.add(gltf.scene);
  tallest = Math.max(tallest, gltf.scene.userData.stature.m);
}
// three quarters from the front, a little above the waist
const camera = new THREE.PerspectiveCamera(30, WIDTH / HEIGHT, 0.1, 50);
camera.position.set(1.3 * DISTANCE / 4.3, tallest * 0.62, DISTANCE);
camera.lookAt(0, tallest * 0.49, 0);
renderer.render(scene, camera);
document.title = "rendered";
</script></body></html>
"""


def main(out: Path = ROOT / "docs" / "gltf-figures.png") -> int:
    with tempfile.TemporaryDirectory() as tmp:
        files = []
        for gender, percentile in ROW:
            path = Path(tmp) / f"{gender}{percentile:02.0f}.glb"
            export_gltf(figure_at(gender, percentile), path)
            files.append(path)
        return screenshot(files, out)


def screenshot(
    files: list[Path], out: Path, size: tuple[int, int] = SIZE, distance: float = 4.3
) -> int:
    """Chromium's picture of three.js showing the .glb `files` in a row,
    SPACING apart, from `distance` metres in front."""
    chromium = shutil.which("chromium")
    if chromium is None or not (THREE / "build" / "three.module.js").exists():
        print("needs Debian's chromium and three.js (npm ci --prefix node)", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        site = Path(tmp)
        (site / "three").symlink_to(THREE)
        placed = []
        for i, glb in enumerate(files):
            name = f"{i}.glb"
            shutil.copyfile(glb, site / name)
            placed.append([f"/{name}", (i - (len(files) - 1) / 2) * SPACING])
        page = (
            PAGE.replace("FILES", repr(placed))
            .replace("WIDTH", str(size[0]))
            .replace("HEIGHT", str(size[1]))
            .replace("DISTANCE", repr(distance))
        )
        (site / "index.html").write_text(page, encoding="utf-8")
        handler = functools.partial(QuietHandler, directory=str(site))
        server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        threading.Thread(target=server.serve_forever, daemon=True).start()
        try:
            subprocess.run(
                [
                    chromium,
                    *CHROMIUM_FLAGS,
                    f"--user-data-dir={site / 'profile'}",
                    f"--window-size={size[0]},{size[1]}",
                    "--hide-scrollbars",
                    "--virtual-time-budget=20000",
                    f"--screenshot={out}",
                    f"http://127.0.0.1:{server.server_address[1]}/index.html",
                ],
                check=True,
                capture_output=True,
                timeout=120,
            )
        finally:
            server.shutdown()
    print(f"wrote {out}")
    return 0


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {
        **http.server.SimpleHTTPRequestHandler.extensions_map,
        ".js": "text/javascript",
    }

    def log_message(self, format: str, *args: object) -> None:
        pass


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1])) if len(sys.argv) > 1 else main())
