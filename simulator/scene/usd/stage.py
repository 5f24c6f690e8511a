"""Opening a stage and walking it: options, files, variants, the world frame, traversal.

Everything here happens before (or around) reading a prim: bad options and
files that are missing or not USD become one-line ``UserError`` messages,
variant selections go into the in-memory override layer, ``metersPerUnit`` and
``upAxis`` become the stage -> world map of the reading context, and the
traversal decides which prims are seen at all.
"""

from __future__ import annotations

import contextlib
import math
import re
from collections.abc import Iterator

import numpy as np
from pxr import Sdf, Tf, Usd, UsdGeom

from simulator.errors import UserError, require_file
from simulator.units import SPECTRA
from simulator.scene.usd.context import _Context

# (x, y, z)_Yup -> (x, -z, y)_Zup: +90 degrees about X.
_Y_UP_TO_Z_UP = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


def _check_options(path, light_units: str, spectrum, time: float | None = None) -> None:
    """Reject bad ``light_units`` / ``radiometric_spectrum`` / ``time`` before opening anything."""
    if time is not None and not (isinstance(time, (int, float)) and not isinstance(time, bool) and math.isfinite(time)):
        raise UserError(f"{path}: time must be a finite number (a USD time code), not {time!r}")
    if light_units not in ("photometric", "radiometric"):
        raise UserError(f"{path}: light_units must be 'photometric' or 'radiometric', not {light_units!r}")
    if isinstance(spectrum, str):
        if spectrum not in SPECTRA:
            raise UserError(
                f"{path}: radiometric_spectrum must be one of {SPECTRA} or a temperature in K, not {spectrum!r}"
            )
    elif not (isinstance(spectrum, (int, float)) and math.isfinite(spectrum) and spectrum > 0):
        raise UserError(
            f"{path}: radiometric_spectrum temperature must be a positive number of kelvin, not {spectrum!r}"
        )


@contextlib.contextmanager
def _mtlx_references_quiet():
    """Drop USD's own stderr warning for each ``.mtlx`` reference it cannot compose while opening a stage.

    usd-core has no usdMtlx plugin, so every such reference fails and USD prints
    a warning on stderr; the material reader opens those documents itself
    (:mod:`.materialx`), so the warning is noise. Every other diagnostic is
    posted as USD would post it; the composition errors stay on the stage.
    """
    trap_type = getattr(Tf, "DiagnosticTrap", None)  # not in every usd-core release
    if trap_type is None:
        yield
        return
    with trap_type() as trap:
        try:
            yield
        finally:
            trap.EraseMatching(lambda d: ".mtlx" in d.commentary and "Cannot determine file format" in d.commentary)


def _open_stage(path) -> Usd.Stage:
    """Open the stage, turning every pxr failure into a one-line UserError."""
    p = require_file(path)
    try:
        stage = Usd.Stage.Open(str(p))
    except Exception as exc:  # Tf.ErrorException and friends
        raise UserError(f"{path}: not a readable USD stage ({_pxr_reason(exc)})") from None
    if stage is None:
        raise UserError(f"{path}: not a readable USD stage")
    return stage


def _pxr_reason(exc: Exception) -> str:
    """First human part of a pxr error: the quoted text after ``in file ... :``."""
    text = str(exc)
    found = re.findall(r" : '(.*?)'(?:\n|$)", text, flags=re.S)
    reason = found[0] if found else text
    return " ".join(reason.split())[:300] or type(exc).__name__


def _select_variants(stage: Usd.Stage, path: str, variants: dict) -> None:
    """Apply variant selections: ``{set: variant}`` on every prim that has variant set ``set``, and
    ``{"/prim/path": {set: variant}}`` on that prim alone (it wins over a by-set selection there).

    Selections go into the stage's in-memory override layer
    (``GetSessionLayer``), the strongest, so they
    override any selection the file authors, and the file is left unchanged.
    All prims are visited (inactive ones too, since a selection may activate
    them), and the walk repeats until nothing changes, so a variant set (or a
    prim) that appears only inside another set's selected variant is honoured
    as well. Prims inside instance prototypes cannot be edited through their
    instances: author the variant set on the instanceable prim or above it.

    Raises
    ------
    UserError
        ``variants.<set>``: no prim has that variant set (the message lists
        the sets the stage offers), or a prim's set does not offer the
        selection (the message lists the variants it offers);
        ``variants.<prim path>``: no prim at that path, or not a prim path;
        ``variants.<prim path>.<set>``: the prim has no such set (the message
        lists its sets), or the set does not offer the variant.
    """
    if not variants:
        return
    by_set = {k: v for k, v in variants.items() if not k.startswith("/")}
    by_path = {k: v for k, v in variants.items() if k.startswith("/")}
    for key in by_path:
        if not bool(Sdf.Path.IsValidPathString(key)) or not Sdf.Path(key).IsAbsoluteRootOrPrimPath() or key == "/":
            raise UserError(f"{path}: variants.{key}: not a prim path (expected an absolute path such as /World/Car)")
    stage.SetEditTarget(Usd.EditTarget(stage.GetSessionLayer()))
    found: set[str] = set()
    for _ in range(64):  # nesting depth bound: a fixed point comes long before
        changed = False
        # a list first: a selection recomposes the stage under a live iterator
        for prim in list(Usd.PrimRange.Stage(stage, Usd.PrimAllPrimsPredicate)):
            if not prim.IsValid():  # removed by a selection made earlier in this pass
                continue
            sets = prim.GetVariantSets()
            own = by_path.get(str(prim.GetPath()), {})
            for name, choice in {**by_set, **own}.items():
                where = f"variants.{prim.GetPath()}.{name}" if name in own else f"variants.{name}"
                if not sets.HasVariantSet(name):
                    if name in own:
                        offered = ", ".join(sets.GetNames()) or "no variant sets"
                        raise UserError(f"{path}: {where}: {prim.GetPath()} has no variant set {name!r} "
                                        f"(it has: {offered})")
                    continue
                found.add(name)
                vset = sets.GetVariantSet(name)
                offered = vset.GetVariantNames()
                if choice not in offered:
                    raise UserError(f"{path}: {where}: {prim.GetPath()} offers no variant {choice!r} "
                                    f"(its variant set {name!r} offers: {', '.join(offered) or 'nothing'})")
                if vset.GetVariantSelection() != choice:
                    vset.SetVariantSelection(choice)
                    changed = True
        if not changed:
            break
    for key in by_path:
        if not stage.GetPrimAtPath(key):
            raise UserError(f"{path}: variants.{key}: no prim at that path in the stage")
    for name in by_set:
        if name not in found:
            offered = sorted({s for prim in Usd.PrimRange.Stage(stage, Usd.PrimAllPrimsPredicate)
                              for s in prim.GetVariantSets().GetNames()})
            raise UserError(f"{path}: variants.{name}: no prim has a variant set {name!r} "
                            f"(the stage offers: {', '.join(offered) or 'no variant sets'})")


def _world_frame(stage: Usd.Stage, path) -> tuple[float, str]:
    """The stage's ``(metersPerUnit, upAxis)``, checked: a positive number, and ``"Y"`` or ``"Z"``."""
    mpu = float(UsdGeom.GetStageMetersPerUnit(stage))
    up_axis = str(UsdGeom.GetStageUpAxis(stage))
    if not (math.isfinite(mpu) and mpu > 0):
        raise UserError(f"{path}: metersPerUnit must be a positive number, not {mpu}")
    if up_axis not in ("Y", "Z"):
        raise UserError(f"{path}: upAxis must be 'Y' or 'Z', not {up_axis!r}")
    return mpu, up_axis


def _reading_context(path, mpu: float, up_axis: str, light_units: str,
                     radiometric_spectrum: str | float, time: float | None = None) -> _Context:
    """The context every reader shares: stage -> world map, time code, transform cache, spectra.

    Attributes are read at time code ``time``, or at
    ``Usd.TimeCode.EarliestTime()`` (each attribute's first time sample, or
    its default value) when it is None; one ``UsdGeom.XformCache`` at that
    time serves every prim's world transform.
    """
    ctx = _Context(
        path=str(path),
        time=Usd.TimeCode.EarliestTime() if time is None else Usd.TimeCode(float(time)),
        to_world=mpu * (_Y_UP_TO_Z_UP if up_axis == "Y" else np.eye(3)),
        light_units=light_units,
        default_spectrum="D65" if light_units == "photometric" else radiometric_spectrum,
        time_given=time is not None,
    )
    ctx.xforms = UsdGeom.XformCache(ctx.time)
    return ctx


def _collect_composition_errors(stage: Usd.Stage, ctx: _Context) -> None:
    """Unresolved references and the like do not stop the read; say so."""
    try:
        errors = stage.GetCompositionErrors()
    except Exception:  # older USD without the API
        return
    # usd-core has no usdMtlx plugin, so every reference to a .mtlx fails to compose; the
    # material reader opens those documents itself (.materialx), so they are not errors here
    errors = [e for e in errors if not (".mtlx" in str(e) and "Cannot determine file format" in str(e))]
    ctx.composition_errors += [" ".join(str(err).split()) for err in errors]  # counted in the summary line


class _Walk:
    """Every active prim of the stage, instance proxies included (the pseudo-root is not a prim).

    Iterate it; ``PruneChildren()`` skips the subtree of the prim just yielded.
    """

    def __init__(self, stage: Usd.Stage) -> None:
        # The default predicate already drops inactive, undefined, unloaded and
        # abstract (class) prims; TraverseInstanceProxies walks into instances.
        self._it = iter(Usd.PrimRange(stage.GetPseudoRoot(), Usd.TraverseInstanceProxies()))

    def __iter__(self) -> Iterator[Usd.Prim]:
        for prim in self._it:
            if not prim.IsPseudoRoot():
                yield prim

    def PruneChildren(self) -> None:  # noqa: N802  (the pxr name)
        self._it.PruneChildren()


def _traverse(stage: Usd.Stage) -> _Walk:
    """A :class:`_Walk` over the stage."""
    return _Walk(stage)


def _warn_unauthored_units(stage: Usd.Stage, ctx: _Context) -> None:
    """A stage that does not author ``metersPerUnit`` is read in centimetres (UsdGeom's fallback 0.01): say so."""
    if not UsdGeom.StageHasAuthoredMetersPerUnit(stage):
        ctx.warn(f"{ctx.path}: metersPerUnit not authored; read as centimetres (UsdGeom's fallback, 0.01 m "
                 "per unit): author metersPerUnit in the root layer if the stage is in other units")


def _is_rendered(ctx: _Context, prim: Usd.Prim) -> bool:
    """False for invisible prims and guide/proxy purpose (render and default are kept)."""
    img = UsdGeom.Imageable(prim)
    if not img:
        return True
    if img.ComputeVisibility(ctx.time) == UsdGeom.Tokens.invisible:
        return False
    return img.ComputePurpose() not in (UsdGeom.Tokens.guide, UsdGeom.Tokens.proxy)
