"""Curved surfaces whose reflection is still read from flat facets: the warning that says so.

Every gprim is traced as the triangles it is tessellated into. Glossy and
mirror faces of a curved prim (an implicit Sphere, Cylinder, Cone or
Capsule, a Mesh with authored normals, a subdivision cage) reflect about
its shading normals (:mod:`.normals`, :mod:`simulator.kernels.glossy`), so
a chrome ball shows a light's reflection where the ball would. Panes and
translucent layers do not: their slab reflects and passes light about the
facet's own normal (a thin slab, :mod:`simulator.kernels.surfaces`), so a
curved glass prim's reflection of a small light or the sun is spread over
its facets as on a faceted gem. Such a prim is named in the summary rather
than read silently.
"""

from __future__ import annotations

import numpy as np


def faceted_reflectors(geometry) -> list[str]:
    """The paths of curved prims (faces with shading normals) whose faces are panes or translucent layers."""
    g = geometry
    if g.surface_id is None or not g.surfaces or g.shading_normals is None:
        return []
    pane = np.array([bool(getattr(s, "pane", False)) for s in g.surfaces] + [False], bool)[g.surface_id]
    curved = np.any(g.shading_normals != 0, axis=(1, 2))
    prims = np.unique(g.prim[pane & curved])
    return [g.prim_names[int(i)] for i in prims]


def faceted_note(names: list[str]) -> str:
    """The summary line for :func:`faceted_reflectors`' prims."""
    shown = ", ".join(names[:3]) + (" ..." if len(names) > 3 else "")
    return (f"curved glass or translucent surface(s) {shown} reflect and pass light about their flat facets' "
            "normals (smooth normals shade glossy and mirror faces only): their reflections of small lights and "
            "the sun are spread over the facets; model such glass flat where its reflection matters")
