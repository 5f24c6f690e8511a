"""Sensor models: their quality indices against their definitions, the electronics' counts, noise and
ranging, the bundled models, the config's keys and their errors, and the columns a run writes.

References: docs/REFERENCES.md §Sensor models: f2 of cosⁿ, f1′, the mismatch factor F, the DIN 5032-7
limits. Independent integrals are numpy trapezoid sums over colour-science's CIE tables, written here,
not the module's code. Statistical checks use fixed seeds: a chi-square p-value over 1e-3, or 4σ.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest
from scipy import stats

from simulator.errors import UserError
from simulator.reference import closed_forms as cf
from simulator.sensor_models.angular import half_power
from simulator.sensor_models.electronics import Electronics, Setting, read_device, reading_stream
from simulator.sensor_models.model import DIN_CLASSES, bundled_names, din_class, load_model
from simulator.sensor_models.spectral import Channel
from simulator.spectra.sources import emitter_spectrum
from simulator.spectra.wide import WIDE_NM

ROOT = Path(__file__).resolve().parents[1]


# ----------------------------------------------------------------------------- indices


@pytest.mark.parametrize("angle", [10.0, 30.0, 47.0, 60.0, 75.0])
def test_half_power_f2_matches_its_closed_form(angle):
    """A half-power model is cosⁿ θ with n = ln ½ / ln cos θ½; its f2 (ISO/CIE 19476: ∫₀^85° |r/(r(0)cos ε)
    − 1| sin 2ε dε) is |1 − c² − 2(1 − c^{n+1})/(n + 1)|, c = cos 85° (docs/REFERENCES.md §Sensor models).
    The module integrates the definition by the midpoint rule: they agree to 1e-7 (60°: the cosine, 0)."""
    h = half_power(angle)
    n = float(cf.half_power_exponent(angle))
    assert h.exponent == pytest.approx(n, rel=1e-12)
    assert h.f2() == pytest.approx(float(cf.cos_power_f2(n)), abs=1e-7)


def _v_and_a():
    """V(λ) and CIE illuminant A on 380–780 nm at 1 nm, from colour-science's CIE tables."""
    import colour

    wl = np.arange(380.0, 781.0)
    v = np.asarray(colour.colorimetry.SDS_LEFS_PHOTOPIC["CIE 1924 Photopic Standard Observer"][wl], float)
    a = np.asarray(colour.SDS_ILLUMINANTS["A"][wl], float)
    return wl, v, a


def _gaussian_file(tmp_path, centre=560.0, width=45.0) -> Path:
    p = tmp_path / "gauss.csv"
    wl = np.arange(300, 1101)
    rows = "\n".join(f"{x},{math.exp(-0.5 * ((x - centre) / width) ** 2):.12g}" for x in wl)
    p.write_text("wavelength_nm,responsivity\n" + rows + "\n")
    return p


def _gaussian_model(tmp_path, centre=560.0, width=45.0):
    (tmp_path / "gauss.toml").write_text(
        f'name = "gauss"\n[angular]\ncos_power = 1.0\n[[channel]]\nresponsivity = "{_gaussian_file(tmp_path, centre, width).name}"\n')
    return load_model(str(tmp_path / "gauss.toml"))


@pytest.mark.parametrize("centre, width", [(560.0, 45.0), (540.0, 60.0), (600.0, 30.0)])
def test_gaussian_f1_prime_matches_its_definition(tmp_path, centre, width):
    """f1′ of a Gaussian responsivity s (ISO/CIE 19476 §5.3.3): s* = s·∫A V/∫A s, f1′ = ∫|s* − V| / ∫V over
    380–780 nm, here by numpy's trapezoid rule on 1 nm with V and A from the CIE tables: the model's f1′
    equals it to 1e-9 relative."""
    m = _gaussian_model(tmp_path, centre, width)
    wl, v, a = _v_and_a()
    s = np.exp(-0.5 * ((wl - centre) / width) ** 2)
    s_star = s * np.trapezoid(a * v, wl) / np.trapezoid(a * s, wl)
    expected = np.trapezoid(np.abs(s_star - v), wl) / np.trapezoid(v, wl)
    assert m.f1_prime() == pytest.approx(expected, rel=1e-9)
    assert expected > 0.05  # a real mismatch, not a degenerate one


def test_mismatch_factor_is_one_under_A_and_its_integral_under_D65(tmp_path):
    """F = ∫S_t V · ∫S_A s / (∫S_A V · ∫S_t s) (ISO/CIE 19476 §5.4): exactly 1 under A, the calibration
    illuminant (1e-12); under D65 the numpy integral with colour-science's A and D65 tables (V over
    380–780 nm, s over 300–780 nm, where those tables stop; the Gaussian at 600 ± 30 nm has under 1e-7
    of its weight beyond) within 1e-6."""
    import colour

    m = _gaussian_model(tmp_path, 600.0, 30.0)
    assert m.mismatch(emitter_spectrum("A").on_wide_grid()) == pytest.approx(1.0, abs=1e-12)
    wl, v, a = _v_and_a()
    wl_s = np.arange(300.0, 781.0)
    s = np.exp(-0.5 * ((wl_s - 600.0) / 30.0) ** 2)
    d65 = colour.SDS_ILLUMINANTS["D65"]
    a_s = np.asarray(colour.SDS_ILLUMINANTS["A"][wl_s], float)
    d_v, d_s = np.asarray(d65[wl], float), np.asarray(d65[wl_s], float)
    expected = (np.trapezoid(d_v * v, wl) * np.trapezoid(a_s * s, wl_s)) / (np.trapezoid(a * v, wl) * np.trapezoid(d_s * s, wl_s))
    f = m.mismatch(emitter_spectrum("D65").on_wide_grid())
    assert f == pytest.approx(expected, rel=1e-6)
    assert abs(f - 1.0) > 0.01  # a Gaussian head misreads daylight


def test_photopic_and_par_heads_have_no_mismatch():
    """A head whose responsivity is its quantity's weighting (V(λ), the ideal quantum response) reads every
    light true: F = 1 to 1e-12 under A, D65, a 3000 K blackbody, LED-B3 and FL2."""
    for name in ("ideal_photometer", "li190r"):
        m = load_model(name)
        for light in ("A", "D65", 3000, "LED-B3", "FL2"):
            assert m.mismatch(emitter_spectrum(light).on_wide_grid()) == pytest.approx(1.0, abs=1e-12), (name, light)


def test_class_heads_sit_at_their_din_limits():
    """The bundled class L, A and B heads meet their DIN 5032-7 class, at its limits: f1′ and f2 within
    2e-4 (absolute) under each limit (docs/REFERENCES.md §Sensor models); and din_class reads the table."""
    limits = {name: (l1, l2) for name, l1, l2 in DIN_CLASSES}
    for k in ("l", "a", "b"):
        m = load_model(f"class_{k}_head")
        ix = m.indices()
        l1, l2 = limits[k.upper()]
        assert ix["din_5032_7_class"] == k.upper()
        assert l1 - 2e-4 <= ix["f1_prime"] <= l1 and l2 - 2e-4 <= ix["f2"] <= l2, ix
    assert din_class(0.01, 0.01) == "L" and din_class(0.02, 0.01) == "A" and din_class(0.05, 0.02) == "B"
    assert din_class(0.08, 0.05) == "C" and din_class(0.1, 0.01) == "none"


@pytest.mark.parametrize("name", bundled_names())
def test_bundled_models_read_true_under_their_calibration(name):
    """Each bundled model reports the true quantity of its calibration illuminant at normal incidence (its
    calibration convention): the optics' value per unit true quantity is 1 (1e-9), two-channel firmware
    included; and ``probesim sensor`` formats it."""
    from simulator.commands.sensor import format_model

    m = load_model(name)
    cal = m.calibration_wide
    assert m.optics_value(m.signals_per_true(cal)) == pytest.approx(1.0, rel=1e-9)
    assert m.name == name and m.source
    assert name in format_model(m)


# ----------------------------------------------------------------------------- electronics


def _plain(**kw) -> tuple[Electronics, tuple[Channel, ...]]:
    el = Electronics(bits=kw.pop("bits", 12), gains=(1.0, 4.0), integration_ms=(100.0, 400.0), reference_gain=1.0,
                     reference_integration_ms=100.0, **kw)
    return el, (Channel("c", np.ones_like(WIDE_NM), "flat", counts_per_unit=10.0),)


def test_counts_are_quantised_to_the_lsb():
    """Without noise the code is ⌊X·counts_per_unit·(g/g_ref)·(t/t_ref)⌋ and the value that code's LSBs:
    X = 12.34 lx at 10 counts/lx, gain 4, 400 ms → μ = 1974.4 counts, code 1974, value 1974/160 lx, within one
    LSB (1/160 lx) below X; noise_sd 0."""
    el, ch = _plain()
    d = read_device(el, ch, [12.34], seed=1, sensor="s", gain=4.0, integration_ms=400.0)
    assert d.counts == (1974,) and d.mean_counts[0] == pytest.approx(1974.4)
    assert d.value == pytest.approx(1974 / 160.0, rel=1e-15)
    assert 0 <= 12.34 - d.value < 1 / 160.0 and d.noise_sd == 0.0 and not d.saturated


def test_saturation_is_flagged_never_silent():
    """A count at or past full scale (2^12 − 1 = 4095) reports full scale and says so: X = 1000 lx at gain
    1, 100 ms is 10,000 counts; below it, no flag."""
    el, ch = _plain()
    d = read_device(el, ch, [1000.0], seed=1, sensor="s", gain=1.0, integration_ms=100.0)
    assert d.saturated and d.counts == (4095,) and d.value == pytest.approx(409.5)
    assert not read_device(el, ch, [409.0], seed=1, sensor="s", gain=1.0, integration_ms=100.0).saturated


def test_auto_ranging_picks_the_most_sensitive_setting_under_its_ceiling():
    """gain = "auto": the most sensitive (gain, time) whose noiseless count stays under auto_range_max ×
    full scale (0.8 × 4095 = 3276): 5 lx → 4×, 400 ms (800 counts); 50 lx → 4×, 100 ms (2000); 200 lx
    → 1×, 100 ms (2000); 1000 lx → none fits: the least sensitive, saturated. The OPT3001 picks its
    exponent so (500 lx: E = 4, 0.16 lx per code); the VEML7700 reads at its application note's gain 1/8,
    100 ms unless told; a TSL2561 at 13.7 ms has its 5,047-count full scale."""
    el, ch = _plain(auto_range=True)
    picks = {x: read_device(el, ch, [x], seed=1, sensor="s", gain="auto").setting for x in (5.0, 50.0, 200.0, 1000.0)}
    assert picks[5.0] == Setting(4.0, 400.0) and picks[50.0] == Setting(4.0, 100.0)
    assert picks[200.0] == Setting(1.0, 100.0) and picks[1000.0] == Setting(1.0, 100.0)
    assert read_device(el, ch, [1000.0], seed=1, sensor="s", gain="auto").saturated
    opt = load_model("opt3001")
    d = read_device(opt.electronics, opt.channels, [500.0], seed=1, sensor="s")
    assert d.setting.gain == pytest.approx(1 / 16) and not d.saturated
    assert abs(d.value - 500.0) < 0.16 * 4 + 0.02  # an LSB of 0.16 lx, the dark codes and the read noise
    veml = load_model("veml7700")
    assert read_device(veml.electronics, veml.channels, [100.0], seed=1, sensor="s").setting == Setting(0.125, 100.0)
    tsl = load_model("tsl2561")
    assert tsl.electronics.full_scale_at(Setting(1.0, 13.7)) == 5047


def test_device_noise_spread_matches_its_stated_sd():
    """The device's noise: N(μ, σ_read² + μ/e) counts, then ⌊·⌋. Over 4,000 readings (streams seeded by the
    sensors' names) at μ = 2000 counts, σ_read = 3, e = 2 (σ² = 1009), the values' variance matches
    noise_sd² + LSB²/12 (quantisation): (N − 1)s²/σ² is chi-square with N − 1 degrees of freedom
    (two-sided p > 1e-3), and their mean is (μ − ½) LSB within 4σ/√N."""
    el, ch = _plain(read_noise_counts=3.0, electrons_per_count=2.0)
    x = 2000.0 / 10.0  # lx at gain 1, 100 ms: 2000 counts
    reads = [read_device(el, ch, [x], seed=7, sensor=f"s{i}", gain=1.0, integration_ms=100.0) for i in range(4000)]
    v = np.array([r.value for r in reads])
    lsb = 0.1
    sd = reads[0].noise_sd
    assert sd == pytest.approx(math.sqrt(1009.0) * lsb, rel=1e-12)
    var = sd**2 + lsb**2 / 12
    n = len(v)
    stat = (n - 1) * v.var(ddof=1) / var
    p = stats.chi2.cdf(stat, n - 1)
    assert 1e-3 / 2 < p < 1 - 1e-3 / 2, (p, v.var(ddof=1), var)
    assert abs(v.mean() - (x - lsb / 2)) <= 4 * math.sqrt(var / n)


def test_noise_streams_depend_on_seed_and_name_only():
    """A reading's noise stream is fixed by (run seed, sensor name): the same pair draws the same numbers
    in any order; another name or seed draws others."""
    a = reading_stream(3, "desk[1,2]").standard_normal(4)
    _ = reading_stream(3, "other").standard_normal(4)
    assert np.array_equal(a, reading_stream(3, "desk[1,2]").standard_normal(4))
    assert not np.array_equal(a, reading_stream(4, "desk[1,2]").standard_normal(4))
    assert not np.array_equal(a, reading_stream(3, "desk[1,3]").standard_normal(4))


def test_two_channel_formula_follows_the_data_sheet():
    """The TSL2561's formula on codes scaled to 16× and 402 ms: at r = CH1/CH0 = 0.3, lux = 0.0304·CH0 −
    0.062·CH0·0.3^1.4; at 0.7, 0.0128·CH0 − 0.0153·CH1; past 1.30, 0 (the data sheet's table). Codes at
    1× and 101 ms are scaled by 16·402/101 first."""
    from simulator.sensor_models.electronics import firmware_value

    el = load_model("tsl2561").electronics
    nominal = Setting(16.0, 402.0)
    assert firmware_value(el, [1000.0, 300.0], nominal) == pytest.approx(0.0304 * 1000 - 0.062 * 1000 * 0.3**1.4)
    assert firmware_value(el, [1000.0, 700.0], nominal) == pytest.approx(0.0128 * 1000 - 0.0153 * 700)
    assert firmware_value(el, [1000.0, 1400.0], nominal) == 0.0
    k = 16 * 402 / 101
    assert firmware_value(el, [100.0, 30.0], Setting(1.0, 101.0)) == pytest.approx(
        0.0304 * 100 * k - 0.062 * 100 * k * 0.3**1.4)


def test_many_readings_at_once_are_the_single_readings():
    """read_devices (a year's hours at once) gives, reading by reading, what read_device gives with the same
    noise draw: the setting (fixed, or auto-ranged per reading), the codes, the saturation flag and the
    value (relative 1e-12), for a one-channel part with shot noise and dark counts ranging over 0.01–5,000 lx
    and for the TSL2561's two channels and formula over 1–50,000 lx."""
    from simulator.sensor_models.electronics import read_devices

    el, ch = _plain(auto_range=True, read_noise_counts=2.0, electrons_per_count=3.0)
    ch = (Channel("c", np.ones_like(WIDE_NM), "flat", counts_per_unit=10.0, dark_counts_per_s=5.0),)
    tsl = load_model("tsl2561")
    rng = np.random.default_rng(3)
    for e, chans, x, gains in ((el, ch, np.geomspace(0.01, 5000.0, 60)[:, None], ("auto", 4.0)),
                               (tsl.electronics, tsl.channels, np.geomspace(1.0, 5e4, 40)[:, None] * [1.0, 0.4], ("auto", 1.0))):
        for gain in gains:
            t = None if gain == "auto" else e.integration_ms[-1]
            z = rng.standard_normal(x.shape)
            many = read_devices(e, chans, x, z, gain, t)
            for n in range(len(x)):
                one = read_device(e, chans, list(x[n]), seed=0, sensor="s", gain=gain, integration_ms=t)
                # the same reading with this draw: replay it through the single reading's arithmetic
                s_ = one.setting
                mu = np.array(one.mean_counts)
                var = e.read_noise_counts ** 2 + (np.maximum(mu, 0.0) / e.electrons_per_count if e.electrons_per_count else 0.0)
                analogue = mu + np.sqrt(var) * z[n]
                fs = e.full_scale_at(s_)
                codes = np.clip(np.floor(analogue), 0, fs).astype(np.int64)
                assert (many.gain[n], many.integration_ms[n]) == (s_.gain, s_.integration_ms)
                assert tuple(many.counts[n]) == tuple(codes) and bool(many.saturated[n]) == bool(np.any(analogue >= fs))
                if e.firmware == "linear":
                    want = codes[0] / (chans[0].counts_per_unit * e.sensitivity(s_))
                else:
                    from simulator.sensor_models.electronics import firmware_value

                    want = firmware_value(e, codes.astype(float), s_)
                assert many.value[n] == pytest.approx(want, rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("gain", [4.0, "auto"])
def test_the_signal_reaching_a_reading_is_its_threshold(gain):
    """signal_reaching gives, per noise draw, the least signal whose reading reaches a value: on a fine grid
    of signals (0.1–500 lx, 20,000 steps) the first that reaches the value lies one step above it at most and
    none below it does (at a fixed gain every one above it does too), for a fixed gain (4×, 400 ms: full
    scale 25.6 lx, so 80 and 250 lx are never reached: +inf) and auto-ranging (a reading's setting changing
    with its signal), read noise 2 counts and shot noise of 3 electrons per count."""
    from simulator.sensor_models.electronics import read_devices, signal_reaching

    el, _ = _plain(auto_range=True, read_noise_counts=2.0, electrons_per_count=3.0)
    ch = (Channel("c", np.ones_like(WIDE_NM), "flat", counts_per_unit=10.0, dark_counts_per_s=5.0),)
    t = None if gain == "auto" else 400.0
    grid = np.linspace(0.1, 500.0, 20001)
    reached = 0
    for value, z in ((12.3, 0.0), (12.3, 1.7), (20.0, -2.2), (80.0, -2.2), (250.0, 0.4), (1e6, 0.0)):
        x_star = float(signal_reaching(el, ch[0], value, np.array([z]), gain, t)[0])
        r = read_devices(el, ch, grid[:, None], np.full((len(grid), 1), z), gain, t).value >= value
        if not r.any():  # saturates below the value (4×, 400 ms: full scale 25.6 lx; any setting: 10⁶ lx)
            assert math.isinf(x_star) and x_star > 0, (value, z, x_star)
            continue
        reached += 1
        first = int(np.argmax(r))
        assert first > 0 and grid[first - 1] - 1e-9 < x_star <= grid[first] + 1e-9, (value, z, x_star)
        if gain != "auto":  # at one setting a reading grows with its signal (ranging can step it back a code)
            assert r[first:].all()
    assert reached >= (2 if gain != "auto" else 5)


# ----------------------------------------------------------------------------- config


def _config(tmp_path, sensor_extra: str, name="c.toml") -> Path:
    p = tmp_path / name
    p.write_text(f'stage = "{ROOT / "stages" / "dome.usda"}"\n[simulation]\nsamples = 256\nseed = 3\n'
                 f'[[sensor]]\nname = "s"\nkind = "irradiance"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]\n{sensor_extra}\n'
                 f'[output]\ncsv = "{tmp_path / "out.csv"}"\n')
    return p


@pytest.mark.parametrize("extra, message", [
    ('model = "opt3002"', "sensor[0].model: unknown sensor model 'opt3002' (did you mean 'opt3001'?)"),
    ('model = "veml7700"\ngain = 3', "sensor[0].gain: 3 is not one of the part's gains (2, 1, 0.25, 0.125)"),
    ('model = "veml7700"\nintegration_ms = 90', "sensor[0].integration_ms: 90 is not one of the part's"),
    ('model = "ideal_photometer"\ngain = 2', "sensor[0].gain: model 'ideal_photometer' has no electronics"),
    ("gain = 2", "sensor[0].gain: only with a model"),
    ('model = "missing.toml"', "sensor[0].model: sensor model file"),
    ('model = "veml7700"\ngain = "high"', "sensor[0].gain: expected a positive number or \"auto\""),
])
def test_model_keys_errors_name_the_key(tmp_path, extra, message):
    """Every mistake in a sensor's model keys is one UserError line naming the config and the key."""
    from simulator.config.loader import load_config

    with pytest.raises(UserError) as e:
        load_config(_config(tmp_path, extra))
    assert message in str(e.value) and str(e.value).startswith(str(tmp_path / "c.toml")) and "\n" not in str(e.value), str(e.value)


@pytest.mark.parametrize("angular, row, message", [
    ("angle_deg,response\n0,1\n40,-0.5\n", 3, "response -0.5 is negative"),
    ("angle_deg,response\n0,1\n91,0\n", 3, "angle 91° is outside 0–90°"),
    ("angle_deg,response\n0,1\n40,0.5\n20,0.8\n", 4, "angle 20° is not above the previous row's (40°)"),
    ("angle_deg,response\n0,0\n40,0.5\n", 2, "the response at normal incidence is 0"),
])
def test_model_file_errors_name_the_file_and_row(tmp_path, angular, row, message):
    """A model file's table at fault is named down to its row, through the config that names the model."""
    from simulator.config.loader import load_config

    (tmp_path / "head.csv").write_text(angular)
    (tmp_path / "head.toml").write_text('name = "head"\n[angular]\ntable = "head.csv"\n[[channel]]\nresponsivity = "photopic"\n')
    with pytest.raises(UserError) as e:
        load_config(_config(tmp_path, 'model = "head.toml"'))
    assert f"head.csv:{row}: {message}" in str(e.value) and "sensor[0].model" in str(e.value), str(e.value)


def test_model_file_key_errors(tmp_path):
    """Unknown keys, a missing angular table and a bad `reports` are named with the model file and key."""
    cases = [('name = "h"\ncolour = 1\n[angular]\ncos_power = 1\n[[channel]]\nresponsivity = "photopic"\n', "colour: unknown key"),
             ('name = "h"\n[[channel]]\nresponsivity = "photopic"\n', "angular: required"),
             ('name = "h"\nreports = "lux"\n[angular]\ncos_power = 1\n[[channel]]\nresponsivity = "photopic"\n', "reports: 'lux'"),
             ('name = "h"\n[angular]\ncos_power = 1\nhalf_power_angle_deg = 40\n[[channel]]\nresponsivity = "photopic"\n',
              "angular: give exactly one")]
    for i, (text, message) in enumerate(cases):
        p = tmp_path / f"h{i}.toml"
        p.write_text(text)
        with pytest.raises(UserError) as e:
            load_model(str(p))
        assert f"{p}: {message}" in str(e.value), str(e.value)


# ----------------------------------------------------------------------------- runs


def _rows(path: Path) -> list[dict]:
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_dome_run_reads_the_model_through_its_optics(tmp_path):
    """Under the dome stage's uniform sky (L = 1 cd/m², D65, black ground), a horizontal sensor naming the
    class B head reads, beside its ideal π·L lx, the head's optics: L·2π/(n + 1) (its cosⁿ response,
    docs/REFERENCES.md §Sensor models) divided by its mismatch factor under D65 (the true illuminance is
    F times its reading), within 4 standard errors + 1e-6; the CSV names the model and the F it used; the
    ideal columns are the bytes a run without the model writes."""
    from simulator.config.loader import load_config
    from simulator.pipeline import run

    out = run(load_config(_config(tmp_path, 'model = "class_b_head"')), log=lambda m: None)
    (row,) = _rows(out.csv_path)
    m = load_model("class_b_head")
    f = m.mismatch(emitter_spectrum("D65").on_wide_grid())
    truth = float(cf.cos_power_dome_reading(1.0, m.angular.exponent)) / f
    assert row["model"] == "class_b_head" and float(row["spectral_mismatch_F"]) == pytest.approx(f, rel=1e-8)
    assert abs(float(row["optics_illuminance_lx"]) - truth) <= 4 * float(row["optics_illuminance_stderr_lx"]) + 1e-6 * truth
    assert row["device_illuminance_lx"] == row["optics_illuminance_lx"]  # no electronics: the optics' signal
    assert "sensor_models" in out.record and "class_b_head" in out.record["sensor_models"]["models"]
    plain = run(load_config(_config(tmp_path, "", name="plain.toml")), log=lambda m: None)
    (ideal,) = _rows(plain.csv_path)
    for k, v in ideal.items():
        if k != "seconds":
            assert row[k] == v, k


def test_patch_names_a_model_and_reads_its_area_average(tmp_path):
    """A `[[sensor]]` patch names a model as an irradiance sensor does (a photometer head's area average):
    under the dome stage's uniform sky (L = 1 cd/m², D65) a 0.4 m × 0.2 m class B patch reads
    L·2π/(n + 1)/F_D65 at every point, so its optics column is that within 4 standard errors + 1e-6; its
    ideal columns (irradiance and flux) are the bytes of the same patch without the model; a VEML7700
    patch at gain 1/8 and 100 ms gets the device columns at that setting."""
    from simulator.config.loader import load_config
    from simulator.pipeline import run

    def cfg(extra: str, name: str) -> Path:
        p = tmp_path / name
        p.write_text(f'stage = "{ROOT / "stages" / "dome.usda"}"\n[simulation]\nsamples = 256\nseed = 3\n'
                     '[[sensor]]\nname = "p"\nkind = "patch"\nposition = [0, 0, 0]\nnormal = [0, 0, 1]\n'
                     f'size = [0.4, 0.2]\nup = [0, 1, 0]\n{extra}\n[output]\ncsv = "{tmp_path / name}.csv"\n')
        return p

    (row,) = _rows(run(load_config(cfg('model = "class_b_head"', "m.toml")), log=lambda m: None).csv_path)
    m = load_model("class_b_head")
    truth = float(cf.cos_power_dome_reading(1.0, m.angular.exponent)) / m.mismatch(emitter_spectrum("D65").on_wide_grid())
    assert row["model"] == "class_b_head"
    assert abs(float(row["optics_illuminance_lx"]) - truth) <= 4 * float(row["optics_illuminance_stderr_lx"]) + 1e-6 * truth
    (ideal,) = _rows(run(load_config(cfg("", "plain.toml")), log=lambda m: None).csv_path)
    assert "luminous_flux_lm" in ideal
    for k, v in ideal.items():
        if k != "seconds":
            assert row[k] == v, k
    (dev,) = _rows(run(load_config(cfg('model = "veml7700"\ngain = 0.125\nintegration_ms = 100', "d.toml")),
                       log=lambda m: None).csv_path)
    assert float(dev["device_gain"]) == 0.125 and float(dev["device_integration_ms"]) == 100.0 and dev["device_counts_als"] != ""


def test_model_output_is_byte_identical_across_threads(tmp_path):
    """A run with modelled sensors (the OPT3001, whose device noise is drawn per reading, and the TSL2561's
    two channels) writes the same CSV cells with 1 and 2 worker threads (the seconds column aside)."""
    from dataclasses import replace

    from simulator.config.loader import load_config
    from simulator.pipeline import run

    extra = ('model = "opt3001"\n[[sensor]]\nname = "t"\nkind = "irradiance"\nposition = [0, 0, 1]\n'
             'normal = [0.6, 0, 0.8]\nmodel = "tsl2561"')
    cfg = load_config(_config(tmp_path, extra))
    texts = []
    for threads in (1, 2):
        c = replace(cfg, simulation=replace(cfg.simulation, threads=threads),
                    output=replace(cfg.output, csv=tmp_path / f"t{threads}.csv"))
        rows = _rows(run(c, log=lambda m: None).csv_path)
        texts.append([{k: v for k, v in r.items() if k != "seconds"} for r in rows])
    assert texts[0] == texts[1]
    assert texts[0][0]["device_counts_als"] != "" and texts[0][1]["device_counts_ch1"] != ""


def test_stage_authored_sensor_names_a_model(tmp_path):
    """An irradiance sensor authored in the stage takes `probesim:sensor:model` (a bundled name): its row
    gains the model's columns; a model on another kind, or an unknown one, is one line naming the prim."""
    from simulator.config.loader import load_config
    from simulator.pipeline import run

    dome = (ROOT / "stages" / "dome.usda").read_text()

    def stage(attrs: str) -> Path:
        extra = ('def Xform "Head"\n{\n    token probesim:sensor:kind = "%s"\n    string probesim:sensor:model = "%s"\n'
                 '    double3 xformOp:translate = (0, 0, 0.5)\n    float3 xformOp:rotateXYZ = (180, 0, 0)\n'
                 '    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]\n}\n') % attrs
        text = dome.rstrip()
        assert text.endswith("}")
        p = tmp_path / "stage.usda"
        p.write_text(text[:-1] + extra + "}\n")
        return p

    def cfg(p: Path) -> Path:
        c = tmp_path / "c.toml"
        c.write_text(f'stage = "{p}"\n[simulation]\nsamples = 256\n[output]\ncsv = "{tmp_path / "o.csv"}"\n')
        return c

    out = run(load_config(cfg(stage(("irradiance", "class_l_head")))), log=lambda m: None)
    (row,) = _rows(out.csv_path)
    assert row["sensor"] == "/World/Head" and row["model"] == "class_l_head" and float(row["optics_illuminance_lx"]) > 0
    for attrs, message in ((("radiance", "class_l_head"), "only an irradiance or a patch sensor takes a model"),
                           (("irradiance", "nope"), "unknown sensor model 'nope'")):
        with pytest.raises(UserError) as e:
            run(load_config(cfg(stage(attrs))), log=lambda m: None)
        assert "/World/Head" in str(e.value) and message in str(e.value), str(e.value)


def test_study_candidates_take_a_model(tmp_path):
    """A study's candidate set that names a model reads through its angular response: its sensors are
    irradiance sensors carrying the model's response (the engine's optics hook), not cones; a model on a
    cylindrical set, or an unknown one, is one line naming the key."""
    from simulator.scene.usd import load_stage
    from simulator.study.inputs.candidates import build_candidates
    from simulator.study.schema import load_study

    def study(extra: str, kind: str = "photosensor") -> Path:
        p = tmp_path / "s.toml"
        p.write_text(f'stage = "{ROOT / "stages" / "office.usda"}"\n[[candidates]]\nname = "ceiling"\nkind = "{kind}"\n'
                     f'points = [[2.0, 2.0, 2.98], [4.0, 2.0, 2.98]]\nnormal = [0, 0, -1]\n{extra}\n'
                     '[[group]]\nname = "sky"\nlights = ["/Office/Sky"]\n[[scenario]]\nname = "day"\nlevels = { sky = 1.0 }\n')
        return p

    s, path = load_study(study('model = "ceiling_photosensor"'))
    scene = load_stage(ROOT / "stages" / "office.usda", light_units="photometric")
    (cset,) = build_candidates(scene, s.candidates, str(path))
    sensors = [c.sensor for c in cset.candidates]
    assert all(x.kind.name == "IRRADIANCE" and x.optics is load_model("ceiling_photosensor").angular for x in sensors)
    for extra, kind, message in (('model = "ceiling_photosensor"\nfacing = [1, 0, 0]', "semicylindrical", "model is for kind"),
                                 ('model = "nope"', "irradiance", "candidates[0].model: unknown sensor model 'nope'")):
        with pytest.raises(UserError) as e:
            s2, p2 = load_study(study(extra, kind))
            build_candidates(scene, s2.candidates, str(p2))
        assert message in str(e.value) and "\n" not in str(e.value), str(e.value)


def test_a_study_chunk_knows_its_head():
    """A study's chunk store keys a chunk by its sensors: two heads at the same place are different
    chunks (a resumed study never reuses another head's readings), and a sensor without a model keys as
    before (no optics in its text)."""
    from simulator.scene.model import Sensor, SensorKind
    from simulator.study.trace.chunks import _sensor_text

    p, n = np.zeros(3), np.array([0.0, 0.0, 1.0])
    plain = _sensor_text(Sensor("a", SensorKind.IRRADIANCE, p, n))
    heads = [_sensor_text(Sensor("a", SensorKind.IRRADIANCE, p, n, optics=load_model(m).angular))
             for m in ("ceiling_photosensor", "opt3001", "class_b_head")]
    assert "optics" not in plain and len({plain, *heads}) == 4


def test_spectral_run_keeps_its_ideal_columns_and_reads_the_ideal_head(tmp_path):
    """In the quickstart room (a coloured rug: hero wavelengths), a work-plane sensor naming the ideal
    photometer writes the ideal cells of the same run without a model (byte for byte, seconds aside),
    and its optics reading (cosine, V(λ), traced apart) equals its ideal illuminance within 4 combined
    standard errors, with a mismatch factor of 1 (1e-6: V against its own response)."""
    from simulator.config.loader import load_config
    from simulator.pipeline import run

    def cfg(extra: str, name: str) -> Path:
        p = tmp_path / f"{name}.toml"
        p.write_text(f'stage = "{ROOT / "stages" / "quickstart.usda"}"\n[simulation]\nsamples = 512\nseed = 2\n'
                     '[[sensor]]\nname = "w"\nkind = "irradiance"\nposition = [2.5, 2.0, 0.8]\nnormal = [0, 0, 1]\n'
                     f'{extra}\n[output]\ncsv = "{tmp_path / name}.csv"\n')
        return p

    with_model = _rows(run(load_config(cfg('model = "ideal_photometer"', "m")), log=lambda m: None).csv_path)
    plain = _rows(run(load_config(cfg("", "p")), log=lambda m: None).csv_path)
    for a, b in zip(with_model, plain):
        assert {k: v for k, v in b.items() if k != "seconds"} == {k: a[k] for k in b if k != "seconds"}
    w = next(r for r in with_model if r["sensor"] == "w")
    e, se = float(w["illuminance_lx"]), float(w["illuminance_stderr_lx"])
    o, ose = float(w["optics_illuminance_lx"]), float(w["optics_illuminance_stderr_lx"])
    assert abs(o - e) <= 4 * math.hypot(se, ose), (o, e)
    assert float(w["spectral_mismatch_F"]) == pytest.approx(1.0, abs=1e-6)
