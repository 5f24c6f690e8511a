"""A study's outputs people read: ``run``'s columns and units, a column per target and per group level,
scores in percent, heat maps with the room's plan, and a self-contained ``report.html`` that renders
in a real headless browser with every name from the study file escaped."""

import base64
import csv
import importlib.util
import io
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from simulator.io.results import COLUMNS
from simulator.study.report.outputs import write_outputs
from simulator.study.runner import run_study
from simulator.study.schema import load_study

_spec = importlib.util.spec_from_file_location("_study_tiny", Path(__file__).with_name("test_study_resume.py"))
_tiny = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_tiny)

EVIL = "<script>alert(1)</script>"
#: the tiny study with a zone and a scenario named with markup, and a p95 placement objective
TEXT = (_tiny.TINY.replace('name = "all"', f'name = "{EVIL}"').replace('name = "overcast"', 'name = "<b>overcast</b>"')
        .replace('objective = "correlation"', 'objective = "p95_rel_error"')
        .replace("drop_inside = [\"/Office/Furniture/*\"]", "drop_inside = [\"/Office/Furniture/*\"]\nwall_band_m = 0.3\n")
        .replace("spacing_m = 1.0", "spacing_m = 0.4"))  # fmt: skip  (0.4 m: three points fall in the shelf)


@pytest.fixture(scope="module")
def study_out(tmp_path_factory):
    d = tmp_path_factory.mktemp("report")
    p = d / "evil_study.toml"
    p.write_text(TEXT.replace("[compute]", '[compute]\nmode = "inprocess"'))
    study, path = load_study(p)
    res = run_study(study, path, d / "out", reference_run=False)
    write_outputs(res, {})
    return res, d / "out"


def _rows(path: Path) -> list[dict]:
    return list(csv.DictReader(io.StringIO(path.read_text())))


def test_readings_use_runs_columns_and_units_with_levels(study_out):
    res, out = study_out
    rows = _rows(out / "readings.csv")
    head = list(rows[0])
    for c in ("x", "y", "z", "dx", "dy", "dz", "illuminance_lx", "illuminance_stderr_lx", "irradiance_W_m2", "luminance_cd_m2",
              "samples", "method", "level_window_row", "level_corridor_row", "level_sky"):  # fmt: skip
        assert c in head, c
    assert all(c in COLUMNS for c in head if c.endswith(("_lx", "_W_m2", "_cd_m2", "_W_m2_sr")))
    wp = [r for r in rows if r["candidates"] == "wp"]
    cell = [r for r in rows if r["candidates"] == "cell"]
    assert {r["kind"] for r in wp} == {"irradiance"} and {r["kind"] for r in cell} == {"radiance"}
    assert all(r["luminance_cd_m2"] == "" for r in wp) and all(r["illuminance_lx"] == "" for r in cell)
    assert all(r["samples"] == "64" and r["method"] == "light" for r in rows)  # [simulation] samples = 64, method = "light"
    assert all((r["dx"], r["dy"], r["dz"]) == ("0", "0", "1") for r in wp)  # the floor grid faces up
    # levels: the scenario's dimming vector, and the readings are in its units (lx = the photometric channel)
    ev = [r for r in rows if r["scenario"] == "evening[window_row=0.5]"]
    assert {(r["level_window_row"], r["level_corridor_row"], r["level_sky"]) for r in ev} == {("0.5", "1", "0")}
    j = [s.name for s in res.scenarios].index("evening[window_row=0.5]")
    i = [c.sensor.name for c in res.candidates].index(ev[0]["sensor"])
    assert float(ev[0]["illuminance_lx"]) == pytest.approx(res.mean[j, i, 1], rel=1e-8)


def test_summary_has_a_column_per_target(study_out):
    _, out = study_out
    rows = _rows(out / "summary.csv")
    assert "mean_required" in rows[0] and "mean_verdict" in rows[0] and "targets" not in rows[0]
    for r in rows:
        assert r["mean_required"] == "300" and r["mean_verdict"] in ("pass", "fail", "unsure")
        # the verdict follows from the figure and its error (pass when above by > 2 standard errors)
        m, se = float(r["mean"]), float(r["mean_stderr"])
        assert r["mean_verdict"] == ("pass" if m - 300 > 2 * se else "fail" if m - 300 < -2 * se else "unsure")


def test_placement_scores_are_percent(study_out):
    res, out = study_out
    rows = _rows(out / "placement.csv")
    pl = res.placement
    assert [r["sensor"] for r in rows] == pl.chosen and {r["unit"] for r in rows} == {"%"}
    for r, s in zip(rows, pl.steps):
        assert float(r["score"]) == pytest.approx(100 * s.score, rel=1e-8)
        assert float(r["score_stderr"]) == pytest.approx(100 * s.score_se, rel=1e-8)


def test_heat_map_has_the_room_plan_and_dropped_points(study_out):
    from simulator.study.report.heat_maps import dropped_in_zone, zone_plan

    res, out = study_out
    plan = zone_plan(res, EVIL)
    assert plan is not None
    # office.usda: a 6 x 4 m room whose west wall (x = 0) holds the window between y = 0.65 and 3.35 m at 1.3 m
    op = np.concatenate(plan.openings)
    assert np.allclose(op[:, 0], 0.0, atol=1e-6) and op[:, 1].min() == pytest.approx(0.65, abs=0.06) and op[:, 1].max() == pytest.approx(3.35, abs=0.06)
    walls = np.concatenate(plan.walls).reshape(-1, 2)
    assert walls[:, 0].min() == pytest.approx(0.0, abs=1e-6) and walls[:, 0].max() == pytest.approx(6.0, abs=1e-6)
    assert len(plan.furniture) >= 4  # four desks at least
    d = dropped_in_zone(res, EVIL)
    cs = next(s for s in res.sets if s.name == "wp")
    assert len(d) == cs.dropped_inside > 0
    png = (out / f"heatmap_{'_script_alert_1___script_'}.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"


def test_per_scenario_scale_and_log_scale_differ_and_are_valid(study_out):
    from simulator.study.report.heat_maps import heat_map_png

    res, _ = study_out
    import copy

    a = heat_map_png(res, EVIL)
    logged = copy.copy(res)
    logged.study = res.study.model_copy(update={"output": res.study.output.model_copy(update={"heat_map_scale": "log"})})
    b = heat_map_png(logged, EVIL)
    assert a != b and b[:4] == b"\x89PNG"


def test_report_is_self_contained_and_escapes_names(study_out):
    _, out = study_out
    page = (out / "report.html").read_text()
    assert "<script" not in page.lower()  # the only script would be the zone's name, and it is text
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in page and "&lt;b&gt;overcast&lt;/b&gt;" in page
    assert not re.search(r'(src|href)="(?!data:|#)', page)  # nothing fetched
    imgs = re.findall(r'src="data:image/png;base64,([A-Za-z0-9+/=]+)"', page)
    assert len(imgs) == 2  # the marginal-gain curve and the zone's heat map
    assert all(base64.b64decode(b)[:8] == b"\x89PNG\r\n\x1a\n" for b in imgs)
    assert "%" in page  # scores in percent


def test_a_registered_section_joins_the_page(study_out):
    from simulator.study.report import page as hr

    res, _ = study_out
    saved = list(hr.SECTIONS)
    try:
        hr.register_section("extra", lambda r: hr.Section("extra", "Extra <daylight>", "<p>here</p>"), after="zones")
        page = hr.report_html(res)
    finally:
        hr.SECTIONS[:] = saved
    assert page.index('id="zones"') < page.index('id="extra"') < page.index('id="placement"')
    assert "Extra &lt;daylight&gt;" in page


def _browser() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome", "chrome"):
        p = shutil.which(name)
        if p:
            return p
    return None


#: injected at the top of a copy of the page: errors go to the title, and every image is checked once loaded
_PROBE = """<script>
window.__errors = [];
window.onerror = function (m) { window.__errors.push(String(m)); };
window.addEventListener('error', function (e) { if (e.target && e.target.tagName) window.__errors.push('load ' + e.target.tagName); }, true);
window.addEventListener('load', function () {
  var bad = 0, imgs = document.images;
  for (var i = 0; i < imgs.length; i++) if (!imgs[i].complete || imgs[i].naturalWidth === 0) bad++;
  document.title = 'PROBE errors=' + window.__errors.length + ' images=' + imgs.length + ' broken=' + bad;
});
</script>"""


def _chromium(browser: str, tmp: Path, *args: str) -> subprocess.CompletedProcess:
    profile = tmp / "profile"
    profile.mkdir(exist_ok=True)
    cmd = [browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
           "--disable-sync", "--no-first-run", "--disable-dev-shm-usage", f"--user-data-dir={profile}", "--enable-logging=stderr",
           "--v=0", *args]  # fmt: skip
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120, env={**os.environ, "HOME": str(tmp)})


def test_report_renders_in_headless_chromium_without_console_errors(study_out, tmp_path):
    browser = _browser()
    if browser is None:
        pytest.skip("no Chromium on this machine (Debian: apt-get install chromium)")
    _, out = study_out
    page = (out / "report.html").read_text()
    probe = tmp_path / "probe.html"
    probe.write_text(page.replace("<head>", "<head>" + _PROBE, 1))
    r = _chromium(browser, tmp_path, "--virtual-time-budget=5000", "--dump-dom", probe.as_uri())
    if r.returncode != 0 and not r.stdout:
        pytest.skip(f"Chromium does not start here: {r.stderr.strip().splitlines()[-1:]}")
    m = re.search(r"<title>PROBE errors=(\d+) images=(\d+) broken=(\d+)</title>", r.stdout)
    assert m, r.stdout[:500]
    assert m.groups() == ("0", "2", "0")
    # the zone's name is text in the rendered document, never an element
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in r.stdout
    assert "alert(1)</script>" not in r.stdout
    # the page itself, unmodified: a screenshot, and no console message at error level
    shot = tmp_path / "shot.png"
    r = _chromium(browser, tmp_path, "--window-size=1280,2400", f"--screenshot={shot}", (out / "report.html").as_uri())
    assert shot.is_file() and shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and shot.stat().st_size > 10_000
    console = [ln for ln in r.stderr.splitlines() if "CONSOLE" in ln]
    assert not [ln for ln in console if "ERROR" in ln or "Uncaught" in ln], console
