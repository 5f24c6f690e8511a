"""report.html's annual section: a year of daylight per zone (metrics, control, charts).

Per zone: the annual metrics under the names designers use (DA300,
sDA300/50%, ASE1000/250h, UDI 100–2000 lx, EN 17037 minimum level: met or
not met; :func:`metric_names`, with each one's definition in words) and
their standard errors (replicate years, :mod:`simulator.study.annual.year`), the photosensor control results of each
``[[control]]`` on the zone (relative energy, hours below target, every
candidate photosensor and the chosen one), and three charts embedded as PNGs:

- DA300 per point (the share of occupied hours with at least 300 lx) as a
  false-colour plan (:mod:`simulator.study.report.plan_maps`), with the room's walls, openings and furniture
  (:func:`simulator.study.report.outline.plan_of_zone`) and the chosen photosensor;
- a temporal map (day of year x hour of day, local standard time, the hour's
  centre) of the zone's mean illuminance;
- the same map of the controlled lamps' level u (0…1) for each control.

With ``[shading]``, a part on the shades: the rule, the occupied hours in
each state, per zone sDA and DA with the shades operated and without, ASE
(shades up, as LM-83 defines it) and with them operated, and a temporal map
of the state chosen each hour. With glare views on the stage, a part on
glare: per view glare autonomy, the hours above DGP 0.35, 0.40 and 0.45 and
EN 17037's level of protection from glare, each with its error, and the
year's glare map (day of year x hour, each occupied hour coloured by its
DGP's class: imperceptible, perceptible, disturbing, intolerable).

A study with scenarios gets this section after its heat maps
(:func:`simulator.study.report.page.register_section`); a study with only
``[annual]`` gets a page of its own (:func:`annual_page`). Every name from
the study file or the stage is escaped. The charts depend only on the
hourly means, so the page is the same bytes in-process, on a cluster and
resumed (on the same day: the title block carries the date, fixed by
``SOURCE_DATE_EPOCH`` where set).
"""

from __future__ import annotations

import io

import numpy as np

from pathlib import Path

from simulator.io.numbers import plain, with_error
from simulator.study.annual.metrics import METRICS
from simulator.study.report.page import (Raw, Section, esc, luminaire_section, page_html, png_img, register_section,
                                         table_html, title_block)  # fmt: skip

__all__ = ["annual_section", "annual_page", "da_per_sensor", "temporal_grid", "metric_names", "shading_part", "glare_part"]


def da_per_sensor(ares, ids, da_lx: float) -> np.ndarray:
    """DA (fraction of occupied hours with E >= ``da_lx``) of each sensor in ``ids``, as
    :func:`simulator.study.annual.metrics.zone_metrics` counts it."""
    eo = ares.mean[ares.occupied][:, ids]
    return np.sum(eo >= da_lx, axis=0) / max(len(eo), 1)


def temporal_grid(ares, values: np.ndarray, rows_mask: np.ndarray | None = None):
    """``(grid, days)``: ``values`` (one per analysed hour, or per hour of ``rows_mask``) on a
    (24, D) grid, hour of day x each day of year present (NaN where no hour was analysed)."""
    centre = ares.weather.centre[ares.rows]
    if rows_mask is not None:
        centre = centre[rows_mask]
    doy = np.asarray(centre.day_of_year)
    hod = np.asarray(centre.hour)
    days = np.unique(doy)
    grid = np.full((24, len(days)), np.nan)
    grid[hod, np.searchsorted(days, doy)] = values
    return grid, days


def _png(fig) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", metadata={"Software": None})
    return buf.getvalue()


def _plan(ares, ids):
    """The room's plan around the zone's candidates, or None (not horizontal, no prims, no stage kept)."""
    from simulator.study.report.outline import plan_of_zone

    scene = getattr(ares, "scene", None)
    cands = [ares.sensors[i] for i in ids]
    if scene is None or not all(abs(abs(float(c.sensor.normal[2])) - 1.0) < 1e-6 for c in cands):
        return None
    prims = sorted({c.prim for c in cands if c.prim})
    if not prims:
        return None
    return plan_of_zone(scene, prims, float(np.median([c.position[2] for c in cands])))


def _da_map_png(ares, zone: str, da_lx: float, chosen: list[str]) -> bytes:
    """The zone's DA per point as a false-colour plan (0–100 %), the chosen photosensors marked."""
    from simulator.study.report.plan_maps import Scale, plan_png

    ids = ares.zones[zone]
    xy = np.array([ares.sensors[i].position[:2] for i in ids])
    da = 100.0 * da_per_sensor(ares, ids, da_lx)
    marks = [c.position[:2] for c in ares.sensors if c.sensor.name in chosen]
    return plan_png(xy, da, Scale(0.0, 100.0), f"DA{da_lx:g} (% of occupied hours)", f"zone {zone}: DA{da_lx:g} per point",
                    _plan(ares, ids), marks)  # fmt: skip


def _day_hour_axes(ax, days) -> None:
    """Label a day-of-year × hour-of-day map's axes: about 12 day ticks, hours 0–23 (LST)."""
    step = max(1, len(days) // 12)
    ax.set_xticks(range(0, len(days), step))
    ax.set_xticklabels([str(int(d)) for d in days[::step]])
    ax.set_yticks([0, 6, 12, 18, 23])
    ax.tick_params(labelsize=9)
    ax.set_xlabel("day of year (days analysed)", fontsize=9)
    ax.set_ylabel("hour of day (LST)", fontsize=9)


def _temporal_png(grid: np.ndarray, days: np.ndarray, title: str, label: str, vmax: float | None = None,
                  grey: str = "hours not analysed") -> bytes:
    from matplotlib.figure import Figure

    from matplotlib import colormaps

    cmap = colormaps["magma"].with_extremes(bad="0.85")  # hours not analysed (or not occupied): light grey
    fig = Figure(figsize=(7.0, 3.0), dpi=110)
    ax = fig.subplots()
    im = ax.imshow(grid, origin="lower", aspect="auto", interpolation="nearest", cmap=cmap, vmin=0.0,
                   vmax=vmax, extent=(-0.5, len(days) - 0.5, -0.5, 23.5))  # fmt: skip
    _day_hour_axes(ax, days)
    ax.set_title(f"{title}\n(grey: {grey})", fontsize=10)
    cb = fig.colorbar(im, ax=ax, fraction=0.046, pad=0.02)
    cb.set_label(label, fontsize=9)
    cb.ax.tick_params(labelsize=8)
    cb.ax.yaxis.set_major_formatter(lambda t, _pos: plain(t))
    fig.tight_layout()
    return _png(fig)


def metric_names(cfg, shaded: bool = False) -> dict[str, tuple[str, str]]:
    """Metric key (:data:`simulator.study.annual.metrics.METRICS`) → (the name designers use, its definition in words),
    with the study's thresholds (``[annual]`` ``da_lx``, ``ase_lx``, ``ase_hours``, ``udi_lx``, ``en17037_lx``) in them;
    ``shaded``: the year's readings are those of the shades as their rule operated them."""
    da, ase, ah = f"{cfg.da_lx:g}", f"{cfg.ase_lx:g}", f"{cfg.ase_hours:g}"
    blinds = "with operable shading: the shades as their rule operated them" if shaded else "no blinds operated"
    lo, hi = (f"{v:g}" for v in cfg.udi_lx)
    t, m = (f"{v:g}" for v in cfg.en17037_lx)
    return {
        "DA": (f"DA{da}", f"Daylight autonomy: the share of occupied hours in which a point gets at least {da} lx from "
                          "daylight, averaged over the zone's points (IES LM-83-12)."),
        "sDA": (f"sDA{da}/50%", f"Spatial daylight autonomy: the share of the zone's points that get at least {da} lx from "
                                f"daylight for at least half of the occupied hours (IES LM-83-12; {blinds})."),
        "ASE": (f"ASE{ase}/{ah}h", f"Annual sunlight exposure: the share of points that get more than {ase} lx of direct "
                                   f"sunlight for more than {ah} occupied hours a year (IES LM-83-12{', shades up' if shaded else ''}; "
                                   "exact, no error)."),
        "UDI_fell_short": (f"UDI < {lo} lx", f"Useful daylight illuminance, fell short: the share of occupied hours below "
                                             f"{lo} lx, averaged over the points."),
        "UDI_useful": (f"UDI {lo}–{hi} lx", f"Useful daylight illuminance: the share of occupied hours from {lo} to {hi} lx, "
                                            "averaged over the points."),
        "UDI_exceeded": (f"UDI > {hi} lx", f"Useful daylight illuminance, exceeded: the share of occupied hours above {hi} lx "
                                           "(glare and heat likely), averaged over the points."),
        "EN17037_target": (f"EN 17037 {t} lx over 50% of the area", f"The share of daylight hours in which at least half "
                           f"of the points get {t} lx (the minimum level asks at least 50% of the hours)."),
        "EN17037_minimum": (f"EN 17037 {m} lx over 95% of the area", f"The share of daylight hours in which at least 95% "
                            f"of the points get {m} lx (the minimum level asks at least 50% of the hours)."),
        "EN17037_pass": ("EN 17037 minimum level", "Met when both shares above are at least 50% of the daylight hours "
                         "(EN 17037:2018, Table A.1)."),
        "DF": ("DF (mean)", "Daylight factor: indoor over unobstructed outdoor horizontal illuminance under the CIE "
                            "overcast sky, averaged over the points."),
    }  # fmt: skip


def _metrics_table(m: dict, cfg, shaded: bool = False) -> str:
    names = metric_names(cfg, shaded)
    rows = []
    for k, (unit, _) in METRICS.items():
        if k not in m:
            continue
        v, se = m[k]
        name, what = names[k]
        if k == "EN17037_pass":
            word = "met" if v >= 0.5 else "not met"
            cell = Raw.of(esc(word + (" (replicate years disagree)" if se > 0 else "")), "pass" if v >= 0.5 else "fail")
        else:
            cell = Raw.of(esc(with_error(v, se, unit)), "n")
        rows.append([name, cell, Raw.of(esc(what), "text")])
    return table_html(["metric", "value", "definition"], rows, "num metrics")


def _control_table(ctl: dict) -> str:
    rows = [[r["photosensor"], Raw.of(esc(with_error(r["relative_energy"], r["relative_energy_stderr"])), "n"),
             Raw.of(esc(with_error(r["hours_below"], r["hours_below_stderr"], "h")), "n"),
             Raw.of(esc(with_error(r["score"], r["score_stderr"])), "n"),
             "yes" if r["photosensor"] == ctl["chosen"] else ""] for r in ctl["candidates"]]  # fmt: skip
    sep = "" if ctl["separable"] else f" (not separable from {ctl['runner_up']})"
    head = (f"<p>Control <b>{esc(ctl['model'])}</b> of {esc(', '.join(ctl['groups']))}, target {esc(plain(ctl['target_lx'], 'lx'))} "
            f"(lamps at full output give the zone {esc(plain(ctl['lamps_zone_lx'], 'lx'))}); chosen photosensor "
            f"<b>{esc(ctl['chosen'])}</b>{esc(sep)}; {ctl['occupied_hours']} occupied hours. Relative energy: the lamps' "
            "energy over the year against full output in every occupied hour.</p>")  # fmt: skip
    return head + table_html(["photosensor", "relative energy", "hours below target", "score", "chosen"], rows, "num")


def _zone_part(ares, zone: str) -> str:
    a = ares.annual_spec
    ctls = [c for c in ares.controls if c["zone"] == zone]
    parts = [f"<h3>Zone {esc(zone)}</h3>", _metrics_table(ares.metrics[zone], a, getattr(ares, "shading", None) is not None)]
    for c in ctls:
        parts.append(_control_table(c))
    chosen = [c["chosen"] for c in ctls]
    figs = [(_da_map_png(ares, zone, float(a.da_lx), chosen), f"DA{a.da_lx:g} per sensor, zone {zone}")]
    ids = ares.zones[zone]
    g, days = temporal_grid(ares, ares.mean[:, ids].mean(axis=1))
    figs.append((_temporal_png(g, days, f"zone {zone}: mean illuminance from daylight", "illuminance E (lx)"),
                 f"temporal map of the mean daylight illuminance, zone {zone}"))  # fmt: skip
    for c in ctls:
        g, days = temporal_grid(ares, np.asarray(c["level"], float), ares.occupied)
        figs.append((_temporal_png(g, days, f"zone {zone}: lamp level, {c['model']} on {c['chosen']}", "lamp level (0 off, 1 full output)", 1.0,
                                   "hours not occupied or not analysed"),
                     f"controlled lighting level over the year, zone {zone}, photosensor {c['chosen']}"))  # fmt: skip
    parts += [f'<figure class="chart">{png_img(png, alt)}<figcaption>{esc(alt)}</figcaption></figure>' for png, alt in figs]
    return "".join(parts)


#: the DGP classes of the glare map: upper bounds and colours (Wienold 2009)
_DGP_CLASSES = ((0.35, "imperceptible", "#5aae61"), (0.40, "perceptible", "#fee08b"), (0.45, "disturbing", "#f46d43"),
                (1.0, "intolerable", "#a50026"))  # fmt: skip


def _state_png(ares) -> bytes:
    """The state chosen each hour, a temporal map (grey: not analysed)."""
    from matplotlib import colormaps
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.figure import Figure

    g, days = temporal_grid(ares, np.asarray(ares.state, float))
    n = len(ares.states)
    base = colormaps["Blues"]
    cmap = ListedColormap([base(0.15 + 0.75 * k / max(n - 1, 1)) for k in range(n)]).with_extremes(bad="0.85")
    fig = Figure(figsize=(7.0, 2.8), dpi=110)
    ax = fig.subplots()
    im = ax.imshow(g, origin="lower", aspect="auto", interpolation="nearest", cmap=cmap,
                   norm=BoundaryNorm(np.arange(n + 1) - 0.5, n), extent=(-0.5, len(days) - 0.5, -0.5, 23.5))  # fmt: skip
    _day_hour_axes(ax, days)
    ax.set_title(f"shades {ares.shading.variant_set}: the state each hour ({ares.shading.rule})\n(grey: hours not analysed)", fontsize=10)
    cb = fig.colorbar(im, ax=ax, fraction=0.046, pad=0.02, ticks=range(n))
    cb.ax.set_yticklabels(ares.states, fontsize=8)
    fig.tight_layout()
    return _png(fig)


def _glare_png(ares, v: int) -> bytes:
    """The year's glare map of view ``v``: each occupied hour coloured by its index's class."""
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.figure import Figure

    g = ares.glare
    vals = np.where(ares.occupied, g.index[:, v], np.nan)
    grid, days = temporal_grid(ares, vals)
    cmap = ListedColormap([c for _, _, c in _DGP_CLASSES]).with_extremes(bad="0.85")
    bounds = [0.0] + [b for b, _, _ in _DGP_CLASSES]
    fig = Figure(figsize=(7.0, 3.0), dpi=110)
    ax = fig.subplots()
    im = ax.imshow(grid, origin="lower", aspect="auto", interpolation="nearest", cmap=cmap, norm=BoundaryNorm(bounds, len(_DGP_CLASSES)),
                   extent=(-0.5, len(days) - 0.5, -0.5, 23.5))  # fmt: skip
    _day_hour_axes(ax, days)
    ax.set_title(f"view {g.views[v]}: {g.index_name.upper()} every occupied hour\n(grey: hours not occupied or not analysed)", fontsize=10)
    cb = fig.colorbar(im, ax=ax, fraction=0.046, pad=0.02, ticks=[0.175, 0.375, 0.425, 0.725])
    cb.ax.set_yticklabels([f"{n} (< {b:.2f})" if b < 1 else f"{n} (≥ 0.45)" for b, n, _ in _DGP_CLASSES], fontsize=8)
    fig.tight_layout()
    return _png(fig)


def _figure(png: bytes, alt: str) -> str:
    return f'<figure class="chart">{png_img(png, alt)}<figcaption>{esc(alt)}</figcaption></figure>'


def shading_part(ares) -> str:
    """The shades' part of the section (module docstring); "" without ``[shading]``."""
    sh = getattr(ares, "shading", None)
    if sh is None:
        return ""
    a, x = ares.annual_spec, ares.extra
    rule = {"lm83": (f"IES LM-83-12's rule: down when more than {100 * sh.share:g}% of the analysis points get over "
                     f"{a.ase_lx:g} lx of direct sun with them up"),
            "glare": f"down when DGP exceeds {sh.dgp_limit:g} at a glare view ({', '.join(sh.views) or 'every view'})",
            "schedule": "a schedule"}[sh.rule]  # fmt: skip
    diff = "".join(f"; {esc(p)} passes {100 * t:g}% of the light on it, diffusely" for p, t in sh.diffusers.items())
    head = (f"<h3>Operable shading: {esc(sh.variant_set)}</h3><p>States {esc(', '.join(ares.states))} (the stage's variants), "
            f"each traced once; every hour takes the first state that passes {esc(rule)}{diff}.</p>")  # fmt: skip
    hours = [[st, Raw.of(esc(with_error(*x[(sh.variant_set, f"hours_{st}")], "h")), "n")] for st in ares.states]
    t1 = table_html(["state", "occupied hours"], hours, "num")
    names = metric_names(a)
    rows = []
    for z in ares.metrics:
        rows.append([z, Raw.of(esc(with_error(*ares.metrics[z]["sDA"], "%")), "n"), Raw.of(esc(with_error(*x[(z, "sDA_open")], "%")), "n"),
                     Raw.of(esc(with_error(*ares.metrics[z]["DA"], "%")), "n"), Raw.of(esc(with_error(*x[(z, "DA_open")], "%")), "n"),
                     Raw.of(esc(with_error(*ares.metrics[z]["ASE"], "%")), "n"), Raw.of(esc(with_error(*x[(z, "ASE_operated")], "%")), "n")])  # fmt: skip
    t2 = table_html(["zone", f"{names['sDA'][0]} operated", "without shading", f"{names['DA'][0]} operated", "without shading",
                     f"{names['ASE'][0]} (shades up)", "shades operated"], rows, "num")  # fmt: skip
    return head + t1 + t2 + _figure(_state_png(ares), f"the state of {sh.variant_set} each hour")


def glare_part(ares) -> str:
    """The views' part of the section (module docstring); "" without glare views."""
    from simulator.study.annual.glare import EN17037_LEVELS

    g = getattr(ares, "glare", None)
    if g is None:
        return ""
    a, x = ares.annual_spec, ares.extra
    level = {code: name for code, name, _ in EN17037_LEVELS}
    idx = g.index_name.upper()
    head = (f"<h3>Glare over the year</h3><p>{idx} at each glare view every occupied hour, from daylight coefficients "
            "(the imageless method: the sky, the ground, the shades and the sun seen directly are the sources; every "
            "surface seen adds to the vertical illuminance at the eye but is never a source). Glare autonomy: the "
            f"share of occupied hours with {idx} below {a.glare_limit:.2f}. EN 17037 protection from glare: the highest "
            f"level (high 0.35, medium 0.40, minimum 0.45) whose {idx} is exceeded in at most 5% of the occupied hours.</p>")  # fmt: skip
    rows = []
    for v in g.views:
        ga = Raw.of(esc(with_error(*x[(v, "GA")], "%")), "n")
        ga_open = [Raw.of(esc(with_error(*x[(v, "GA_open")], "%")), "n")] if (v, "GA_open") in x else []
        hrs = [Raw.of(esc(with_error(*x[(v, f"hours_above_{b}")], "h")), "n") for b in ("0.35", "0.40", "0.45")]
        code = int(x[(v, "EN17037_glare")][0])
        en = Raw.of(esc(level.get(code, "not met") + (" (replicate years disagree)" if x[(v, "EN17037_glare")][1] > 0 else "")),
                    "pass" if code > 0 else "fail")  # fmt: skip
        rows.append([v, ga, *ga_open, *hrs, en])
    cols = ["view", "glare autonomy"] + (["shades open"] if getattr(ares, "shading", None) is not None else [])
    table = table_html(cols + [f"hours {idx} > 0.35", "> 0.40", "> 0.45", "EN 17037 protection from glare"], rows, "num")
    figs = "".join(_figure(_glare_png(ares, v), f"the glare map of view {n}: {idx} each occupied hour") for v, n in enumerate(g.views))
    return head + table + figs


def annual_section(ares) -> Section:
    """The section: hours, notes, then every zone's metrics, control and charts."""
    w = ares.weather
    intro = (f"<p>Weather {esc(w.site)} ({w.latitude_deg:.2f}°, {w.longitude_deg:.2f}°): {len(ares.rows)} hours analysed, "
             f"{int(ares.occupied.sum())} occupied, {int(ares.daylight.sum())} with the sun up. "
             "Each figure's ± is its standard error (the standard deviation over replicate years).</p>"
             + ("<ul>" + "".join(f"<li>{esc(n)}</li>" for n in ares.notes) + "</ul>" if ares.notes else ""))  # fmt: skip
    return Section("annual", "A year of daylight", intro + "".join(_zone_part(ares, z) for z in ares.metrics) + shading_part(ares)
                   + glare_part(ares))


def _builder(res) -> Section | None:
    ares = getattr(res, "annual", None)
    return None if ares is None else annual_section(ares)


def annual_page(ares, path, study=None) -> str:
    """The whole report page of a study with only ``[annual]`` (with its title block and luminaire schedule when
    ``study`` is given)."""
    secs = [annual_section(ares)]
    lum = luminaire_section(getattr(ares, "scene", None))
    if lum is not None:
        secs.append(lum)
    head = "" if study is None else title_block(study, path, "Annual daylight report")
    name = (study.project or Path(study.stage).stem) if study is not None else "probesim study"
    return page_html(f"{name}: {path.name}", secs, head)


register_section("annual", _builder, after="heatmaps")
