"""USD as people author it, traced: instancers, subsets, implicit shapes, white floors, image domes.

Each stage is a few lines of usda written to ``tmp_path``; the readings are
checked against closed forms from ``simulator.reference.closed_forms``.

Most scenes are lit by a zero-angle DistantLight shining down -Z of
``inputs:intensity = 1000``: a delta direction, so an irradiance sensor facing
up reads exactly E = 1000 lx (photometric channel) where the sky is open and
exactly 0 in a shadow, with a standard error of 0, and a radiance meter
looking at a floor reads rho E / pi exactly (one delta light, one reflection:
nothing random). Those readings are held to float32 precision (2e-6 relative)
plus 1e-9 absolute. Dome readings are Monte Carlo: |estimate - truth| <= 4
standard errors (+2e-6 relative), fixed seeds.
"""

from __future__ import annotations

import math
import struct
import zlib
from pathlib import Path

import numpy as np

from simulator.engine.driver import Engine
from simulator.reference import closed_forms as cf
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage

E_SUN = 1000.0  # lx: the DistantLight's intensity (normal illuminance of a delta sun)
SUN = 'def DistantLight "Sun"\n{\n    float inputs:intensity = 1000\n    float inputs:angle = 0\n}\n'
F32 = 2e-6


def stage(tmp_path: Path, body: str, name: str = "s.usda") -> Path:
    path = tmp_path / name
    path.write_text(f'#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n\n{body}\n')
    return path


def up_sensor(name: str, x: float, y: float, z: float = 0.0) -> Sensor:
    return Sensor(name=name, kind=SensorKind.IRRADIANCE, position=np.array([x, y, z], float),
                  normal=np.array([0.0, 0.0, 1.0]))


def down_meter(name: str, x: float, y: float, z: float = 1.0) -> Sensor:
    return Sensor(name=name, kind=SensorKind.RADIANCE, position=np.array([x, y, z], float),
                  normal=np.array([0.0, 0.0, -1.0]))


def read(path: Path, sensors: list[Sensor], method: str = "light", samples: int = 64, seed: int = 5):
    """Photometric readings and standard errors of ``sensors`` in the stage at ``path``."""
    scene = load_stage(path)
    res = Engine(scene, sensors).run(method, samples=samples, seed=seed)
    return scene, res.mean[:, 1], res.stderr[:, 1]


def assert_exact(values, expected, names):
    for v, e, n in zip(values, expected, names):
        assert abs(v - e) <= F32 * abs(e) + 1e-9, f"{n}: {v} vs {e}"


def material(name: str, rho: float) -> str:
    return f"""
def Material "{name}"
{{
    token outputs:surface.connect = </{name}/S.outputs:surface>
    def Shader "S"
    {{
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = ({rho}, {rho}, {rho})
        token outputs:surface
    }}
}}
"""


# --------------------------------------------------------------------------- #
# PointInstancer
# --------------------------------------------------------------------------- #

INSTANCER = """
def Xform "Set"
{
    double3 xformOp:translate = (0, 0, 1)
    uniform token[] xformOpOrder = ["xformOp:translate"]

    def PointInstancer "Boxes"
    {
        rel prototypes = [</Set/Boxes/Protos/Box>, </Set/Boxes/Protos/Bar>, </Set/Boxes/Protos/Row>]
        int[] protoIndices = [0, 0, 0, 1, 2, 2]
        int64[] ids = [10, 11, 12, 13, 14, 15]
        int64[] invisibleIds = [12]
        point3f[] positions = [(0, 0, 0), (3, 0, 0), (6, 0, 0), (20, 0, 0), (10, 0, 0), (10, 4, 0)]
        quath[] orientations = [(1, 0, 0, 0), (1, 0, 0, 0), (1, 0, 0, 0),
                                (0.70710678, 0, 0, 0.70710678), (1, 0, 0, 0), (1, 0, 0, 0)]
        float3[] scales = [(1, 1, 1), (1, 1, 1), (1, 1, 1), (4, 0.2, 0.2), (1, 1, 1), (1, 1, 1)]

        def Xform "Protos"
        {
            double3 xformOp:translate = (50, 0, 0)
            uniform token[] xformOpOrder = ["xformOp:translate"]

            def Cube "Box"
            {
                double size = 1
            }
            def Cube "Bar"
            {
                double size = 1
            }
            def PointInstancer "Row"
            {
                rel prototypes = [</Set/Boxes/Protos/Row/Cell>]
                int[] protoIndices = [0, 0]
                point3f[] positions = [(0, 0, 0), (2, 0, 0)]
                def Cube "Cell"
                {
                    double size = 1
                }
            }
        }
    }
}
"""

# (name, x, y, shadowed)
INSTANCER_SENSORS = [
    ("under_box_0", 0.0, 0.0, True),
    ("under_box_1", 3.0, 0.0, True),
    ("between_boxes", 1.5, 0.0, False),
    ("beside_box", 0.0, 2.0, False),
    ("invisible_id_12", 6.0, 0.0, False),
    ("prototype_own_place", 50.0, 0.0, False),
    ("row_0_cell_0", 10.0, 0.0, True),
    ("row_0_cell_1", 12.0, 0.0, True),
    ("row_1_cell_0", 10.0, 4.0, True),
    ("row_1_cell_1", 12.0, 4.0, True),
    ("between_cells", 11.0, 0.0, False),
    ("bar_turned_along_y", 20.0, 1.5, True),
    ("bar_if_not_turned", 21.5, 0.0, False),
    ("bar_if_not_scaled", 20.3, 0.0, False),
]


def test_point_instancer_shadows_exactly_where_instances_stand(tmp_path):
    """Unit cubes instanced 1 m up (the instancer's parent translates it) under a
    delta sun: sensors under an instance read 0, all others E = 1000 lx.

    Checked at once: two plain instances; an ``invisibleIds`` instance (no
    shadow); the prototypes' own place (their parent Xform at x = 50 is not
    part of an instance transform, and a prototype is never drawn in place);
    a nested instancer (2 cells x 2 rows: cells at x = 10, 12 and y = 0, 4);
    a bar scaled (4, 0.2, 0.2) and turned 90 degrees about Z by a quath
    orientation, so it spans y in [-2, 2] and x in [19.9, 20.1].
    """
    sensors = [up_sensor(n, x, y) for n, x, y, _ in INSTANCER_SENSORS]
    scene, value, stderr = read(stage(tmp_path, SUN + INSTANCER), sensors)
    assert scene.geometry.n_triangles == 12 * (2 + 1 + 4)
    expected = [0.0 if shadowed else E_SUN for *_, shadowed in INSTANCER_SENSORS]
    assert_exact(value, expected, [n for n, *_ in INSTANCER_SENSORS])
    assert np.all(stderr == 0.0)


# --------------------------------------------------------------------------- #
# GeomSubset material bindings and albedo 1
# --------------------------------------------------------------------------- #

SUBSET_FLOOR = """
def Mesh "Floor"
{
    int[] faceVertexCounts = [4, 4, 4]
    int[] faceVertexIndices = [0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6]
    point3f[] points = [(-2, -1, 0), (0, -1, 0), (2, -1, 0), (4, -1, 0),
                        (-2, 1, 0), (0, 1, 0), (2, 1, 0), (4, 1, 0)]
    rel material:binding = </Grey>
    uniform token subsetFamily:materialBind:familyType = "partition"

    def GeomSubset "BlackHalf"
    {
        uniform token elementType = "face"
        uniform token familyName = "materialBind"
        int[] indices = [0]
        rel material:binding = </Black>
    }
    def GeomSubset "WhiteHalf"
    {
        uniform token elementType = "face"
        uniform token familyName = "materialBind"
        int[] indices = [1]
        rel material:binding = </White>
    }
}
"""


def test_geom_subsets_give_each_face_its_own_albedo(tmp_path):
    """A floor of three faces: subsets bind rho = 0.05 and 0.9 to the first two,
    the mesh's own binding (0.5) covers the third. A radiance meter above each
    face, looking down, reads rho E / pi (Lambertian reflection of the delta
    sun, ``closed_forms.lambertian_radiance``)."""
    body = SUN + material("Black", 0.05) + material("White", 0.9) + material("Grey", 0.5) + SUBSET_FLOOR
    meters = [down_meter("black", -1.0, 0.0), down_meter("white", 1.0, 0.0), down_meter("grey", 3.0, 0.0)]
    _, value, stderr = read(stage(tmp_path, body), meters)
    expected = [cf.lambertian_radiance(rho, E_SUN) for rho in (0.05, 0.9, 0.5)]
    assert_exact(value, expected, [m.name for m in meters])
    assert np.all(stderr == 0.0)


def test_albedo_one_reads_e_over_pi_in_an_open_scene(tmp_path):
    """diffuseColor (1, 1, 1) is accepted (with a warning): the white floor's
    radiance is E / pi. Traced with interreflection on ("path"): paths leave the
    floor upward and escape, so the run ends and the reading is exact."""
    floor = """
def Mesh "Floor"
{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(-5, -5, 0), (5, -5, 0), (5, 5, 0), (-5, 5, 0)]
    rel material:binding = </Snow>
}
"""
    scene, value, stderr = read(stage(tmp_path, SUN + material("Snow", 1.0) + floor), [down_meter("m", 0.0, 0.0)],
                                method="path")
    assert np.all(scene.geometry.albedo == 1.0)
    assert any("albedo 1" in w and "/Floor" in w for w in scene.warnings)
    assert_exact(value, [cf.lambertian_radiance(1.0, E_SUN)], ["white floor"])


# --------------------------------------------------------------------------- #
# Capsule, Cone, Cylinder, Plane
# --------------------------------------------------------------------------- #

SHAPES = """
def Capsule "Capsule"
{
    double radius = 0.5
    double height = 1
    double3 xformOp:translate = (0, 0, 2)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Cone "Cone"
{
    double radius = 0.5
    double height = 1
    double3 xformOp:translate = (10, 0, 2)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Cylinder "Cylinder"
{
    double radius = 0.5
    double height = 4
    uniform token axis = "X"
    double3 xformOp:translate = (20, 0, 2)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Plane "Plane"
{
    double width = 1
    double length = 3
    double3 xformOp:translate = (30, 0, 2)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
"""

# (name, x, y, shadowed): under each shape, and beside it (3 m off, in the sun)
SHAPE_SENSORS = [
    ("under_capsule", 0.0, 0.0, True), ("beside_capsule", 0.0, 3.0, False),
    ("under_cone", 10.0, 0.0, True), ("under_cone_rim", 10.4, 0.0, True), ("beside_cone", 10.0, 3.0, False),
    ("under_cylinder_end", 21.5, 0.0, True), ("beside_cylinder", 20.0, 0.8, False),
    ("under_plane_far_end", 30.0, 1.4, True), ("beside_plane", 30.8, 0.0, False),
]


def test_capsule_cone_cylinder_plane_cast_shadows(tmp_path):
    """Each implicit shape 2 m up under the delta sun: a sensor under it reads 0,
    one beside it E = 1000 lx. The Cylinder lies along X (axis = "X", 4 m long),
    so x = 21.5 is under it and y = 0.8 is not; the Plane is 1 x 3 m (width
    along X, length along Y), so y = 1.4 is under it and x = 0.8 is not."""
    sensors = [up_sensor(n, x, y) for n, x, y, _ in SHAPE_SENSORS]
    scene, value, stderr = read(stage(tmp_path, SUN + SHAPES), sensors)
    expected = [0.0 if shadowed else E_SUN for *_, shadowed in SHAPE_SENSORS]
    assert_exact(value, expected, [n for n, *_ in SHAPE_SENSORS])
    assert not [w for w in scene.warnings if "not read" in w]


# --------------------------------------------------------------------------- #
# dome textures: Radiance .hdr and 8-bit PNG
# --------------------------------------------------------------------------- #

def _rgbe_uniform(path: Path, width: int, height: int, rgbe: tuple[int, int, int, int]) -> None:
    """A flat (not run-length encoded) Radiance picture, every pixel the bytes ``rgbe``."""
    head = f"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {height} +X {width}\n".encode()
    path.write_bytes(head + bytes(rgbe) * (width * height))


def _png_grey(path: Path, width: int, height: int, value: int) -> None:
    """An 8-bit greyscale PNG (colour type 0), every pixel ``value``, written from the PNG specification."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    raw = b"".join(b"\x00" + bytes([value]) * width for _ in range(height))  # filter 0 per row
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw))
                     + chunk(b"IEND", b""))


def _dome(texture: str) -> str:
    return f'def DomeLight "Sky"\n{{\n    float inputs:intensity = 100\n    asset inputs:texture:file = @{texture}@\n}}\n'


def _dome_reading(tmp_path, texture: str):
    sensors = [up_sensor("up", 0.0, 0.0)]
    scene, value, stderr = read(stage(tmp_path, _dome(texture)), sensors, method="light", samples=20000, seed=11)
    return scene, float(value[0]), float(stderr[0])


def test_hdr_dome_texture_reads_pi_l(tmp_path):
    """A uniform 16 x 8 Radiance picture of bytes (192, 192, 192, 128) decodes to
    (192 + 1/2) * 2**(128 - 136) = 0.751953125 (Radiance ``colr_color``), so the
    dome's radiance is 100 x 0.751953125 nit and an open upward sensor reads
    E = pi L (``closed_forms.dome_irradiance`` at tilt 0) within 4 sigma."""
    _rgbe_uniform(tmp_path / "sky.hdr", 16, 8, (192, 192, 192, 128))
    scene, value, se = _dome_reading(tmp_path, "sky.hdr")
    truth = float(cf.dome_irradiance(100 * 0.751953125, 0.0))
    assert abs(value - truth) <= 4 * se + F32 * truth, (value, truth, se)
    assert not any("clips" in w for w in scene.warnings)


def test_png_dome_texture_is_srgb_decoded_with_a_warning(tmp_path):
    """A uniform 8-bit PNG of value 128 is sRGB: linear ((128/255 + 0.055)/1.055)**2.4
    = 0.2158605 (IEC 61966-2-1), not 128/255 = 0.502. The sensor reads
    pi x 100 x 0.2158605 within 4 sigma, and one warning says the map clips."""
    _png_grey(tmp_path / "sky.png", 16, 8, 128)
    scene, value, se = _dome_reading(tmp_path, "sky.png")
    linear = ((128 / 255 + 0.055) / 1.055) ** 2.4
    assert math.isclose(linear, 0.2158605, rel_tol=1e-6)
    truth = float(cf.dome_irradiance(100 * linear, 0.0))
    assert abs(value - truth) <= 4 * se + F32 * truth, (value, truth, se)
    assert abs(value - truth * (128 / 255) / linear) > 100 * se  # the undecoded value is far off
    assert sum("clips" in w for w in scene.warnings) == 1
