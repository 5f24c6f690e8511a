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
        .replace("spacing_m = 1.0", "spacing_m = 0.4")  # (0.4 m: three points fall in the shelf)
        .replace("seed = 11", 'seed = 11\nproject = "Office <i>2</i>"', 1))  # fmt: skip


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
    res, _ = study_out
    assert len(imgs) == 1 + len(res.scenarios)  # the marginal-gain curve and one plan of the zone per scenario
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


#: injected at the top of a copy of the page: errors go to the title, every image is checked once loaded, the page
#: and every table, figure, image and paragraph checked for overflowing the window's width (or its own box), and
#: the print style sheet counted (rules under @media print, an A4 @page)
_PROBE = """<script>
window.__errors = [];
window.onerror = function (m) { window.__errors.push(String(m)); };
window.addEventListener('error', function (e) { if (e.target && e.target.tagName) window.__errors.push('load ' + e.target.tagName); }, true);
window.addEventListener('load', function () {
  var bad = 0, imgs = document.images, wide = 0, printed = 0, page = 0;
  for (var i = 0; i < imgs.length; i++) if (!imgs[i].complete || imgs[i].naturalWidth === 0) bad++;
  var root = document.documentElement, over = root.scrollWidth > root.clientWidth + 1 ? 1 : 0;
  var boxes = document.querySelectorAll('table, figure, img, header, p, .scroll');
  for (var j = 0; j < boxes.length; j++) {
    var r = boxes[j].getBoundingClientRect();
    if (r.right > root.clientWidth + 1 || boxes[j].scrollWidth > boxes[j].clientWidth + 1) wide++;
  }
  for (var k = 0; k < document.styleSheets.length; k++) {
    var rules = document.styleSheets[k].cssRules;
    for (var m = 0; m < rules.length; m++) {
      if (rules[m].type === CSSRule.MEDIA_RULE && rules[m].media.mediaText.indexOf('print') >= 0) printed += rules[m].cssRules.length;
      if (rules[m].type === CSSRule.PAGE_RULE && /a4/i.test(rules[m].style.getPropertyValue('size'))) page++;
    }
  }
  document.title = 'PROBE errors=' + window.__errors.length + ' images=' + imgs.length + ' broken=' + bad +
    ' overflow=' + over + ' wide=' + wide + ' print=' + printed + ' a4=' + page;
});
</script>"""


def _chromium(browser: str, tmp: Path, *args: str) -> subprocess.CompletedProcess:
    profile = tmp / "profile"
    profile.mkdir(exist_ok=True)
    cmd = [browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
           "--disable-sync", "--no-first-run", "--disable-dev-shm-usage", f"--user-data-dir={profile}", "--enable-logging=stderr",
           "--v=0", *args]  # fmt: skip
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120, env={**os.environ, "HOME": str(tmp)})


PROBE_RE = r"<title>PROBE errors=(\d+) images=(\d+) broken=(\d+) overflow=(\d+) wide=(\d+) print=(\d+) a4=(\d+)</title>"


def probe_page(browser: str, tmp: Path, page: str, width_px: int) -> dict:
    """The probe's counts for ``page`` laid out in a window ``width_px`` wide (None: Chromium does not start)."""
    probe = tmp / "probe.html"
    probe.write_text(page.replace("<head>", "<head>" + _PROBE, 1))
    r = _chromium(browser, tmp, f"--window-size={width_px},1200", "--virtual-time-budget=5000", "--dump-dom", probe.as_uri())
    if r.returncode != 0 and not r.stdout:
        pytest.skip(f"Chromium does not start here: {r.stderr.strip().splitlines()[-1:]}")
    m = re.search(PROBE_RE, r.stdout)
    assert m, r.stdout[:500]
    keys = ("errors", "images", "broken", "overflow", "wide", "print", "a4")
    return {**dict(zip(keys, map(int, m.groups()))), "dom": r.stdout}


def check_layout(browser: str, tmp: Path, page: str, images: int) -> None:
    """No script error, every image decodes, nothing wider than the window on a desktop screen (1280 px) or an
    A4 page's width at 96 dpi (794 px), and a print style sheet with an A4 page."""
    for width in (1280, 794):
        p = probe_page(browser, tmp, page, width)
        assert (p["errors"], p["images"], p["broken"]) == (0, images, 0), (width, p["errors"], p["images"], p["broken"])
        assert p["overflow"] == 0 and p["wide"] == 0, f"{width} px: the page overflows ({p['wide']} boxes too wide)"
        assert p["print"] >= 5 and p["a4"] == 1, "no print style sheet"


def print_pdf(browser: str, tmp: Path, html: Path) -> bytes:
    """The page printed by Chromium (its print style sheet applies), PDF bytes."""
    pdf = tmp / "page.pdf"
    _chromium(browser, tmp, "--no-pdf-header-footer", f"--print-to-pdf={pdf}", html.as_uri())
    assert pdf.is_file(), "Chromium printed nothing"
    return pdf.read_bytes()


def test_report_renders_in_headless_chromium_without_console_errors(study_out, tmp_path):
    browser = _browser()
    if browser is None:
        pytest.skip("no Chromium on this machine (Debian: apt-get install chromium)")
    res, out = study_out
    page = (out / "report.html").read_text()
    check_layout(browser, tmp_path, page, 1 + len(res.scenarios))
    dom = probe_page(browser, tmp_path, page, 1280)["dom"]
    # the zone's name is text in the rendered document, never an element
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in dom
    assert "alert(1)</script>" not in dom
    # printed: A4 pages (595 × 842 pt)
    pdf = print_pdf(browser, tmp_path, out / "report.html")
    assert pdf[:5] == b"%PDF-" and re.search(rb"/MediaBox \[0 0 59[45]\.\d+ 84[12]\.\d+\]", pdf), "not printed on A4"
    # the page itself, unmodified: a screenshot, and no console message at error level
    shot = tmp_path / "shot.png"
    r = _chromium(browser, tmp_path, "--window-size=1280,2400", f"--screenshot={shot}", (out / "report.html").as_uri())
    assert shot.is_file() and shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and shot.stat().st_size > 10_000
    console = [ln for ln in r.stderr.splitlines() if "CONSOLE" in ln]
    assert not [ln for ln in console if "ERROR" in ln or "Uncaught" in ln], console


def _text(page: str) -> str:
    """The page without its embedded images."""
    return re.sub(r'src="data:[^"]*"', 'src=""', page)


def test_report_opens_with_a_title_block(study_out):
    """Project (from the study's ``project``, escaped), stage, study file, date, probesim version and seed."""
    from simulator import __version__

    res, out = study_out
    page = (out / "report.html").read_text()
    head = page[page.index('<header class="title">'):page.index("</header>")]
    assert "<h1>Office &lt;i&gt;2&lt;/i&gt;</h1>" in head
    fields = dict(re.findall(r"<dt>([^<]+)</dt><dd>([^<]*)</dd>", head))
    assert fields["Stage"] == "office.usda" and fields["Study file"] == "evil_study.toml"
    assert re.fullmatch(r"\d{4}-\d{2}-\d{2}", fields["Date"]) and fields["probesim"] == __version__
    assert fields["Seed"] == str(res.study.seed) == "11"
    assert all(v.strip() for v in fields.values())  # no empty cell
    assert "<th></th>" not in page  # no empty header cell anywhere


def test_the_summary_has_emin_emax_u0_with_errors_and_coloured_verdicts(study_out):
    import html

    from simulator.io.numbers import with_error

    res, out = study_out
    page = (out / "report.html").read_text()
    sec = html.unescape(page[page.index('id="zones"'):page.index("</section>", page.index('id="zones"'))])
    for h in ("Ē (lx)", "Emin (lx)", "Emax (lx)", "U0 = Emin/Ē", "Ē verdict"):
        assert f"<th>{h}</th>" in sec, h
    assert "required: Ē ≥ 300\u00a0lx" in sec
    n = {"pass": 0, "fail": 0, "unsure": 0}
    for (z, sc), f in res.figures.items():
        for v, se in ((f.mean, f.mean_se), (f.min, f.min_se), (f.max, f.max_se), (f.u0, f.u0_se)):
            assert f"<td class=\"n\">{with_error(v, se)}</td>" in sec, (sc, v, se)
        n[res.checks[(z, sc)]["mean"]] += 1
    for verdict, count in n.items():  # each verdict in its colour's class
        assert sec.count(f'<td class="{verdict}">{verdict}</td>') == count, verdict
    assert "more samples decide" in sec  # what "unsure" means, under the table


def test_every_figure_has_a_sane_precision(study_out):
    """No exponent (2.216e+04) and no error with more than 2 significant digits (± 0.007362) anywhere on the page."""
    import html

    res, out = study_out
    text = html.unescape(_text((out / "report.html").read_text()))
    assert not re.search(r"\d\.?\d*e[+-]\d", text)
    # every zone figure (Ē, Emin, Emax, U0) carries its error beside it, not in a column of its own
    assert text.count("\u00a0±\u00a0") >= 4 * len(res.figures)
    for err in re.findall(r"±\u00a0([\d.,]+)", text):
        digits = err.replace(",", "").replace(".", "").lstrip("0")
        assert len(digits.rstrip("0") if "." not in err else digits) <= 2, err


def test_the_report_has_a_luminaire_schedule(study_out):
    import html

    _, out = study_out
    page = html.unescape((out / "report.html").read_text())
    sec = page[page.index('id="luminaires"'):]
    assert "rectangular panel 1.20 × 0.30 m" in sec and "4,524\u00a0lm" in sec and "27,143\u00a0lm" in sec
    assert "<th>IES file</th>" in sec


def test_plans_share_one_scale_by_default_and_each_its_own_on_request(study_out):
    from simulator.study.report.heat_maps import zone_scales

    res, _ = study_out
    assert res.study.output.heat_map_scale == "shared"
    shared = zone_scales(res, EVIL, res.scenarios)
    assert len({(s.lo, s.hi) for s in shared}) == 1
    own = res.study.model_copy(update={"output": res.study.output.model_copy(update={"heat_map_scale": "per_scenario"})})
    import copy

    r2 = copy.copy(res)
    r2.study = own
    per = zone_scales(r2, EVIL, res.scenarios)
    ids = res.zones[EVIL]
    assert [s.hi for s in per] == pytest.approx([float(res.mean[j, ids, 1].max()) for j in range(len(res.scenarios))], rel=1e-12)
