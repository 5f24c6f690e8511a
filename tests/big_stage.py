"""A large stage for timing the planner and the stage reader: a tessellated
heightfield floor of about ``n_triangles`` triangles, a black occluder, a
rect light and a sun, and a config with ``n_sensors`` sensors in five grids
(up, down, two vertical and one tilted orientation, so that most sensors'
planes cut the floor).

Written at test time (nothing large is committed). As a script it writes the
stage into a temporary folder and prints the load and plan times::

    python tests/big_stage.py --triangles 1000000 --sensors 1000
"""

from __future__ import annotations

import argparse
import math
import tempfile
import time
from pathlib import Path

import numpy as np

#: grid orientations: (name, normal, up); each grid is a square of sensors
GRIDS = (
    ("up", (0.0, 0.0, 1.0), (0.0, 1.0, 0.0)),
    ("down", (0.0, 0.0, -1.0), (0.0, 1.0, 0.0)),
    ("east", (1.0, 0.0, 0.0), (0.0, 0.0, 1.0)),
    ("north", (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)),
    ("tilted", (0.5773502691896258, 0.5773502691896258, 0.5773502691896258), (0.0, 0.0, 1.0)),
)


def floor_mesh(n_triangles: int, size_m: float = 20.0) -> tuple[np.ndarray, np.ndarray]:
    """A size × size heightfield (z = 0.05·sin x·cos y) of n×n quads, 2n² ≈ ``n_triangles``.

    Returns
    -------
    points : ndarray, shape (P, 3), metres
    quads : ndarray, shape (n², 4), int, counter-clockwise seen from +Z
    """
    n = max(1, int(math.sqrt(n_triangles / 2.0)))
    u = np.linspace(-0.5 * size_m, 0.5 * size_m, n + 1)
    x, y = np.meshgrid(u, u, indexing="xy")
    z = 0.05 * np.sin(x) * np.cos(y)
    points = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="xy")
    a = (j * (n + 1) + i).ravel()
    quads = np.column_stack([a, a + 1, a + n + 2, a + n + 1])
    return points, quads


def _array(values: np.ndarray, fmt: str) -> str:
    return ", ".join(fmt % tuple(v) for v in values) if values.ndim == 2 else ", ".join(map(str, values.tolist()))


def write_big_stage(folder: Path, n_triangles: int = 1_000_000, n_sensors: int = 1000) -> Path:
    """Write ``big.usda`` and ``big.toml`` into ``folder``; return the config's path."""
    folder = Path(folder)
    points, quads = floor_mesh(n_triangles)
    pts_text = ", ".join(f"({x:.6g}, {y:.6g}, {z:.6g})" for x, y, z in points.tolist())
    stage = f"""#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
    defaultPrim = "World"
)

def Xform "World"
{{
    def Mesh "Floor" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {{
        int[] faceVertexCounts = [{", ".join(["4"] * len(quads))}]
        int[] faceVertexIndices = [{_array(quads.ravel(), "")}]
        point3f[] points = [{pts_text}]
        rel material:binding = </World/Looks/Grey>
    }}

    def Mesh "Blocker" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {{
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 1, 2, 3]
        point3f[] points = [(3, 3, 2), (4, 3, 2), (4, 4, 2), (3, 4, 2)]
        rel material:binding = </World/Looks/Black>
    }}

    def RectLight "Panel"
    {{
        float inputs:intensity = 1000
        float inputs:width = 2
        float inputs:height = 2
        double3 xformOp:translate = (0, 0, 4)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }}

    def DistantLight "Sun"
    {{
        float inputs:angle = 0.53
        float inputs:intensity = 1000
        float3 xformOp:rotateXYZ = (30, 20, 0)
        uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]
    }}

    def Scope "Looks"
    {{
        def Material "Grey"
        {{
            token outputs:surface.connect = </World/Looks/Grey/Surface.outputs:surface>
            def Shader "Surface"
            {{
                uniform token info:id = "UsdPreviewSurface"
                color3f inputs:diffuseColor = (0.5, 0.5, 0.5)
                token outputs:surface
            }}
        }}
        def Material "Black"
        {{
            token outputs:surface.connect = </World/Looks/Black/Surface.outputs:surface>
            def Shader "Surface"
            {{
                uniform token info:id = "UsdPreviewSurface"
                color3f inputs:diffuseColor = (0, 0, 0)
                token outputs:surface
            }}
        }}
    }}
}}
"""
    (folder / "big.usda").write_text(stage)
    per_grid = max(1, -(-n_sensors // len(GRIDS)))
    side = max(1, math.ceil(math.sqrt(per_grid)))
    spacing = 0.1
    lines = ['stage = "big.usda"', "", "[simulation]", "samples = 16", "seed = 1", ""]
    for k, (name, normal, up) in enumerate(GRIDS):
        cols = -(-per_grid // side)
        lines += [
            "[[grid]]", f'name = "{name}"', f"position = [{-6.0 + 3.0 * k}, {1.0 - 0.5 * k}, 1.0]",
            f"normal = [{', '.join(map(repr, normal))}]", f"up = [{', '.join(map(repr, up))}]",
            f"size = [{cols * spacing!r}, {side * spacing!r}]", f"spacing = {spacing!r}", "",
        ]  # fmt: skip
    lines += ["[output]", 'csv = "big.csv"', ""]
    (folder / "big.toml").write_text("\n".join(lines))
    return folder / "big.toml"


def time_plan(config: Path) -> dict:
    """Load the config's stage and plan its sensors; seconds of each step and the counts."""
    from simulator.config.loader import load_config
    from simulator.pipeline import collect_sensors, load_scene
    from simulator.plan.planner import make_plan

    t0 = time.perf_counter()
    cfg = load_config(config)
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    t1 = time.perf_counter()
    plan = make_plan(scene, sensors, "auto", "total")
    t2 = time.perf_counter()
    return {"triangles": scene.geometry.n_triangles, "sensors": len(sensors), "load_s": t1 - t0, "plan_s": t2 - t1,
            "methods": {m: len(ix) for m, ix in plan.groups().items()}}  # fmt: skip


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--triangles", type=int, default=1_000_000)
    ap.add_argument("--sensors", type=int, default=1000)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as d:
        t0 = time.perf_counter()
        cfg = write_big_stage(Path(d), args.triangles, args.sensors)
        print(f"wrote {cfg.parent / 'big.usda'} ({(cfg.parent / 'big.usda').stat().st_size / 1e6:.0f} MB) "
              f"in {time.perf_counter() - t0:.1f} s")  # fmt: skip
        print(time_plan(cfg))


if __name__ == "__main__":
    main()
