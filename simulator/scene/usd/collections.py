"""USD collections (``UsdCollectionAPI``) resolved to the lights they hold.

Every collection authored on the stage, named ``<prim path>.collection:<name>``
(the form ``Usd.CollectionAPI.GetCollectionPath`` gives), is resolved with its
membership query: ``includes`` and ``excludes`` (a path excluded below an
included one is out, and in again if included below that), ``includeRoot``,
included collections, and the ``expansionRule`` (``expandPrims`` and
``expandPrimsAndProperties`` take the descendants of an included path,
``explicitOnly`` only the paths named). A light belongs to a collection when
its prim path is included. UsdLux's linking collections (``lightLink``,
``shadowLink`` of every light, ``filterLink`` of a light filter) select the
geometry a light or filter acts on, not lights, and are left out. A study's light group can name a collection
instead of prim patterns (:func:`simulator.study.inputs.scenarios.resolve_groups`).

References
----------
OpenUSD API, ``UsdCollectionAPI`` and ``UsdCollectionMembershipQuery``.
"""

from __future__ import annotations

from pxr import Sdf, Usd

from simulator.scene.model import Light

__all__ = ["light_collections", "LINKING_COLLECTIONS"]

#: UsdLux's built-in linking collections (what a light shines on or shadows, not a set of lights)
LINKING_COLLECTIONS = frozenset({"lightLink", "shadowLink", "filterLink"})


def light_collections(stage: Usd.Stage, lights: list[Light]) -> dict[str, tuple[str, ...]]:
    """Every collection on ``stage`` → the names (prim paths) of the ``lights`` it includes, in light order.

    Collections on inactive or abstract prims are not read; a collection that holds no
    light maps to an empty tuple (so that a study can say so).
    """
    paths = []
    for l in lights:
        paths.append(Sdf.Path(l.name) if Sdf.Path.IsValidPathString(l.name) else None)
    out: dict[str, tuple[str, ...]] = {}
    for prim in stage.Traverse():
        for coll in Usd.CollectionAPI.GetAllCollections(prim):
            if coll.GetName() in LINKING_COLLECTIONS:
                continue
            query = coll.ComputeMembershipQuery()
            members = tuple(l.name for l, p in zip(lights, paths) if p is not None and query.IsPathIncluded(p))
            out[str(coll.GetCollectionPath())] = members
    return out
