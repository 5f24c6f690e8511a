"""UsdLuxShapingAPI: spot cones, focus, and IES/EULUMDAT luminaires.

Readings of a shaped point light follow E = I(ω)·cosψ/d² (the inverse-
square cosine law with the direction-dependent intensity I(ω) = I0 ×
shaping factor; OpenUSD user guide, "ShapingAPI": cone, softness, focus).
A point light is a delta distribution: its sample is exact, so unoccluded
receivers read the formula to float32 precision with zero variance.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from simulator.config.loader import load_config
from simulator.engine.driver import Engine
from simulator.errors import UserError
from simulator.pipeline import collect_sensors, load_scene
from simulator.scene.photometry import read_photometry

FLOAT32_SLACK = 2e-6
H_M = 3.0  # light height


def _stage(tmp_path, light_body: str, kind: str = "SphereLight") -> None:
    (tmp_path / "s.usda").write_text(f'''#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
    defaultPrim = "World"
)
def Xform "World"
{{
    def {kind} "Lamp" (
        prepend apiSchemas = ["ShapingAPI"]
    )
    {{
{light_body}
        double3 xformOp:translate = (0, 0, {H_M})
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }}
}}
''')


def _sensor_toml(name, p, n):
    return f'[[sensor]]\nname = "{name}"\nkind = "irradiance"\nposition = [{p[0]!r}, {p[1]!r}, {p[2]!r}]\nnormal = [{n[0]!r}, {n[1]!r}, {n[2]!r}]\n\n'


def _run(tmp_path, sensors, method="light", samples=64, extra=""):
    body = "".join(_sensor_toml(*s) for s in sensors)
    (tmp_path / "c.toml").write_text(f'stage = "s.usda"\n{extra}\n[simulation]\nsamples = {samples}\nseed = 1\n\n{body}')
    cfg = load_config(tmp_path / "c.toml")
    scene = load_scene(cfg)
    res = Engine(scene, collect_sensors(cfg, scene)).run(method, samples=samples, seed=1)
    return scene, res


POINT_100CD = """        float inputs:intensity = 400
        bool inputs:normalize = 1
        float inputs:radius = 0
        bool treatAsPoint = 1"""


def _floor(x):
    return (f"x{x}", (x, 0.0, 0.0), (0.0, 0.0, 1.0))


def _e_floor(i_cd, x):
    """E = I·cosψ/d² on the floor at (x, 0, 0) from (0, 0, H): cosψ = H/d."""
    d2 = x * x + H_M * H_M
    return i_cd * H_M / d2**1.5


def _theta(x):
    return math.atan2(abs(x), H_M)


def test_spot_cone_inside_exact_outside_zero(tmp_path):
    """A 30° cone: receivers at 0°, 18.4° and 29.1° off axis read
    100 cd·cosψ/d² exactly (zero variance); at 30.5°, 45° and 80° they read 0."""
    _stage(tmp_path, POINT_100CD + "\n        float inputs:shaping:cone:angle = 30")
    xs = [0.0, 1.0, 1.67, 1.77, 3.0, 17.0]
    scene, res = _run(tmp_path, [_floor(x) for x in xs])
    assert scene.lights[0].shaping is not None
    for i, x in enumerate(xs):
        inside = math.degrees(_theta(x)) <= 30.0
        truth = _e_floor(100.0, x) if inside else 0.0
        assert res.stderr[i, 1] == 0.0
        assert abs(res.mean[i, 1] - truth) <= FLOAT32_SLACK * truth + 1e-12, (x, res.mean[i, 1], truth)


@pytest.mark.parametrize("softness", [0.5, 1.0])
def test_spot_cone_softness_follows_smoothstep(tmp_path, softness):
    """Softness s: factor 1 − smoothstep(θc(1 − s), θc, θ) (OpenUSD
    ShapingAPI, θ_smoothStart = lerp(s, θc, 0)); 1 inside θc(1 − s)."""
    _stage(tmp_path, POINT_100CD + f"\n        float inputs:shaping:cone:angle = 40\n        float inputs:shaping:cone:softness = {softness}")
    xs = [0.0, 0.5, 1.0, 1.5, 2.0, 2.4]
    scene, res = _run(tmp_path, [_floor(x) for x in xs])
    cut = math.radians(40.0)
    start = cut * (1 - softness)
    for i, x in enumerate(xs):
        th = _theta(x)
        t = min(max((th - start) / (cut - start), 0.0), 1.0)
        truth = _e_floor(100.0, x) * (1 - t * t * (3 - 2 * t))
        assert abs(res.mean[i, 1] - truth) <= FLOAT32_SLACK * _e_floor(100.0, x) + 1e-9, (x, res.mean[i, 1], truth)


def test_focus_and_tint(tmp_path):
    """Focus f with tint τ: factor τ + (1 − τ)·cos^f θ (a 90° cone is the default)."""
    _stage(tmp_path, POINT_100CD + "\n        float inputs:shaping:focus = 4\n        color3f inputs:shaping:focusTint = (0.25, 0.25, 0.25)")
    xs = [0.0, 1.0, 2.0, 5.0]
    _, res = _run(tmp_path, [_floor(x) for x in xs])
    for i, x in enumerate(xs):
        c = math.cos(_theta(x))
        truth = _e_floor(100.0, x) * (0.25 + 0.75 * c**4)
        assert abs(res.mean[i, 1] - truth) <= FLOAT32_SLACK * truth + 1e-12


ASYM_IES = "tests/data/photometry/asymmetric_2002_crlf.ies"


def _ies_light(path, absolute=True, llf=None, normalize=False):
    body = POINT_100CD + f'\n        asset inputs:shaping:ies:file = @{path}@\n        float inputs:shaping:cone:angle = 180'
    if absolute:
        body += "\n        bool probesim:ies:absolute = 1"
    if llf is not None:
        body += f"\n        float probesim:lightLossFactor = {llf}"
    if normalize:
        body += "\n        bool inputs:shaping:ies:normalize = 1"
    return body


def _around(n_dirs=8, r=2.0):
    """Receivers on a sphere of radius r about the light, each facing it
    (cosψ = 1), at (θ, φ) from the light's −Z axis and +X."""
    rng = np.random.default_rng(3)
    out = []
    for k in range(n_dirs):
        th = math.radians(rng.uniform(2, 178))
        ph = math.radians(rng.uniform(0, 360))
        d = np.array([math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), -math.cos(th)])
        p = np.array([0, 0, H_M]) + r * d
        out.append((f"d{k}", tuple(map(float, p)), tuple(map(float, -d)), th, ph))
    return out


@pytest.mark.parametrize("llf", [None, 0.8])
def test_absolute_ies_candelas_reproduced(tmp_path, llf):
    """Absolute mode: E·d²/cosψ at 8 directions equals the file's candela
    (bilinear between measured angles) × the light loss factor, whatever the
    authored intensity."""
    from pathlib import Path

    ies = Path(ASYM_IES).resolve()
    _stage(tmp_path, _ies_light(ies, llf=llf))
    rec = _around()
    _, res = _run(tmp_path, [(n, p, d) for n, p, d, _, _ in rec])
    dist = read_photometry(ies)
    for i, (_, _, _, th, ph) in enumerate(rec):
        truth = dist.candela_at(math.degrees(th), math.degrees(ph)) * (llf or 1.0)
        got = res.mean[i, 1] * 4.0
        assert abs(got - truth) <= 1e-5 * truth + 1e-9, (math.degrees(th), math.degrees(ph), got, truth)


def test_relative_ies_peak_is_authored_intensity(tmp_path):
    """Relative mode (normalize 0): I(ω) = I0 · I_file(ω)/max I_file."""
    from pathlib import Path

    ies = Path(ASYM_IES).resolve()
    _stage(tmp_path, _ies_light(ies, absolute=False))
    rec = _around()
    _, res = _run(tmp_path, [(n, p, d) for n, p, d, _, _ in rec])
    dist = read_photometry(ies)
    for i, (_, _, _, th, ph) in enumerate(rec):
        truth = 100.0 * dist.candela_at(math.degrees(th), math.degrees(ph)) / dist.max_candela()
        assert abs(res.mean[i, 1] * 4.0 - truth) <= 1e-5 * truth + 1e-9


def test_cone_does_not_affect_an_ies_profile(tmp_path):
    """UsdLux ShapingAPI: the cone angle "does not affect IES profiles (if any
    are applied for this light)": a 10° cone on an IES light leaves every
    direction, inside or far outside the cone, at the file's candela."""
    from pathlib import Path

    ies = Path(ASYM_IES).resolve()
    _stage(tmp_path, _ies_light(ies).replace("float inputs:shaping:cone:angle = 180", "float inputs:shaping:cone:angle = 10"))
    rec = _around()
    _, res = _run(tmp_path, [(n, p, d) for n, p, d, _, _ in rec])
    dist = read_photometry(ies)
    assert any(th > math.radians(10) for _, _, _, th, _ in rec)
    for i, (_, _, _, th, ph) in enumerate(rec):
        truth = dist.candela_at(math.degrees(th), math.degrees(ph))
        assert abs(res.mean[i, 1] * 4.0 - truth) <= 1e-5 * truth + 1e-9


def _cube_patches(half=1.0, n=2):
    """Inward-facing patches tiling a cube of half-size ``half`` centred on the light."""
    c = np.array([0, 0, H_M])
    s = 2 * half / n
    out = []
    for axis in range(3):
        for sign in (-1, 1):
            normal = np.zeros(3)
            normal[axis] = -sign
            u_ax, v_ax = [a for a in range(3) if a != axis]
            up = np.zeros(3)
            up[v_ax] = 1.0
            for i in range(n):
                for j in range(n):
                    p = c.copy()
                    p[axis] += sign * half
                    p[u_ax] += -half + (i + 0.5) * s
                    p[v_ax] += -half + (j + 0.5) * s
                    out.append((p, normal, up, s))
    return out


@pytest.mark.parametrize("normalize", [False, True])
def test_total_flux_through_closed_cube_matches_total_lumens(tmp_path, normalize):
    """24 patches closing a cube around the luminaire catch all its flux:
    Σ Φ = total_lumens() (absolute mode) or, normalized relative mode,
    4π·I0 (the unshaped light's flux), within 4 combined standard errors."""
    from pathlib import Path

    ies = Path(ASYM_IES).resolve()
    _stage(tmp_path, _ies_light(ies, absolute=not normalize, normalize=normalize))
    body = ""
    for k, (p, n, up, s) in enumerate(_cube_patches()):
        p, n, up = (list(map(float, v)) for v in (p, n, up))
        body += (f'[[sensor]]\nname = "p{k}"\nkind = "patch"\nposition = [{p[0]!r}, {p[1]!r}, {p[2]!r}]\n'
                 f'normal = [{n[0]!r}, {n[1]!r}, {n[2]!r}]\nsize = [{s!r}, {s!r}]\nup = [{up[0]!r}, {up[1]!r}, {up[2]!r}]\n\n')
    (tmp_path / "c.toml").write_text(f'stage = "s.usda"\n[simulation]\nsamples = 16384\nseed = 1\n\n{body}')
    cfg = load_config(tmp_path / "c.toml")
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    res = Engine(scene, sensors).run("light", samples=16384, seed=1)
    area = np.array([s.size[0] * s.size[1] for s in sensors])
    flux = float(np.sum(res.mean[:, 1] * area))
    se = float(np.sqrt(np.sum((res.stderr[:, 1] * area) ** 2)))
    truth = 4 * math.pi * 100.0 if normalize else read_photometry(ies).total_lumens()
    assert abs(flux - truth) <= 4 * se + 1e-5 * truth, (flux, se, truth)
    assert se < 0.005 * truth


def test_no_warning_without_shaping_and_warning_for_angle_scale(tmp_path):
    """The reader warns only about what it does not read."""
    (tmp_path / "s.usda").write_text('#usda 1.0\n(\n    upAxis = "Z"\n    metersPerUnit = 1\n)\ndef SphereLight "L"\n{\n    float inputs:intensity = 4\n    bool treatAsPoint = 1\n}\n')
    (tmp_path / "c.toml").write_text('stage = "s.usda"\n[[sensor]]\nname = "a"\nkind = "irradiance"\nposition = [0, 0, -1]\nnormal = [0, 0, 1]\n')
    scene = load_scene(load_config(tmp_path / "c.toml"))
    assert not [w for w in scene.warnings if "Shaping" in w or "shaping" in w]
    _stage(tmp_path, POINT_100CD + "\n        float inputs:shaping:ies:angleScale = 0.5")
    scene = load_scene(load_config(tmp_path / "c.toml"))
    assert any("angleScale" in w for w in scene.warnings)


def test_bad_ies_file_is_one_line_error(tmp_path):
    _stage(tmp_path, POINT_100CD + '\n        asset inputs:shaping:ies:file = @missing.ies@')
    (tmp_path / "c.toml").write_text('stage = "s.usda"\n[[sensor]]\nname = "a"\nkind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]\n')
    with pytest.raises(UserError) as e:
        load_scene(load_config(tmp_path / "c.toml"))
    assert "shaping:ies:file" in str(e.value) and "\n" not in str(e.value)
