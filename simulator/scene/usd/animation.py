"""Animated stages: which prims the reading depends on that change with time.

A stage is read at one USD time code: the config's ``time`` (``--time``),
or, when none is given, ``Usd.TimeCode.EarliestTime()``, which reads every
attribute at *its own* first time sample. For a stage that animates
nothing the two are the same; for one whose lights or geometry move the
reading is of a frame nobody chose, so the summary line names the animated
prims and asks for a time.

A prim counts as animated when one of its authored attributes might vary
in time (``ValueMightBeTimeVarying``: points, sizes, light inputs, its own
xformOps) or the transform of an ancestor might
(``UsdGeom.Xformable.TransformMightBeTimeVarying``). Skinned meshes are
animated through their skeleton's animation (:mod:`.skinning`).
"""

from __future__ import annotations

from pxr import Usd, UsdGeom

from simulator.scene.usd.context import _Context

__all__ = ["note_animated"]


def note_animated(ctx: _Context, prim: Usd.Prim) -> None:
    """Add ``prim`` to ``ctx.animated`` when its reading changes with time (only when no time was given:
    with one, every prim is read at that time and there is nothing to warn about)."""
    if ctx.time_given:
        return
    if any(a.ValueMightBeTimeVarying() for a in prim.GetAuthoredAttributes()) or _moving_ancestor(ctx, prim):
        ctx.animated[str(prim.GetPath())] = None


def _moving_ancestor(ctx: _Context, prim: Usd.Prim) -> bool:
    """True when the transform of a parent (or its parents) might vary in time; memoised by path."""
    parent = prim.GetParent()
    if not parent or parent.IsPseudoRoot():
        return False
    key = str(parent.GetPath())
    if key not in ctx.moving:
        xf = UsdGeom.Xformable(parent)
        try:
            varying = bool(xf and xf.TransformMightBeTimeVarying())
        except Exception:  # a bad xformOpOrder: the transform itself is refused, naming the prim, when read
            varying = False
        ctx.moving[key] = varying or _moving_ancestor(ctx, parent)
    return ctx.moving[key]
