"""Light probes: lat-long maps of incident radiance and their sphere integrals.

Statistical checks use |estimate − truth| ≤ 4·stderr + 2e-6·|truth| (fixed
seeds; four standard errors is a 6e-5 two-sided false-alarm chance for a
correct estimator; 2e-6 relative covers float32 arithmetic in the kernels,
so zero-variance readings must be exact to float32). Reference values come
from docs/REFERENCES.md §Radiometric quantities: a uniform environment of radiance L gives
scalar irradiance (fluence rate) ∫L dω = 4πL and πL on any face; a uniform
cone of half-angle θ gives 2πL(1 − cos θ); a point light gives I/d² along the
direction to it.
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np
import pytest

from simulator.reference import closed_forms as cf
from simulator.config.loader import DEFAULT_PROBE_RESOLUTION, load_config
from simulator.engine.driver import Engine
from simulator.errors import UserError
from simulator.io.latlong import latlong_uv_to_direction, texel_solid_angles
from simulator.engine.probes import FACE_NAMES, latlong_layout, pixel_solid_angles, probe_frame
from simulator.scene.model import LightKind, Sensor, SensorKind
from simulator.scene.usd import load_stage

FLOAT32_SLACK = 2e-6
AXES = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], float)  # FACE_NAMES order
SH_Y00 = 0.5 / math.sqrt(math.pi)


def _stage(tmp_path: Path, body: str, name: str = "stage.usda", up: str = "Z") -> Path:
    path = tmp_path / name
    path.write_text(f'#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "{up}"\n)\n\n' + textwrap.dedent(body))
    return path


def _probe(position=(0.0, 0.0, 0.0), resolution=(64, 32), name="probe") -> Sensor:
    return Sensor(name, SensorKind.PROBE, np.asarray(position, float), np.array([0.0, 0.0, 1.0]), resolution=resolution)


def _run(stage: Path, probes, method="light", samples=65536, seed=1, units="radiometric", **kw):
    scene = load_stage(stage, light_units=units, radiometric_spectrum="E")
    return scene, Engine(scene, []).run_probes(probes, method, samples=samples, seed=seed, **kw)


def _close(est, se, truth, what):
    bound = 4.0 * se + FLOAT32_SLACK * abs(truth) + 1e-12
    assert abs(est - truth) <= bound, f"{what}: {est} vs {truth} ± {se}"


def _angle_deg(a, b) -> float:
    return math.degrees(math.acos(min(1.0, abs(float(np.dot(a, b))) / (np.linalg.norm(a) * np.linalg.norm(b)))) if np.dot(a, b) >= 0 else 180.0)


# --------------------------------------------------------------------------- config and layout


def test_config_probe_kind(tmp_path):
    """[[sensor]] kind = "probe" takes a position and an optional resolution
    (default 64 x 32, the stage reader's default); keys of other kinds and a
    bad resolution are one-line errors naming the key."""
    (tmp_path / "s.usda").write_text("#usda 1.0\n")

    def cfg(extra):
        p = tmp_path / "c.toml"
        p.write_text(f'stage = "s.usda"\n[[sensor]]\nname = "p"\nkind = "probe"\nposition = [1, 2, 3]\n{extra}')
        return p

    (s,) = load_config(cfg("")).sensors
    assert s.kind == SensorKind.PROBE and s.resolution == DEFAULT_PROBE_RESOLUTION == (64, 32)
    assert np.allclose(s.position, [1, 2, 3])
    (s,) = load_config(cfg("resolution = [16, 8]\n")).sensors
    assert s.resolution == (16, 8)
    for extra, key in [
        ("resolution = [16]\n", "sensor[0].resolution"),
        ("resolution = [0, 8]\n", "sensor[0].resolution[0]"),
        ("resolution = [1.5, 8]\n", "sensor[0].resolution[0]"),
        ("resolution = [4096, 4096]\n", "sensor[0].resolution"),
        ("normal = [0, 0, 1]\n", "sensor[0].normal"),
    ]:
        with pytest.raises(UserError) as e:
            load_config(cfg(extra))
        msg = str(e.value)
        assert f": {key}:" in msg and "\n" not in msg, msg


@pytest.mark.parametrize("w,h", [(64, 32), (7, 3)])
def test_pixel_layout_is_the_shared_latlong_convention(w, h):
    """The kernel's pixel (i, j) spans lon0 + [i, i+1]·dlon, lat0 + [j, j+1]·dlat
    with d = (sin lon cos lat, sin lat, cos lon cos lat): every pixel corner
    must be the direction simulator.io.latlong gives for (u, v) = (i/W, j/H), and
    the pixel solid angles must tile the sphere (Σ = 4π)."""
    lon0, dlon, lat0, dlat = latlong_layout(w, h)
    i, j = np.meshgrid(np.arange(w + 1), np.arange(h + 1))
    lon, lat = lon0 + i * dlon, lat0 + j * dlat
    mine = np.stack([np.sin(lon) * np.cos(lat), np.sin(lat), np.cos(lon) * np.cos(lat)], axis=-1)
    theirs = latlong_uv_to_direction(np.stack([i / w, j / h], axis=-1))
    assert np.abs(mine - theirs).max() < 1e-12
    om = pixel_solid_angles(w, h)
    assert om.shape == (h, w) and abs(om.sum() - 4 * math.pi) < 1e-12


@pytest.mark.parametrize("up", ["Z", "Y"])
def test_probe_frame_is_an_untransformed_domes_frame(tmp_path, up):
    """The map frame of a probe is the frame the stage reader gives an
    untransformed DomeLight of the same stage (identity for Z-up; the Y-up
    stage's axes, pole = world +Z, for Y-up), so a probe map can be that
    DomeLight's texture."""
    stage = _stage(tmp_path, 'def DomeLight "Sky"\n{\n    float inputs:intensity = 1\n}\n', up=up)
    scene = load_stage(stage, light_units="radiometric", radiometric_spectrum="E")
    (dome,) = scene.lights
    assert np.allclose(dome.frame, probe_frame(scene.up_axis), atol=1e-12)


# --------------------------------------------------------------------------- uniform environment


@pytest.mark.parametrize("resolution", [(64, 32), (4, 2)])
def test_uniform_environment(tmp_path, resolution):
    """An untextured DomeLight of radiance L = 2 W m⁻² sr⁻¹ and no geometry:
    every map pixel is L with zero variance, scalar irradiance is 4πL exactly
    (the pixels tile the sphere), each of the six faces reads πL, the vector
    irradiance is 0, and the SH coefficients are (2√π·L, 0, …, 0), all within
    4 stderr. The 4 × 2 map has pixels of π/2 × π/2: its face and SH
    estimates hold only if directions are uniform within each pixel."""
    stage = _stage(tmp_path, 'def DomeLight "Sky"\n{\n    float inputs:intensity = 2\n}\n')
    scene, (r,) = _run(stage, [_probe(resolution=resolution)], samples=65536)
    (dome,) = scene.lights
    L = np.array(dome.emission)
    assert r.radiance.shape == (resolution[1], resolution[0], 2)
    assert np.all(r.radiance == L.astype(np.float32)) and np.all(r.radiance_stderr == 0.0)
    for ch in (0, 1):
        _close(r.integrals[0, ch], r.integrals_stderr[0, ch], 4 * math.pi * L[ch], f"scalar[{ch}]")
        assert r.integrals_stderr[0, ch] == 0.0
        for k, face in enumerate(FACE_NAMES):
            _close(r.integrals[1 + k, ch], r.integrals_stderr[1 + k, ch], math.pi * L[ch], f"face {face}[{ch}]")
        for k in range(3):
            _close(r.integrals[7 + k, ch], r.integrals_stderr[7 + k, ch], 0.0, f"vector[{k}][{ch}]")
        for k in range(9):
            truth = 4 * math.pi * SH_Y00 * L[ch] if k == 0 else 0.0
            _close(r.integrals[10 + k, ch], r.integrals_stderr[10 + k, ch], truth, f"SH[{k}][{ch}]")
    assert r.passes >= 8 and r.samples == r.passes * resolution[0] * resolution[1]


# --------------------------------------------------------------------------- distant, sphere and point lights


_SUN_ROT = "double3 xformOp:rotateXYZ = (30, 0, 40)\n    uniform token[] xformOpOrder = [\"xformOp:rotateXYZ\"]"


@pytest.mark.parametrize("angle_deg", [0.0, 10.0])
def test_distant_light_direction_and_integrals(tmp_path, angle_deg):
    """A lone DistantLight: the mean direction of arrival (normalised vector
    irradiance) is the light's direction within 0.5° and within 4 of its
    angular standard errors. Angle 0 (delta): added
    exactly by next-event estimation, so scalar irradiance is E⊥ and each face
    E⊥·max(0, ω·n) with zero variance. Angle 10° (a cone of radiance L, half
    angle 5°): scalar irradiance 2πL(1 − cos 5°), faces as from a sphere
    subtending the same cone (sphere_irradiance), within 4 stderr; its map
    holds all of the light."""
    stage = _stage(tmp_path, f'def DistantLight "Sun"\n{{\n    float inputs:intensity = 50\n    float inputs:angle = {angle_deg}\n    {_SUN_ROT}\n}}\n')
    scene, (r,) = _run(stage, [_probe(resolution=(64, 32))], samples=65536)
    (sun,) = scene.lights
    axis = sun.frame[:, 2]
    m, m_se = r.mean_direction(0)
    assert _angle_deg(m, axis) <= 0.5, (m, axis)
    # its standard error (RMS angle across the direction) is honest too
    assert _angle_deg(m, axis) <= 4 * m_se + 1e-4, (_angle_deg(m, axis), m_se)
    half = math.radians(angle_deg / 2)
    for ch in (0, 1):
        e = sun.emission[ch]
        if angle_deg == 0.0:
            truth_scalar = e
            truth_faces = e * np.maximum(0.0, AXES @ axis)
            assert np.all(r.integrals_stderr[:, ch] == 0.0)
            assert np.all(r.radiance == 0.0)  # a delta light fills no pixel
            assert np.allclose(r.delta[:, ch], r.integrals[:, ch])
        else:
            truth_scalar = 2 * math.pi * e * (1 - math.cos(half))
            truth_faces = [cf.sphere_irradiance(e, axis, math.sin(half), np.zeros(3), n) for n in AXES]
            map_total = float(np.sum(r.radiance[..., ch] * r.solid_angle_sr))
            assert abs(map_total - r.integrals[0, ch]) <= 1e-9 * abs(map_total)
        _close(r.integrals[0, ch], r.integrals_stderr[0, ch], truth_scalar, f"scalar[{ch}]")
        for k, face in enumerate(FACE_NAMES):
            _close(r.integrals[1 + k, ch], r.integrals_stderr[1 + k, ch], float(truth_faces[k]), f"face {face}[{ch}]")
        vec = r.integrals[7:10, ch]
        assert _angle_deg(vec, axis) <= 0.5


def test_sphere_light(tmp_path):
    """A SphereLight of radiance L, radius 0.5 m, 2 m from the probe (sin σ =
    1/4): scalar irradiance 2πL(1 − cos σ) and each face's irradiance by the
    sphere closed form, within 4 stderr; mean direction toward its centre
    within 0.5° and 4 angular standard errors. The standard errors must be
    honest for a light seen only by some pixels."""
    stage = _stage(tmp_path, textwrap.dedent('''\
        def SphereLight "Ball"
        {
            float inputs:intensity = 10
            float inputs:radius = 0.5
            double3 xformOp:translate = (1.2, -0.9, 1.6)
            uniform token[] xformOpOrder = ["xformOp:translate"]
        }
        '''))  # fmt: skip
    scene, (r,) = _run(stage, [_probe(resolution=(64, 32))], samples=262144)
    (ball,) = scene.lights
    c = ball.position
    d = float(np.linalg.norm(c))
    for ch in (0, 1):
        L = ball.emission[ch]
        s2 = (ball.radius / d) ** 2
        _close(r.integrals[0, ch], r.integrals_stderr[0, ch], 2 * math.pi * L * (1 - math.sqrt(1 - s2)), f"scalar[{ch}]")
        for k, n in enumerate(AXES):
            truth = cf.sphere_irradiance(L, c, ball.radius, np.zeros(3), n)
            _close(r.integrals[1 + k, ch], r.integrals_stderr[1 + k, ch], float(truth), f"face {FACE_NAMES[k]}[{ch}]")
        assert r.integrals_stderr[0, ch] < 0.02 * r.integrals[0, ch]
    m, m_se = r.mean_direction(0)
    assert _angle_deg(m, c) <= min(0.5, 4 * m_se), (_angle_deg(m, c), m_se)


def test_point_light_exact_with_shadow_and_bsdf_blind(tmp_path):
    """A point light of intensity I at distance d: scalar irradiance I/d²,
    face n reads I/d²·max(0, ω·n), SH coefficient Y_lm(ω)·I/d², all with zero
    variance (next-event estimation, no direction sampling can see it). A
    second probe behind a black quad reads 0. Method bsdf cannot see delta
    lights (as for every sensor): it reads 0."""
    stage = _stage(tmp_path, textwrap.dedent('''\
        def SphereLight "Lamp"
        {
            float inputs:intensity = 400
            bool inputs:normalize = 1
            float inputs:radius = 0.05
            bool treatAsPoint = 1
            double3 xformOp:translate = (1, 2, 3)
            uniform token[] xformOpOrder = ["xformOp:translate"]
        }
        def Mesh "Blocker"
        {
            int[] faceVertexCounts = [4]
            int[] faceVertexIndices = [0, 1, 2, 3]
            point3f[] points = [(4, 4, 5), (6, 4, 5), (6, 6, 5), (4, 6, 5)]
            color3f[] primvars:displayColor = [(0, 0, 0)]
        }
        '''))  # fmt: skip
    probes = [_probe((0.2, 0.1, -0.5), (16, 8), "open"), _probe((8.5, 8.0, 7.0), (16, 8), "shadowed")]
    scene, (r, rs) = _run(stage, probes, samples=4096)
    (lamp,) = scene.lights
    assert lamp.kind == LightKind.POINT
    v = lamp.position - probes[0].position
    d = float(np.linalg.norm(v))
    w = v / d
    x, y, z = w
    sh = np.array([SH_Y00, 0.4886025119029199 * y, 0.4886025119029199 * z, 0.4886025119029199 * x,
                   1.0925484305920792 * x * y, 1.0925484305920792 * y * z, 0.31539156525252005 * (3 * z * z - 1),
                   1.0925484305920792 * x * z, 0.5462742152960396 * (x * x - y * y)])  # fmt: skip
    for ch in (0, 1):
        e = lamp.emission[ch] / d**2
        truth = np.concatenate([[e], e * np.maximum(0, AXES @ w), e * w, e * sh])
        assert np.all(r.integrals_stderr[:, ch] == 0.0)
        assert np.all(np.abs(r.integrals[:, ch] - truth) <= FLOAT32_SLACK * e + 1e-12), (r.integrals[:, ch], truth)
        assert np.all(rs.integrals[:, ch] == 0.0)  # the quad hides the lamp
    assert np.all(r.radiance == 0.0)
    m, m_se = r.mean_direction(0)
    assert _angle_deg(m, w) < 1e-3 and m_se == 0.0
    _, (rb,) = _run(stage, probes[:1], method="bsdf", samples=4096)
    assert np.all(rb.integrals == 0.0)


# --------------------------------------------------------------------------- textured dome round trips


def _sky_map(seed=5, h=8, w=16) -> np.ndarray:
    """A lat-long map with no symmetry: every texel its own value in [0.2, 3)."""
    return np.random.default_rng(seed).uniform(0.2, 3.0, (h, w)).astype(np.float32)


def _textured_stage(tmp_path, sky: np.ndarray, up="Z", floor_albedo: float | None = None) -> Path:
    from simulator.io.exr import write_channels

    write_channels(tmp_path / "sky.exr", {"R": sky, "G": sky, "B": sky})
    floor = ""
    if floor_albedo is not None:
        # a 20 km floor through the origin (its edge is 1e-4 rad below a
        # probe 1 m up): stage coordinates, Z-up (x, y, 0) or Y-up (x, 0, -y)
        pts = [(-1e4, -1e4), (1e4, -1e4), (1e4, 1e4), (-1e4, 1e4)]
        pts = [(a, b, 0) for a, b in pts] if up == "Z" else [(a, 0, -b) for a, b in pts]
        g = floor_albedo
        floor = textwrap.dedent(f'''\
            def Mesh "Floor"
            {{
                int[] faceVertexCounts = [4]
                int[] faceVertexIndices = [0, 1, 2, 3]
                point3f[] points = [{", ".join(f"({a}, {b}, {c})" for a, b, c in pts)}]
                color3f[] primvars:displayColor = [({g}, {g}, {g})]
            }}
            ''')  # fmt: skip
    body = 'def DomeLight "Sky"\n{\n    float inputs:intensity = 1\n    asset inputs:texture:file = @./sky.exr@\n}\n' + floor
    return _stage(tmp_path, body, up=up)


def test_probe_reproduces_a_textured_dome(tmp_path):
    """A probe at the centre of a stage lit only by a textured DomeLight (a
    random 16 × 8 map) reproduces the map. At 32 × 16 every probe pixel lies
    inside one texel: it must equal that texel's radiance exactly (float32)
    with zero variance. At 8 × 4 every pixel averages 2 × 2 texels: the truth
    is their solid-angle-weighted mean, and with 256 passes per pixel the
    standardised residuals z = (probe − truth)/stderr must all satisfy
    |z| ≤ 5 (a 6e-7 chance per pixel for a correct estimator) and their mean
    square must lie within 1 ± 4·√(2/N) (the χ²/N band, N = 32 pixels)."""
    sky = _sky_map()
    stage = _textured_stage(tmp_path, sky)
    fine, coarse = _probe(resolution=(32, 16), name="fine"), _probe(resolution=(8, 4), name="coarse")
    scene, (rf,) = _run(stage, [fine], samples=32 * 16 * 8)
    (dome,) = scene.lights
    emission = np.array(dome.emission)
    texel = np.repeat(np.repeat(sky.astype(np.float64), 2, 0), 2, 1)
    for ch in (0, 1):
        truth = texel * emission[ch]
        assert np.all(np.abs(rf.radiance[..., ch] - truth) <= FLOAT32_SLACK * truth), ch
        assert np.all(rf.radiance_stderr[..., ch] == 0.0)
    _, (rc,) = _run(stage, [coarse], samples=8 * 4 * 256)
    om = texel_solid_angles(16, 8)[:, None] * np.ones((1, 16))
    mean_sky = (sky * om).reshape(4, 2, 8, 2).sum(axis=(1, 3)) / om.reshape(4, 2, 8, 2).sum(axis=(1, 3))
    n = mean_sky.size
    for ch in (0, 1):
        z = (rc.radiance[..., ch] - mean_sky * emission[ch]) / rc.radiance_stderr[..., ch]
        assert np.abs(z).max() <= 5.0, np.abs(z).max()
        assert abs(np.mean(z**2) - 1.0) <= 4 * math.sqrt(2 / n), np.mean(z**2)
        # and the sphere integral is exact: Σ Ω·map
        _close(rc.integrals[0, ch], rc.integrals_stderr[0, ch], float((sky * om).sum() * emission[ch]), "scalar")


@pytest.mark.parametrize("up", ["Z", "Y"])
def test_probe_map_relights_an_empty_stage(tmp_path, up):
    """Capture and relight. Stage A: a textured DomeLight (random map) over a
    20 km grey floor (albedo 0.5); a probe 1 m above the floor captures a
    16 × 8 map (the floor's horizon falls on pixel edges, so each pixel's
    radiance is uniform over it and the map is a faithful DomeLight).
    Stage B: an empty stage whose only light is a DomeLight with the probe's
    EXR as ``texture:file`` (intensity 1, untransformed, same upAxis).
    Irradiance sensors there facing ±X, ±Y, ±Z must read what the probe said
    for its six faces, within 4·√(σ_probe² + σ_sensor²) (+ float32 slack):
    this checks the EXR's orientation, frame, units (R = G = B in the stage's
    light units, photometric here) and the face integrals together."""
    from simulator.pipeline import run

    sky = _sky_map(seed=11)
    a_dir = tmp_path / "a"
    a_dir.mkdir()
    _textured_stage(a_dir, sky, up=up, floor_albedo=0.5)
    (a_dir / "a.toml").write_text(textwrap.dedent('''\
        stage = "stage.usda"
        [simulation]
        samples = 65536
        seed = 4
        method = "path"
        [[sensor]]
        name = "capture"
        kind = "probe"
        position = [0, 0, 1]
        resolution = [16, 8]
        [output]
        csv = "out/a.csv"
        '''))  # fmt: skip
    out_a = run(load_config(a_dir / "a.toml"), log=lambda m: None)
    exr_path = a_dir / "out" / "a.capture.exr"
    assert exr_path.exists()
    import json

    probe = json.loads((a_dir / "out" / "a.probes.json").read_text())["probes"][0]
    b_dir = tmp_path / "b"
    b_dir.mkdir()
    _stage(b_dir, f'def DomeLight "Relit"\n{{\n    float inputs:intensity = 1\n    asset inputs:texture:file = @{exr_path.as_posix()}@\n}}\n', up=up)
    sensors = "".join(
        f'[[sensor]]\nname = "{n}"\nkind = "irradiance"\nposition = [0, 0, 0]\nnormal = [{", ".join(str(int(c)) for c in ax)}]\n'
        for n, ax in zip(FACE_NAMES, AXES)
    )
    (b_dir / "b.toml").write_text(f'stage = "stage.usda"\n[simulation]\nsamples = 65536\nseed = 9\nmethod = "light"\n{sensors}[output]\ncsv = "out/b.csv"\n')
    out_b = run(load_config(b_dir / "b.toml"), log=lambda m: None)
    assert out_a.rows[0].sensor.kind == SensorKind.PROBE
    for row in out_b.rows:
        face = probe["faces"][row.sensor.name]
        for key, unit in (("irradiance", "W_m2"), ("illuminance", "lx")):
            unit_col = "W_m2" if unit == "W_m2" else "lx"
            est = row.values[f"{key}_{unit_col}"]
            se = row.values[f"{key}_stderr_{unit_col}"]
            truth, se_p = face[unit], face[f"stderr_{unit}"]
            bound = 4 * math.hypot(se, se_p) + FLOAT32_SLACK * abs(truth) + 1e-12
            assert abs(est - truth) <= bound, (row.sensor.name, key, est, truth, se, se_p)


# --------------------------------------------------------------------------- bookkeeping


def test_same_seed_same_numbers_whatever_the_threads(tmp_path):
    """Sample k of pixel p always draws from the same random stream, so a
    probe's numbers do not depend on how many CPU threads share the work."""
    stage = _textured_stage(tmp_path, _sky_map(), floor_albedo=0.3)
    scene = load_stage(stage, light_units="radiometric", radiometric_spectrum="E")
    p = [_probe((0, 0, 1), (16, 8))]
    a = Engine(scene, [], threads=1).run_probes(p, "path", samples=4096, seed=3)[0]
    b = Engine(scene, [], threads=3).run_probes(p, "path", samples=4096, seed=3)[0]
    c = Engine(scene, [], threads=3).run_probes(p, "path", samples=4096, seed=4)[0]
    assert np.array_equal(a.radiance, b.radiance) and np.array_equal(a.integrals, b.integrals)
    assert not np.array_equal(a.integrals, c.integrals)


def test_adaptive_probe_meets_its_target(tmp_path):
    """With rel_error, a probe draws passes until its scalar irradiance's 95%
    half-width is under rel_error × the reading (both channels)."""
    stage = _textured_stage(tmp_path, _sky_map(), floor_albedo=0.3)
    _, (r,) = _run(stage, [_probe((0, 0, 1), (16, 8))], method="path", samples=1024, rel_error=0.002)
    assert r.target_met is True
    val, se = r.scalar_irradiance
    assert np.all(1.959963984540054 * se <= 0.002 * val)


def test_engine_run_refuses_probes(tmp_path):
    """Engine.run reads irradiance, radiance and patch sensors; probes go
    through Engine.run_probes (a probe is not a one-sided receiver)."""
    stage = _stage(tmp_path, 'def DomeLight "Sky"\n{\n    float inputs:intensity = 1\n}\n')
    scene = load_stage(stage, light_units="radiometric", radiometric_spectrum="E")
    with pytest.raises(ValueError, match="run_probes"):
        Engine(scene, [_probe()]).run("light", samples=64, seed=1)


def test_stage_authored_probe_runs_end_to_end(tmp_path):
    """A prim with probesim:sensor:kind = "probe" and resolution (8, 4) in a
    uniform environment of luminance 1 cd/m² (photometric units) is read like
    a config probe: its CSV row holds scalar illuminance 4π lx exactly and
    its EXR is 8 × 4 with R = G = B = 1 cd/m²."""
    from simulator.io.exr import read_channels
    from simulator.pipeline import run

    _stage(tmp_path, textwrap.dedent('''\
        def DomeLight "Sky"
        {
            float inputs:intensity = 1
        }
        def Xform "Probe"
        {
            token probesim:sensor:kind = "probe"
            string probesim:sensor:name = "authored"
            int2 probesim:sensor:resolution = (8, 4)
            double3 xformOp:translate = (1, 2, 3)
            uniform token[] xformOpOrder = ["xformOp:translate"]
        }
        '''))  # fmt: skip
    (tmp_path / "c.toml").write_text('stage = "stage.usda"\n[simulation]\nsamples = 1024\n[output]\ncsv = "out/c.csv"\n')
    out = run(load_config(tmp_path / "c.toml"), log=lambda m: None)
    (row,) = out.rows
    assert row.sensor.kind == SensorKind.PROBE and row.sensor.resolution == (8, 4)
    _close(row.values["scalar_illuminance_lx"], row.values["scalar_illuminance_stderr_lx"], 4 * math.pi, "scalar lx")
    ch = read_channels(tmp_path / "out" / "c.authored.exr")
    assert ch["R"].shape == (4, 8) and np.all(ch["R"] == 1.0) and np.all(ch["G"] == ch["R"])


def test_dark_probe(tmp_path):
    """No light reaches a probe inside a closed black box: every integral is
    0 with zero standard error, the map is black, and the mean direction is
    undefined (NaN; its CSV columns are left empty)."""
    from simulator.io.results import probe_readings

    box = textwrap.dedent('''\
        def Cube "Box"
        {
            double size = 2
            color3f[] primvars:displayColor = [(0, 0, 0)]
        }
        def SphereLight "Outside"
        {
            float inputs:intensity = 10
            float inputs:radius = 0.1
            double3 xformOp:translate = (0, 0, 3)
            uniform token[] xformOpOrder = ["xformOp:translate"]
        }
        ''')  # fmt: skip
    _, (r,) = _run(_stage(tmp_path, box), [_probe(resolution=(8, 4))], samples=1024)
    assert np.all(r.integrals == 0.0) and np.all(r.integrals_stderr == 0.0) and np.all(r.radiance == 0.0)
    m, se = r.mean_direction(0)
    assert np.all(np.isnan(m)) and math.isnan(se)
    (row,) = probe_readings([r], "light")
    assert "mean_direction_x" not in row.values and row.values["scalar_irradiance_W_m2"] == 0.0
