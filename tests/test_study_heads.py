"""Studies read a sensor model whole: each light group through the head's spectral response (its mismatch
factor per group), and an annual control through the device's electronics (setting, counts, saturation,
noise per hour and sensor).

A one-channel head reads a light of spectrum S at 1/F(S) of its true illuminance (ISO/CIE 19476 §5.4,
docs/REFERENCES.md §Sensor models): F = ∫S V · ∫S_A s / (∫S_A V · ∫S s), so a recombined reading is
Σ_g c_g·d_g/F_g. Integrals here are numpy's trapezoid rule on colour-science's CIE tables and Planck's
law written out, no code shared with simulator.sensor_models.
"""

import math
from pathlib import Path

import numpy as np
import pytest

from simulator.errors import UserError
from simulator.sensor_models.electronics import Electronics
from simulator.sensor_models.spectral import Channel
from simulator.spectra.wide import WIDE_NM
from simulator.study.annual import control as CT
from simulator.study.annual import heads as AH
from simulator.study.schema import load_study
from simulator.study.trace.distributed import QUIET_CLUSTER

ROOT = Path(__file__).resolve().parents[1]
H_C_K = 1.438776877e-2  # c₂ = hc/k, m·K (CODATA 2018)


def _gaussian_model(tmp_path, centre=600.0, width=30.0, extra: str = "") -> Path:
    """A cosine head with a Gaussian responsivity (a strong spectral mismatch), calibrated under A."""
    wl = np.arange(300, 1101)
    (tmp_path / "g.csv").write_text("wavelength_nm,responsivity\n" + "\n".join(
        f"{x},{math.exp(-0.5 * ((x - centre) / width) ** 2):.12g}" for x in wl) + "\n")
    p = tmp_path / "g.toml"
    p.write_text('name = "gauss"\n[angular]\ncos_power = 1.0\n[[channel]]\nname = "g"\nresponsivity = "g.csv"\n' + extra)
    return p


def _f_by_integral(spectrum, centre=600.0, width=30.0) -> float:
    """F of a light for the Gaussian head, by numpy's trapezoid rule: ``spectrum`` "D65" or "A" (colour-science's
    tables, 380–780 nm, where the Gaussian's weight outside is under 1e-7) or a temperature (Planck's law)."""
    import colour

    wl = np.arange(380.0, 781.0)
    v = np.asarray(colour.colorimetry.SDS_LEFS_PHOTOPIC["CIE 1924 Photopic Standard Observer"][wl], float)
    s = np.exp(-0.5 * ((wl - centre) / width) ** 2)

    def spd(name):
        if isinstance(name, (int, float)):
            lam = wl * 1e-9
            return 1.0 / (lam**5 * (np.exp(H_C_K / (lam * name)) - 1.0))
        return np.asarray(colour.SDS_ILLUMINANTS[name][wl], float)

    a, t = spd("A"), spd(spectrum)
    return (np.trapezoid(t * v, wl) * np.trapezoid(a * s, wl)) / (np.trapezoid(a * v, wl) * np.trapezoid(t * s, wl))


# --- spectral factors per light group ---------------------------------------------------------------------------------


OPEN = """
stage = "{stage}"
seed = 5
[simulation]
samples = 256
[[candidates]]
name = "plain"
points = [[0, 0, 0.5]]
normal = [0, 0, 1]
[[candidates]]
name = "head"
model = "{model}"
points = [[0, 0, 0.5], [3, 0, 0.5]]
normal = [0, 0, 1]
{extra}
[[group]]
name = "sky"
lights = ["/World/Sky"]
sky = "tregenza"
[[zone]]
name = "roof"
candidates = "head"
"""


def test_each_group_reads_at_its_spectrum_s_factor(tmp_path):
    """The factor a modelled candidate applies to each light group is 1/F of the group's spectrum, F by its
    integral: the sky (the stage's dome, D65), lamps of a 3000 K blackbody (the group's `spectrum`) and the
    annual sun under illuminant A (F = 1: the calibration light) agree with the trapezoid integrals to 1e-5
    (the spectra's tables and grids differ in their last digits); the record names each group's spectrum."""
    from simulator.scene.usd import load_stage
    from simulator.study.inputs.candidates import build_candidates
    from simulator.study.inputs.heads import head_factors
    from simulator.study.inputs.scenarios import resolve_groups
    from simulator.spectra.sources import emitter_spectrum

    stage = tmp_path / "lamp.usda"
    text = (ROOT / "stages" / "dome.usda").read_text().rstrip()
    stage.write_text(text[:-1] + 'def SphereLight "Lamp"\n{\n    float inputs:intensity = 1\n    float inputs:radius = 0.1\n'
                     '    double3 xformOp:translate = (0, 0, 3)\n    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n}\n')
    p = tmp_path / "s.toml"
    p.write_text(OPEN.format(stage=stage, model=_gaussian_model(tmp_path), extra="")
                 + '[[group]]\nname = "lamp"\nlights = ["/World/Lamp"]\nspectrum = 3000\n[[scenario]]\nname = "x"\nlevels = { sky = 1 }\n')
    study, path = load_study(p)
    scene = load_stage(stage, light_units="photometric", radiometric_spectrum="E")
    cands = [c for s in build_candidates(scene, study.candidates, str(path)) for c in s.candidates]
    groups, _ = resolve_groups(scene, study.group, str(path))
    hf = head_factors(study, scene, cands, groups, str(path), {AH.SUN: emitter_spectrum("A")})
    assert list(hf.index) == [1, 2]
    for light, spec in (("sky", "D65"), ("lamp", 3000.0), (AH.SUN, "A")):
        f = _f_by_integral(spec)
        assert 1.0 / hf.factors[0][light][0] == pytest.approx(f, rel=1e-5), (light, f)
    assert abs(_f_by_integral("D65") - 1.0) > 0.05 and abs(_f_by_integral(3000.0) - _f_by_integral("D65")) > 0.05
    rec = hf.record(cands)["gauss"]
    assert rec["spectra"] == {"sky": "D65", "lamp": "blackbody 3000 K", AH.SUN: "A"} and rec["sets"] == ["head"]


@pytest.fixture(scope="module")
def open_roof(tmp_path_factory):
    """The open roof (dome.usda: a uniform sky over a black ground) for four days of the bundled year, a plain
    sensor and two Gaussian heads; the sun under illuminant A (the group holding the stage's DistantLight)."""
    import importlib.util

    from simulator.study.annual.year import run_annual

    spec = importlib.util.spec_from_file_location("_annual_days", Path(__file__).with_name("test_study_annual.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    tmp = tmp_path_factory.mktemp("heads_roof")
    stage = tmp / "roof.usda"  # the dome with a DistantLight whose group names the sun's spectrum
    text = (ROOT / "stages" / "dome.usda").read_text().rstrip()
    stage.write_text(text[:-1] + 'def DistantLight "Sun"\n{\n    float inputs:intensity = 1\n}\n}\n')
    body = OPEN.format(stage=stage, model=_gaussian_model(tmp), extra="")
    body += '[[group]]\nname = "sun"\nlights = ["/World/Sun"]\nspectrum = "A"\n'
    body += f'[annual]\nweather = "{mod._days(tmp)}"\nsky_group = "sky"\nreplicates = 16\n'
    (tmp / "s.toml").write_text(body)
    study, p = load_study(tmp / "s.toml")
    return run_annual(study, p, tmp / "out", log=lambda m: None)


def test_a_head_under_the_open_sky_reads_each_light_at_its_factor(open_roof):
    """Every hour an unobstructed horizontal cosine head with a Gaussian responsivity reads the sky's
    diffuse illuminance at 1/F(D65) and the sun's E_n·sin h at 1/F(A) = 1: E_dh/F_D65 + E_n sin h, within
    4 of its standard errors (the sky's part is traced) + 1e-6; the plain sensor beside it reads
    E_dh + E_n sin h as before; its daylight factor is 100%/F_D65."""
    res = open_roof
    f_sky = _f_by_integral("D65")
    want = res.skies.dhi_lx / f_sky + res.skies.dni_lx * np.maximum(res.skies.sun_dir[:, 2], 0.0)
    for i in (1, 2):
        dev = np.abs(res.mean[:, i] - want)
        assert np.all(dev <= 4 * res.stderr[:, i] + 1e-6 * want + 1e-5 * want), float(np.max(dev / np.maximum(res.stderr[:, i], 1e-12)))
        assert abs(res.df[i] * 100 - 100.0 / f_sky) <= 4 * res.df_se[i] * 100 + 1e-4
    assert np.all(np.abs(res.mean[:, 0] - res.skies.global_lx) <= 4 * res.stderr[:, 0] + 1e-6 * res.skies.global_lx)
    assert (res.skies.dni_lx > 0).sum() > 20 and res.sensor_models["gauss"]["spectra"][AH.SUN] == "A"


# --- the device in the control ----------------------------------------------------------------------------------------


def _noiseless_part(bits=16, counts_per_lx=10.0):
    """A one-channel linear part, one setting, no noise: full scale (2^bits − 1)/counts_per_lx lx."""
    el = Electronics(bits=bits, gains=(1.0,), integration_ms=(100.0,), reference_gain=1.0, reference_integration_ms=100.0)
    ch = (Channel("c", np.ones_like(WIDE_NM), "flat", counts_per_unit=counts_per_lx),)
    from types import SimpleNamespace

    return SimpleNamespace(electronics=el, channels=ch, two_channel=False, name="part")


def test_saturated_hours_on_a_hand_computed_year():
    """A 12-bit part at 1 count per lx (full scale 4095 lx, no noise), lamps giving the zone 600 lx and the
    sensor 200 lx at full output, target 500 lx, floor u = 0.1. Daylight signals 100, 3000, 4100, 4080 and
    10,000 lx. Open loop (it reads daylight only): 4100 and 10,000 reach full scale: 2 hours saturated.
    Closed loop: the set point is ⌊200·500/600⌋ = 166 counts; at 100 lx the lamps settle at
    u = (166 − 100)/200 = 0.33 (166 lx, no saturation); from 3000 lx on daylight passes the set point and the
    lamps sit at the floor, adding 20 lx: 3020 (not), 4120, 4100 (saturated: the lamps push 4080 over) and
    10,020: 3 hours saturated."""
    part = _noiseless_part(bits=12, counts_per_lx=1.0)
    x = np.array([[100.0, 3000.0, 4100.0, 4080.0, 10000.0]])
    zone_day = np.array([0.0, 300.0, 400.0, 400.0, 1000.0])
    z = np.zeros((5, 1))
    spec = type("Spec", (), {"model": "open_loop", "min_level": 0.1, "deadband": 0.2})
    o, sat = AH.control_outcome(spec, part, (None, None), x, np.array([200.0]), np.array([1000.0]), 100.0, zone_day, 600.0,
                                500.0, z)
    assert sat.tolist() == [False, False, True, False, True] and o.saturated_hours == 2.0
    spec.model = "closed_loop"
    o, sat = AH.control_outcome(spec, part, (None, None), x, np.array([200.0]), np.array([1000.0]), 100.0, zone_day, 600.0,
                                500.0, z)
    assert sat.tolist() == [False, False, True, True, True] and o.saturated_hours == 3.0
    np.testing.assert_allclose(o.level, [0.33, 0.1, 0.1, 0.1, 0.1], rtol=1e-12)
    # the zone's lux per unit of lamp signal (600/200) times one code (1 lx): it holds the target within 3 lx;
    # lit 198, 360, 460, 460, 1060 lx: four hours below 497
    assert o.target_tolerance_lx == pytest.approx(3.0, rel=1e-12) and o.hours_below == 4.0


def test_a_fine_noiseless_device_controls_as_the_ideal_law():
    """With a device far finer than the signals (2^32 − 1 codes at 10⁴ counts per lx, no noise) the closed
    loop on its reports is the ideal law u = clip((SP − s)/S_e) within its resolution (1e-4 lx over
    S_e = 150 lx), and so is the open loop's (gain from its overcast reading), on 200 random hours."""
    part = _noiseless_part(bits=32, counts_per_lx=1e4)
    rng = np.random.default_rng(2)
    s = rng.uniform(0.0, 400.0, 200)
    day = 3.0 * s
    spec = type("Spec", (), {"model": "closed_loop", "min_level": 0.1, "deadband": 0.2})
    o, sat = AH.control_outcome(spec, part, (None, None), s[None, :], np.array([150.0]), np.array([50.0]), 120.0, day, 450.0,
                                500.0, np.zeros((200, 1)))
    ideal = CT.levels("closed_loop", s, 150.0, 450.0, 500.0, 0.1)
    np.testing.assert_allclose(o.level, ideal, atol=1e-4 / 150.0 * 2)
    assert not sat.any()
    spec.model = "open_loop"
    o, _ = AH.control_outcome(spec, part, (None, None), s[None, :], np.array([150.0]), np.array([50.0]), 120.0, day, 450.0,
                              500.0, np.zeros((200, 1)))
    np.testing.assert_allclose(o.level, CT.levels("open_loop", s, 0.0, 450.0, 500.0, 0.1, gain=120.0 / 50.0), atol=1e-6)


def test_hour_noise_is_fixed_by_seed_sensor_and_weather_row():
    """An hour's draw depends only on (seed, sensor, weather row): the rows analysed pick from one stream, so
    every second hour's draws are the every-hour draws of those rows; another sensor draws others."""
    all_rows = AH.hour_noise(7, "ceiling[1,2]", np.arange(100), 8760, 2)
    half = AH.hour_noise(7, "ceiling[1,2]", np.arange(0, 100, 2), 8760, 2)
    np.testing.assert_array_equal(half, all_rows[::2])
    assert not np.array_equal(all_rows, AH.hour_noise(7, "ceiling[1,3]", np.arange(100), 8760, 2))


# --- a study end to end ----------------------------------------------------------------------------------------------


OFFICE = """
stage = "{stage}"
seed = 3
[simulation]
samples = 128
[compute]
sensor_block = {block}
[[candidates]]
name = "wp"
points = [[1.0, 2.0, 0.8], [4.5, 2.0, 0.8]]
normal = [0, 0, 1]
[[candidates]]
name = "ceiling"
kind = "photosensor"
model = "{model}"
gain = 2
integration_ms = 100
points = [[0.6, 2.0, 2.9], [1.5, 2.0, 2.9], [4.5, 2.0, 2.9]]
normal = [0, 0, -1]
[[group]]
name = "sky"
lights = ["/Office/Sky"]
sky = "tregenza"
[[group]]
name = "rows"
lights = ["/Office/Lights/*"]
spectrum = "LED-B2"
[[zone]]
name = "room"
candidates = "wp"
targets = {{ mean = 500 }}
[annual]
weather = "{weather}"
sky_group = "sky"
replicates = 8
[[control]]
zone = "room"
groups = ["rows"]
photosensor = "ceiling"
[[control]]
zone = "room"
groups = ["rows"]
photosensor = "ceiling"
model = "open_loop"
"""


def _office(tmp_path, block: int) -> Path:
    import importlib.util

    spec = importlib.util.spec_from_file_location("_annual_days", Path(__file__).with_name("test_study_annual.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    p = tmp_path / f"office_{block}.toml"
    p.write_text(OFFICE.format(stage=ROOT / "stages" / "office.usda", model=ROOT / "simulator" / "sensor_models" / "data" / "ceiling_photosensor_als.toml",
                               weather=mod._days(tmp_path), block=block))
    return p


def test_device_readings_are_the_same_bytes_whatever_the_workers(tmp_path):
    """The office for four days with a VEML7700-based ceiling head at gain 2, 100 ms (full scale 1,887 lx, read
    noise 1 count drawn per hour and sensor): the annual CSVs are the same bytes in this process, on a
    LocalCluster of two workers (chunks of two sensors) and resumed; the control table gains the hours each
    candidate saturated: the head by the window saturates in some sunny hours, the one at the back never."""
    distributed = pytest.importorskip("distributed")
    from simulator.study.annual.outputs import write_annual_outputs
    from simulator.study.annual.year import run_annual

    outs = []
    for how in ("inprocess", "cluster", "resumed"):
        study, p = load_study(_office(tmp_path, 2))
        out = tmp_path / ("cluster" if how == "resumed" else how)
        if how == "cluster":
            with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False, **QUIET_CLUSTER) as cluster:  # fmt: skip
                res = run_annual(study, p, out, log=lambda m: None, scheduler=cluster.scheduler_address)
        else:
            res = run_annual(study, p, out, log=lambda m: None, mode="inprocess")
        files = write_annual_outputs(res, study, out)
        outs.append({f.name: f.read_bytes() for f in files if f.suffix == ".csv"})
        if how == "resumed":
            assert res.chunks_computed == 0
    assert outs[0] == outs[1] == outs[2]
    import csv
    import io

    rows = list(csv.DictReader(io.StringIO(outs[0]["annual_control.csv"].decode())))
    assert list(rows[0])[-2:] == ["hours_saturated", "hours_saturated_stderr"]
    sat = {(r["photosensor"], r["model"]): float(r["hours_saturated"]) for r in rows}
    assert sat[("ceiling[0]", "open_loop")] > 0 and sat[("ceiling[2]", "open_loop")] == 0, sat


@pytest.mark.parametrize("extra, message", [
    ("gain = 3", "candidates[1].gain: 3 is not one of the part's gains (2, 1, 0.25, 0.125)"),
    ("integration_ms = 90", "candidates[1].integration_ms: 90 is not one of the part's"),
])
def test_a_set_s_device_setting_is_the_part_s(tmp_path, extra, message):
    """A candidate set's gain or integration time not in its part's lists is one line naming the key."""
    from simulator.scene.usd import load_stage
    from simulator.study.inputs.candidates import build_candidates

    p = tmp_path / "s.toml"
    p.write_text(OPEN.format(stage=ROOT / "stages" / "dome.usda", model=ROOT / "simulator" / "sensor_models" / "data" / "ceiling_photosensor_als.toml",
                             extra=extra) + '[[scenario]]\nname = "x"\nlevels = { sky = 1 }\n')
    study, path = load_study(p)
    scene = load_stage(ROOT / "stages" / "dome.usda", light_units="photometric")
    with pytest.raises(UserError) as e:
        build_candidates(scene, study.candidates, str(path))
    assert message in str(e.value) and "\n" not in str(e.value), str(e.value)


@pytest.mark.parametrize("model, extra, group, message", [
    ("class_b_head", "gain = 2", "", "gain and integration_ms are for a set with a model"),
    ("li190r", "", "", "candidates[1].model: 'li190r' reports ppfd; a photometric study reads illuminance"),
    ("class_b_head", "", 'spectrum = "D99"', "group[0].spectrum"),
])
def test_study_model_mistakes_are_one_line(tmp_path, model, extra, group, message):
    """A gain on a set without electronics, a model that does not report the study's quantity and a group
    spectrum that is no spectrum stop the study with one line naming the key."""
    from simulator.study.runner import run_study

    body = OPEN.format(stage=ROOT / "stages" / "dome.usda", model=model, extra=extra)
    if model == "class_b_head" and extra:
        body = body.replace('model = "class_b_head"\n', "")
    body = body.replace('sky = "tregenza"\n', f'sky = "tregenza"\n{group}\n')
    p = tmp_path / "s.toml"
    p.write_text(body + '[[scenario]]\nname = "x"\nlevels = { sky = 1 }\n')
    with pytest.raises(UserError) as e:
        study, path = load_study(p)
        run_study(study, path, tmp_path / "o", log=lambda m: None, reference_run=False)
    assert message in str(e.value) and "\n" not in str(e.value), str(e.value)


def test_a_scenario_study_reads_a_head_through_its_spectrum(tmp_path):
    """A scenario study (the uniform sky of dome.usda, L = 1 cd/m², at level 0.8, traced as sky patches)
    reads a Gaussian cosine head at 0.8·π·L/F(D65) within 4 standard errors, and the plain sensor beside it
    0.8·π·L as before."""
    from simulator.study.runner import run_study

    p = tmp_path / "s.toml"
    p.write_text(OPEN.format(stage=ROOT / "stages" / "dome.usda", model=_gaussian_model(tmp_path), extra="")
                 + '[[scenario]]\nname = "x"\nlevels = { sky = 0.8 }\n')
    study, path = load_study(p)
    res = run_study(study, path, tmp_path / "o", log=lambda m: None, reference_run=False)
    e = 0.8 * math.pi
    want = [e, e / _f_by_integral("D65"), e / _f_by_integral("D65")]
    for i, w in enumerate(want):
        assert abs(res.mean[0, i, 1] - w) <= 4 * res.stderr[0, i, 1] + 1e-5 * w, (i, res.mean[0, i, 1], w)
    assert res.sensor_models["gauss"]["sets"] == ["head"]
