"""A zone's false-colour plans (PNG) with the room's plan: the study's heatmap files, report.html and its annual section."""

from __future__ import annotations

import numpy as np

__all__ = ["MAX_PANELS", "heat_map_png", "zone_plan_pngs", "zone_scales", "scale_mode", "zone_plan", "dropped_in_zone"]

#: most scenario panels in one zone's heat map
MAX_PANELS = 16


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


def scale_mode(res) -> str:
    """``[output] heat_map_scale``: ``shared`` (default), ``per_scenario`` or ``log``."""
    return getattr(res.study.output, "heat_map_scale", "shared")


def zone_scales(res, zone: str, scenarios) -> list:
    """The colour scale of each scenario's plan of ``zone``: one shared linear scale (``shared``), each its
    own from 0 to its largest reading (``per_scenario``), or one shared log scale (``log``).

    The shared scale runs from 0 to the *median* of the scenarios' largest readings, so that one sunlit
    scenario at 30,000 lx does not paint the evening ones a single colour; readings above it are drawn in the
    over-range colour (:data:`simulator.study.report.plan_maps.OVER_RGB`, the colour bar's arrow)."""
    from simulator.study.report.plan_maps import Scale

    ch = 1 if res.study.light_units == "photometric" else 0
    ids = res.zones[zone]
    vals = res.mean[: len(scenarios), ids, ch]
    mode = scale_mode(res)
    top = float(vals.max()) if vals.size and vals.max() > 0 else 1.0
    if mode == "per_scenario":
        return [Scale(min(0.0, float(v.min())), float(v.max()) if v.max() > 0 else 1.0) for v in vals]
    if mode == "log":
        pos = vals[vals > 0]
        lo = float(pos.min()) if pos.size else top / 10
        return [Scale(lo, top if top > lo else lo * 10, log=True)] * len(scenarios)
    tops = vals.max(axis=1) if vals.size else np.ones(1)
    mid = float(np.median(tops))
    return [Scale(min(0.0, float(vals.min())), mid if mid > 0 else top)] * len(scenarios)


def _marks(res, zone: str, xy: np.ndarray):
    """Chosen sensors near the zone (x, y) and the points dropped inside furniture within it."""
    chosen = [] if res.placement is None else res.placement.chosen
    index = {c.sensor.name: c for c in res.candidates}
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    marks = [index[n].position[:2] for n in chosen
             if lo[0] - 1 <= index[n].position[0] <= hi[0] + 1 and lo[1] - 1 <= index[n].position[1] <= hi[1] + 1]  # fmt: skip
    return marks, dropped_in_zone(res, zone)[:, :2]


def zone_plan_pngs(res, zone: str) -> list[bytes]:
    """One false-colour plan (PNG) of ``zone`` per scenario (up to :data:`MAX_PANELS`), in scenario order,
    on the scales of :func:`zone_scales`."""
    from simulator.study.report.plan_maps import plan_png

    ch = 1 if res.study.light_units == "photometric" else 0
    ids = res.zones[zone]
    xy = np.array([res.candidates[i].position[:2] for i in ids])
    scen = res.scenarios[:MAX_PANELS]
    scales = zone_scales(res, zone, scen)
    plan = zone_plan(res, zone)
    chosen, dropped = _marks(res, zone, xy)
    label = "illuminance E (lx)" if ch == 1 else "irradiance E (W/m²)"
    region = next(z.region for z in res.study.zone if z.name == zone)
    return [plan_png(xy, res.mean[k, ids, ch], scales[k], label, sc.name, plan, chosen, dropped, region) for k, sc in enumerate(scen)]


def heat_map_png(res, zone: str, pngs: list[bytes] | None = None) -> bytes:
    """PNG of one zone's false-colour plans (:func:`zone_plan_pngs`, or ``pngs`` already drawn), three a row.

    Each plan is :func:`simulator.study.report.plan_maps.plan_png`: the readings
    interpolated inside the grid's cells, round bands and labelled
    isolines, the room's walls (dark grey), openings (blue) and furniture
    (brown) of :func:`zone_plan`, the chosen sensors (red ×) and the points
    dropped inside furniture (grey +). The scale (``[output] heat_map_scale``)
    is one for all plans of the zone (``"shared"``, the default: scenarios
    compare at a glance), each plan's own (``"per_scenario"``: an evening at
    50 lx and a sunny afternoon at 5,000 lx both show their pattern) or one
    logarithmic scale (``"log"``)."""
    from simulator.study.report.plan_maps import tile_pngs

    pngs = zone_plan_pngs(res, zone) if pngs is None else pngs
    more = f" (first {MAX_PANELS} of {len(res.scenarios)} scenarios)" if len(res.scenarios) > MAX_PANELS else ""
    scale = {"shared": "one scale for all plans", "log": "one log scale for all plans"}.get(scale_mode(res), "each plan its own scale")
    return tile_pngs(pngs, 3, f"zone {zone}{more}: {scale}")
