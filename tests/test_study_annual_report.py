"""report.html's annual section: per zone the annual metrics and control results with their errors, and
the DA map, temporal map and lamp-level charts as embedded PNGs; rendered in headless Chromium; the same
bytes on resume; a study with only ``[annual]`` gets a page of its own."""

import base64
import importlib.util
import re
from pathlib import Path

import numpy as np
import pytest

from simulator.study.trace.distributed import QUIET_CLUSTER

pytest.importorskip("pvlib")
ROOT = Path(__file__).resolve().parents[1]


def _load(name: str):
    spec = importlib.util.spec_from_file_location(f"_ar_{name}", Path(__file__).with_name(name))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


_ann = _load("test_study_annual.py")
_rep = _load("test_study_report.py")

EVIL = "<script>alert(1)</script>"
#: the office, a coarse floor grid (its plan drawn under the DA map), two ceiling photosensors, one overcast scenario,
#: four days of weather every second hour
TEXT = """
stage = "{stage}"
seed = 7
[simulation]
samples = 64
[compute]
mode = "inprocess"
[[candidates]]
name = "floor"
on = ["/Office/Room/Floor"]
height_m = 0.8
spacing_m = 1.0
drop_inside = ["/Office/Furniture/*"]
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
name = "{evil}"
candidates = "floor"
targets = {{ mean = 500 }}
{scenario}
[annual]
weather = "{weather}"
sky_group = "sky"
replicates = 8
step_h = 2
[[control]]
zone = "{evil}"
groups = ["rows"]
photosensor = "ceiling"
[output]
dir = "out"
"""
SCENARIO = '[[scenario]]\nname = "overcast"\nlevels = { sky = 1.0 }\nsky = { group = "sky", cie = "overcast" }'


def _text(tmp: Path, scenario: str) -> str:
    return TEXT.format(stage=(ROOT / "stages" / "office.usda").as_posix(), weather=_ann._days(tmp).as_posix(), evil=EVIL,
                       scenario=scenario)  # fmt: skip


def _imgs(page: str) -> list[bytes]:
    return [base64.b64decode(b) for b in re.findall(r'src="data:image/png;base64,([A-Za-z0-9+/=]+)"', page)]


@pytest.fixture(scope="module")
def both(tmp_path_factory):
    from simulator.commands.study import main_study

    d = tmp_path_factory.mktemp("annual_report")
    p = d / "both.toml"
    p.write_text(_text(d, SCENARIO))
    assert main_study(str(p), None, None) == 0
    return d, p, (d / "out" / "report.html").read_bytes()


def test_the_report_holds_the_annual_section_after_the_heat_maps(both):
    _, _, raw = both
    page = raw.decode()
    assert page.index('id="heatmaps"') < page.index('id="annual"')
    sec = page[page.index('id="annual"'):]
    # every metric under the name designers use, with its definition in words
    for name in ("DA300", "sDA300/50%", "ASE1000/250h", "UDI &lt; 100 lx", "UDI 100–2000 lx", "UDI &gt; 2000 lx",
                 "EN 17037 300 lx over 50% of the area", "EN 17037 100 lx over 95% of the area", "EN 17037 minimum level",
                 "DF (mean)"):  # fmt: skip
        assert f"<td>{name}</td>" in sec, name
    assert "Daylight autonomy: the share of occupied hours in which a point gets at least 300 lx" in sec
    assert re.search(r'<td>EN 17037 minimum level</td><td class="(pass|fail)">(met|not met)', sec)
    # no config key names, no 0/1 unit, no bare "DA" for DA300
    for key in ("da_lx", "udi_lx", "ase_lx", "ase_hours", "en17037_lx", "E &gt;= ", "E >= ", "0/1", "<td>DA</td>",
                "EN17037_pass", "UDI_useful"):  # fmt: skip
        assert key not in page, key
    assert "relative energy" in sec and "hours below target" in sec and "chosen photosensor" in sec
    # the zone's name is text everywhere; the only script would be the name
    assert "<script" not in page.lower() and "&lt;script&gt;alert(1)&lt;/script&gt;" in sec
    assert not re.search(r'(src|href)="(?!data:|#)', page)
    imgs = _imgs(page)
    # the scenario part's heat map, then DA map, temporal map of illuminance and of the lamps' level
    assert len(imgs) == 1 + 3 and all(b[:8] == b"\x89PNG\r\n\x1a\n" for b in imgs)


def test_the_annual_tables_carry_the_runs_figures(both):
    """The page's metric values and control figures are those of annual_metrics.csv / annual_control.csv,
    each with its error by the report's one rule (simulator.io.numbers.with_error)."""
    import csv
    import html
    import io

    from simulator.io.numbers import with_error
    from simulator.study.annual.report import metric_names
    from simulator.study.schema import AnnualSpec

    d, _, raw = both
    sec = html.unescape(raw.decode()[raw.decode().index('id="annual"'):])
    names = metric_names(AnnualSpec(weather="w.csv", sky_group="sky"))
    for r in csv.DictReader(io.StringIO((d / "out" / "annual_metrics.csv").read_text())):
        v, se = float(r["value"]), float(r["stderr"])
        if r["metric"] == "EN17037_pass":
            assert f"<td>{names[r['metric']][0]}</td><td class=\"{'pass' if v >= 0.5 else 'fail'}\">{'met' if v >= 0.5 else 'not met'}" in sec
        else:
            assert f"<td>{names[r['metric']][0]}</td><td class=\"n\">{with_error(v, se, '%')}</td>" in sec, r
    rows = list(csv.DictReader(io.StringIO((d / "out" / "annual_control.csv").read_text())))
    assert len(rows) == 2 and sum(int(r["chosen"]) for r in rows) == 1
    for r in rows:
        assert f"<td class=\"n\">{with_error(float(r['relative_energy']), float(r['relative_energy_stderr']))}</td>" in sec


def test_da_per_sensor_matches_the_zone_metric_and_the_temporal_grid_places_each_hour(tmp_path):
    """The DA map's values average to the zone's DA; the temporal grid puts each hour at its day and hour."""
    from simulator.study.annual.year import run_annual
    from simulator.study.annual.report import da_per_sensor, temporal_grid
    from simulator.study.schema import load_study

    tmp = tmp_path
    p = tmp / "a.toml"
    p.write_text(_ann.OPEN.format(stage=ROOT / "stages" / "dome.usda", weather=_ann._days(tmp)))
    study, path = load_study(p)
    res = run_annual(study, path, tmp / "out", log=lambda m: None)
    ids = res.zones["roof"]
    da = da_per_sensor(res, ids, study.annual.da_lx)
    assert 100.0 * np.mean(da) == pytest.approx(res.metrics["roof"]["DA"][0], rel=1e-12)
    g, days = temporal_grid(res, np.arange(len(res.rows), dtype=float))
    assert len(days) == 4 and np.sum(np.isfinite(g)) == len(res.rows)
    c = res.weather.centre[res.rows]
    k = len(res.rows) // 2
    assert g[c[k].hour, list(days).index(c[k].day_of_year)] == k


def test_the_report_is_the_same_bytes_on_resume(both):
    from simulator.commands.study import main_study

    d, p, raw = both
    assert main_study(str(p), None, None) == 0  # every chunk from the store
    assert (d / "out" / "report.html").read_bytes() == raw


def test_an_annual_only_study_gets_a_report_of_its_own(both):
    from simulator.commands.study import main_study

    d, _, _ = both
    p = d / "annual_only.toml"
    p.write_text(_text(d, ""))  # the same [annual]: its chunks come from the store, its files are the same bytes
    assert main_study(str(p), None, None) == 0
    page = (d / "out" / "report.html").read_text()
    assert 'id="annual"' in page and 'id="zones"' not in page and "<script" not in page.lower()
    # its own title block (project: the stage's name), and the luminaire schedule of the lamps it controls
    assert '<p class="kind">Annual daylight report</p><h1>office</h1>' in page and "<dt>Seed</dt><dd>7</dd>" in page
    assert 'id="luminaires"' in page and "rectangular panel 1.20 × 0.30 m" in page
    imgs = _imgs(page)
    assert len(imgs) == 3 and all(b[:8] == b"\x89PNG\r\n\x1a\n" for b in imgs)


def test_the_annual_report_renders_in_headless_chromium_without_console_errors(both, tmp_path):
    browser = _rep._browser()
    if browser is None:
        pytest.skip("no Chromium on this machine (Debian: apt-get install chromium)")
    _, _, raw = both
    page = raw.decode()
    src = tmp_path / "report.html"
    src.write_bytes(raw)
    _rep.check_layout(browser, tmp_path, page, 1 + 3)  # every image decodes, nothing overflows, print CSS
    dom = _rep.probe_page(browser, tmp_path, page, 1280)["dom"]
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in dom and "alert(1)</script>" not in dom
    shot = tmp_path / "shot.png"
    r = _rep._chromium(browser, tmp_path, "--window-size=1280,3200", f"--screenshot={shot}", src.as_uri())
    assert shot.is_file() and shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and shot.stat().st_size > 10_000
    console = [ln for ln in r.stderr.splitlines() if "CONSOLE" in ln]
    assert not [ln for ln in console if "ERROR" in ln or "Uncaught" in ln], console


def test_the_report_is_the_same_bytes_on_a_scheduler(both, tmp_path):
    """Both parts' chunks on a dask scheduler (a threaded LocalCluster): report.html and the annual CSVs
    are the in-process run's bytes."""
    distributed = pytest.importorskip("distributed")
    from simulator.commands.cli import main

    d, p, raw = both
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False, **QUIET_CLUSTER) as cluster:  # fmt: skip
        assert main(["study", str(p), "--out", str(tmp_path / "sched"), "--scheduler", cluster.scheduler_address]) == 0
    assert (tmp_path / "sched" / "report.html").read_bytes() == raw
    for name in ("annual_hourly.csv", "annual_hourly_stderr.csv", "annual_metrics.csv", "annual_control.csv"):
        assert (tmp_path / "sched" / name).read_bytes() == (d / "out" / name).read_bytes(), name
