"""A zone's heat map (PNG) with the room's plan: shared by the study's files, report.html and its annual section."""

from __future__ import annotations

import io
import math

import numpy as np

__all__ = ["MAX_PANELS", "heat_map_png", "zone_plan", "dropped_in_zone", "draw_plan"]

#: most scenario panels in one zone's heat map
MAX_PANELS = 16


def _raster(xy: np.ndarray, v: np.ndarray):
    """``(image, extent)`` of values on a regular grid of points, or None when the points are not one."""
    xs, ys = np.unique(np.round(xy[:, 0], 6)), np.unique(np.round(xy[:, 1], 6))
    if len(xs) < 2 or len(ys) < 2:
        return None
    dx, dy = np.diff(xs), np.diff(ys)
    if np.ptp(dx) > 1e-6 or np.ptp(dy) > 1e-6:
        return None
    img = np.full((len(ys), len(xs)), np.nan)
    ix = np.searchsorted(xs, np.round(xy[:, 0], 6))
    iy = np.searchsorted(ys, np.round(xy[:, 1], 6))
    img[iy, ix] = v
    ext = (xs[0] - dx[0] / 2, xs[-1] + dx[0] / 2, ys[0] - dy[0] / 2, ys[-1] + dy[0] / 2)
    return img, ext


def zone_plan(res, zone: str):
    """The room's plan around a zone (:func:`simulator.study.report.outline.plan_of_zone`), or None
    (no stage scene kept, a zone that is not horizontal, no prims of its own)."""
    from simulator.study.report.outline import plan_of_zone

    scene = getattr(res, "scene", None)
    ids = res.zones[zone]
    cands = [res.candidates[i] for i in ids]
    def facing(sn):  # a cylinder's axis; a plane receiver's normal
        return sn.up if sn.spec.name in ("cylindrical", "semicylindrical") else sn.normal

    if scene is None or not all(abs(abs(float(facing(c.sensor)[2])) - 1.0) < 1e-6 for c in cands):
        return None
    prims = sorted({c.prim for c in cands if c.prim})
    if not prims:
        return None
    return plan_of_zone(scene, prims, float(np.median([c.position[2] for c in cands])))


def dropped_in_zone(res, zone: str) -> np.ndarray:
    """Positions (N, 3) of the zone's set's points dropped inside furniture, within the zone's region."""
    z = next(z for z in res.study.zone if z.name == zone)
    cs = next(s for s in res.sets if s.name == z.candidates)
    pts = [p for p in getattr(cs, "dropped_points", [])
           if z.region is None or (z.region[0] <= p[0] <= z.region[2] and z.region[1] <= p[1] <= z.region[3])]  # fmt: skip
    return np.array(pts).reshape(-1, 3)


def draw_plan(ax, plan) -> None:
    """The room's walls (dark grey), openings (blue) and furniture (brown) of a :class:`~simulator.study.report.outline.Plan`
    on a plan axis (x, y in metres); nothing when ``plan`` is None."""
    if plan is None:
        return
    for seg in plan.walls:
        ax.plot(seg[:, 0], seg[:, 1], color="0.25", lw=1.6, solid_capstyle="butt")
    for line in plan.openings:
        ax.plot(line[:, 0], line[:, 1], color="tab:blue", lw=2.2)
    for line in plan.furniture:
        ax.plot(line[:, 0], line[:, 1], color="saddlebrown", lw=0.8)


def heat_map_png(res, zone: str) -> bytes:
    """PNG of one zone's readings, a panel per scenario (up to :data:`MAX_PANELS`).

    Each panel has its own colour scale (``[output] heat_map_scale =
    "per_scenario"``, the default: an evening at 50 lx and a sunny
    afternoon at 5,000 lx both show their pattern) or all share one
    logarithmic scale (``"log"``); world x and y in metres on the axes; the
    room's walls (dark grey), openings (blue) and furniture (brown) of
    :func:`zone_plan`; the chosen sensors (red ×) and the points dropped
    inside furniture (grey +)."""
    from matplotlib.colors import LogNorm, Normalize
    from matplotlib.figure import Figure

    ch = 1 if res.study.light_units == "photometric" else 0
    ids = res.zones[zone]
    xy = np.array([res.candidates[i].position[:2] for i in ids])
    scen = res.scenarios[:MAX_PANELS]
    vals = res.mean[: len(scen), ids, ch]
    log = getattr(res.study.output, "heat_map_scale", "per_scenario") == "log"
    ncol = min(4, len(scen))
    nrow = math.ceil(len(scen) / ncol)
    fig = Figure(figsize=(3.0 * ncol + (1.2 if log else 0.3), 2.5 * nrow + 1.0), dpi=80)
    fig.subplots_adjust(left=0.06, right=0.86 if log else 0.95, bottom=0.1, top=1.0 - 0.95 / (2.5 * nrow + 1.0), wspace=0.55, hspace=0.75)
    axes = fig.subplots(nrow, ncol, squeeze=False)
    pos_vals = vals[vals > 0]
    shared = None
    if log and pos_vals.size:
        shared = LogNorm(vmin=float(pos_vals.min()), vmax=float(pos_vals.max()) if pos_vals.max() > pos_vals.min() else float(pos_vals.min()) * 10)
    chosen = [] if res.placement is None else res.placement.chosen
    index = {c.sensor.name: c for c in res.candidates}
    plan = zone_plan(res, zone)
    dropped = dropped_in_zone(res, zone)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    unit = "lx" if ch == 1 else "W/m²"
    im = None
    for k, ax in enumerate(axes.flat):
        if k >= len(scen):
            ax.set_visible(False)
            continue
        v = vals[k]
        if shared is not None:
            norm = shared
        else:
            vmax = float(v.max()) if v.size and v.max() > 0 else 1.0
            norm = Normalize(vmin=min(0.0, float(v.min())), vmax=vmax)
        r = _raster(xy, v)
        if r is not None:
            im = ax.imshow(np.where(r[0] > 0, r[0], np.nan) if shared is not None else r[0], origin="lower", extent=r[1],
                           cmap="viridis", norm=norm, interpolation="nearest")  # fmt: skip
        else:
            im = ax.scatter(xy[:, 0], xy[:, 1], c=v, cmap="viridis", norm=norm, marker="s", s=30, linewidths=0)
        draw_plan(ax, plan)
        if len(dropped):
            ax.plot(dropped[:, 0], dropped[:, 1], "+", color="0.5", markersize=5, mew=1)
        for name in chosen:
            p = index[name].position
            if lo[0] - 1 <= p[0] <= hi[0] + 1 and lo[1] - 1 <= p[1] <= hi[1] + 1:
                ax.plot(p[0], p[1], marker="x", color="red", markersize=7, mew=2)
        f = res.figures[(zone, scen[k].name)]
        ax.set_title(f"{scen[k].name}\nmean {f.mean:.0f} {unit}, U0 {f.u0:.2f}", fontsize=6)
        ax.tick_params(labelsize=6)
        ax.set_xlabel("x (m)", fontsize=6)
        ax.set_ylabel("y (m)", fontsize=6)
        ax.set_aspect("equal", adjustable="datalim")
        if shared is None:
            cb = fig.colorbar(im, ax=ax, fraction=0.046, pad=0.04)
            cb.ax.tick_params(labelsize=5)
    if shared is not None and im is not None:
        cax = fig.add_axes((0.89, 0.15, 0.02, 0.65))
        fig.colorbar(im, cax=cax).set_label(f"illuminance ({unit}, log scale)", fontsize=7)
    more = f" (first {MAX_PANELS} of {len(res.scenarios)} scenarios)" if len(res.scenarios) > MAX_PANELS else ""
    scale = "one log scale" if shared is not None else f"each panel its own scale ({unit})"
    key = "x chosen sensors" + (", + dropped inside furniture" if len(dropped) else "")
    if plan is not None:
        key += "; walls grey, openings blue, furniture brown"
    fig.suptitle(f"zone {zone}{more}; {scale}\n{key}", fontsize=7)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", metadata={"Software": None})
    return buf.getvalue()
