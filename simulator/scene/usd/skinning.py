"""Skinned meshes (UsdSkel) posed at the run's time code.

A gprim bound to a ``Skeleton`` under a ``SkelRoot`` (``SkelBindingAPI``:
``skel:skeleton``, ``primvars:skel:jointIndices`` / ``jointWeights``,
``primvars:skel:geomBindTransform``) is drawn where the skeleton puts it,
not at its authored (bind-pose) points. pxr's own UsdSkel does the
skinning: ``UsdSkel.Cache`` resolves the bindings of each ``SkelRoot``,
``SkeletonQuery.ComputeSkinningTransforms(t)`` gives each joint's skinning
transform ``inverse(bind) * world(t)`` in skeleton space, and
``SkinningQuery.ComputeSkinnedPoints`` blends them per point by the
authored weights with the prim's ``skel:skinningMethod`` (linear blend:
``p' = sum_j w_j · p · geomBind · S_j``, or dual quaternion). The posed
points are in skeleton space, so the world map that places them is the
``Skeleton`` prim's, not the mesh's own transform (UsdSkel: a skinned
prim's transform is replaced by its skeleton's). A rigidly deformed prim
(constant joint influences, any gprim) moves by
``SkinningQuery.ComputeSkinnedTransform`` instead.

Not read, and counted in the summary line: blend shapes (the prim is skinned
without them), and joint influences with no skeleton to pose them (no
``SkelRoot`` above, or no ``skel:skeleton`` binding): those prims are read
in their authored points.
"""

from __future__ import annotations

import numpy as np
from pxr import Usd, UsdGeom, UsdSkel

from simulator.scene.usd.context import _Context
from simulator.scene.usd.transforms import _world_affine

__all__ = ["posed_points"]


def posed_points(ctx: _Context, prim: Usd.Prim, local: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """``(points, a, t)`` of a skinned gprim at ``ctx.time``: its posed points (P, 3) in skeleton space
    (stage units) and the skeleton's world map ``p -> a @ p + t``; None when the prim is not skinned.

    Parameters
    ----------
    local : ndarray, shape (P, 3)
        The prim's own points as tessellated (a Mesh's authored points, or
        a Cube's / Sphere's tessellation for a rigidly bound one).
    """
    if not prim.HasAPI(UsdSkel.BindingAPI):
        return None
    found = _binding(ctx, prim)
    if found is None:
        if UsdSkel.BindingAPI(prim).GetJointIndicesPrimvar().HasAuthoredValue():
            ctx.ignored["skinning with no skeleton bound (UsdSkel: read in its authored points)"] += 1
        return None
    skel_query, skinning, skel_prim = found
    if skinning.HasBlendShapes():
        ctx.ignored["UsdSkel blend shapes (skinned without them)"] += 1
    xforms = skel_query.ComputeSkinningTransforms(ctx.time)
    if not ctx.time_given and (skinning.GetTimeSamples() or _animated(skel_query)):
        ctx.animated[str(prim.GetPath())] = None
    if prim.IsA(UsdGeom.Mesh) and not skinning.IsRigidlyDeformed():
        points = UsdGeom.Mesh(prim).GetPointsAttr().Get(ctx.time)
        if points is None or len(points) != len(local) or not skinning.ComputeSkinnedPoints(xforms, points, ctx.time):
            raise ctx.error(prim, "UsdSkel could not skin its points (joint influences do not match the points)")
        posed = np.asarray(points, dtype=float).reshape(-1, 3)
    else:
        m = np.array(skinning.ComputeSkinnedTransform(xforms, ctx.time), dtype=float)  # row vectors: p' = p M
        posed = local @ m[:3, :3] + m[3, :3]
    if not np.all(np.isfinite(posed)):
        raise ctx.error(prim, "skinned points contain NaN or Inf")
    a, t = _world_affine(ctx, skel_prim)
    return posed, a, t


def _animated(skel_query) -> bool:
    anim = skel_query.GetAnimQuery()
    return bool(anim) and anim.JointTransformsMightBeTimeVarying()


def _binding(ctx: _Context, prim: Usd.Prim):
    """``(SkeletonQuery, SkinningQuery, Skeleton prim)`` of a skinning target, None when it is not one.

    The bindings of a ``SkelRoot`` are resolved once, on the first of its prims asked about.
    """
    root = UsdSkel.Root.Find(prim)
    if not root:
        return None
    key = str(root.GetPrim().GetPath())
    if key not in ctx.skel_roots:
        if ctx.skel_cache is None:
            ctx.skel_cache = UsdSkel.Cache()
        cache, predicate = ctx.skel_cache, Usd.TraverseInstanceProxies()
        cache.Populate(root, predicate)
        targets = {}
        for binding in cache.ComputeSkelBindings(root, predicate):
            skel = binding.GetSkeleton()
            query = cache.GetSkelQuery(skel)
            for skinning in binding.GetSkinningTargets():
                targets[str(skinning.GetPrim().GetPath())] = (query, skinning, skel.GetPrim())
        ctx.skel_roots[key] = targets
    return ctx.skel_roots[key].get(str(prim.GetPath()))
