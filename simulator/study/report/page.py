"""``report.html``: one self-contained page a designer hands on.

It opens with a title block (project, stage, study file, date, probesim
version, seed), then a summary table per zone (Ē, Emin, Emax, U0 with their
errors, the required values and coloured pass / fail / unsure verdicts, a
blank one explained), the EN 12464-1 areas, the luminaire schedule, one
continuous false-colour plan per zone and scenario
(:mod:`simulator.study.plan_maps`), the placement and the study's numbers.
Every figure is printed by :mod:`simulator.io.numbers` (the error to 2
significant digits, the value to match, its unit); a print style sheet lays
it out on A4.

Everything is in the file: images are PNGs embedded as base64 ``data:``
URIs, the style sheet is inline, there is no script and nothing is fetched,
so the page opens offline and can be mailed. Every text that comes from the
study file or the stage (zone, scenario, group, candidate and sensor names,
warnings) goes through :func:`html.escape`: a name ``<script>`` shows as text.

Sections are a list of builders, each ``builder(res) -> Section | None``
(None: nothing to show for this study), in page order;
:func:`register_section` adds one (annual charts, control results) before or
after a named built-in section, without touching this module.
"""

from __future__ import annotations

import base64
import html
import io
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

from simulator.io.numbers import plain, with_error

__all__ = ["Section", "SECTIONS", "Raw", "register_section", "report_html", "page_html", "png_img", "table_html", "title_block",
           "verdict_cell", "luminaire_section", "report_date"]


@dataclass(frozen=True)
class Section:
    """One part of the page: an anchor id, a heading (plain text, escaped on output) and its HTML body (already safe)."""

    id: str
    title: str
    body: str


def esc(x) -> str:
    """Text for HTML content or a quoted attribute."""
    return html.escape(str(x), quote=True)


def png_img(png: bytes, alt: str) -> str:
    """An ``<img>`` holding ``png`` as a base64 data URI."""
    return f'<img alt="{esc(alt)}" src="data:image/png;base64,{base64.b64encode(png).decode("ascii")}">'


class Raw(str):
    """A table cell that is already HTML (built from escaped parts); ``cls`` its CSS class."""

    cls: str = ""

    @classmethod
    def of(cls, html_text: str, css: str = "") -> "Raw":
        r = cls(html_text)
        r.cls = css
        return r


def _cell(v) -> str:
    if isinstance(v, Raw):
        return f'<td class="{esc(v.cls)}">{v}</td>' if v.cls else f"<td>{v}</td>"
    if isinstance(v, (float, np.floating)):
        return f"<td>{esc(plain(float(v)))}</td>"
    return f"<td>{esc(v)}</td>"


def table_html(header: list[str], rows: list[list], cls: str = "") -> str:
    """A table; every cell escaped (floats by :func:`simulator.io.numbers.plain`) but :class:`Raw` ones."""
    head = "".join(f"<th>{esc(h)}</th>" for h in header)
    body = "".join("<tr>" + "".join(_cell(v) for v in r) + "</tr>" for r in rows)
    c = f' class="{esc(cls)}"' if cls else ""
    return f'<div class="scroll"><table{c}><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table></div>'


def _unit(res) -> str:
    return "lx" if res.study.light_units == "photometric" else "W/m²"


def report_date() -> str:
    """The report's date (ISO, local): today, or ``SOURCE_DATE_EPOCH`` (the reproducible-builds convention) when set."""
    import datetime
    import os

    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    if epoch and epoch.strip().isdigit():
        return datetime.datetime.fromtimestamp(int(epoch), datetime.timezone.utc).date().isoformat()
    return datetime.date.today().isoformat()


def title_block(study, path, kind: str) -> str:
    """The page's title block: project, stage, study file, date, probesim version, seed, light units, samples."""
    from pathlib import Path

    from simulator import __version__

    stage = Path(study.stage).name
    project = study.project or Path(study.stage).stem
    sim = study.simulation
    samples = f"{sim.samples} per sensor" + (f", adaptive to a 95% half-width of {plain(100 * sim.rel_error, '%')}"
                                             if getattr(sim, "rel_error", None) else "")  # fmt: skip
    rows = [("Stage", stage), ("Study file", Path(path).name), ("Date", report_date()), ("probesim", __version__),
            ("Seed", str(study.seed)), ("Light units", study.light_units), ("Samples", samples)]  # fmt: skip
    cells = "".join(f"<div><dt>{esc(k)}</dt><dd>{esc(v)}</dd></div>" for k, v in rows)
    return (f'<header class="title"><p class="kind">{esc(kind)}</p><h1>{esc(project)}</h1>'
            f'<dl>{cells}</dl></header>')  # fmt: skip


def _overview(res) -> Section:
    st = res.study
    rows = [["candidate points", len(res.candidates)], ["scenarios", len(res.scenarios)], ["trace groups", len(res.trace_groups)],
            ["light groups", ", ".join(g.name for g in st.group)], ["chunks", res.chunks_total]]  # fmt: skip
    ref = res.reference
    if ref:
        rows.append(["recombined vs a separate run", f"{ref['sensors_within_4_sigma']}/{ref['sensors']} sensors within 4 σ "
                                                     f"(scenario {ref['scenario']})"])  # fmt: skip
    body = "".join(f"<tr><th>{esc(k)}</th><td>{esc(v)}</td></tr>" for k, v in rows)
    return Section("overview", "Study", f'<table class="kv"><tbody>{body}</tbody></table>')


#: what each verdict means, shown under every table that has verdicts
VERDICT_KEY = ("<p class=\"key\"><span class=\"pass\">pass</span> meets the requirement by more than 2 standard errors; "
               "<span class=\"fail\">fail</span> misses it by more than 2; <span class=\"unsure\">unsure</span> within 2 "
               "standard errors of it (more samples decide); <span class=\"none\">—</span> no requirement set for that figure"
               "{extra}.</p>")  # fmt: skip


def verdict_cell(v: str, why: str = "no requirement set") -> Raw:
    """A coloured verdict cell; an empty verdict reads ``—`` with its reason as a tooltip."""
    if not v:
        return Raw.of(f'<span title="{esc(why)}">—</span>', "none")
    return Raw.of(esc(v), v if v in ("pass", "fail", "unsure") else "")


def name_cell(name: str) -> Raw:
    """A scenario's name that may break after its commas and brackets, not inside a level (``0.25``)."""
    return Raw.of(esc(name).replace(",", ",<wbr>").replace("[", "[<wbr>"), "text")


def _fig(v: float, se: float, unit: str = "") -> Raw:
    """A figure cell: value ± error (unit), never broken over lines."""
    return Raw.of(esc(with_error(v, se, unit)), "n")


#: a zone target's figure and how it is compared (ZoneFigures attribute, ≥ or ≤)
_TARGET_LABELS = {"mean": ("Ē", "≥"), "min": ("Emin", "≥"), "max": ("Emax", "≤"), "u0": ("U0", "≥"), "min_max": ("Emin/Emax", "≥")}


def _zones(res) -> Section:
    from simulator.study.figures.scores import target_keys

    unit = _unit(res)
    keys = target_keys(res)
    parts = []
    for z in res.study.zone:
        req = [f"{_TARGET_LABELS.get(k, (k, '≥'))[0]} {_TARGET_LABELS.get(k, (k, '≥'))[1]} "
               f"{plain(z.targets[k], '' if k in ('u0', 'min_max') else unit)}" for k in keys if k in z.targets]  # fmt: skip
        head = ["scenario", f"Ē ({unit})", f"Emin ({unit})", f"Emax ({unit})", "U0 = Emin/Ē",
                *(f"{_TARGET_LABELS.get(k, (k,))[0]} verdict" for k in keys)]  # fmt: skip
        rows = []
        for sc in res.scenarios:
            f = res.figures[(z.name, sc.name)]
            chk = res.checks[(z.name, sc.name)]
            rows.append([name_cell(sc.name), _fig(f.mean, f.mean_se), _fig(f.min, f.min_se), _fig(f.max, f.max_se), _fig(f.u0, f.u0_se),
                         *(verdict_cell(chk.get(k, "") if k in z.targets else "", f"zone {z.name} sets no {k} target") for k in keys)])  # fmt: skip
        parts.append(f"<h3>Zone {esc(z.name)}</h3><p>{len(res.zones[z.name])} calculation points; required: "
                     f"{esc(', '.join(req) if req else 'none set')}.</p>" + table_html(head, rows, "num"))  # fmt: skip
    return Section("zones", "Summary per zone", "".join(parts) + VERDICT_KEY.format(extra=""))


def _areas(res) -> Section | None:
    rows_in = getattr(res, "areas", [])
    if not rows_in:
        return None
    unit = _unit(res)
    rows = []
    for r in rows_in:
        f = r.figures
        why = f"no calculation point lies in the {r.part}"
        if f is None:
            figs = [Raw.of('<span title="%s">—</span>' % esc(why), "none")] * 4
        else:
            figs = [_fig(f.mean, f.mean_se), _fig(f.min, f.min_se), _fig(f.max, f.max_se), _fig(f.u0, f.u0_se)]
        if r.modelling is None:
            model = verdict_cell("", "no horizontal set given for the modelling ratio")
        else:
            model = Raw.of(esc(f"{with_error(r.modelling[0], r.modelling[1])} ({r.modelling_verdict})"), r.modelling_verdict)
        rows.append([r.area, r.part, r.scenario, r.sensors, *figs, f"Ē ≥ {plain(r.required_mean, unit)}, U0 ≥ {plain(r.required_u0)}",
                     verdict_cell(r.verdicts["mean"], why), verdict_cell(r.verdicts["u0"], why), model])  # fmt: skip
    head = ["area", "part", "scenario", "points", f"Ē maintained ({unit})", f"Emin ({unit})", f"Emax ({unit})", "U0",
            "required", "Ē verdict", "U0 verdict", "E_z/E_h"]  # fmt: skip
    return Section("areas", "EN 12464-1 areas", "<p>Maintained values (maintenance factor × the computed ones), each with its "
                   "standard error.</p>" + table_html(head, rows, "num")
                   + VERDICT_KEY.format(extra="; in a part with no calculation point, no figure"))  # fmt: skip


def _luminaires(res) -> Section | None:
    return luminaire_section(getattr(res, "scene", None))


def luminaire_section(scene) -> Section | None:
    """The luminaire schedule (:mod:`simulator.study.report.luminaires`); None without a stage or luminaires."""
    from simulator.study.report.luminaires import daylight_sources, luminaire_schedule

    if scene is None:
        return None
    rows_in = luminaire_schedule(scene)
    day = daylight_sources(scene)
    if not rows_in and not day:
        return None
    rows = [[r.kind, r.count, plain(r.lumens, "lm"), plain(r.lumens * r.count, "lm"), r.ies or "—",
             Raw.of(esc(", ".join(r.prims[:3]) + (f" … ({len(r.prims)} in all)" if len(r.prims) > 3 else "")), "text")]
            for r in rows_in]  # fmt: skip
    body = ""
    if rows:
        total = sum(r.lumens * r.count for r in rows_in)
        body += (table_html(["luminaire", "count", "lumens each", "lumens in all", "IES file", "lights"], rows, "num")
                 + f"<p>{esc(plain(total, 'lm'))} emitted by all luminaires at full output, from the emission, size and "
                 "shaping the stage gives each light (rect and disc: π·A·L; sphere: 4π²r²·L; point: 4π·I; "
                 "shaped: the shaping's integral).</p>")  # fmt: skip
    if day:
        body += f"<p>Daylight: {esc(', '.join(day))} (sky and sun, set per scenario).</p>"
    return Section("luminaires", "Luminaire schedule", body)


def _gain_curve_png(res) -> bytes:
    from matplotlib.figure import Figure

    from simulator.study.figures.scores import placement_unit, score_value

    pl = res.placement
    fig = Figure(figsize=(5.2, 3.2), dpi=110)
    ax = fig.subplots()
    ks = [0] + [s.k for s in pl.steps]
    sc = [score_value(pl.objective, pl.baseline)] + [score_value(pl.objective, s.score) for s in pl.steps]
    se = [0.0] + [score_value(pl.objective, s.score_se) for s in pl.steps]
    ax.errorbar(ks, sc, yerr=[2 * e for e in se], marker="o", capsize=3)
    ax.set_xlabel("sensors chosen (k)", fontsize=10)
    unit = placement_unit(pl.objective)
    ax.set_ylabel("mean correlation" if unit == "correlation" else "relative error (%)", fontsize=10)
    ax.set_title(f"score after each pick, {pl.objective} (bars: ±2 standard errors)", fontsize=10)
    ax.tick_params(labelsize=9)
    ax.set_xticks(ks)
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png", metadata={"Software": None})
    return buf.getvalue()


def _placement(res) -> Section | None:
    from simulator.study.figures.scores import score_text

    pl = res.placement
    if pl is None:
        return None
    pos = {c.sensor.name: c.position for c in res.candidates}
    rows = [[s.k, s.sensor, "({:.2f}, {:.2f}, {:.2f})".format(*pos[s.sensor]), score_text(pl.objective, s.gain, s.gain_se),
             score_text(pl.objective, s.score, s.score_se), "yes" if s.separable else f"no (vs {s.runner_up})"] for s in pl.steps]  # fmt: skip
    body = (f"<p>Objective <b>{esc(pl.objective)}</b> over zones {esc(', '.join(pl.zones))}; score with no sensor "
            f"{esc(score_text(pl.objective, pl.baseline, 0.0))}; {pl.evaluations} evaluations for "
            f"{pl.candidates} candidates; {pl.replicates} bootstrap replicates.</p>"
            + table_html(["k", "sensor", "position (m)", "gain", "score", "separable"], rows)
            + "<p>Zone → sensor: " + esc(", ".join(f"{z} → {s}" for z, s in pl.assignment.items())) + "</p>"
            + f'<figure class="chart">{png_img(_gain_curve_png(res), "marginal gain curve")}'
            "<figcaption>Placement score after each sensor is added.</figcaption></figure>")  # fmt: skip
    return Section("placement", "Sensor placement", body)


def _heat_maps(res) -> Section:
    from simulator.study.report.heat_maps import MAX_PANELS, scale_mode, zone_plan_pngs

    unit = _unit(res)
    mode = scale_mode(res)
    scale = {"shared": "one colour scale for all scenarios of a zone (so they compare at a glance)",
             "log": "one logarithmic colour scale for all scenarios of a zone",
             "per_scenario": "each plan its own colour scale"}[mode]  # fmt: skip
    more = f" The first {MAX_PANELS} of {len(res.scenarios)} scenarios are drawn." if len(res.scenarios) > MAX_PANELS else ""
    parts = [f"<p>Work-plane {'illuminance' if unit == 'lx' else 'irradiance'} interpolated between the calculation points, "
             f"inside the grid's cells; isolines labelled in {unit}; {scale} (<code>[output] heat_map_scale</code>). "
             "Walls dark grey, openings blue, furniture brown; red ×: chosen sensors; grey +: points dropped inside "
             f"furniture.{more}</p>"]  # fmt: skip
    for z in res.study.zone:
        pngs = getattr(res, "plan_cache", {}).get(z.name) or zone_plan_pngs(res, z.name)
        figs = []
        for sc, png in zip(res.scenarios, pngs):
            f = res.figures[(z.name, sc.name)]
            cap = f"Ē {with_error(f.mean, f.mean_se, unit)}, Emin {with_error(f.min, f.min_se, unit)}, Emax {with_error(f.max, f.max_se, unit)}, U0 {with_error(f.u0, f.u0_se)}"
            figs.append(f'<figure class="plan">{png_img(png, f"false-colour plan of zone {z.name}, scenario {sc.name}")}'
                        f"<figcaption><b>{esc(sc.name)}</b>: {esc(cap)}</figcaption></figure>")  # fmt: skip
        parts.append(f'<h3>Zone {esc(z.name)}</h3><div class="plans">{"".join(figs)}</div>')
    return Section("heatmaps", "False-colour plans", "".join(parts))


def _warnings(res) -> Section | None:
    if not res.warnings:
        return None
    return Section("warnings", "Warnings", "<ul>" + "".join(f"<li>{esc(w)}</li>" for w in res.warnings) + "</ul>")


#: the page's sections in order: (name, builder)
SECTIONS: list[tuple[str, Callable]] = [
    ("zones", _zones), ("areas", _areas), ("luminaires", _luminaires), ("heatmaps", _heat_maps), ("placement", _placement),
    ("overview", _overview), ("warnings", _warnings),
]  # fmt: skip


def register_section(name: str, builder: Callable, *, after: str | None = None, before: str | None = None) -> None:
    """Add a section builder ``builder(res) -> Section | None``, after or before a named one (default: at the end).
    Registering a name again replaces its builder in place."""
    for i, (n, _) in enumerate(SECTIONS):
        if n == name:
            SECTIONS[i] = (name, builder)
            return
    names = [n for n, _ in SECTIONS]
    if after is not None:
        SECTIONS.insert(names.index(after) + 1, (name, builder))
    elif before is not None:
        SECTIONS.insert(names.index(before), (name, builder))
    else:
        SECTIONS.append((name, builder))


_STYLE = """
body{font-family:system-ui,"DejaVu Sans",sans-serif;margin:1.5em auto;padding:0 1.5em;color:#222;max-width:70em;line-height:1.35}
h1{font-size:1.6em;margin:.1em 0 .3em}h2{font-size:1.2em;margin-top:1.6em;border-bottom:2px solid #345}h3{font-size:1.02em;margin:1.2em 0 .3em}
header.title{border:2px solid #345;padding:.6em 1em;margin-bottom:1em}header.title .kind{margin:0;color:#567;font-size:.9em;text-transform:uppercase;letter-spacing:.06em}
header.title dl{display:grid;grid-template-columns:repeat(auto-fill,minmax(14em,1fr));gap:.2em 1.2em;margin:.3em 0 0}
header.title dt{font-size:.75em;color:#567}header.title dd{margin:0;font-weight:600;overflow-wrap:anywhere}
.scroll{max-width:100%;overflow-x:auto}
table{border-collapse:collapse;font-size:.85em;margin:.4em 0}
th,td{border:1px solid #bbb;padding:.2em .5em;text-align:left;vertical-align:top}thead th{background:#e8edf2}
table.num td{text-align:right}table.num td:first-child,table.num td.text{text-align:left}
td{overflow-wrap:anywhere}td.text{min-width:9em}td.n{white-space:nowrap;overflow-wrap:normal}
table.kv th{background:#f3f5f7;font-weight:normal}
.pass{background:#cdebc9;color:#14501b}.fail{background:#f6c9c5;color:#7a1410}.unsure{background:#fbe7b0;color:#6a4a00}
.none{color:#777}table.num td.pass,table.num td.fail,table.num td.unsure,table.num td.none{text-align:center}
p.key span{padding:0 .3em;border-radius:2px}p.key{font-size:.85em;color:#444}
img{max-width:100%;height:auto}figure{margin:.6em 0}figcaption{font-size:.85em;color:#333}
.plans{display:grid;grid-template-columns:repeat(auto-fill,minmax(26em,1fr));gap:.8em 1.2em}
figure.plan,figure.chart{break-inside:avoid}
nav{font-size:.9em}nav a{margin-right:1em}
@page{size:A4;margin:14mm 12mm}
@media print{
 body{font-size:9.5pt;max-width:none;margin:0;padding:0}
 nav{display:none}
 h2{break-after:avoid}h3{break-after:avoid}table,figure{break-inside:avoid}
 .scroll{overflow:visible}table{font-size:8pt}
 .plans{grid-template-columns:1fr 1fr;gap:3mm 5mm}
 .pass,.fail,.unsure,thead th{-webkit-print-color-adjust:exact;print-color-adjust:exact}
 a{color:inherit;text-decoration:none}
}
"""


def report_html(res) -> str:
    """The whole page (UTF-8 text)."""
    head = title_block(res.study, res.path, "Lighting study report")
    return page_html(f"{res.study.project or Path(res.study.stage).stem}: {res.path.name}",
                     [s for s in (b(res) for _, b in SECTIONS) if s is not None], head)  # fmt: skip


def page_html(title: str, secs: list[Section], head_html: str = "") -> str:
    """A page of ``secs`` under ``title`` (both escaped here) with their index; ``head_html`` (safe HTML, a
    title block) opens the page, else ``title`` as its heading."""
    nav = "".join(f'<a href="#{esc(s.id)}">{esc(s.title)}</a>' for s in secs)
    body = "".join(f'<section id="{esc(s.id)}"><h2>{esc(s.title)}</h2>{s.body}</section>' for s in secs)
    top = head_html or f"<h1>{esc(title)}</h1>"
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
            f"<title>{esc(title)}</title><style>{_STYLE}</style></head>"
            f"<body>{top}<nav>{nav}</nav>{body}</body></html>\n")  # fmt: skip
