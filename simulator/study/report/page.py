"""``report.html``: one self-contained page a designer reads (tables, heat maps, the marginal-gain curve).

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
import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

__all__ = ["Section", "SECTIONS", "register_section", "report_html", "page_html", "png_img", "table_html"]


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


def _cell(v) -> str:
    if isinstance(v, (float, np.floating)):
        return "" if math.isnan(v) else f"{float(v):.4g}"
    return esc(v)


def table_html(header: list[str], rows: list[list], cls: str = "") -> str:
    """A table; every cell escaped (floats to 4 significant digits)."""
    head = "".join(f"<th>{esc(h)}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{_cell(v)}</td>" for v in r) + "</tr>" for r in rows)
    c = f' class="{esc(cls)}"' if cls else ""
    return f"<table{c}><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _overview(res) -> Section:
    st = res.study
    rows = [["stage", st.stage], ["light units", st.light_units], ["candidates", len(res.candidates)],
            ["scenarios", len(res.scenarios)], ["trace groups", len(res.trace_groups)],
            ["light groups", ", ".join(g.name for g in st.group)], ["chunks", res.chunks_total]]  # fmt: skip
    ref = res.reference
    if ref:
        rows.append(["recombined vs a separate run", f"{ref['sensors_within_4_sigma']}/{ref['sensors']} sensors within 4 σ "
                                                     f"(scenario {ref['scenario']})"])  # fmt: skip
    return Section("overview", "Study", table_html(["", ""], rows, "kv"))


def _zones(res) -> Section:
    from simulator.study.figures.scores import target_keys

    unit = "lx" if res.study.light_units == "photometric" else "W/m²"
    keys = target_keys(res)
    head = ["zone", "scenario", "sensors", f"mean ({unit})", "±", f"min ({unit})", "U0", "±", *(f"{k} target" for k in keys)]
    rows = []
    for z in res.study.zone:
        for sc in res.scenarios:
            f = res.figures[(z.name, sc.name)]
            chk = res.checks[(z.name, sc.name)]
            tv = [f"{chk[k]} ({'≥' if k != 'max' else '≤'} {z.targets[k]:g})" if k in z.targets else "" for k in keys]
            rows.append([z.name, sc.name, len(res.zones[z.name]), f.mean, f.mean_se, f.min, f.u0, f.u0_se, *tv])
    return Section("zones", "Zones and targets", table_html(head, rows, "num"))


def _areas(res) -> Section | None:
    rows_in = getattr(res, "areas", [])
    if not rows_in:
        return None
    unit = "lx" if res.study.light_units == "photometric" else "W/m²"
    rows = []
    for r in rows_in:
        f = r.figures
        model = "" if r.modelling is None else f"{r.modelling[0]:.2f} ± {r.modelling[1]:.2f} ({r.modelling_verdict})"
        rows.append([r.area, r.part, r.scenario, r.sensors, float("nan") if f is None else f.mean, float("nan") if f is None else f.u0,
                     f"≥ {r.required_mean:g} / ≥ {r.required_u0:g}", r.verdicts["mean"], r.verdicts["u0"], model])  # fmt: skip
    head = ["area", "part", "scenario", "points", f"Ē maintained ({unit})", "U0", "required Ē / U0", "Ē", "U0", "E_z/E_h"]
    return Section("areas", "EN 12464-1 areas", "<p>Maintained values (maintenance factor × the computed ones).</p>"
                   + table_html(head, rows, "num"))  # fmt: skip


def _gain_curve_png(res) -> bytes:
    from matplotlib.figure import Figure

    from simulator.study.figures.scores import placement_unit, score_value

    pl = res.placement
    fig = Figure(figsize=(5.0, 3.0), dpi=80)
    ax = fig.subplots()
    ks = [0] + [s.k for s in pl.steps]
    sc = [score_value(pl.objective, pl.baseline)] + [score_value(pl.objective, s.score) for s in pl.steps]
    se = [0.0] + [score_value(pl.objective, s.score_se) for s in pl.steps]
    ax.errorbar(ks, sc, yerr=[2 * e for e in se], marker="o", capsize=3)
    ax.set_xlabel("sensors chosen (k)", fontsize=8)
    unit = placement_unit(pl.objective)
    ax.set_ylabel(f"score ({'mean correlation' if unit == 'correlation' else 'relative error, %'})", fontsize=8)
    ax.set_title(f"marginal gain, {pl.objective} (bars: ±2 standard errors)", fontsize=8)
    ax.tick_params(labelsize=7)
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
            f"{esc(score_text(pl.objective, pl.baseline, 0.0).split(' ±')[0])}; {pl.evaluations} evaluations for "
            f"{pl.candidates} candidates; {pl.replicates} bootstrap replicates.</p>"
            + table_html(["k", "sensor", "position (m)", "gain", "score", "separable"], rows)
            + "<p>Zone → sensor: " + esc(", ".join(f"{z} → {s}" for z, s in pl.assignment.items())) + "</p>"
            + png_img(_gain_curve_png(res), "marginal gain curve"))  # fmt: skip
    return Section("placement", "Sensor placement", body)


def _heat_maps(res) -> Section:
    from simulator.study.report.heat_maps import heat_map_png

    parts = []
    for z in res.study.zone:
        png = getattr(res, "heat_map_cache", {}).get(z.name) or heat_map_png(res, z.name)
        parts.append(f"<figure>{png_img(png, f'heat map of zone {z.name}')}<figcaption>zone {esc(z.name)}</figcaption></figure>")
    return Section("heatmaps", "Heat maps", "".join(parts))


def _warnings(res) -> Section | None:
    if not res.warnings:
        return None
    return Section("warnings", "Warnings", "<ul>" + "".join(f"<li>{esc(w)}</li>" for w in res.warnings) + "</ul>")


#: the page's sections in order: (name, builder)
SECTIONS: list[tuple[str, Callable]] = [
    ("overview", _overview), ("zones", _zones), ("areas", _areas), ("placement", _placement), ("heatmaps", _heat_maps), ("warnings", _warnings),
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
body{font-family:system-ui,sans-serif;margin:1.5em;color:#222;max-width:80em}
h1{font-size:1.4em}h2{font-size:1.15em;margin-top:1.6em;border-bottom:1px solid #ccc}h3{font-size:1em;margin-top:1.2em}
table{border-collapse:collapse;font-size:.85em;margin:.5em 0}
th,td{border:1px solid #ccc;padding:.2em .5em;text-align:left}
table.num td{text-align:right}table.num td:nth-child(-n+2){text-align:left}
img{max-width:100%}figure{margin:1em 0}figcaption{font-size:.85em;color:#555}
nav a{margin-right:1em}
"""


def report_html(res) -> str:
    """The whole page (UTF-8 text)."""
    return page_html(f"probesim study: {res.path.name}", [s for s in (b(res) for _, b in SECTIONS) if s is not None])


def page_html(title: str, secs: list[Section]) -> str:
    """A page of ``secs`` under ``title`` (both escaped here), with their index."""
    nav = "".join(f'<a href="#{esc(s.id)}">{esc(s.title)}</a>' for s in secs)
    body = "".join(f'<section id="{esc(s.id)}"><h2>{esc(s.title)}</h2>{s.body}</section>' for s in secs)
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<title>{esc(title)}</title><style>{_STYLE}</style></head>"
            f"<body><h1>{esc(title)}</h1><nav>{nav}</nav>{body}</body></html>\n")  # fmt: skip
