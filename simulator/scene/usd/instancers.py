"""UsdGeom.PointInstancer: copies of prototype subtrees where the instances stand.

Each instance ``i`` of an instancer draws the prototype subtree
``prototypes[protoIndices[i]]`` with the world transform (USD row vectors,
``p' = p M``)::

    M(gprim, i) = R(gprim, proto) * T_i * M_instancer

where ``T_i`` is ``UsdGeomPointInstancer.ComputeInstanceTransformsAtTime``
with the prototype root's own transform included (``scales``,
``orientations`` (quath), ``positions`` and the prototype's xform, in the
order the schema states), ``R(gprim, proto)`` the gprim's transform relative
to its prototype root (``UsdGeom.XformCache.ComputeRelativeTransform``), and
``M_instancer`` the instancer's local-to-world transform. Instances hidden by
``invisibleIds`` or deactivated (``inactiveIds``) are left out
(``ComputeMaskAtTime``).

A prototype is drawn only where instances place it, never in its own place:
the stage traversal does not descend into a PointInstancer (prototypes are
usually its children, often under a ``Scope`` or in an ``over``, which the
traversal would skip anyway). A prototype defined elsewhere in the stage is
still drawn where it stands, as Hydra draws it. A PointInstancer inside a
prototype (nested instancing) is read the same way for every placement of
its parent instance. Inside a prototype, prims whose own visibility is
``invisible`` or whose purpose is ``guide``/``proxy`` (up to the prototype
root) are skipped; UsdLux lights and sensors inside prototypes are not read
(counted in the summary warning).

References
----------
OpenUSD, ``UsdGeomPointInstancer`` class documentation ("Instance transforms",
"Varying instance identity", "Prototypes ... should be defined beneath the
PointInstancer").
"""

from __future__ import annotations

import numpy as np
from pxr import Usd, UsdGeom, UsdLux, UsdSkel

from simulator.scene.usd.context import _Context
from simulator.scene.usd.geometry import _add_placed, _GeometryBuilder, _gprim_part

# nesting depth beyond which an instancer is taken to instance itself
_MAX_NESTING = 32


def _read_instancer(ctx: _Context, prim: Usd.Prim, geo: _GeometryBuilder,
                    placements: np.ndarray | None = None, depth: int = 0) -> None:
    """Add every instance of a PointInstancer's prototypes to ``geo``.

    Parameters
    ----------
    placements : ndarray, shape (N, 4, 4), optional
        Local-to-world matrices (USD row-vector convention, stage units) of
        the instancer itself, one per placement of an enclosing instance;
        default: its own local-to-world transform.
    """
    if depth > _MAX_NESTING:
        raise ctx.error(prim, f"PointInstancers nested more than {_MAX_NESTING} deep (an instancer instancing itself?)")
    if placements is None:
        placements = np.array(ctx.xforms.GetLocalToWorldTransform(prim), float)[None]
    inst = UsdGeom.PointInstancer(prim)
    protos = inst.GetPrototypesRel().GetForwardedTargets()
    indices = np.asarray(inst.GetProtoIndicesAttr().Get(ctx.time) or [], np.int64)
    if len(indices) == 0:
        return
    if indices.min() < 0 or indices.max() >= len(protos):
        raise ctx.error(prim, f"protoIndices out of range for {len(protos)} prototype(s)")
    xforms = inst.ComputeInstanceTransformsAtTime(ctx.time, ctx.time, UsdGeom.PointInstancer.IncludeProtoXform,
                                                  UsdGeom.PointInstancer.IgnoreMask)
    if len(xforms) != len(indices):
        raise ctx.error(prim, f"{len(indices)} protoIndices but {len(xforms)} instance transforms "
                              "(positions, orientations and scales must match protoIndices in length)")
    t_inst = np.array([np.array(m, float) for m in xforms]).reshape(-1, 4, 4)
    mask = np.asarray(inst.ComputeMaskAtTime(ctx.time) or [True] * len(indices), bool)
    if not np.all(np.isfinite(t_inst[mask])):
        raise ctx.error(prim, "instance transforms contain NaN or Inf")
    stage = prim.GetStage()
    for k, path in enumerate(protos):
        chosen = np.flatnonzero((indices == k) & mask)
        proto = stage.GetPrimAtPath(path)
        if len(chosen) == 0:
            continue
        if not proto:
            raise ctx.error(prim, f"prototype {path} does not exist")
        # every placement of the instancer times every instance of this prototype: (N * n, 4, 4)
        world = np.matmul(t_inst[chosen][None], placements[:, None]).reshape(-1, 4, 4)
        _read_prototype(ctx, prim, proto, world, geo, depth)


def _read_prototype(ctx: _Context, instancer: Usd.Prim, proto: Usd.Prim, world: np.ndarray,
                    geo: _GeometryBuilder, depth: int) -> None:
    """Add the gprims of one prototype subtree at ``world`` (N, 4, 4): each instance's proto-root-to-world."""
    predicate = Usd.TraverseInstanceProxies(Usd.PrimIsActive & Usd.PrimIsLoaded)
    it = iter(Usd.PrimRange(proto, predicate))
    for prim in it:
        if not _shown_in_prototype(ctx, prim, proto):
            it.PruneChildren()
            continue
        rel = _relative(ctx, prim, proto)
        if prim.IsA(UsdGeom.PointInstancer):
            it.PruneChildren()
            _read_instancer(ctx, prim, geo, np.matmul(rel[None], world), depth + 1)
        elif prim.IsA(UsdGeom.Gprim):
            part = _gprim_part(ctx, prim)
            if prim.HasAPI(UsdSkel.BindingAPI) and part is not None:  # not posed (skinning places one prim)
                ctx.ignored["UsdSkel skinning in PointInstancer prototypes (read unposed)"] += 1
            if part is not None:
                m = np.matmul(rel[None], world)  # (N, 4, 4) row-vector gprim-to-world
                a = np.einsum("ij,njk->nik", ctx.to_world, m[:, :3, :3].transpose(0, 2, 1))
                t = m[:, 3, :3] @ ctx.to_world.T
                _add_placed(ctx, prim, part, a, t, geo, f"{instancer.GetPath()}[{len(m)} x {prim.GetPath()}]")
        elif prim.HasAPI(UsdLux.LightAPI):
            ctx.not_read["UsdLux light(s) in PointInstancer prototypes"] += 1
        if prim.HasAttribute("probesim:sensor:kind"):
            ctx.not_read["sensor(s) in PointInstancer prototypes"] += 1


def _shown_in_prototype(ctx: _Context, prim: Usd.Prim, proto: Usd.Prim) -> bool:
    """False when ``prim`` itself is invisible or guide/proxy purpose (its ancestors up to ``proto`` were checked)."""
    img = UsdGeom.Imageable(prim)
    if not img:
        return True
    if img.GetVisibilityAttr().Get(ctx.time) == UsdGeom.Tokens.invisible:
        return False
    return img.GetPurposeAttr().Get() not in (UsdGeom.Tokens.guide, UsdGeom.Tokens.proxy)


def _relative(ctx: _Context, prim: Usd.Prim, proto: Usd.Prim) -> np.ndarray:
    """(4, 4) transform of ``prim`` relative to its prototype root (identity for the root itself)."""
    if prim == proto:
        return np.eye(4)
    m, _ = ctx.xforms.ComputeRelativeTransform(prim, proto)
    m = np.array(m, float)
    if not np.all(np.isfinite(m)):
        raise ctx.error(prim, "transform contains NaN or Inf")
    return m
