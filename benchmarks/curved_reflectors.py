"""Curved reflectors as a user models them: a chrome ball, a clear-coated ball and a glossy ball, read
against their closed forms.

A UsdGeom.Sphere of radius 0.5 m at (0, 0, 1) with its default tessellation
(64 × 32), under a sun of 1000 lx normal illuminance (0.53°, zenith 30°) or
beside a lamp (a SphereLight of radius 3 cm, intensity 100), seen by radiance
meters 2 m away:

- ``chrome ball, sun``: metallic 1, roughness 0, diffuseColor 0.9, a meter
  of 0.02° aimed at the sun's highlight: F·L_sun with F = 0.9;
- ``chrome ball, lamp``: the same ball, the lamp 1.5 m from it, a meter
  aimed at its image: F·L_lamp;
- ``clearcoat highlight``: car paint (diffuseColor 0.3, roughness 0.5) under
  a clearcoat of weight 1 at its fallback roughness (0.01: a mirror), the
  sun's highlight: F_c(μ)·L_sun (Schlick, F0 = 0.04) plus the base's lobes'
  share of the sun, f_base·E⊥·cos θ_i, μ the incidence cosine;
- ``glossy highlight``: diffuseColor 0.5, roughness 0.2 (metallic 0): a
  meter of 0.1° at the sun's highlight reads f(wi, wo)·E⊥·cos θ_i (the lobe
  is ~6° wide, the sun 0.53°: within 1e-3);
- ``point lamp's image``: an irradiance sensor beside the chrome ball,
  facing it, a point lamp behind the sensor: Coddington's equations
  (``simulator.reference.convex_mirror``).

The closed forms take the sphere itself; the 64 × 32 facets stand up to
0.6 mm inside it and tilt up to 1.4° from it, which the printed
difference includes. Run from the repository root (the tree on PYTHONPATH
is the one measured):

    PYTHONPATH=. python benchmarks/curved_reflectors.py [--samples 4096] [--seed 1] [--tessellation 256 128]
    PYTHONPATH=. python benchmarks/curved_reflectors.py --cost [--samples 4096]
    PYTHONPATH=. python benchmarks/curved_reflectors.py --flat-mirror --samples 16384 --seed 11
"""

from __future__ import annotations

import argparse
import math
import tempfile
from pathlib import Path

import numpy as np

from simulator.engine.driver import Engine
from simulator.reference.convex_mirror import image_irradiance, reflection_point
from simulator.reference.microfacet import bsdf_value, preview_lobes
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage

C = np.array([0.0, 0.0, 1.0])
R = 0.5
METER = C + 2.0 * np.array([1.0, 0.3, 0.5]) / math.sqrt(1.34)
LAMP = C + 1.5 * np.array([-0.4, 0.6, 0.7]) / math.sqrt(1.01)
POINT = np.array([1.5, -0.8, 2.5])
X, N = np.array([1.2, 0.3, 1.4]), np.array([-1.0, -0.2, -0.3]) / math.sqrt(1.13)


def _unit(v):
    return np.asarray(v, float) / np.linalg.norm(v)


TESSELLATION = None  # (n_lon, n_lat) for probesim:tessellation, None: the default 64 × 32


def _material(extra: str, rho: float) -> str:
    tess = "" if TESSELLATION is None else f"    int2 probesim:tessellation = ({TESSELLATION[0]}, {TESSELLATION[1]})\n"
    return f'''def Material "M"
{{
    token outputs:surface.connect = </M/S.outputs:surface>
    def Shader "S"
    {{
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = ({rho}, {rho}, {rho})
        {extra}
        token outputs:surface
    }}
}}
def Sphere "Ball" (
    prepend apiSchemas = ["MaterialBindingAPI"]
)
{{
    double radius = {R}
    rel material:binding = </M>
{tess}    double3 xformOp:translate = (0, 0, 1)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}}
'''


SUN = '''def DistantLight "Sun"
{
    float inputs:intensity = 1000
    float inputs:angle = 0.53
    bool inputs:normalize = 1
    float3 xformOp:rotateXYZ = (30, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]
}
'''


def _lamp(p, point: bool) -> str:
    return ('def SphereLight "Lamp"\n{\n    float inputs:intensity = 100\n    float inputs:radius = 0.03\n'
            + ("    bool treatAsPoint = 1\n" if point else "")
            + f"    double3 xformOp:translate = ({float(p[0])!r}, {float(p[1])!r}, {float(p[2])!r})\n"
            '    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n')


CHROME = ("float inputs:roughness = 0\n        float inputs:metallic = 1", 0.9)
PAINT = ("float inputs:roughness = 0.5\n        float inputs:clearcoat = 1", 0.3)
GLOSSY = ("float inputs:roughness = 0.2", 0.5)


def _scene(folder: Path, name: str, body: str):
    path = folder / f"{name}.usda"
    path.write_text('#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n' + body)
    return load_stage(path)


def _highlight_case(scene, lobes, half_deg: float, coat_dim: bool = False):
    """The meter at the sun's highlight, the sun's radiance reflected there by the non-delta lobes, L ∫ f
    cos θ_i dω over the sun's disc (24 × 48 nodes; with ``coat_dim`` the base dimmed by a mirror coat,
    (1 − F_c(μ_i))(1 − F_c(μ_o))), and the view's incidence cosine μ."""
    sun = scene.lights[0]
    s = sun.frame[:, 2]
    h = reflection_point(C, R, METER, None, s)
    n = _unit(h - C)
    v = _unit(METER - h)
    mu = float(np.dot(v, n))
    t = _unit(np.cross(n, [0.3, 0.5, 0.7]))
    b = np.cross(n, t)
    loc = lambda w: np.array([np.dot(w, t), np.dot(w, b), np.dot(w, n)])  # noqa: E731
    fc = lambda c: 0.04 + 0.96 * (1.0 - c) ** 5  # noqa: E731
    ex = _unit(np.cross(s, [1.0, 0.0, 0.0]))
    ey = np.cross(s, ex)
    xg, wg = np.polynomial.legendre.leggauss(24)
    th, wt = 0.5 * sun.half_angle * (xg + 1), 0.5 * sun.half_angle * wg
    total = 0.0
    for ti, wi in zip(th, wt):
        for p in 2 * math.pi * np.arange(48) / 48:
            d = math.cos(ti) * s + math.sin(ti) * (math.cos(p) * ex + math.sin(p) * ey)
            f = float(bsdf_value(lobes, loc(d)[None], loc(v)[None])[0])
            if coat_dim:
                f *= (1.0 - fc(float(np.dot(d, n)))) * (1.0 - fc(mu))
            total += wi * math.sin(ti) * (2 * math.pi / 48) * f * float(np.dot(d, n))
    meter = Sensor(name="m", kind=SensorKind.RADIANCE, position=METER, normal=_unit(h - METER),
                   half_angle=math.radians(half_deg))
    return meter, sun.emission[1] * total, mu


def cases(folder: Path):
    """``(name, scene, sensor, closed form, unit)`` of each case."""
    out = []
    scene = _scene(folder, "chrome_sun", _material(*CHROME) + SUN)
    meter, _, _ = _highlight_case(scene, preview_lobes(0.9, 0.0, 1.0), 0.02)
    out.append(("chrome ball, sun", scene, meter, 0.9 * scene.lights[0].emission[1], "cd/m²"))
    scene = _scene(folder, "chrome_lamp", _material(*CHROME) + _lamp(LAMP, False))
    h = reflection_point(C, R, METER, LAMP)
    meter = Sensor(name="m", kind=SensorKind.RADIANCE, position=METER, normal=_unit(h - METER),
                   half_angle=math.radians(0.02))
    out.append(("chrome ball, lamp", scene, meter, 0.9 * scene.lights[0].emission[1], "cd/m²"))
    scene = _scene(folder, "clearcoat", _material(*PAINT) + SUN)
    meter, lobes_part, mu = _highlight_case(scene, preview_lobes(0.3, 0.5), 0.02, coat_dim=True)
    coat = (0.04 + 0.96 * (1.0 - mu) ** 5) * scene.lights[0].emission[1]
    out.append(("clearcoat highlight", scene, meter, coat + lobes_part, "cd/m²"))
    scene = _scene(folder, "glossy", _material(*GLOSSY) + SUN)
    meter, truth, _ = _highlight_case(scene, preview_lobes(0.5, 0.2), 0.02)
    out.append(("glossy highlight", scene, meter, truth, "cd/m²"))
    scene = _scene(folder, "point_lamp", _material(*CHROME) + _lamp(POINT, True))
    sensor = Sensor(name="s", kind=SensorKind.IRRADIANCE, position=X, normal=N)
    out.append(("point lamp's image", scene, sensor, image_irradiance(C, R, X, N, POINT,
                                                                       scene.lights[0].emission[1], 0.9), "lx"))
    return out


def room_cost(folder: Path, samples: int, seed: int) -> None:
    """Process CPU seconds per sample of a 4 × 4 × 3 m room (walls 0.5) with a ball on its floor and a point
    lamp under its ceiling, nine floor sensors, ``path``: the ball chrome (every vertex solves for the
    lamp's image in it) against the ball at roughness 0.3 (no curved mirror: no solve)."""
    import time

    h = 2.0
    walls = [((-h, -h, 0), (h, -h, 0), (h, h, 0), (-h, h, 0)), ((-h, -h, 3), (-h, h, 3), (h, h, 3), (h, -h, 3)),
             ((-h, -h, 0), (-h, -h, 3), (h, -h, 3), (h, -h, 0)), ((h, -h, 0), (h, -h, 3), (h, h, 3), (h, h, 0)),
             ((h, h, 0), (h, h, 3), (-h, h, 3), (-h, h, 0)), ((-h, h, 0), (-h, h, 3), (-h, -h, 3), (-h, -h, 0))]
    pts = [p for w in walls for p in w]
    room = f'''def Material "Wall"
{{
    token outputs:surface.connect = </Wall/S.outputs:surface>
    def Shader "S"
    {{
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = (0.5, 0.5, 0.5)
        token outputs:surface
    }}
}}
def Mesh "Room" (
    prepend apiSchemas = ["MaterialBindingAPI"]
)
{{
    int[] faceVertexCounts = [4, 4, 4, 4, 4, 4]
    int[] faceVertexIndices = [{", ".join(map(str, range(24)))}]
    point3f[] points = [{", ".join(f"({x}, {y}, {z})" for x, y, z in pts)}]
    rel material:binding = </Wall>
}}
'''
    sensors = [Sensor(name=f"s{i}", kind=SensorKind.IRRADIANCE, position=np.array([x, y, 0.01]),
                      normal=np.array([0.0, 0.0, 1.0])) for i, (x, y) in enumerate(
                          (x, y) for x in (-1.2, 0.0, 1.2) for y in (-1.2, 0.0, 1.2))]
    lamp = _lamp(np.array([-0.5, -0.5, 2.7]), True)
    for name, mat in (("chrome ball", CHROME), ("glossy ball", ("float inputs:roughness = 0.3\n        "
                                                                  "float inputs:metallic = 1", 0.9))):
        scene = _scene(folder, name.replace(" ", "_"), room + _material(*mat) + lamp)
        eng = Engine(scene, sensors)
        eng.run("path", samples=64, seed=seed)  # compile and warm
        t0 = time.process_time()
        eng.run("path", samples=samples, seed=seed)
        cpu = time.process_time() - t0
        print(f"{name} in a room: {1e6 * cpu / (samples * len(sensors)):.1f} µs of CPU per sample")


def flat_mirror_variance(folder: Path, samples: int, seed: int) -> None:
    """Variance per sample (lx²) of a down-facing irradiance sensor 1 m over a flat mirror (metallic 1,
    roughness 0, ρ 0.9, 20 km wide) that sees only the image of a sphere light (r 0.2 m), a disk (r
    0.2 m) or a rect light (0.4 m) 2 m over the mirror, intensity 100 photometric: the globe of
    tests/test_delta_paths.py. ``path``; compare trees on PYTHONPATH."""
    shapes = {"sphere": "float inputs:radius = 0.2", "disk": "float inputs:radius = 0.2",
              "rect": "float inputs:width = 0.4\n    float inputs:height = 0.4"}
    kinds = {"sphere": "SphereLight", "disk": "DiskLight", "rect": "RectLight"}
    h = 1e4
    mirror = (_material(*CHROME).split('def Sphere')[0]
              + f'''def Mesh "Plane" (
    prepend apiSchemas = ["MaterialBindingAPI"]
)
{{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(-{h}, -{h}, 0), ({h}, -{h}, 0), ({h}, {h}, 0), (-{h}, {h}, 0)]
    rel material:binding = </M>
}}
''')
    sensor = Sensor(name="s", kind=SensorKind.IRRADIANCE, position=np.array([0.0, 0.0, 1.0]),
                    normal=np.array([0.0, 0.0, -1.0]))
    for name, shape in shapes.items():
        light = (f'def {kinds[name]} "L"\n{{\n    float inputs:intensity = 100\n    {shape}\n'
                 '    double3 xformOp:translate = (0, 0, 2)\n    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n')
        scene = _scene(folder, f"flat_{name}", mirror + light)
        res = Engine(scene, [sensor]).run("path", samples=samples, seed=seed)
        se = float(res.stderr[0, 1])
        print(f"{name} light's image in a flat mirror: {float(res.mean[0, 1]):.6g} ± {se:.3g} lx, "
              f"variance per sample {se * se * samples:.3g} lx²")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--samples", type=int, default=4096)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--tessellation", type=int, nargs=2, metavar=("N_LON", "N_LAT"),
                    help="the ball's probesim:tessellation (default: the Sphere's own 64 × 32)")
    ap.add_argument("--flat-mirror", action="store_true", help="variance per sample of area lights' images in a "
                    "flat mirror at an irradiance sensor (flat_mirror_variance)")
    ap.add_argument("--cost", action="store_true", help="CPU per sample of a room with a chrome ball and a lamp "
                    "against the same ball glossy (room_cost)")
    args = ap.parse_args()
    global TESSELLATION
    TESSELLATION = args.tessellation
    if args.flat_mirror:
        with tempfile.TemporaryDirectory() as tmp:
            flat_mirror_variance(Path(tmp), args.samples, args.seed)
        return
    if args.cost:
        with tempfile.TemporaryDirectory() as tmp:
            room_cost(Path(tmp), args.samples, args.seed)
        return
    with tempfile.TemporaryDirectory() as tmp:
        print(f"{'case':22s} {'reading':>14s} {'± stderr':>11s} {'closed form':>14s} {'difference':>11s}")
        for name, scene, sensor, truth, unit in cases(Path(tmp)):
            res = Engine(scene, [sensor]).run("path", samples=args.samples, seed=args.seed)
            v, se = float(res.mean[0, 1]), float(res.stderr[0, 1])
            print(f"{name:22s} {v:14.6g} {se:11.3g} {truth:14.6g} {100 * (v / truth - 1):+10.2f}%  {unit}")


if __name__ == "__main__":
    main()
