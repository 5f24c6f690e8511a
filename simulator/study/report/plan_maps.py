"""A continuous false-colour plan of a zone's readings, with isolines, the room and a labelled colour bar.

The grid's readings are interpolated onto a fine raster of the plan
(piecewise linear over the Delaunay triangles of the sensor points, the
nearest reading beyond their hull) and drawn only inside the *calculation
area*: the union of the grid's cells, one cell of the grid's pitch centred
on each sensor (EN 12464-1 points sit at cell centres). Where furniture
removed a point its cell stays blank, so no value is painted under a desk.
Filled bands at round levels (1, 2, 2.5 or 5 × 10^k), labelled isolines on
every other level, and the room's walls (dark grey), openings (blue) and
furniture (brown) of :func:`simulator.study.report.outline.plan_of_zone` on top.
"""

from __future__ import annotations

import io
import math
from dataclasses import dataclass

import numpy as np

from simulator.io.numbers import plain

__all__ = ["Scale", "OVER_RGB", "plan_levels", "draw_false_colour", "draw_plan", "plan_png", "tile_pngs", "cell_pitch_m", "room_box",
           "colour_bar"]

#: raster points along the longer side of the drawn area
RASTER_PX = 240
#: most filled bands of a linear scale
MOST_BANDS = 10
#: the plan's margin around the zone's points, metres
MARGIN_M = 0.35
#: the map's height (inches) and the font size (pt) of a single plan: readable at half an A4 page's width
MAP_H_IN = 3.0
FONT_PT = 10


@dataclass(frozen=True)
class Scale:
    """A colour scale: ``lo``…``hi`` in the readings' unit, linear or logarithmic; readings above ``hi``
    are drawn in :data:`OVER_RGB` (the colour bar's arrow)."""

    lo: float
    hi: float
    log: bool = False


#: readings above a scale's top: a colour outside viridis, so a sunlit patch reads as "above the scale"
OVER_RGB = "#f4a6c8"


def plan_levels(scale: Scale) -> np.ndarray:
    """Round band edges covering [lo, hi]: a linear scale in steps of 1, 2, 2.5 or 5 × 10^k (at most
    :data:`MOST_BANDS` bands), a log scale at 1, 2, 5 × 10^k."""
    lo, hi = float(scale.lo), float(scale.hi)
    if scale.log:
        lo = max(lo, hi * 1e-4, 1e-12)
        out = [m * 10.0**k for k in range(math.floor(math.log10(lo)) - 1, math.ceil(math.log10(hi)) + 1) for m in (1, 2, 5)]
        below = [v for v in out if v <= lo]
        above = [v for v in out if v >= hi]
        return np.array([below[-1], *[v for v in out if lo < v < hi], above[0]])
    if not hi > lo:
        hi = lo + (abs(lo) if lo else 1.0)
    span = hi - lo
    k = math.floor(math.log10(span / MOST_BANDS))
    for base in (1.0, 2.0, 2.5, 5.0, 10.0, 20.0):
        step = base * 10.0**k
        first, last = math.floor(lo / step + 1e-9), math.ceil(hi / step - 1e-9)
        if last - first <= MOST_BANDS:
            return np.array([round(i * step, 12) for i in range(first, last + 1)])
    return np.array([lo, hi])


def cell_pitch_m(xy: np.ndarray) -> tuple[float, float]:
    """The grid's pitch along x and y (m): the smallest step between distinct coordinates, else the
    median nearest-neighbour distance (points not on a grid), else 0.5 m (one point)."""
    out = []
    for a in (xy[:, 0], xy[:, 1]):
        u = np.unique(np.round(a, 6))
        d = np.diff(u)
        out.append(float(d.min()) if len(d) else 0.0)
    if len(xy) > 1 and not all(out):
        from scipy.spatial import cKDTree

        nn = float(np.median(cKDTree(xy).query(xy, k=2)[0][:, 1]))
        out = [v or nn for v in out]
    return out[0] or 0.5, out[1] or 0.5


def _raster(xy: np.ndarray, v: np.ndarray, box: tuple[float, float, float, float]):
    """``(X, Y, Z)``: the readings interpolated on a raster of ``box`` (x0, y0, x1, y1), NaN outside the cells."""
    from scipy.interpolate import griddata
    from scipy.spatial import cKDTree

    x0, y0, x1, y1 = box
    n = RASTER_PX
    w, h = x1 - x0, y1 - y0
    nx, ny = (n, max(2, round(n * h / w))) if w >= h else (max(2, round(n * w / h)), n)
    X, Y = np.meshgrid(np.linspace(x0, x1, nx), np.linspace(y0, y1, ny))
    pts = np.column_stack([X.ravel(), Y.ravel()])
    Z = np.full(len(pts), np.nan)
    if len(xy) >= 3:
        try:
            Z = griddata(xy, v, pts, method="linear")
        except Exception:  # collinear points: Qhull finds no triangle
            pass
    gap = ~np.isfinite(Z)
    if gap.any():
        Z[gap] = griddata(xy, v, pts[gap], method="nearest") if len(xy) > 1 else v[0]
    px, py = cell_pitch_m(xy)
    scale = np.array([1.0 / px, 1.0 / py])
    d, _ = cKDTree(xy * scale).query(pts * scale, p=np.inf)
    Z[d > 0.5 + 1e-6] = np.nan  # outside every cell: not in the calculation area
    return X, Y, Z.reshape(X.shape)


def plan_box(xy: np.ndarray) -> tuple[float, float, float, float]:
    """The drawn area: the zone's cells and a margin, metres."""
    px, py = cell_pitch_m(xy)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    return (lo[0] - px / 2 - MARGIN_M, lo[1] - py / 2 - MARGIN_M, hi[0] + px / 2 + MARGIN_M, hi[1] + py / 2 + MARGIN_M)


def room_box(xy: np.ndarray, plan=None, region=None) -> tuple[float, float, float, float]:
    """The drawn area: the zone's cells with a margin, grown to the room's walls within the zone's ``region``
    (x0, y0, x1, y1) so that the walls and windows beside the zone show, metres."""
    box = plan_box(xy)
    if plan is None or not plan.walls:
        return box
    pts = np.concatenate([np.asarray(w).reshape(-1, 2) for w in plan.walls])
    lo, hi = pts.min(axis=0) - 0.15, pts.max(axis=0) + 0.15
    if region is not None:
        lo = np.maximum(lo, np.asarray(region[:2]) - 0.15)
        hi = np.minimum(hi, np.asarray(region[2:]) + 0.15)
    return (min(box[0], lo[0]), min(box[1], lo[1]), max(box[2], hi[0]), max(box[3], hi[1]))


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


def draw_false_colour(ax, xy: np.ndarray, v: np.ndarray, scale: Scale, plan=None, chosen_xy=(), dropped_xy=(),
                      font_pt: float = FONT_PT, box=None):  # fmt: skip
    """Draw one plan on ``ax``; returns the filled contour set (for a colour bar).

    Parameters
    ----------
    xy : ndarray, shape (N, 2)
        Sensor positions on the plan, metres.
    v : ndarray, shape (N,)
        Their readings.
    scale : Scale
    plan : simulator.study.report.outline.Plan or None
    chosen_xy, dropped_xy : sequence of (x, y)
        Chosen sensors (red ×) and points dropped inside furniture (grey +).
    """
    from matplotlib import colormaps
    from matplotlib.colors import BoundaryNorm, LogNorm

    box = plan_box(xy) if box is None else box
    X, Y, Z = _raster(xy, np.asarray(v, float), box)
    levels = plan_levels(scale)
    over = bool(np.nanmax(Z) > levels[-1] * (1 + 1e-9)) if np.isfinite(Z).any() else False
    cmap = colormaps["viridis"].with_extremes(over=OVER_RGB)
    extend = "max" if over else "neither"
    if scale.log:
        Z = np.where(Z > 0, np.maximum(Z, levels[0]), np.nan)
        norm = LogNorm(levels[0], levels[-1])
    else:
        Z = np.maximum(Z, levels[0])
        norm = BoundaryNorm(levels, cmap.N, extend=extend)
    if not over:
        Z = np.minimum(Z, levels[-1])
    cf = ax.contourf(X, Y, Z, levels=levels, cmap=cmap, norm=norm, extend=extend)
    iso = levels[1:-1:2] if len(levels) > 6 else levels[1:-1]
    if len(iso) and np.isfinite(Z).any() and np.nanmax(Z) > np.nanmin(Z):
        cs = ax.contour(X, Y, Z, levels=iso, colors="k", linewidths=0.6, alpha=0.8)
        ax.clabel(cs, fmt=lambda t: plain(t), fontsize=font_pt - 2, inline_spacing=2)
    draw_plan(ax, plan)
    if len(dropped_xy):
        d = np.asarray(dropped_xy)
        ax.plot(d[:, 0], d[:, 1], "+", color="0.45", markersize=5, mew=1)
    for p in chosen_xy:
        ax.plot(p[0], p[1], marker="x", color="red", markersize=8, mew=2)
    ax.set_xlim(box[0], box[2])
    ax.set_ylim(box[1], box[3])
    ax.set_aspect("equal")
    ax.tick_params(labelsize=font_pt - 1)
    ax.set_xlabel("x (m)", fontsize=font_pt - 1)
    ax.set_ylabel("y (m)", fontsize=font_pt - 1)
    return cf


def colour_bar(fig, cf, ax, label: str, font_pt: float = FONT_PT, cax=None):
    """A colour bar of ``cf`` labelled ``label`` (with its unit), ticks at the band edges in plain numbers."""
    cb = fig.colorbar(cf, ax=None if cax is not None else ax, cax=cax, fraction=0.05, pad=0.03)
    ticks = cf.levels if len(cf.levels) <= 11 else cf.levels[::2]
    cb.set_ticks(ticks)
    cb.set_ticklabels([plain(t) for t in ticks])
    cb.ax.tick_params(labelsize=font_pt - 1)
    cb.set_label(label, fontsize=font_pt)
    return cb


def plan_png(xy, v, scale: Scale, bar_label: str, title: str = "", plan=None, chosen_xy=(), dropped_xy=(),
             region=None) -> bytes:  # fmt: skip
    """PNG bytes of one false-colour plan at 110 dpi: the map :data:`MAP_H_IN` high (its width from the drawn
    area's aspect), the colour bar beside it; a fixed layout (no tight-layout pass: half the drawing time)."""
    from matplotlib.figure import Figure

    xy = np.asarray(xy, float)
    box = room_box(xy, plan, region)
    x0, y0, x1, y1 = box
    map_h = MAP_H_IN
    map_w = min(max(map_h * (x1 - x0) / (y1 - y0), 1.6), 2.2 * map_h)
    map_h = map_w * (y1 - y0) / (x1 - x0)  # equal aspect: the box decides
    left, bottom, top, right = 0.62, 0.5, 0.42 if title else 0.15, 1.45
    w_in, h_in = left + map_w + right, bottom + map_h + top
    fig = Figure(figsize=(w_in, h_in), dpi=110)
    ax = fig.add_axes((left / w_in, bottom / h_in, map_w / w_in, map_h / h_in))
    cax = fig.add_axes(((left + map_w + 0.15) / w_in, bottom / h_in, 0.14 / w_in, map_h / h_in))
    cf = draw_false_colour(ax, xy, v, scale, plan, chosen_xy, dropped_xy, box=box)
    colour_bar(fig, cf, ax, bar_label, cax=cax)
    if title:
        ax.set_title(title, fontsize=FONT_PT)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", metadata={"Software": None})
    return buf.getvalue()


def tile_pngs(pngs: list[bytes], columns: int = 3, title: str = "") -> bytes:
    """The plans side by side, ``columns`` a row, on white (one file of a zone's plans), with a title line."""
    from PIL import Image, ImageDraw, ImageFont

    from simulator.io.map_png import png_bytes

    ims = [Image.open(io.BytesIO(b)).convert("RGB") for b in pngs]
    cw, ch = max(i.width for i in ims), max(i.height for i in ims)
    head = 34 if title else 0
    rows = math.ceil(len(ims) / columns)
    sheet = Image.new("RGB", (cw * min(columns, len(ims)), head + ch * rows), "white")
    for k, im in enumerate(ims):
        sheet.paste(im, ((k % columns) * cw, head + (k // columns) * ch))
    if title:
        ImageDraw.Draw(sheet).text((10, 8), title, fill=(0, 0, 0), font=ImageFont.load_default(size=18))
    return png_bytes(np.asarray(sheet), level=6)
