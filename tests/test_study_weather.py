"""The year read right: an EPW and its TMY3 twin give the same year; the Perez sky clamped to its fitted
range; weather whose components do not close is warned of, and swapped columns refused."""

import csv
import math
import os
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from simulator.errors import UserError
from simulator.study.inputs import sky_patches as SP
from simulator.study.annual.climate import CLOSURE_HOUR_TOL, daylight_mask, hour_of_day, read_weather
from simulator.study.annual.perez import BRIGHTNESS_RANGE, _patch_grid, air_mass, hour_skies, perez_parameters, relative_luminance

pvlib = pytest.importorskip("pvlib")
ROOT = Path(__file__).resolve().parents[1]
BUNDLED = ROOT / "stages" / "weather" / "greensboro_tmy3_lux.csv"
#: an equinox, both solstices, a September day of the bundled year, and the last day of its February (from 1996,
#: a leap year: pvlib's read_tmy3 moves the row "02/28/1996 24:00" to 1 March)
DAYS = ("03/21", "06/21", "12/21", "09/10", "02/28")
PROJ = np.array([SP.patch_projected_solid_angle(p) for p in range(SP.N_PATCHES)])


def _table(days=DAYS) -> tuple[list[str], list[dict]]:
    """The bundled TMY3 file's site line and the rows of ``days`` (every column as text), read with csv alone."""
    lines = BUNDLED.read_text().splitlines()
    rows = [r for r in csv.DictReader(lines[1:]) if r["Date (MM/DD/YYYY)"][:5] in days]
    return next(csv.reader([lines[0]])), rows


def write_tmy3(path: Path, site: list[str], rows: list[dict]) -> Path:
    """The table as a TMY3 file: the site line, the column names, a row per hour labelled with its end (01:00 … 24:00)."""
    cols = list(rows[0])
    head = f'{site[0]},"{site[1]}",{",".join(site[2:])}'
    path.write_text("\n".join([head, ",".join(cols)] + [",".join(r[c] for c in cols) for r in rows]) + "\n")
    return path


def write_epw(path: Path, site: list[str], rows: list[dict], swap: bool = False) -> Path:
    """The same table as an EPW file (EnergyPlus weather format: 8 header lines, 35 fields a row, hour 1…24
    the hour ending at that time, minute 60); ``swap`` writes the direct-normal values into the diffuse
    fields and the diffuse into the direct (irradiances and illuminances), as a mistaken export would."""
    usaf, name, state, tz, lat, lon, alt = site
    head = [f"LOCATION,{name},{state},USA,TMY3,{usaf},{lat},{lon},{tz},{alt}", "DESIGN CONDITIONS,0", "TYPICAL/EXTREME PERIODS,0",
            "GROUND TEMPERATURES,0", "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0", "COMMENTS 1,the bundled TMY3 year's rows",
            "COMMENTS 2,written as EPW", "DATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31"]  # fmt: skip
    out = []
    for r in rows:
        mo, da, yr = (int(x) for x in r["Date (MM/DD/YYYY)"].split("/"))
        hr = int(r["Time (HH:MM)"].split(":")[0])  # TMY3 01:00 … 24:00 is EPW hour 1 … 24
        dni, dhi = r["DNI (W/m^2)"], r["DHI (W/m^2)"]
        dnl, dhl = r["DN illum (lx)"], r["DH illum (lx)"]
        if swap:
            dni, dhi, dnl, dhl = dhi, dni, dhl, dnl
        out.append(",".join([str(yr), str(mo), str(da), str(hr), "60", "?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9?9?9*9*9?9?9?9",
                             "20.0", r["Dew-point (C)"], "50", "101325", "9999", "9999", "9999", r["GHI (W/m^2)"], dni, dhi,
                             r["GH illum (lx)"], dnl, dhl, r["Zenith lum (cd/m^2)"], "0", "0.0", "0", "0", "9999", "99999", "9",
                             "999999999", "0", "0.1", "0", "88", "0.2", "0", "0"]))  # fmt: skip
    path.write_text("\n".join(head + out) + "\n")
    return path


@pytest.fixture(scope="module")
def twins(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("twins")
    site, rows = _table()
    return write_epw(tmp / "four_days.epw", site, rows), write_tmy3(tmp / "four_days.csv", site, rows)


# --- an EPW and its TMY3 twin -----------------------------------------------------------------------------------------


def test_an_epw_and_its_tmy3_twin_read_the_same_year(twins):
    """Both formats label a row with the end of its hour of data; pvlib indexes a TMY3 row by that end and an
    EPW row by its start (hour − 1). Read right, every row of the twins has the same end, centre, sun,
    values, daylight and occupancy hour; the sun of the row ending 13:00 is at 12:30 local standard time."""
    from simulator.study.inputs.sun import solar_position

    e, t = read_weather(twins[0]), read_weather(twins[1])
    assert len(e) == len(t) == 120
    assert list(e.end) == list(t.end) and list(e.centre) == list(t.centre)
    np.testing.assert_allclose(e.sun_elevation_deg, t.sun_elevation_deg, rtol=0, atol=1e-9)
    np.testing.assert_allclose(e.sun_azimuth_deg, t.sun_azimuth_deg, rtol=0, atol=1e-9)
    for k in ("dni_w_m2", "dhi_w_m2", "ghi_w_m2", "dni_lx", "dhi_lx", "ghi_lx", "dew_c"):
        np.testing.assert_array_equal(getattr(e, k), getattr(t, k), err_msg=k)
    np.testing.assert_array_equal(hour_of_day(e), hour_of_day(t))
    np.testing.assert_array_equal(daylight_mask(e), daylight_mask(t))
    last = int(np.nonzero([str(x).startswith("1996-02-29 00:00") for x in e.end])[0][0])  # the hour 23:00–24:00 of 28 February
    assert t.centre[last].day == 28 and t.centre[last].hour == 23
    r = int(np.nonzero([str(x).startswith("1990-03-21 13:00") for x in e.end])[0][0])  # 21 March, 12:00–13:00
    assert e.end[r].hour == 13 and e.centre[r].hour == 12 and e.centre[r].minute == 30
    az, el = solar_position(e.latitude_deg, e.longitude_deg, f"{e.centre[r].date()}T12:30:00-05:00")
    assert math.isclose(e.sun_elevation_deg[r], el, abs_tol=0.01) and math.isclose(e.sun_azimuth_deg[r], az, abs_tol=0.01)


OPEN = """
stage = "{stage}"
seed = 5
[simulation]
samples = 64
[[candidates]]
name = "open"
points = [[0, 0, 0.5], [3, 0, 0.5]]
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
replicates = 8
occupied_h = [8, 18]
"""


def test_the_annual_study_reads_the_same_year_from_an_epw_and_its_tmy3_twin(twins, tmp_path):
    """The open roof (stages/dome.usda) under both files, same seed: the same rows, suns, hourly readings
    and annual metrics (the traced coefficients do not depend on the weather; each hour's sky and sun do)."""
    from simulator.study.annual.year import run_annual
    from simulator.study.schema import load_study

    out = []
    for w in twins:
        p = tmp_path / f"{w.suffix[1:]}.toml"
        p.write_text(OPEN.format(stage=ROOT / "stages" / "dome.usda", weather=w))
        study, p = load_study(p)
        out.append(run_annual(study, p, tmp_path / f"{w.suffix[1:]}.out", log=lambda m: None))
    e, t = out
    np.testing.assert_array_equal(e.rows, t.rows)
    np.testing.assert_array_equal(e.occupied, t.occupied)
    np.testing.assert_allclose(e.skies.sun_dir, t.skies.sun_dir, rtol=0, atol=1e-12)
    np.testing.assert_allclose(e.skies.patch_cd_m2, t.skies.patch_cd_m2, rtol=1e-12, atol=0)
    np.testing.assert_allclose(e.mean, t.mean, rtol=1e-12, atol=1e-9)
    assert e.metrics.keys() == t.metrics.keys()
    for k, (v, se) in e.metrics["roof"].items():
        assert math.isclose(v, t.metrics["roof"][k][0], rel_tol=1e-12, abs_tol=1e-9), k
        assert math.isclose(se, t.metrics["roof"][k][1], rel_tol=1e-9, abs_tol=1e-9), k
    assert (e.skies.dni_lx > 0).sum() > 20 and e.metrics["roof"]["DA"][0] > 0  # sunny hours, and a figure that is not trivially 0


# --- the Perez sky at a low sun under a bright diffuse sky ------------------------------------------------------------


def test_a_low_sun_under_a_bright_diffuse_sky_keeps_its_sky():
    """One hour, sun 2° up, 300 W/m² diffuse and 30,000 lx: Δ = I_dh·m/I₀ ≈ 300·18/1400 ≈ 4, far above the
    fitted 0.6. Clamped (Perez 1990; gendaymtx: 0.01 ≤ Δ ≤ 0.6), the sky is the all-weather model at
    Δ = 0.6 — not uniform, its horizon and zenith apart — and its horizontal illuminance Σ L_p Π_p is the
    hour's 30,000 lx (normalisation, 1e-9). Unclamped every patch came out negative and was clipped to 0."""
    w = read_weather(BUNDLED)
    r = int(np.nonzero((w.sun_elevation_deg > 20) & (w.dhi_w_m2 > 0))[0][0])
    arrays = {k: getattr(w, k).copy() for k in ("sun_elevation_deg", "dhi_w_m2", "dni_w_m2", "dhi_lx", "dni_lx")}
    arrays["sun_elevation_deg"][r], arrays["dhi_w_m2"][r], arrays["dni_w_m2"][r] = 2.0, 300.0, 20.0
    arrays["dhi_lx"][r], arrays["dni_lx"][r] = 30000.0, 1500.0
    w = replace(w, **arrays)
    sk = hour_skies(w, np.array([r]))
    assert sk.delta[0] == BRIGHTNESS_RANGE[1]
    assert 300.0 * air_mass(math.radians(88.0)) / 1415.0 > 3.0  # the unclamped Δ
    assert math.isclose(float(sk.patch_cd_m2[0] @ PROJ), 30000.0, rel_tol=1e-9)
    # the patch luminances are the model's at the clamped Δ, normalised (not the uniform fallback)
    zen = np.radians(90.0 - np.array([2.0]))
    params = perez_parameters(sk.epsilon, np.array([BRIGHTNESS_RANGE[1]]), zen)
    dirs, _ = _patch_grid(8)
    rel = relative_luminance(params, dirs, sk.sun_dir).reshape(1, SP.N_PATCHES, 64).mean(axis=2)
    np.testing.assert_allclose(sk.patch_cd_m2, rel * (30000.0 / float(rel[0] @ PROJ)), rtol=1e-9)
    assert sk.patch_cd_m2.min() > 0 and sk.patch_cd_m2.max() > 1.2 * sk.patch_cd_m2.min()


def test_every_hour_of_a_year_read_an_hour_early_still_has_its_sky():
    """The issue's case on real data: the bundled year with each row's light at the sun of the hour before (as an
    EPW was read), so large diffuse meets a low or set sun; hundreds of hours have Δ above 0.6. Every hour's
    sky integrates to its diffuse horizontal illuminance (1e-9): none vanishes (177 did, up to 16.4 klx)."""
    w = read_weather(BUNDLED)
    w = replace(w, **{k: np.roll(getattr(w, k), -1) for k in ("dhi_w_m2", "dni_w_m2", "dhi_lx", "dni_lx", "ghi_lx")})
    rows = np.nonzero(w.dhi_w_m2 > 0)[0]
    sk = hour_skies(w, rows)
    zen = np.radians(90.0 - np.clip(w.sun_elevation_deg[rows], 0.0, 87.0))
    raw = w.dhi_w_m2[rows] * air_mass(zen) / 1415.0  # I₀ at most 1415 W/m² (perihelion): a lower bound on Δ
    assert (raw > 0.6).sum() > 100
    assert np.all((sk.delta >= BRIGHTNESS_RANGE[0]) & (sk.delta <= BRIGHTNESS_RANGE[1]))
    np.testing.assert_allclose(sk.patch_cd_m2 @ PROJ, sk.dhi_lx, rtol=1e-9)
    assert np.all(sk.patch_cd_m2 >= 0)


# --- weather that does not close ---------------------------------------------------------------------------------------


def test_a_good_year_and_its_epw_twin_do_not_warn(twins):
    for p in (BUNDLED, *twins):
        assert read_weather(p).warnings == [], p


def test_an_epw_with_direct_and_diffuse_swapped_is_refused(tmp_path):
    """DNI and DHI exchanged (both the irradiance and the illuminance fields): as given, G = D + N cos z
    misses by a median of ~34%; swapped back it closes to ~0.1%. One line naming the file and the columns."""
    site, rows = _table(days=tuple(f"{m:02d}/{d:02d}" for m in range(1, 13) for d in (5, 20)))
    p = write_epw(tmp_path / "swapped.epw", site, rows, swap=True)
    with pytest.raises(UserError) as e:
        read_weather(p)
    msg = str(e.value)
    assert "\n" not in msg and str(p) in msg and "look swapped" in msg
    assert "diffuse horizontal column reads as direct normal" in msg and "direct normal column reads as diffuse horizontal" in msg


def test_a_swapped_epw_stops_the_study_with_one_line_and_no_output(tmp_path):
    site, rows = _table()
    w = write_epw(tmp_path / "swapped.epw", site, rows, swap=True)
    p = tmp_path / "a.toml"
    p.write_text(OPEN.format(stage=ROOT / "stages" / "dome.usda", weather=w))
    r = subprocess.run([sys.executable, "-m", "simulator", "study", str(p)], capture_output=True, text=True, cwd=ROOT,
                       env={**os.environ, "PYTHONPATH": str(ROOT)})  # fmt: skip
    assert r.returncode == 2, r.stderr
    assert "look swapped" in r.stderr and "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "a.out" / "annual_hourly.csv").exists()


def test_a_year_whose_global_does_not_close_warns_with_the_count_and_the_worst_hour(tmp_path):
    """Global horizontal raised by 30% on one bright hour in 10 (more than the 1% of hours the year may miss
    by over 10%): a warning, one line, with the count and the hour ending of the worst; the direct and
    diffuse columns close better neither way round, so it is not read as swapped."""
    site, rows = _table()
    bright = [i for i, r in enumerate(rows) if float(r["GHI (W/m^2)"]) > 300][::10]
    for i in bright:
        rows[i]["GHI (W/m^2)"] = str(round(1.3 * float(rows[i]["GHI (W/m^2)"])))
    p = write_epw(tmp_path / "open.epw", site, rows)
    w = read_weather(p)
    assert len(w.warnings) == 1, w.warnings
    msg = w.warnings[0]
    assert "\n" not in msg and str(p) in msg and "irradiance columns do not close" in msg
    assert f"in {len(bright)} of " in msg and "worst the hour ending" in msg and f"{CLOSURE_HOUR_TOL:.0%}" in msg
    # the illuminance fields were left alone: they close
    assert "illuminance" not in msg


# --- the Radiance cross-check on an EPW (benchmarks/annual_radiance.py; Radiance itself not needed here) ---------------


def _cross_check_script():
    import importlib.util

    spec = importlib.util.spec_from_file_location("annual_radiance", ROOT / "benchmarks" / "annual_radiance.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_the_cross_check_runs_on_an_epw_and_writes_its_hours_at_their_centres(twins, tmp_path):
    """``--weather`` puts an EPW in place of the study's TMY3; the ``.wea`` it writes for gendaymtx from the EPW is
    the one it writes from the TMY3 twin (same site, hour centres and illuminances); ``--radiance-reads-epw`` hands
    the EPW itself over and switches probesim to the efficacy model, and refuses a TMY3."""
    from simulator.study.schema import load_study

    ar = _cross_check_script()
    study, p = load_study(ROOT / "configs" / "studies" / "office_annual.toml")
    s_epw, native = ar.with_weather(study, p, str(twins[0]))
    assert native is None and Path(s_epw.annual.weather) == twins[0].resolve() and s_epw.annual.illuminance == "file"
    ar.write_wea(read_weather(twins[0]), tmp_path / "e.wea")
    ar.write_wea(read_weather(twins[1]), tmp_path / "t.wea")
    # (the first line names the site: the EPW's adds its country)
    assert (tmp_path / "e.wea").read_text().splitlines()[1:] == (tmp_path / "t.wea").read_text().splitlines()[1:]
    noon = next(line for line in (tmp_path / "e.wea").read_text().splitlines() if line.startswith("3 21 12.500 "))
    assert noon  # 21 March 12:00–13:00 at 12:30
    s_nat, native = ar.with_weather(study, p, str(twins[0]), radiance_reads_epw=True)
    assert native == twins[0].resolve() and s_nat.annual.illuminance == "efficacy"
    with pytest.raises(SystemExit, match="needs an EPW"):
        ar.with_weather(study, p, str(twins[1]), radiance_reads_epw=True)
