"""A plan of the room around a zone: walls, window openings and furniture, projected onto the zone's plane.

The heat maps draw it under the readings so a reader sees where the values
lie. Only horizontal zones (candidates on a floor or a desk, normal ±z) get
a plan; the plan is in world x and y, metres.

Notes
-----
Walls: the section of the stage at the *cut height* ``h + CUT_ABOVE_M``
(1.3 m for a 0.8 m work plane, about where plan drawings cut a room, through
the windows): each triangle crossing the plane z = z_c leaves a segment
(the two points where its edges cross it). Window openings: the boundary of
the zone's floor prim (its triangles projected and merged) where no section
segment lies within ``GAP_TOL_M``: a stretch of room edge with no wall at the
cut height lets the sky in. Furniture: every prim other than the floor prim
and the walls (prims whose section touches the floor's boundary) that has
triangles inside the band ``[h − BAND_BELOW_M, h + BAND_ABOVE_M]``, drawn as
the union of those triangles' footprints (a desk's top, a cabinet's box).
Points dropped inside furniture (``drop_inside``) are marked by the caller.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["Plan", "plan_of_zone", "CUT_ABOVE_M", "BAND_BELOW_M", "BAND_ABOVE_M", "GAP_TOL_M"]

#: the wall section's height above the zone's plane, metres
CUT_ABOVE_M = 0.5
#: the furniture band below and above the zone's plane, metres
BAND_BELOW_M = 0.5
BAND_ABOVE_M = 1.0
#: a stretch of the room's edge farther than this from every wall segment is an opening, metres
GAP_TOL_M = 0.05
#: an opening shorter than this is a joint between walls, not a window, metres
MIN_OPENING_M = 0.1


@dataclass
class Plan:
    """Line work of one plan, world x/y in metres.

    Attributes
    ----------
    walls : list of ndarray (2, 2)
        Section segments at the cut height.
    openings : list of ndarray (K, 2)
        Polylines along the room's edge with no wall at the cut height (windows, doors).
    furniture : list of ndarray (K, 2)
        Closed outlines of furniture footprints.
    """

    walls: list = field(default_factory=list)
    openings: list = field(default_factory=list)
    furniture: list = field(default_factory=list)


def _section(tri: np.ndarray, z: float) -> np.ndarray:
    """Segments (M, 2, 2) where triangles (T, 3, 3) cross the plane at height ``z``."""
    d = tri[:, :, 2] - z
    out = []
    for t, dz in zip(tri, d):
        pts = []
        for a, b in ((0, 1), (1, 2), (2, 0)):
            if (dz[a] < 0) != (dz[b] < 0):
                s = dz[a] / (dz[a] - dz[b])
                pts.append(t[a, :2] + s * (t[b, :2] - t[a, :2]))
        if len(pts) == 2 and np.linalg.norm(pts[0] - pts[1]) > 1e-9:
            out.append(pts)
    return np.array(out).reshape(-1, 2, 2)


def _lines(geom) -> list[np.ndarray]:
    """Coordinates of a shapely (multi)line or polygon boundary as arrays."""
    if geom.is_empty:
        return []
    if hasattr(geom, "geoms"):
        return [a for g in geom.geoms for a in _lines(g)]
    if geom.geom_type == "Polygon":
        return [np.asarray(geom.exterior.coords)] + [np.asarray(r.coords) for r in geom.interiors]
    return [np.asarray(geom.coords)]


def plan_of_zone(scene, floor_prims: list[str], height_m: float) -> Plan | None:
    """The plan of the room around a horizontal zone whose candidates lie at ``height_m`` (world z).

    Parameters
    ----------
    scene : Scene
    floor_prims : list of str
        The prims the zone's candidates were gridded on (their merged footprint is the room's edge).
    height_m : float
        The zone's plane, world z in metres.

    Returns
    -------
    Plan or None
        None when the floor prims are not in the stage or shapely is missing.
    """
    try:
        from shapely.geometry import LineString, MultiLineString, Polygon
        from shapely.ops import unary_union
    except ImportError:
        return None
    g = scene.geometry
    names = {n: i for i, n in enumerate(g.prim_names)}
    fids = [names[p] for p in floor_prims if p in names]
    if not fids:
        return None
    tri_all = g.points[g.triangles]  # (T, 3, 3)
    floor_mask = np.isin(g.prim, fids)
    floor = unary_union([Polygon(t[:, :2]).buffer(1e-6) for t in tri_all[floor_mask] if Polygon(t[:, :2]).area > 1e-12])
    if floor.is_empty:
        return None
    edge = floor.boundary
    plan = Plan()
    z_cut = height_m + CUT_ABOVE_M
    # walls: the prims whose section touches the room's edge
    wall_prims: set[int] = set()
    seg_list = []
    crossing = [i for i, t in enumerate(tri_all) if not floor_mask[i] and (t[:, 2] - z_cut < 0).any() and (t[:, 2] - z_cut >= 0).any()]
    for i in crossing:
        s = _section(tri_all[i : i + 1], z_cut)
        if not len(s):
            continue
        line = LineString(s[0])
        if line.distance(edge) <= GAP_TOL_M:
            wall_prims.add(int(g.prim[i]))
            seg_list.append(s[0])
    plan.walls = seg_list
    if seg_list:
        walls = MultiLineString([s.tolist() for s in seg_list]).buffer(GAP_TOL_M)
        gaps = edge.difference(walls)
        plan.openings = [a for a in _lines(gaps) if LineString(a).length >= MIN_OPENING_M]
    else:
        plan.openings = [a for a in _lines(edge)]
    lo, hi = height_m - BAND_BELOW_M, height_m + BAND_ABOVE_M
    polys: dict[int, list] = {}
    for i, t in enumerate(tri_all):
        pid = int(g.prim[i])
        if floor_mask[i] or pid in wall_prims:
            continue
        if t[:, 2].max() < lo or t[:, 2].min() > hi:
            continue
        p = Polygon(t[:, :2])
        if p.area > 1e-8:
            polys.setdefault(pid, []).append(p.buffer(1e-6))
    for pid in sorted(polys):
        plan.furniture += _lines(unary_union(polys[pid]))
    return plan
