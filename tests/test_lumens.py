"""A luminaire given by its lumens (``probesim:flux_lm``) or watts × efficacy.

The light must emit exactly the stated lumens as traced, whatever its kind
and shaping (simulator.scene.usd.flux, simulator.scene.light_flux):

- conversions against the closed forms Φ = π A L (rect, disk), 4π² r² L
  (sphere), 2π² r ℓ L (cylinder side), 4π I (point), 2π(1 − cos θc)·I (a
  point light's hard cone), π sin²θc·A·L (a flat light's hard cone);
- the illuminance under a 3,000 lm 0.6 × 0.6 m panel against the rectangle
  form factor (Howell's catalogue, C-11: a point under the corner of a
  parallel rectangle, F = (1/2π)[X/√(1+X²)·atan(Y/√(1+X²)) + Y/√(1+Y²)·atan(X/√(1+Y²))]);
- an enclosing measurement: 24 inward patches tiling a cube around the light
  catch all it emits, Σ E·A = Φ within 4 combined standard errors, per kind
  (rect, disk, sphere, cylinder, an IES-shaped point and rect light, a soft
  cone with focus);
- conflicting or bad inputs refused in one line naming the prim.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from simulator.config.loader import load_config
from simulator.engine.driver import Engine
from simulator.errors import UserError
from simulator.pipeline import collect_sensors, load_scene, run
from simulator.scene.light_flux import emitted_flux
from simulator.scene.model import LightKind

H_M = 1.5  # light height above the origin
ASYM_IES = Path("tests/data/photometry/asymmetric_2002_crlf.ies").resolve()
REL = 1e-9  # conversions are closed forms in float64


def _stage(tmp_path, kind: str, body: str, api: str = "") -> None:
    apis = f' (\n        prepend apiSchemas = ["{api}"]\n    )' if api else ""
    (tmp_path / "s.usda").write_text(f'''#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def {kind} "Lamp"{apis}
{{
{body}
    double3 xformOp:translate = (0, 0, {H_M})
    uniform token[] xformOpOrder = ["xformOp:translate"]
}}
''')


def _config(tmp_path, sensors: str = "", samples: int = 64) -> Path:
    if not sensors:
        sensors = '[[sensor]]\nname = "below"\nkind = "irradiance"\nposition = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n'
    (tmp_path / "c.toml").write_text(f'stage = "s.usda"\n[simulation]\nsamples = {samples}\nseed = 1\n\n{sensors}')
    return tmp_path / "c.toml"


def _light(tmp_path, kind, body, api=""):
    _stage(tmp_path, kind, body, api)
    scene = load_scene(load_config(_config(tmp_path)))
    assert len(scene.lights) == 1
    return scene.lights[0]


RECT = "    float inputs:width = 0.6\n    float inputs:height = 0.6\n"
DISK = "    float inputs:radius = 0.25\n"
SPHERE = "    float inputs:radius = 0.1\n"
CYLINDER = "    float inputs:radius = 0.05\n    float inputs:length = 1.2\n"
POINT = "    float inputs:radius = 0\n    bool treatAsPoint = 1\n"
FLUX = "    float probesim:flux_lm = 3000\n"


@pytest.mark.parametrize("kind,body,per_emission", [
    ("RectLight", RECT, math.pi * 0.36),
    ("DiskLight", DISK, math.pi * math.pi * 0.25**2),
    ("SphereLight", SPHERE, 4 * math.pi**2 * 0.1**2),
    ("CylinderLight", CYLINDER, 2 * math.pi**2 * 0.05 * 1.2),
    ("SphereLight", POINT, 4 * math.pi),
])
def test_lumens_give_the_closed_form_emission(tmp_path, kind, body, per_emission):
    """3000 lm → L (or I) = 3000 / G with G the kind's closed form (module docstring)."""
    light = _light(tmp_path, kind, body + FLUX)
    assert light.emission[1] == pytest.approx(3000.0 / per_emission, rel=REL)
    assert emitted_flux(light)[1] == pytest.approx(3000.0, rel=REL)
    assert light.authored == {"flux_lm": 3000.0}


def test_watts_times_efficacy_are_the_lumens(tmp_path):
    """25 W at 120 lm/W is 3000 lm: the same panel as probesim:flux_lm = 3000."""
    light = _light(tmp_path, "RectLight", RECT + "    float probesim:power_W = 25\n    float probesim:efficacy_lm_per_W = 120\n")
    assert light.emission[1] == pytest.approx(3000.0 / (math.pi * 0.36), rel=REL)
    assert light.authored["flux_lm"] == pytest.approx(3000.0, rel=REL)


@pytest.mark.parametrize("kind,body,per_emission", [
    ("SphereLight", POINT, 2 * math.pi * (1 - math.cos(math.radians(30)))),
    ("DiskLight", DISK, math.pi * 0.25**2 * math.pi * math.sin(math.radians(30)) ** 2),
])
def test_a_hard_cone_keeps_the_lumens(tmp_path, kind, body, per_emission):
    """A 30° cone: ∫ f dω = 2π(1 − cos 30°) (point), A·∫ f cosθ dω = A·π sin²30° (flat light)."""
    light = _light(tmp_path, kind, body + FLUX + "    float inputs:shaping:cone:angle = 30\n", "ShapingAPI")
    assert light.emission[1] == pytest.approx(3000.0 / per_emission, rel=1e-9)


def test_ies_file_gives_only_the_shape(tmp_path):
    """An IES-shaped point light with its lumens stated: its candelas are the file's × Φ / Φ_file,
    whatever shaping:ies:normalize says."""
    from simulator.scene.photometry import read_photometry

    dist = read_photometry(ASYM_IES)
    shaped = f"    asset inputs:shaping:ies:file = @{ASYM_IES}@\n"
    for normalize in (0, 1):
        light = _light(tmp_path, "SphereLight", POINT + FLUX + shaped + f"    bool inputs:shaping:ies:normalize = {normalize}\n",
                       "ShapingAPI")
        peak_cd = light.emission[1] * light.shaping.ies_scale * dist.max_candela()
        assert peak_cd == pytest.approx(dist.max_candela() * 3000.0 / dist.total_lumens(), rel=1e-6)


def _corner_factor(x, y):
    """Form factor from a point to a parallel rectangle with a corner above it, X = a/h, Y = b/h."""
    return (x / math.sqrt(1 + x * x) * math.atan(y / math.sqrt(1 + x * x))
            + y / math.sqrt(1 + y * y) * math.atan(x / math.sqrt(1 + y * y))) / (2 * math.pi)


def test_panel_of_3000_lm_reads_its_closed_form_below(tmp_path):
    """E under the centre of a 3000 lm 0.6 × 0.6 m panel 1.5 m up: π L · 4 F(0.3/1.5, 0.3/1.5), L = 3000/(π·0.36).
    The run record states the lumens given, the luminance derived and the lumens emitted."""
    _stage(tmp_path, "RectLight", RECT + FLUX)
    out = run(load_config(_config(tmp_path)), log=lambda s: None, write=False)
    lum = 3000.0 / (math.pi * 0.36)
    truth = math.pi * lum * 4 * _corner_factor(0.3 / H_M, 0.3 / H_M)
    reading = out.rows[0].values["illuminance_lx"]
    stderr = out.rows[0].values.get("illuminance_stderr_lx", 0.0)
    assert abs(reading - truth) <= max(4 * stderr, 1e-6 * truth), (reading, stderr, truth)
    (rec,) = out.record["lights"]
    assert rec["authored"] == {"flux_lm": 3000.0}
    assert rec["emission"]["photometric"] == pytest.approx(lum, rel=REL)
    assert rec["emission"]["units"][1] == "cd/m²"
    assert rec["flux_lm"] == pytest.approx(3000.0, rel=REL)


def _cube_sensors(half=1.0, n=2) -> str:
    """Inward patches tiling a cube of half-size ``half`` centred on the light (all its flux)."""
    c = np.array([0.0, 0.0, H_M])
    s = 2 * half / n
    out, k = "", 0
    for axis in range(3):
        for sign in (-1, 1):
            normal, up = np.zeros(3), np.zeros(3)
            normal[axis] = -sign
            u_ax, v_ax = [a for a in range(3) if a != axis]
            up[v_ax] = 1.0
            for i in range(n):
                for j in range(n):
                    p = c.copy()
                    p[axis] += sign * half
                    p[u_ax] += -half + (i + 0.5) * s
                    p[v_ax] += -half + (j + 0.5) * s
                    out += (f'[[sensor]]\nname = "p{k}"\nkind = "patch"\nposition = {list(map(float, p))}\n'
                            f'normal = {list(map(float, normal))}\nsize = [{s}, {s}]\nup = {list(map(float, up))}\n\n')
                    k += 1
    return out


@pytest.mark.parametrize("kind,body,api", [
    ("RectLight", RECT, ""),
    ("DiskLight", DISK + "    float inputs:shaping:cone:angle = 50\n    float inputs:shaping:cone:softness = 0.4\n"
                        "    float inputs:shaping:focus = 2\n    float inputs:shaping:focusTint = 0.2\n", "ShapingAPI"),
    ("SphereLight", SPHERE, ""),
    ("CylinderLight", CYLINDER, ""),
    ("SphereLight", POINT + f"    asset inputs:shaping:ies:file = @{ASYM_IES}@\n", "ShapingAPI"),
    ("RectLight", RECT + f"    asset inputs:shaping:ies:file = @{ASYM_IES}@\n", "ShapingAPI"),
], ids=["rect", "disk-soft-cone-focus", "sphere", "cylinder", "point-ies", "rect-ies"])
def test_enclosing_cube_catches_the_stated_lumens(tmp_path, kind, body, api):
    """Σ over 24 inward patches of E·A = 3000 lm within 4 combined standard errors (and a 1% error bar)."""
    _stage(tmp_path, kind, body + FLUX, api)
    cfg = load_config(_config(tmp_path, _cube_sensors(), samples=16384))
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    res = Engine(scene, sensors).run("light", samples=16384, seed=1)
    area = np.array([s.size[0] * s.size[1] for s in sensors])
    flux = float(np.sum(res.mean[:, 1] * area))
    se = float(np.sqrt(np.sum((res.stderr[:, 1] * area) ** 2)))
    assert abs(flux - 3000.0) <= 4 * se + 1e-6 * 3000.0, (flux, se)
    assert se < 0.01 * 3000.0


@pytest.mark.parametrize("body,message", [
    (RECT + FLUX + "    float probesim:power_W = 25\n    float probesim:efficacy_lm_per_W = 120\n", "state the output once"),
    (RECT + "    float probesim:power_W = 25\n", "needs probesim:efficacy_lm_per_W"),
    (RECT + "    float probesim:efficacy_lm_per_W = 120\n", "needs probesim:power_W"),
    (RECT + FLUX + "    float inputs:intensity = 500\n", "inputs:intensity"),
    (RECT + FLUX + "    float intensity = 500\n", "intensity"),
    (RECT + FLUX + "    float inputs:exposure = 2\n", "inputs:exposure"),
    (RECT + FLUX + "    bool inputs:normalize = 1\n", "inputs:normalize"),
    (RECT + "    float probesim:flux_lm = -3000\n", "non-negative"),
    (RECT + '    string probesim:flux_lm = "3000"\n', "must be a number"),
])
def test_conflicting_or_bad_output_is_one_line_naming_the_prim(tmp_path, body, message):
    _stage(tmp_path, "RectLight", body)
    with pytest.raises(UserError) as e:
        load_scene(load_config(_config(tmp_path)))
    text = str(e.value)
    assert "/Lamp" in text and message in text and "\n" not in text, text


def test_lumens_refused_where_no_finite_flux_or_with_absolute_ies(tmp_path):
    """A DistantLight has no finite flux; probesim:ies:absolute states the output a second time."""
    _stage(tmp_path, "DistantLight", FLUX)
    with pytest.raises(UserError, match=r"/Lamp: probesim:flux_lm: a Distant light has no finite flux"):
        load_scene(load_config(_config(tmp_path)))
    _stage(tmp_path, "SphereLight", POINT + FLUX + f"    asset inputs:shaping:ies:file = @{ASYM_IES}@\n"
           "    bool probesim:ies:absolute = 1\n", "ShapingAPI")
    with pytest.raises(UserError, match=r"/Lamp: both probesim:flux_lm and probesim:ies:absolute"):
        load_scene(load_config(_config(tmp_path)))


def test_normalize_off_and_no_lumens_keep_todays_emission(tmp_path):
    """Without lumens nothing changes: L = intensity·2^exposure (RectLight, normalize off); the record says so."""
    light = _light(tmp_path, "RectLight", RECT + "    float inputs:intensity = 500\n    float inputs:exposure = 1\n")
    assert light.emission[1] == pytest.approx(1000.0, rel=REL)
    assert light.authored == {"intensity": 500.0, "exposure": 1.0, "normalize": False, "color_grey": 1.0}
    assert emitted_flux(light)[1] == pytest.approx(1000.0 * math.pi * 0.36, rel=REL)
    assert light.kind == LightKind.RECT


def test_lumens_on_a_mesh_light_are_refused(tmp_path):
    """A mesh light (MeshLightAPI) does not read probesim:flux_lm: one line naming the prim, not a silent intensity 1."""
    (tmp_path / "s.usda").write_text('''#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def Mesh "Lamp" (
    prepend apiSchemas = ["MeshLightAPI"]
)
{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(-0.3, -0.3, 2), (-0.3, 0.3, 2), (0.3, 0.3, 2), (0.3, -0.3, 2)]
    float probesim:flux_lm = 3000
}
''')
    with pytest.raises(UserError, match=r"/Lamp: probesim:flux_lm/probesim:power_W/probesim:efficacy_lm_per_W are read on "
                                        r"Sphere, Rect, Disk and Cylinder lights, not on a mesh light"):
        load_scene(load_config(_config(tmp_path)))


def test_record_states_an_absolute_ies_lights_lumens(tmp_path):
    """probesim:ies:absolute: the light emits the file's candelas × LLF, so its lumens as traced are
    LLF × the file's total lumens (the file's bilinear interpolant integrated exactly, as traced)."""
    from simulator.scene.light_flux import lights_record
    from simulator.scene.photometry import read_photometry

    light = _light(tmp_path, "SphereLight", POINT + f"    asset inputs:shaping:ies:file = @{ASYM_IES}@\n"
                   "    bool probesim:ies:absolute = 1\n    float probesim:lightLossFactor = 0.8\n", "ShapingAPI")
    (rec,) = lights_record([light])
    assert rec["authored"] == {"ies_absolute": True, "light_loss_factor": pytest.approx(0.8, rel=1e-7)}
    assert rec["shaping"] == "ies" and rec["emission"]["units"] == ["W/sr", "cd"]
    # 1e-7: the LLF is read as float32 (0.800000012); the two integrals agree to 1e-15
    assert rec["flux_lm"] == pytest.approx(0.8 * read_photometry(ASYM_IES).total_lumens(), rel=1e-7)
