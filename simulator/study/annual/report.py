"""report.html's annual section: a year of daylight per zone (metrics, control, charts).

Per zone: the annual metrics with their standard errors (replicate years,
:mod:`simulator.study.annual.year`), the photosensor control results of each
``[[control]]`` on the zone (relative energy, hours below target, every
candidate photosensor and the chosen one), and three charts embedded as PNGs:

- DA300 per sensor (share of occupied hours with E >= ``da_lx``) on the
  zone's plan, with the room's walls, openings and furniture
  (:func:`simulator.study.report.outline.plan_of_zone`) and the chosen photosensor;
- a temporal map (day of year x hour of day, local standard time, the hour's
  centre) of the zone's mean illuminance;
- the same map of the controlled lamps' level u (0…1) for each control.

A study with scenarios gets this section after its heat maps
(:func:`simulator.study.report.page.register_section`); a study with only
``[annual]`` gets a page of its own (:func:`annual_page`). Every name from
the study file or the stage is escaped. The charts depend only on the
hourly means, so the page is the same bytes in-process, on a cluster and
resumed.
"""

from __future__ import annotations

import io

import numpy as np

from simulator.study.report.page import Section, esc, page_html, png_img, register_section, table_html
from simulator.study.annual.metrics import METRICS

__all__ = ["annual_section", "annual_page", "da_per_sensor", "temporal_grid"]


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
    from matplotlib.figure import Figure

    from simulator.study.report.heat_maps import _raster, draw_plan

    ids = ares.zones[zone]
    xy = np.array([ares.sensors[i].position[:2] for i in ids])
    da = 100.0 * da_per_sensor(ares, ids, da_lx)
    fig = Figure(figsize=(4.2, 3.4), dpi=80)
    ax = fig.subplots()
    r = _raster(xy, da)
    kw = {"cmap": "viridis", "vmin": 0.0, "vmax": 100.0}
    if r is not None:
        im = ax.imshow(r[0], origin="lower", extent=r[1], interpolation="nearest", **kw)
    else:
        im = ax.scatter(xy[:, 0], xy[:, 1], c=da, marker="s", s=30, linewidths=0, **kw)
    plan = _plan(ares, ids)
    draw_plan(ax, plan)
    for c in ares.sensors:
        if c.sensor.name in chosen:
            ax.plot(c.position[0], c.position[1], marker="x", color="red", markersize=7, mew=2)
    ax.set_aspect("equal", adjustable="datalim")
    ax.tick_params(labelsize=6)
    ax.set_xlabel("x (m)", fontsize=6)
    ax.set_ylabel("y (m)", fontsize=6)
    fig.colorbar(im, ax=ax, fraction=0.046, pad=0.04).set_label(f"DA{da_lx:g} (% of occupied hours)", fontsize=6)
    key = "x chosen photosensor" + ("; walls grey, openings blue, furniture brown" if plan is not None else "")
    ax.set_title(f"zone {zone}: DA{da_lx:g} per sensor\n{key}", fontsize=7)
    fig.tight_layout()
    return _png(fig)


def _temporal_png(grid: np.ndarray, days: np.ndarray, title: str, label: str, vmax: float | None = None,
                  grey: str = "hours not analysed") -> bytes:
    from matplotlib.figure import Figure

    from matplotlib import colormaps

    cmap = colormaps["magma"].with_extremes(bad="0.85")  # hours not analysed (or not occupied): light grey
    fig = Figure(figsize=(6.0, 2.6), dpi=80)
    ax = fig.subplots()
    im = ax.imshow(grid, origin="lower", aspect="auto", interpolation="nearest", cmap=cmap, vmin=0.0,
                   vmax=vmax, extent=(-0.5, len(days) - 0.5, -0.5, 23.5))  # fmt: skip
    step = max(1, len(days) // 12)
    ax.set_xticks(range(0, len(days), step))
    ax.set_xticklabels([str(int(d)) for d in days[::step]])
    ax.set_yticks([0, 6, 12, 18, 23])
    ax.tick_params(labelsize=6)
    ax.set_xlabel("day of year (days analysed)", fontsize=6)
    ax.set_ylabel("hour of day (LST)", fontsize=6)
    ax.set_title(f"{title}\n(grey: {grey})", fontsize=7)
    fig.colorbar(im, ax=ax, fraction=0.046, pad=0.02).set_label(label, fontsize=6)
    fig.tight_layout()
    return _png(fig)


def _metrics_table(m: dict) -> str:
    rows = [[k, v, se, unit, what] for k, (unit, what) in METRICS.items() if k in m for v, se in [m[k]]]
    return table_html(["metric", "value", "±", "unit", "definition"], rows, "num")


def _control_table(ctl: dict) -> str:
    rows = [[r["photosensor"], r["relative_energy"], r["relative_energy_stderr"], r["hours_below"], r["hours_below_stderr"],
             r["score"], r["score_stderr"], "yes" if r["photosensor"] == ctl["chosen"] else ""] for r in ctl["candidates"]]  # fmt: skip
    sep = "" if ctl["separable"] else f" (not separable from {ctl['runner_up']})"
    head = (f"<p>Control <b>{esc(ctl['model'])}</b> of {esc(', '.join(ctl['groups']))}, target {ctl['target_lx']:g} lx "
            f"(lamps at full output give the zone {ctl['lamps_zone_lx']:.4g} lx); chosen photosensor "
            f"<b>{esc(ctl['chosen'])}</b>{esc(sep)}; {ctl['occupied_hours']} occupied hours.</p>")  # fmt: skip
    return head + table_html(["photosensor", "relative energy", "±", "hours below target", "±", "score", "±", "chosen"], rows, "num")


def _zone_part(ares, zone: str) -> str:
    a = ares.annual_spec
    ctls = [c for c in ares.controls if c["zone"] == zone]
    parts = [f"<h3>zone {esc(zone)}</h3>", _metrics_table(ares.metrics[zone])]
    for c in ctls:
        parts.append(_control_table(c))
    chosen = [c["chosen"] for c in ctls]
    figs = [(_da_map_png(ares, zone, float(a.da_lx), chosen), f"DA{a.da_lx:g} per sensor, zone {zone}")]
    ids = ares.zones[zone]
    g, days = temporal_grid(ares, ares.mean[:, ids].mean(axis=1))
    figs.append((_temporal_png(g, days, f"zone {zone}: mean illuminance from daylight", "lx"),
                 f"temporal map of the mean daylight illuminance, zone {zone}"))  # fmt: skip
    for c in ctls:
        g, days = temporal_grid(ares, np.asarray(c["level"], float), ares.occupied)
        figs.append((_temporal_png(g, days, f"zone {zone}: lamp level, {c['model']} on {c['chosen']}", "level u (0-1)", 1.0,
                                   "hours not occupied or not analysed"),
                     f"controlled lighting level over the year, zone {zone}, photosensor {c['chosen']}"))  # fmt: skip
    parts += [f"<figure>{png_img(png, alt)}<figcaption>{esc(alt)}</figcaption></figure>" for png, alt in figs]
    return "".join(parts)


def annual_section(ares) -> Section:
    """The section: hours, notes, then every zone's metrics, control and charts."""
    w = ares.weather
    intro = (f"<p>Weather {esc(w.site)} ({w.latitude_deg:.2f}°, {w.longitude_deg:.2f}°): {len(ares.rows)} hours analysed, "
             f"{int(ares.occupied.sum())} occupied, {int(ares.daylight.sum())} with the sun up. "
             "Errors are standard deviations over replicate years.</p>"
             + ("<ul>" + "".join(f"<li>{esc(n)}</li>" for n in ares.notes) + "</ul>" if ares.notes else ""))  # fmt: skip
    return Section("annual", "A year of daylight", intro + "".join(_zone_part(ares, z) for z in ares.metrics))


def _builder(res) -> Section | None:
    ares = getattr(res, "annual", None)
    return None if ares is None else annual_section(ares)


def annual_page(ares, path) -> str:
    """The whole report page of a study with only ``[annual]``."""
    return page_html(f"probesim study: {path.name}", [annual_section(ares)])


register_section("annual", _builder, after="heatmaps")
