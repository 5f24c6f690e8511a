"""A year of daylight: climate files, the Perez sky, exact direct sun, annual metrics and photosensor control."""

import math
import os
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from simulator.errors import UserError
from simulator.study.annual import control as CT
from simulator.study.inputs import sky_patches as SP
from simulator.study.annual.year import run_annual, sky_levels_of
from simulator.study.annual.outputs import write_annual_outputs
from simulator.study.annual.climate import derive_tmy3_lux, read_weather
from simulator.study.annual.perez import hour_skies, perez_parameters
from simulator.study.schema import load_study

pvlib = pytest.importorskip("pvlib")
ROOT = Path(__file__).resolve().parents[1]
BUNDLED = ROOT / "stages" / "weather" / "greensboro_tmy3_lux.csv"
PVLIB_TMY3 = Path(pvlib.__file__).parent / "data" / "723170TYA.CSV"
#: four days of the bundled year: an equinox, both solstices and a September day
DAYS = ("03/21", "06/21", "12/21", "09/10")


def _days(tmp_path, twilight: int = 0) -> Path:
    """The four days of :data:`DAYS`, and ``twilight`` more hours whose centre has the sun below the
    horizon but whose file has diffuse and direct light (the sun rose or set within the hour)."""
    lines = BUNDLED.read_text().splitlines()
    keep = [i for i in range(len(lines) - 2) if lines[i + 2][:5] in DAYS]
    if twilight:
        w = read_weather(BUNDLED)
        extra = np.nonzero((w.sun_elevation_deg <= 0) & (w.dhi_lx > 0) & (w.dni_lx > 0))[0][:twilight]
        keep = sorted(set(keep) | set(int(r) for r in extra))
    p = tmp_path / "four_days.csv"
    p.write_text("\n".join(lines[:2] + [lines[i + 2] for i in keep]) + "\n")
    return p


def _study(tmp_path, body: str, name: str = "annual.toml"):
    p = tmp_path / name
    p.write_text(body)
    return load_study(p)


# --- climate files -------------------------------------------------------------------------------------------------


def test_pvlib_tmy3_illuminances_are_in_units_of_100_lx():
    """pvlib's 723170TYA.CSV: GH illuminance / GHI has a median near 1.07 as stored, so its illuminance
    fields are read ×100 (a luminous efficacy of 107 lm/W), and said so."""
    w = read_weather(PVLIB_TMY3)
    assert any("units of 100 lx" in n for n in w.notes)
    m = w.ghi_w_m2 > 50
    eff = float(np.median(w.ghi_lx[m] / w.ghi_w_m2[m]))
    assert 100.0 < eff < 115.0, eff  # daylight's global efficacy is about 100–120 lm/W
    assert len(w) == 8760


def test_the_bundled_weather_file_is_derived_from_pvlibs_tmy3():
    assert derive_tmy3_lux(PVLIB_TMY3) == BUNDLED.read_text()
    a, b = read_weather(BUNDLED), read_weather(PVLIB_TMY3)
    assert not any("units of 100" in n for n in a.notes)
    np.testing.assert_array_equal(a.dhi_lx, b.dhi_lx)
    np.testing.assert_array_equal(a.dni_lx, b.dni_lx)


def test_rows_label_the_end_of_the_hour_and_the_sun_is_at_its_centre():
    """Row 13 of 1 January (label 13:00) is 12:00–13:00: the sun is placed at 12:30 local standard time (UTC−5)."""
    from simulator.study.inputs.sun import solar_position

    w = read_weather(BUNDLED)
    r = 12
    assert w.end[r].hour == 13 and w.centre[r].hour == 12 and w.centre[r].minute == 30
    az, el = solar_position(w.latitude_deg, w.longitude_deg, f"{w.centre[r].date()}T12:30:00-05:00")
    # 0.01 deg: the weather's sun takes the site's altitude (273 m) into the refraction, the study's sun does not
    assert math.isclose(w.sun_elevation_deg[r], el, abs_tol=0.01) and math.isclose(w.sun_azimuth_deg[r], az, abs_tol=0.01)
    az1, el1 = solar_position(w.latitude_deg, w.longitude_deg, f"{w.centre[r].date()}T13:00:00-05:00")
    assert abs(w.sun_azimuth_deg[r] - az1) > 5.0  # the label's own time is half an hour off


def test_weather_mistakes_are_one_line(tmp_path):
    with pytest.raises(UserError, match="weather file not found"):
        read_weather(tmp_path / "nope.epw")
    bad = tmp_path / "bad.txt"
    bad.write_text("x")
    with pytest.raises(UserError, match="expected an EPW"):
        read_weather(bad)


# --- the Perez sky ---------------------------------------------------------------------------------------------------


def test_perez_parameters_follow_the_papers_equations():
    """Eqn. 6 for a clear bin and eqns. 7–8 for the first bin, written out by hand from Table 1."""
    z, dl = 0.6, 0.25
    p = perez_parameters(np.array([7.0]), np.array([dl]), np.array([z]))[0]  # ε ≥ 6.2: bin 8
    a8 = -1.0500 + 0.0289 * z + dl * (0.4260 + 0.3590 * z)
    e8 = 1.5000 - 0.6426 * z + dl * (1.8564 + 0.5636 * z)
    assert math.isclose(p[0], a8, rel_tol=1e-12) and math.isclose(p[4], e8, rel_tol=1e-12)
    p = perez_parameters(np.array([1.02]), np.array([dl]), np.array([z]))[0]  # bin 1
    c1 = math.exp((dl * (2.8000 + 0.6004 * z)) ** 1.2375) - 1.0000
    d1 = -math.exp(dl * (1.8734 + 0.6297 * z)) + 0.9738 + dl * 0.2809
    assert math.isclose(p[2], c1, rel_tol=1e-12) and math.isclose(p[3], d1, rel_tol=1e-12)


def test_hour_skies_meet_the_files_diffuse_illuminance_and_peak_at_the_sun():
    w = read_weather(BUNDLED)
    rows = np.nonzero(w.dhi_w_m2 > 0)[0][::3]
    sk = hour_skies(w, rows)
    proj = np.array([SP.patch_projected_solid_angle(p) for p in range(SP.N_PATCHES)])
    np.testing.assert_allclose(sk.patch_cd_m2 @ proj, sk.dhi_lx, rtol=1e-9)
    np.testing.assert_array_equal(sk.dhi_lx, w.dhi_lx[rows])
    clear = np.nonzero((sk.epsilon > 6.2) & (w.sun_elevation_deg[rows] > 20) & (w.sun_elevation_deg[rows] < 80))[0]
    assert len(clear) > 20
    brightest = np.argmax(sk.patch_cd_m2[clear], axis=1)
    sun_patch = SP.patch_index(sk.sun_dir[clear])
    # the circumsolar peak: the brightest patch is the sun's or touches it (centres within 20 degrees)
    cent = np.stack([SP.patch_direction(p) for p in range(SP.N_PATCHES)])
    ang = np.degrees(np.arccos(np.clip(np.sum(cent[brightest] * cent[sun_patch], axis=1), -1, 1)))
    assert np.all(ang < 20.0), ang.max()


def test_a_sun_below_the_horizon_at_the_hours_centre_leaves_the_sky_alone():
    """Hours whose file has direct light (the sun up for part of the hour) but whose centre has the sun down."""
    w = read_weather(BUNDLED)
    rows = np.nonzero((w.sun_elevation_deg <= 0) & (w.dni_lx > 0))[0]
    assert len(rows) >= 5
    sk = hour_skies(w, rows)
    assert np.all(sk.dni_lx == 0) and np.all(~sk.sun_up)
    np.testing.assert_array_equal(sk.global_lx, sk.dhi_lx)


def test_the_efficacy_model_reproduces_the_files_illuminances():
    """Perez (1990) diffuse and direct efficacies on the file's irradiances against its own illuminance
    fields (median ratio within 10%; measured 1.06 diffuse, 0.94 direct)."""
    w = read_weather(BUNDLED)
    rows = np.nonzero((w.ghi_w_m2 > 100) & (w.sun_elevation_deg > 5))[0][::4]
    f, e = hour_skies(w, rows, "file"), hour_skies(w, rows, "efficacy")
    assert 0.9 < np.median(e.dhi_lx / f.dhi_lx) < 1.1
    m = f.dni_lx > 1000
    assert 0.9 < np.median(e.dni_lx[m] / f.dni_lx[m]) < 1.1


# --- an open roof: the unobstructed sky -----------------------------------------------------------------------------

OPEN = """
stage = "{stage}"
seed = 5
[simulation]
samples = 256
[[candidates]]
name = "open"
points = [[0, 0, 0.5], [3, 0, 0.5], [0, 3, 0.5], [-2, -2, 0.5]]
normal = [0, 0, 1]
[[group]]
name = "sky"
lights = ["/World/Sky"]
sky = "tregenza"
[[zone]]
name = "roof"
candidates = "open"
[annual]
weather = "{weather}"
sky_group = "sky"
replicates = 16
"""


@pytest.fixture(scope="module")
def open_roof(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("open")
    study, p = _study(tmp, OPEN.format(stage=ROOT / "stages" / "dome.usda", weather=_days(tmp, twilight=6)))
    res = run_annual(study, p, tmp / "out", log=lambda m: None)
    return study, p, tmp, res


def test_an_unobstructed_sensor_reads_the_global_horizontal_illuminance_every_hour(open_roof):
    """Above a black ground under the open sky, every hour reads E_dh + E_n sin h (the sky as built plus
    the sun) within 4 standard errors; where the sun is below the horizon at the hour's centre, E_dh alone."""
    _, _, _, res = open_roof
    want = res.skies.global_lx[:, None]
    dev = np.abs(res.mean - want)
    assert np.all(dev <= 4 * res.stderr + 1e-6 * want), float(np.max(dev / np.maximum(res.stderr, 1e-12)))
    down = res.weather.sun_elevation_deg[res.rows] <= 0
    assert ((res.weather.dni_lx[res.rows] > 0) & (res.skies.dhi_lx > 0) & down).sum() >= 6
    np.testing.assert_array_equal(res.skies.global_lx[down], res.skies.dhi_lx[down])
    assert np.all(res.sun_direct[down] == 0.0)
    assert (res.skies.dni_lx > 0).sum() > 20  # sunny hours are there too


def test_an_open_roof_has_sda_100_and_daylight_factor_100(open_roof):
    _, _, _, res = open_roof
    m = res.metrics["roof"]
    assert m["sDA"][0] == 100.0
    df, se = m["DF"]
    assert abs(df - 100.0) <= 4 * se + 1e-9 and se < 1.0
    assert m["EN17037_pass"][0] == 1.0 and m["UDI_fell_short"][0] < m["UDI_useful"][0] + m["UDI_exceeded"][0]


def test_annual_outputs_are_the_same_bytes_on_resume(open_roof):
    study, p, tmp, res = open_roof
    files = write_annual_outputs(res, study, tmp / "out")
    first = {f.name: f.read_bytes() for f in files if f.suffix == ".csv"}
    again = run_annual(study, p, tmp / "out", log=lambda m: None)
    assert again.chunks_computed == 0 and again.chunks_total == res.chunks_total
    files = write_annual_outputs(again, study, tmp / "out")
    assert {f.name: f.read_bytes() for f in files if f.suffix == ".csv"} == first
    head = first["annual_hourly.csv"].decode().splitlines()
    assert head[0].split(",")[:8] == ["hour_end", "hour_centre", "sun_azimuth_deg", "sun_elevation_deg", "diffuse_horizontal_lx",
                                      "direct_normal_lx", "global_horizontal_lx", "occupied"]  # fmt: skip
    assert len(head) == len(res.rows) + 1 and len(head[0].split(",")) == 8 + 4


# --- the office: recombined hours against single-instant runs, control ----------------------------------------------

OFFICE = """
stage = "{stage}"
seed = 3
[simulation]
samples = 256
[[candidates]]
name = "wp"
points = [[1.0, 2.0, 0.8], [2.0, 1.0, 0.8], [4.5, 2.0, 0.8], [0.6, 3.0, 0.8], [2.5, 3.0, 0.8]]
normal = [0, 0, 1]
[[candidates]]
name = "onplane"
points = [[2.0, 1.0, 0.8]]
normal = [0, 0, 1]
[[candidates]]
name = "ceiling"
kind = "photosensor"
points = [[1.5, 2.0, 2.9], [4.5, 2.0, 2.9]]
normal = [0, 0, -1]
[[group]]
name = "sky"
lights = ["/Office/Sky"]
sky = "tregenza"
[[group]]
name = "rows"
lights = ["/Office/Lights/*"]
[[zone]]
name = "spot"
candidates = "wp"
region = [1.9, 0.9, 2.1, 1.1]
targets = {{ mean = 500 }}
[[zone]]
name = "room"
candidates = "wp"
targets = {{ mean = 500 }}
[annual]
weather = "{weather}"
sky_group = "sky"
replicates = 16
[[control]]
zone = "spot"
groups = ["rows"]
photosensor = "onplane[0]"
[[control]]
zone = "room"
groups = ["rows"]
photosensor = "ceiling"
model = "switched"
"""


@pytest.fixture(scope="module")
def office(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("office")
    study, p = _study(tmp, OFFICE.format(stage=ROOT / "stages" / "office.usda", weather=_days(tmp)))
    return study, p, run_annual(study, p, tmp / "out", log=lambda m: None)


_TEXEL_PATCH: dict = {}


def _instant(res, base, k, sensors, samples, seed):
    """One ordinary run of hour k: the hour's patch sky as a textured dome (texels take their patch's
    luminance) and its sun as a delta DistantLight, all in one trace."""
    from simulator.config.loader import SimulationConfig
    from simulator.engine.driver import Engine
    from simulator.io import latlong
    from simulator.pipeline import run_plan
    from simulator.plan.planner import make_plan
    from simulator.scene.model import Light, LightKind
    from simulator.study.trace.groups import group_scene
    from simulator.study.inputs.sun import sun_frame

    dome = next(l for l in base.lights if l.kind == LightKind.DOME)
    d = sky_levels_of(res.skies, dome.emission[1], 0.2)[k]
    w, h = 1024, 512
    key = (w, h, np.asarray(dome.frame).tobytes())
    if key not in _TEXEL_PATCH:  # the same for every hour: each texel's patch, computed once
        _TEXEL_PATCH[key] = SP.patch_index(latlong.texel_centre_directions(w, h, dome.frame).reshape(-1, 3))
    pid = _TEXEL_PATCH[key]
    lights = [replace(dome, texture_map=d[pid].reshape(h, w), texture="patch-sky")]
    if res.skies.dni_lx[k] > 0:
        en = float(res.skies.dni_lx[k])
        lights.append(Light("/Sun", LightKind.DISTANT, np.zeros(3), sun_frame(res.skies.sun_dir[k]), (en / 683.0, en)))
    sc = replace(group_scene(base, []), lights=lights)
    sim = SimulationConfig(samples=samples, seed=seed)
    r = run_plan(Engine(sc, sensors), make_plan(sc, sensors, sim.method, sim.component), sim)
    return r.mean[:, 1], r.stderr[:, 1]


def _agreement(res, hours, samples=256):
    """|z| of every (hour, sensor) of single-instant runs against the recombination, and of the sky-only hours."""
    from simulator.scene.usd import load_stage

    base = load_stage(ROOT / "stages" / "office.usda", light_units="photometric", radiometric_spectrum="E")
    ids = [i for i, c in enumerate(res.sensors) if c.set_name in ("wp", "ceiling")]
    sensors = [res.sensors[i].sensor for i in ids]
    z_all, z_sky = [], []
    for n, k in enumerate(hours):
        m, e = _instant(res, base, k, sensors, samples, 100 + n)
        z = np.abs(m - res.mean[k, ids]) / np.sqrt(e**2 + res.stderr[k, ids] ** 2)
        z_all += list(z)
        if res.skies.dni_lx[k] == 0:
            z_sky += list(z)
    return np.array(z_all), np.array(z_sky)


def test_recombined_hours_agree_with_single_instant_runs(office):
    """24 hours over four days (low sun at 06:30 and 18:30 included) on five work-plane sensors and two
    downward ceiling photosensors: every sky-only hour within 4 standard errors, all hours in at least
    95% of readings (the interreflected sun is spread over the 4 patches around it, an approximation;
    see docs/studies.md, "A year of daylight")."""
    _, _, res = office
    el = res.weather.sun_elevation_deg[res.rows]
    hours = list(np.nonzero(res.skies.dhi_lx > 0)[0][::2][:24])
    assert len(hours) >= 20 and any(0 < el[k] < 5 for k in hours) and any(el[k] > 30 for k in hours)
    z_all, z_sky = _agreement(res, hours)
    assert len(z_sky) >= 10 and np.all(z_sky <= 4.0), z_sky.max()
    assert np.mean(z_all <= 4.0) >= 0.95, np.sort(z_all)[-8:]


def test_a_traced_sun_agrees_with_single_instant_runs_every_sunny_hour(tmp_path):
    """``sun_indirect = "traced"``: the sun traced at binned positions (6 degrees), its exact direct part
    per hour: 24 hours with the sun's direct beam over four days, low sun included (0.1 and 1.1 degrees at
    the hour's centre, three more at 12-13 degrees, up to 77), all 168 readings (seven sensors) within 4
    standard errors."""
    text = OFFICE.format(stage=ROOT / "stages" / "office.usda", weather=_days(tmp_path)).replace(
        "replicates = 16", 'replicates = 16\nsun_indirect = "traced"\nsun_group = "sun"').replace(
        "[[zone]]", '[[group]]\nname = "sun"\nlights = ["/Office/Sun"]\n[[zone]]', 1)  # fmt: skip
    study, p = _study(tmp_path, text)
    res = run_annual(study, p, tmp_path / "out", log=lambda m: None)
    assert any("traced at" in n for n in res.notes)
    el = res.weather.sun_elevation_deg[res.rows]
    sunny = np.nonzero(res.skies.dni_lx > 0)[0]
    hours = list(sunny[:: max(1, len(sunny) // 24)][:24])
    assert len(hours) >= 20 and sum(0 < el[k] < 10 for k in hours) >= 2 and any(el[k] > 60 for k in hours)
    z_all, _ = _agreement(res, hours)
    assert np.all(z_all <= 4.0), np.sort(z_all)[-5:]


def test_a_photosensor_on_the_work_plane_keeps_its_zone_at_target_every_hour(office):
    """Closed loop, the photosensor at the zone's one work-plane point: daylight + dimmed lamps read the
    set point there, so not one occupied hour is below target, and daylight saves energy."""
    _, _, res = office
    c = res.controls[0]
    assert c["zone"] == "spot" and c["chosen"] == "onplane[0]"
    row = c["candidates"][0]
    assert row["hours_below"] == 0.0
    assert 0.0 < row["relative_energy"] < 1.0
    ids = res.zones["spot"] if hasattr(res, "zones") else None
    del ids
    sw = res.controls[1]
    assert sw["model"] == "switched" and {r["photosensor"] for r in sw["candidates"]} == {"ceiling[0]", "ceiling[1]"}
    assert np.all(np.isin(sw["level"], (0.0, 1.0)))


def test_control_on_a_three_hour_toy_year_matches_a_hand_computation():
    """Zone: lamps give 400 lx at full; target 500 lx; daylight 0, 300, 900 lx on the work plane.
    Photosensor: 0.5 per lx of zone daylight, 100 for the lamps at full (so 0, 150, 450)."""
    day = np.array([0.0, 300.0, 900.0])
    sig = 0.5 * day
    # closed loop: SP = 100·min(1, 500/400) = 100; u = clip((100 − s)/100, 0.1, 1) = 1, 0.1 (clipped from −0.5), 0.1
    u = CT.levels("closed_loop", sig, 100.0, 400.0, 500.0, min_level=0.1)
    np.testing.assert_allclose(u, [1.0, 0.1, 0.1])
    o = CT.outcome(u, day, 400.0, 500.0)
    assert math.isclose(o.relative_energy, 1.2 / 3, rel_tol=1e-12)
    assert o.hours_below == 2.0  # 0 + 400 = 400 < 500 and 300 + 40 = 340 < 500; 900 + 40 passes
    # open loop, gain 2 (zone lux per unit of signal): u = clip((500 − 2s)/400, 0.1, 1) = 1, 0.5, 0.1
    u = CT.levels("open_loop", sig, 0.0, 400.0, 500.0, min_level=0.1, gain=2.0)
    np.testing.assert_allclose(u, [1.0, 0.5, 0.1])
    o = CT.outcome(u, day, 400.0, 500.0)
    assert math.isclose(o.relative_energy, 1.6 / 3, rel_tol=1e-12) and o.hours_below == 1.0
    # switched, deadband 0.2: estimates 0, 300, 900 → on, on, off (900 ≥ 600); energy 2/3
    u = CT.levels("switched", sig, 0.0, 400.0, 500.0, deadband=0.2, gain=2.0)
    np.testing.assert_array_equal(u, [1.0, 1.0, 0.0])
    o = CT.outcome(u, day, 400.0, 500.0)
    assert math.isclose(o.relative_energy, 2 / 3, rel_tol=1e-12) and o.hours_below == 1.0
    assert math.isclose(o.score, 2 / 3 + 1 / 3, rel_tol=1e-12)


def test_the_switched_control_holds_its_state_inside_the_deadband():
    est = np.array([0.0, 650.0, 550.0, 450.0, 550.0, 650.0])  # target 500, off at ≥ 600, on at < 500
    u = CT.levels("switched", est, 0.0, 400.0, 500.0, deadband=0.2, gain=1.0)
    np.testing.assert_array_equal(u, [1, 0, 0, 1, 1, 0])


# --- the study file -------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("old, new, message", [
    ('sky_group = "sky"', 'sky_group = "rows"', "annual.sky_group: no [[group]] named 'rows' with sky"),
    ('zone = "spot"', 'zone = "spott"', "control[0].zone: no [[zone]] named 'spott' (did you mean 'spot'?)"),
    ('groups = ["rows"]\nphotosensor = "onplane[0]"', 'groups = ["sky"]\nphotosensor = "onplane[0]"', "control[0].groups[0]: no lamp [[group]]"),
    ('model = "switched"', 'model = "pid"', "control[1].model"),
    ('replicates = 16', 'occupied_h = [18, 8]', "occupied_h: expected"),
    ('replicates = 16', 'sun_indirect = "traced"', "annual.sun_group: sun_indirect = \"traced\" needs sun_group"),
])  # fmt: skip
def test_annual_mistakes_are_one_line(tmp_path, old, new, message):
    text = OFFICE.format(stage=ROOT / "stages" / "office.usda", weather=tmp_path / "w.csv")
    assert old in text
    with pytest.raises(UserError) as e:
        _study(tmp_path, text.replace(old, new))
    assert message in str(e.value) and "\n" not in str(e.value)


def test_a_study_needs_scenarios_or_an_annual_table(tmp_path):
    text = OFFICE.format(stage=ROOT / "stages" / "office.usda", weather=tmp_path / "w.csv")
    text = text.split("[annual]")[0]
    with pytest.raises(UserError, match="give at least one \\[\\[scenario\\]\\]"):
        _study(tmp_path, text)


def test_a_missing_weather_file_exits_2_with_one_line(tmp_path):
    import subprocess
    import sys

    p = tmp_path / "a.toml"
    p.write_text(OPEN.format(stage=ROOT / "stages" / "dome.usda", weather=tmp_path / "missing.epw"))
    r = subprocess.run([sys.executable, "-m", "simulator", "study", str(p)], capture_output=True, text=True, cwd=ROOT,
                       env={**os.environ, "PYTHONPATH": str(ROOT)})  # fmt: skip
    assert r.returncode == 2, r.stderr
    assert "weather file not found" in r.stderr and "Traceback" not in r.stderr
    assert not (tmp_path / "a.out" / "annual_hourly.csv").exists()


def host_sun_against_engine(base, sensors, suns) -> tuple[np.ndarray, int]:
    """The host's exact direct sun E_n·cos·V(·T through panes) at ``sensors`` for each (azimuth, elevation)
    of ``suns`` (deg, E_n = 50,000 lx), held to an ordinary direct-light run of a delta sun at each (1e-4
    relative and 4σ); the suns' directions and the count of (sun, sensor) pairs the host finds lit."""
    from simulator.config.loader import SimulationConfig
    from simulator.engine.driver import Engine, load_kernels
    from simulator.pipeline import run_plan
    from simulator.plan.planner import make_plan
    from simulator.scene.model import Light, LightKind
    from simulator.study.annual.sunlight import direct_sun
    from simulator.study.inputs.sun import sun_direction, sun_frame
    from simulator.study.trace.groups import group_scene

    dirs = np.stack([sun_direction(a, e) for a, e in suns])
    host = direct_sun(sensors, base, dirs, np.full(len(suns), 50000.0))
    load_kernels("cpu")
    sim = SimulationConfig(samples=16, seed=1, component="direct")
    for k, d in enumerate(dirs):
        sc = replace(group_scene(base, []), lights=[Light("/Sun", LightKind.DISTANT, np.zeros(3), sun_frame(d), (50000 / 683.0, 50000.0))])
        r = run_plan(Engine(sc, sensors), make_plan(sc, sensors, sim.method, sim.component), sim)
        np.testing.assert_allclose(r.mean[:, 1], host[k], rtol=1e-4, atol=1e-3 + 4 * float(r.stderr[:, 1].max()))
    return dirs, int(np.sum(host > 0))


def test_the_host_shadow_rays_read_the_suns_direct_light_as_the_engine_does():
    """Direct light of a delta sun at office sensors (sunlit, shadowed and in the window's edge light)
    for 12 sun positions: the host's exact E_n·cos·V against an ordinary direct-light run."""
    from simulator.scene.model import Sensor, SensorKind
    from simulator.scene.usd import load_stage

    base = load_stage(ROOT / "stages" / "office.usda", light_units="photometric", radiometric_spectrum="E")
    xs = np.linspace(0.3, 5.7, 10)
    sensors = [Sensor(f"s{i}", SensorKind.IRRADIANCE, np.array([x, y, 0.8]), np.array([0.0, 0.0, 1.0]))
               for i, (x, y) in enumerate((x, y) for x in xs for y in (0.8, 2.0, 3.2))]  # fmt: skip
    suns = [(az, el) for az in (200, 230, 250, 270, 290, 310) for el in (12, 35)]
    _, lit = host_sun_against_engine(base, sensors, suns)
    assert 0 < lit < len(suns) * len(sensors)  # some sunlit, some in shadow


def test_the_bundled_annual_study_reads_its_derived_weather():
    study, p = load_study(ROOT / "configs" / "studies" / "office_annual.toml")
    assert not study.scenario and study.annual.sky_group == "sky" and len(study.control) == 2
    assert (p.parent / study.annual.weather).resolve() == BUNDLED


def test_probesim_study_runs_the_scenarios_and_the_year_into_one_folder(tmp_path):
    import subprocess
    import sys

    p = tmp_path / "both.toml"
    p.write_text(OPEN.format(stage=ROOT / "stages" / "dome.usda", weather=_days(tmp_path))
                 + '[[scenario]]\nname = "overcast"\nlevels = { sky = 1.0 }\nsky = { group = "sky", cie = "overcast" }\n')  # fmt: skip
    r = subprocess.run([sys.executable, "-m", "simulator", "study", str(p)], capture_output=True, text=True, cwd=ROOT,
                       env={**os.environ, "PYTHONPATH": str(ROOT)})  # fmt: skip
    assert r.returncode == 0, r.stderr
    out = tmp_path / "both.out"
    for name in ("readings.csv", "summary.csv", "study.json", "annual_hourly.csv", "annual_metrics.csv", "annual.json"):
        assert (out / name).is_file(), name
    assert "annual: " in r.stdout and "roof: sDA300/50% 100.0" in r.stdout


def test_an_annual_folder_another_build_traced_is_traced_again(open_roof, tmp_path, monkeypatch):
    """Resumed by another build of probesim (tests/test_study_resume.py), an annual study traces every
    chunk again, and its notes say how many of the other build's it removed; the hourly readings are the same."""
    import shutil

    from simulator.study.trace import chunks

    study, p, tmp, res = open_roof
    shutil.copytree(tmp / "out", tmp_path / "out")
    monkeypatch.setattr(chunks, "code_digest", lambda: "another build")
    again = run_annual(study, p, tmp_path / "out", log=lambda m: None)
    assert again.chunks_computed == again.chunks_total == res.chunks_total
    n = res.chunks_total
    assert [x for x in again.notes if "another build" in x] == [
        f"warning: {tmp_path / 'out'}: {n} finished chunk{'s' if n != 1 else ''} in this folder "
        f"{'were' if n != 1 else 'was'} traced by another build of probesim: removed, and traced again where this "
        "study needs them"]  # fmt: skip
    np.testing.assert_array_equal(again.mean, res.mean)
