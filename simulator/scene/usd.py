"""Read a USD stage into a :class:`~simulator.scene.model.Scene`.

This is the only module in probesim that imports ``pxr``. It turns a stage
into numpy arrays and small records in the *probesim world frame* (metres,
right-handed, Z up), so nothing downstream needs to know about USD.

What is read
------------
Geometry
    ``UsdGeom.Mesh`` (any polygon counts), ``UsdGeom.Cube`` and
    ``UsdGeom.Sphere``, merged into one triangle soup. Faces are wound so that
    ``cross(p1 - p0, p2 - p0)`` is the front face in world space: a
    ``leftHanded`` prim is re-wound, and so is a prim whose world transform
    has a negative determinant (a mirror swaps handedness); both together
    cancel. Other gprims (Cylinder, Cone, Capsule, Plane, curves, points,
    volumes) are skipped with a warning.
    A Sphere becomes a UV sphere of :data:`SPHERE_SEGMENTS` (longitude
    segments, latitude rings), vertices on the surface, so its facets lie
    inside it by up to about r·((pi/n_lon)^2 + (pi/(2 n_lat))^2)/2: 0.24% of
    r at 64 x 32. Where that matters (an integrating sphere) author
    ``int2 probesim:tessellation = (512, 256)`` on the prim: 261,120
    triangles, within 3.8e-5·r of the sphere.
Materials
    The bound material's ``UsdPreviewSurface``: ``diffuseColor`` is the
    Lambertian albedo, ``emissiveColor`` the front-face emitted radiance in
    the stage's light units, ``opacity`` 0 removes the prim (it blocks
    nothing). Inputs are followed through connections to authored constant
    values (e.g. a Material interface input); anything else (a texture)
    falls back to the UsdPreviewSurface default with a warning. With no bound
    material, ``primvars:displayColor`` is the albedo if authored, else
    UsdPreviewSurface's default 0.18. Colours become their luminance-weighted
    grey (BT.709 Y), with one warning naming the prims whose colour was not
    grey.
Lights
    UsdLux Sphere, Rect, Disk, Distant, Dome (and DomeLight_1) and Cylinder
    lights, resolved to world size and emission as described in
    :func:`load_stage`. Lights emit but are not geometry: they neither
    reflect nor block. ``Light.frame`` is the right-handed orthonormal frame
    of the prim's world rotation, except for domes, where it is the frame of
    the lat-long texture in the OpenEXR convention: latitude +pi/2 along
    ``frame[:, 1]``, (lat 0, lon 0) along ``frame[:, 2]``, (lat 0, lon pi/2)
    along ``frame[:, 0]`` (UsdLux DomeLight: the prim's own frame;
    DomeLight_1 with a Z ``poleAxis``: the prim frame turned +90 deg about X).
    A dome's ``texture:file`` must be a lat-long OpenEXR image
    (``texture:format`` ``latlong``, or ``automatic`` for a ``.exr`` file);
    it is read into ``Light.texture_map`` as luminance grey (BT.709 Y) and
    scales the dome's emission texel by texel (see :mod:`simulator.latlong`
    for the pixel <-> direction map). Portal and plugin lights are ignored
    with a warning.
Geometry lights
    A Mesh, Cube or Sphere with ``MeshLightAPI`` (or ``LightAPI`` applied
    directly) is geometry that emits: it blocks light like any surface and
    emits from its front face (both faces when ``doubleSided``) the radiance
    ``intensity * 2**exposure * grey(color)``, divided by its world area when
    ``normalize`` is on, with the spectrum rules of other lights. The bound
    material's ``emissiveColor`` is not added (warned when non-zero): the
    light's own inputs set its emission. Its albedo is the bound
    UsdPreviewSurface's ``diffuseColor``, or 0 when no material is bound or
    ``light:materialSyncMode`` is ``noMaterialResponse`` (a light with no
    material response reflects nothing). ``VolumeLightAPI`` is ignored with
    a warning (the prim is read as a plain surface).
Sensors
    See "Stage-authored sensors" below.
Variants
    ``load_stage(..., variants={"reflectance": "rho_0_9"})`` (a config's
    ``variants`` table) selects that variant on every prim that has the
    variant set, in the stage's in-memory override layer, before anything is read: one stage can
    serve a whole parameter sweep. An unknown set or variant is an error that
    lists what the stage offers.

Prims are traversed through instance proxies, so instanceable prims count.
Inactive prims are skipped (with their subtrees). Geometry and lights are
skipped when their computed visibility is ``invisible`` or their computed
purpose is ``guide`` or ``proxy``; sensors are measurement points, not
rendered things, so visibility and purpose do not hide them (deactivate a
sensor prim to drop it). Time-varying attributes are read at
``Usd.TimeCode.EarliestTime()`` (the first time sample, or the default value).

World frame
-----------
Stage coordinates are scaled by ``UsdGeom.GetStageMetersPerUnit``. A Y-up
stage is rotated +90 degrees about X, ``(x, y, z)_Yup -> (x, -z, y)_Zup``, so
stage "up" becomes world +Z. Positions, directions, frames and lengths all go
through the same map ``p_world = s * R_up @ (A_stage @ p + t_stage)``.

Stage-authored sensors
----------------------
Any prim (usually an ``Xform``) that has the attribute
``probesim:sensor:kind`` is a sensor:

===============================  ===========  ===========================================
attribute                        type         meaning
===============================  ===========  ===========================================
``probesim:sensor:kind``         token/string ``irradiance``, ``radiance``, ``patch`` or
                                              ``probe`` (required)
``probesim:sensor:name``         string       name in results (default: the prim path)
``probesim:sensor:halfAngleDeg`` float        radiance: cone half-angle, degrees, in
                                              [0, 90] (default 0: one direction)
``probesim:sensor:size``         float2       patch: (width, height) in stage units along
                                              the prim's local X and Y (required); the
                                              world transform's scale applies too
``probesim:sensor:resolution``   int2         probe: lat-long map (width, height) in
                                              pixels (default (64, 32))
===============================  ===========  ===========================================

The sensor sits at the prim's world origin and faces down its local -Z axis,
like a USD camera: ``normal = world(-Z)`` and ``up = world(+Y)``
orthonormalised against it. An upward-facing irradiance sensor is therefore
an Xform rotated 180 degrees about X. ``Sensor.source`` is the prim path.

Example::

    def Xform "TableSensor"
    {
        token probesim:sensor:kind = "irradiance"
        double3 xformOp:translate = (0, 0, 0.75)
        float3 xformOp:rotateXYZ = (180, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
    }
"""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from pxr import Usd, UsdGeom, UsdLux, UsdShade

from ..errors import UserError
from ..units import SPECTRA, emission_pair, luminance_grey
from .model import Geometry, Light, LightKind, Scene, Sensor, SensorKind

__all__ = [
    "load_stage",
    "SENSOR_ATTR_PREFIX",
    "SENSOR_KINDS",
    "DEFAULT_PROBE_RESOLUTION",
    "DEFAULT_ALBEDO",
    "SPHERE_SEGMENTS",
]

#: namespace of the attributes that make a prim a sensor
SENSOR_ATTR_PREFIX = "probesim:sensor:"

#: ``probesim:sensor:kind`` values and the kinds they map to
SENSOR_KINDS = {
    "irradiance": SensorKind.IRRADIANCE,
    "radiance": SensorKind.RADIANCE,
    "patch": SensorKind.PATCH,
    "probe": SensorKind.PROBE,
}

#: default probe map size (width, height) when ``probesim:sensor:resolution`` is not authored
DEFAULT_PROBE_RESOLUTION = (64, 32)

#: UsdPreviewSurface's fallback diffuseColor (0.18, 0.18, 0.18), used when nothing is authored
DEFAULT_ALBEDO = 0.18

#: UsdGeom.Sphere tessellation: (longitude segments, latitude rings)
SPHERE_SEGMENTS = (64, 32)
#: per-Sphere override of :data:`SPHERE_SEGMENTS`: ``int2 probesim:tessellation = (n_lon, n_lat)``
TESSELLATION_ATTR = "probesim:tessellation"
#: most faces (n_lon * n_lat) a tessellated Sphere may have
MAX_SPHERE_FACES = 1 << 22

# UsdPreviewSurface input fallbacks (from its specification).
_PREVIEW_DEFAULTS = {
    "diffuseColor": (DEFAULT_ALBEDO,) * 3,
    "emissiveColor": (0.0, 0.0, 0.0),
    "opacity": 1.0,
}

# (x, y, z)_Yup -> (x, -z, y)_Zup: +90 degrees about X.
_Y_UP_TO_Z_UP = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])

# Light schemas we read, in the order they are tested.
_LIGHT_SCHEMAS = (
    (UsdLux.SphereLight, LightKind.SPHERE),
    (UsdLux.RectLight, LightKind.RECT),
    (UsdLux.DiskLight, LightKind.DISK),
    (UsdLux.DistantLight, LightKind.DISTANT),
    (UsdLux.DomeLight, LightKind.DOME),
    (UsdLux.DomeLight_1, LightKind.DOME),
    (UsdLux.CylinderLight, LightKind.CYLINDER),
)

# How many prim paths a summary warning names before "and N more".
_MAX_NAMED = 10


# --------------------------------------------------------------------------- #
# public entry point
# --------------------------------------------------------------------------- #


def load_stage(
    path: str | os.PathLike,
    light_units: str = "photometric",
    radiometric_spectrum: str | float = "E",
    variants: dict[str, str] | None = None,
) -> Scene:
    """Read a USD stage into a :class:`Scene` in world metres, Z up.

    Parameters
    ----------
    path : str or os.PathLike
        A ``.usda``, ``.usdc``, ``.usd`` or ``.usdz`` file.
    light_units : {"photometric", "radiometric"}
        How to read the stage's light numbers. ``"photometric"`` (UsdLux's
        own): intensities are luminance (nits), a delta or normalized
        DistantLight gives illuminance (lux), and the spectrum is Illuminant
        D65. ``"radiometric"``: the same numbers are W m^-2 sr^-1 (W/m^2),
        with spectral shape ``radiometric_spectrum``.
    radiometric_spectrum : {"E", "D65"} or float
        Spectrum assumed for emitters in radiometric mode (a float is a
        blackbody temperature in kelvin). A light with
        ``enableColorTemperature`` uses its blackbody in either mode.
    variants : dict of str to str, optional
        Variant selections, variant-set name to variant name (a config's
        ``variants`` table), applied before anything is read; see
        :func:`_select_variants`.

    Returns
    -------
    Scene
        Geometry (one triangle soup), lights, stage-authored sensors,
        ``meters_per_unit``, ``up_axis`` and any warnings.

    Raises
    ------
    UserError
        The file is missing or not a USD stage, or the stage has a value
        probesim cannot honour (negative intensity or size, albedo outside
        [0, 1), NaN/Inf transform, unknown sensor kind, ...). The message
        names the file and the prim.

    Notes
    -----
    UsdLux emission (the "Quantities and units" rules)::

        value      = intensity * 2**exposure * grey(color) / sizeFactor
        sizeFactor = 1                          unless normalize
                   = world area                 Rect w*h, Disk pi r^2,
                                                Sphere 4 pi r^2, Cylinder 2 pi r len
                   = pi * sin(half_angle)**2    DistantLight, half_angle = angle/2

    ``value`` is a radiance for area, sphere, cylinder, dome and distant
    lights with an angle. Special cases:

    * A SphereLight with ``treatAsPoint`` (or radius 0) is a point source
      of intensity ``I = L * pi * r**2``; with ``normalize`` that is
      ``intensity * 2**exposure * grey(color) / 4``, finite even at r = 0.
      Without ``normalize``, radius 0 emits nothing (warned).
    * A DistantLight with ``angle`` 0 is a delta direction whose emission is
      the normal irradiance ``value`` (with or without ``normalize``): the
      limit of a normalized light as the angle shrinks, which is how
      renderers treat a zero-angle sun.
    * The blackbody colour of ``colorTemperature`` is luminance-normalised in
      UsdLux, so it changes only the spectrum (hence the radiometric/
      photometric ratio), not ``grey(color)``.
    * A zero-area Rect, Disk or Cylinder light emits nothing and is dropped
      with a warning.

    ``emission = emission_pair(value, light_units, spectrum)`` with spectrum
    the blackbody temperature when enabled, else ``"D65"`` (photometric) or
    ``radiometric_spectrum`` (radiometric). Sizes are world sizes: the
    transform's scale (and metersPerUnit) applies to width, height, radius
    and length; a non-uniform scale on a round shape uses the mean scale of
    the affected axes, with a warning.
    """
    _check_options(path, light_units, radiometric_spectrum)
    stage = _open_stage(path)
    _select_variants(stage, str(path), variants or {})
    mpu = float(UsdGeom.GetStageMetersPerUnit(stage))
    up_axis = str(UsdGeom.GetStageUpAxis(stage))
    if not (math.isfinite(mpu) and mpu > 0):
        raise UserError(f"{path}: metersPerUnit must be a positive number, not {mpu}")
    if up_axis not in ("Y", "Z"):
        raise UserError(f"{path}: upAxis must be 'Y' or 'Z', not {up_axis!r}")

    ctx = _Context(
        path=str(path),
        time=Usd.TimeCode.EarliestTime(),
        to_world=mpu * (_Y_UP_TO_Z_UP if up_axis == "Y" else np.eye(3)),
        light_units=light_units,
        default_spectrum="D65" if light_units == "photometric" else radiometric_spectrum,
    )
    ctx.xforms = UsdGeom.XformCache(ctx.time)
    _collect_composition_errors(stage, ctx)
    geometry, lights, sensors = _read_prims(ctx, stage)
    _finish_warnings(ctx)
    return Scene(
        geometry=geometry,
        lights=lights,
        sensors=sensors,
        path=str(path),
        meters_per_unit=mpu,
        up_axis=up_axis,
        warnings=ctx.warnings,
    )


def _select_variants(stage: Usd.Stage, path: str, variants: dict[str, str]) -> None:
    """Select ``variants[set]`` on every prim that has variant set ``set``.

    Selections go into the stage's in-memory override layer
    (``GetSessionLayer``), the strongest, so they
    override any selection the file authors, and the file is left unchanged.
    All prims are visited (inactive ones too, since a selection may activate
    them), and the walk repeats until nothing changes, so a variant set that
    appears only inside another set's selected variant is honoured as well.
    Prims inside instance prototypes cannot be edited through their
    instances: author the variant set on the instanceable prim or above it.

    Raises
    ------
    UserError
        ``variants.<set>``: no prim has that variant set (the message lists
        the sets the stage offers), or a prim's set does not offer the
        selection (the message lists the variants it offers).
    """
    if not variants:
        return
    stage.SetEditTarget(Usd.EditTarget(stage.GetSessionLayer()))
    found: set[str] = set()
    for _ in range(64):  # nesting depth bound: a fixed point comes long before
        changed = False
        # a list first: a selection recomposes the stage under a live iterator
        for prim in list(Usd.PrimRange.Stage(stage, Usd.PrimAllPrimsPredicate)):
            if not prim.IsValid():  # removed by a selection made earlier in this pass
                continue
            sets = prim.GetVariantSets()
            for name, choice in variants.items():
                if not sets.HasVariantSet(name):
                    continue
                found.add(name)
                vset = sets.GetVariantSet(name)
                offered = vset.GetVariantNames()
                if choice not in offered:
                    raise UserError(f"{path}: variants.{name}: {prim.GetPath()} offers no variant {choice!r} "
                                    f"(its variant set {name!r} offers: {', '.join(offered) or 'nothing'})")
                if vset.GetVariantSelection() != choice:
                    vset.SetVariantSelection(choice)
                    changed = True
        if not changed:
            break
    for name in variants:
        if name not in found:
            offered = sorted({s for prim in Usd.PrimRange.Stage(stage, Usd.PrimAllPrimsPredicate)
                              for s in prim.GetVariantSets().GetNames()})
            raise UserError(f"{path}: variants.{name}: no prim has a variant set {name!r} "
                            f"(the stage offers: {', '.join(offered) or 'no variant sets'})")


def _read_prims(ctx: _Context, stage: Usd.Stage) -> tuple[Geometry, list[Light], list[Sensor]]:
    """Walk every active prim, instance proxies included, and sort it into geometry, lights, sensors."""
    geo = _GeometryBuilder()
    lights: list[Light] = []
    sensors: list[Sensor] = []
    # The default predicate already drops inactive, undefined, unloaded and
    # abstract (class) prims; TraverseInstanceProxies walks into instances.
    for prim in Usd.PrimRange(stage.GetPseudoRoot(), Usd.TraverseInstanceProxies()):
        if prim.IsPseudoRoot():
            continue
        if prim.HasAttribute(SENSOR_ATTR_PREFIX + "kind"):
            sensors.append(_read_sensor(ctx, prim))  # sensors ignore visibility and purpose
        if not _is_rendered(ctx, prim):
            continue
        if prim.IsA(UsdGeom.Gprim):
            _read_gprim(ctx, prim, geo)  # MeshLightAPI prims too: geometry that emits
        elif prim.HasAPI(UsdLux.LightAPI):
            light = _read_light(ctx, prim)
            if light is not None:
                lights.append(light)
    return geo.build(), lights, sensors


# --------------------------------------------------------------------------- #
# reading context
# --------------------------------------------------------------------------- #


@dataclass
class _Context:
    """What every helper needs: the file name for messages, time, world map, units."""

    path: str
    time: Usd.TimeCode
    to_world: np.ndarray  # 3x3: metersPerUnit * (up-axis rotation)
    light_units: str
    default_spectrum: str | float
    xforms: UsdGeom.XformCache | None = None
    warnings: list[str] = field(default_factory=list)
    coloured: dict[str, None] = field(default_factory=dict)  # ordered set of prim paths
    materials: dict[str, dict] = field(default_factory=dict)  # material path -> raw inputs

    def warn(self, message: str) -> None:
        if message not in self.warnings:
            self.warnings.append(message)

    def error(self, prim: Usd.Prim | str, message: str) -> UserError:
        return UserError(f"{self.path}: {prim if isinstance(prim, str) else prim.GetPath()}: {message}")


def _check_options(path, light_units: str, spectrum) -> None:
    """Reject bad ``light_units`` / ``radiometric_spectrum`` before opening anything."""
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


def _open_stage(path) -> Usd.Stage:
    """Open the stage, turning every pxr failure into a one-line UserError."""
    p = Path(path)
    if not p.exists():
        raise UserError(f"{path}: no such file")
    if not p.is_file():
        raise UserError(f"{path}: not a file")
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


def _collect_composition_errors(stage: Usd.Stage, ctx: _Context) -> None:
    """Unresolved references and the like do not stop the read; say so."""
    try:
        errors = stage.GetCompositionErrors()
    except Exception:  # older USD without the API
        return
    for err in errors[:_MAX_NAMED]:
        ctx.warn(f"composition error: {' '.join(str(err).split())}")


def _finish_warnings(ctx: _Context) -> None:
    """One summary warning for every colour that was reduced to grey."""
    if ctx.coloured:
        ctx.warn(f"coloured albedo/emission/light colour reduced to luminance grey: {_name_list(list(ctx.coloured))}")


def _name_list(names: list[str]) -> str:
    shown = ", ".join(names[:_MAX_NAMED])
    more = len(names) - _MAX_NAMED
    return shown + (f" and {more} more" if more > 0 else "")


def _is_rendered(ctx: _Context, prim: Usd.Prim) -> bool:
    """False for invisible prims and guide/proxy purpose (render and default are kept)."""
    img = UsdGeom.Imageable(prim)
    if not img:
        return True
    if img.ComputeVisibility(ctx.time) == UsdGeom.Tokens.invisible:
        return False
    return img.ComputePurpose() not in (UsdGeom.Tokens.guide, UsdGeom.Tokens.proxy)


# --------------------------------------------------------------------------- #
# transforms
# --------------------------------------------------------------------------- #


def _world_affine(ctx: _Context, prim: Usd.Prim) -> tuple[np.ndarray, np.ndarray]:
    """World map ``p -> A @ p + t`` in metres, Z up.

    USD matrices act on row vectors (``p' = p M``, translation in the last
    row), so the column-vector linear part is ``M[:3, :3].T``.
    """
    m = np.array(ctx.xforms.GetLocalToWorldTransform(prim), dtype=float)
    if not np.all(np.isfinite(m)):
        raise ctx.error(prim, "transform contains NaN or Inf")
    a = ctx.to_world @ m[:3, :3].T
    t = ctx.to_world @ m[3, :3]
    return a, t


def _axis_scales(a: np.ndarray) -> np.ndarray:
    """World length of the prim's unit X, Y, Z axes (metres per local unit)."""
    return np.linalg.norm(a, axis=0)


def _unit(v: np.ndarray) -> np.ndarray | None:
    n = float(np.linalg.norm(v))
    return v / n if n > 0 and math.isfinite(n) else None


def _frame(ctx: _Context, prim: Usd.Prim, a: np.ndarray) -> np.ndarray:
    """Right-handed orthonormal frame whose Z (and X, as far as possible) follow the prim's.

    Gram-Schmidt from Z keeps the emission axis exact; Y = Z x X makes the
    frame right-handed even under a mirroring transform.
    """
    z = _unit(a[:, 2])
    x = None if z is None else _unit(a[:, 0] - np.dot(a[:, 0], z) * z)
    if z is None or x is None:
        raise ctx.error(prim, "transform is degenerate (zero scale); cannot orient it")
    return np.column_stack([x, np.cross(z, x), z])


def _mean_scale(ctx: _Context, prim: Usd.Prim, scales: np.ndarray, what: str) -> float:
    """Mean of the given axis scales; warn when they differ (shape becomes round again)."""
    if np.ptp(scales) > 1e-6 * max(float(np.max(scales)), 1e-300):
        ctx.warn(f"{prim.GetPath()}: non-uniform scale on a {what}; using the mean scale")
    return float(np.mean(scales))


# --------------------------------------------------------------------------- #
# geometry
# --------------------------------------------------------------------------- #


class _GeometryBuilder:
    """Accumulates per-prim triangle lists, then concatenates them once."""

    def __init__(self) -> None:
        self._points: list[np.ndarray] = []
        self._tris: list[np.ndarray] = []
        self._albedo: list[np.ndarray] = []
        self._emission: list[np.ndarray] = []
        self._two_sided: list[np.ndarray] = []
        self._prim: list[np.ndarray] = []
        self._names: list[str] = []
        self._n_points = 0

    def add(self, name: str, points: np.ndarray, tris: np.ndarray, albedo: float,
            emission: tuple[float, float], two_sided: bool) -> None:
        t = len(tris)
        if t == 0:
            return
        index = len(self._names)
        self._names.append(name)
        self._points.append(points)
        self._tris.append(tris.astype(np.int64) + self._n_points)
        self._n_points += len(points)
        self._albedo.append(np.full(t, albedo))
        self._emission.append(np.tile(np.asarray(emission, float), (t, 1)))
        self._two_sided.append(np.full(t, bool(two_sided)))
        self._prim.append(np.full(t, index, np.int32))

    def build(self) -> Geometry:
        if not self._tris:
            return Geometry()
        return Geometry(
            points=np.concatenate(self._points).astype(np.float64),
            triangles=np.concatenate(self._tris).astype(np.int32),
            albedo=np.concatenate(self._albedo),
            emission=np.concatenate(self._emission),
            two_sided=np.concatenate(self._two_sided),
            prim=np.concatenate(self._prim),
            prim_names=list(self._names),
        )


def _read_gprim(ctx: _Context, prim: Usd.Prim, geo: _GeometryBuilder) -> None:
    """Tessellate one gprim, resolve its material, and add it to the soup."""
    local = _gprim_polygons(ctx, prim)
    if local is None:
        return
    points, counts, indices = local
    is_light = _is_geometry_light(ctx, prim)
    surface = _geometry_light_surface(ctx, prim) if is_light else _surface(ctx, prim)
    if surface is None:  # opacity 0: it lets light through
        return
    a, t = _world_affine(ctx, prim)
    tris = _triangulate(ctx, prim, points, counts, indices)
    gprim = UsdGeom.Gprim(prim)
    left = gprim.GetOrientationAttr().Get(ctx.time) == UsdGeom.Tokens.leftHanded
    mirrored = np.linalg.det(a) < 0
    if left != mirrored:  # either one flips which side is the front; both cancel
        tris = tris[:, [0, 2, 1]]
    world = points @ a.T + t
    tris = _drop_zero_area(world, tris)
    albedo, emission = surface
    if is_light:
        emission = _geometry_light_emission(ctx, prim, world, tris)
    geo.add(str(prim.GetPath()), world, tris, albedo, emission, bool(gprim.GetDoubleSidedAttr().Get(ctx.time)))


def _gprim_polygons(ctx: _Context, prim: Usd.Prim):
    """Local ``(points, faceVertexCounts, faceVertexIndices)`` of a supported gprim, else None."""
    if prim.IsA(UsdGeom.Mesh):
        return _mesh_polygons(ctx, prim)
    if prim.IsA(UsdGeom.Cube):
        size = float(_get(ctx, UsdGeom.Cube(prim).GetSizeAttr()))
        if not math.isfinite(size) or size < 0:
            raise ctx.error(prim, f"Cube size must be a non-negative number, not {size}")
        return _cube_polygons(size) if size > 0 else None
    if prim.IsA(UsdGeom.Sphere):
        radius = float(_get(ctx, UsdGeom.Sphere(prim).GetRadiusAttr()))
        if not math.isfinite(radius) or radius < 0:
            raise ctx.error(prim, f"Sphere radius must be a non-negative number, not {radius}")
        return _sphere_polygons(radius, *_sphere_segments(ctx, prim)) if radius > 0 else None
    ctx.warn(f"{prim.GetPath()}: {prim.GetTypeName()} is not supported (only Mesh, Cube, Sphere); ignored")
    return None


def _sphere_segments(ctx: _Context, prim: Usd.Prim) -> tuple[int, int]:
    """``(longitude segments, latitude rings)`` of a Sphere: ``probesim:tessellation`` if authored,
    else :data:`SPHERE_SEGMENTS`."""
    attr = prim.GetAttribute(TESSELLATION_ATTR)
    value = attr.Get(ctx.time) if attr and attr.HasAuthoredValue() else None
    if value is None:
        return SPHERE_SEGMENTS
    try:
        n_lon, n_lat = (int(v) for v in value)
    except (TypeError, ValueError):
        raise ctx.error(prim, f"{TESSELLATION_ATTR} must be two integers (int2), not {value!r}") from None
    if n_lon < 3 or n_lat < 2 or n_lon * n_lat > MAX_SPHERE_FACES:
        raise ctx.error(prim, f"{TESSELLATION_ATTR} {(n_lon, n_lat)} must have longitude segments >= 3, "
                              f"latitude rings >= 2 and at most {MAX_SPHERE_FACES} faces in all")
    return n_lon, n_lat


def _mesh_polygons(ctx: _Context, prim: Usd.Prim):
    """A Mesh's points and face lists, validated (indices in range, counts sum up)."""
    mesh = UsdGeom.Mesh(prim)
    points = np.asarray(mesh.GetPointsAttr().Get(ctx.time) or [], dtype=float).reshape(-1, 3)
    counts = np.asarray(mesh.GetFaceVertexCountsAttr().Get(ctx.time) or [], dtype=np.int64)
    indices = np.asarray(mesh.GetFaceVertexIndicesAttr().Get(ctx.time) or [], dtype=np.int64)
    if not np.all(np.isfinite(points)):
        raise ctx.error(prim, "points contain NaN or Inf")
    if np.any(counts < 0):
        raise ctx.error(prim, "faceVertexCounts has a negative count")
    if int(counts.sum()) != len(indices):
        raise ctx.error(
            prim, f"faceVertexCounts sum to {int(counts.sum())} but there are {len(indices)} faceVertexIndices"
        )
    if len(indices) and (indices.min() < 0 or indices.max() >= len(points)):
        raise ctx.error(prim, f"faceVertexIndices out of range for {len(points)} points")
    if mesh.GetHoleIndicesAttr().Get(ctx.time):
        ctx.warn(f"{prim.GetPath()}: holeIndices ignored (hole faces are kept)")
    if np.any(counts < 3):
        ctx.warn(f"{prim.GetPath()}: {int(np.sum(counts < 3))} face(s) with fewer than 3 vertices skipped")
    return points, counts, indices


def _cube_polygons(size: float):
    """UsdGeom.Cube: an axis-aligned cube of edge ``size`` centred at the origin, faces outward."""
    h = 0.5 * size
    # vertex i + 2j + 4k sits at (+-h, +-h, +-h) with bit set -> +h
    points = np.array([[(-h, h)[i], (-h, h)[j], (-h, h)[k]] for k in (0, 1) for j in (0, 1) for i in (0, 1)])
    quads = [(1, 3, 7, 5), (0, 4, 6, 2), (2, 6, 7, 3), (0, 1, 5, 4), (4, 5, 7, 6), (0, 2, 3, 1)]  # +X -X +Y -Y +Z -Z
    return points, np.full(6, 4, np.int64), np.array(quads, np.int64).ravel()


def _sphere_polygons(radius: float, n_lon: int, n_lat: int):
    """UsdGeom.Sphere as a UV sphere: pole caps of triangles, quads between rings, faces outward."""
    theta = np.pi * np.arange(1, n_lat) / n_lat  # ring polar angles, north to south
    phi = 2 * np.pi * np.arange(n_lon) / n_lon
    st, ct = np.sin(theta)[:, None], np.cos(theta)[:, None]
    ring = np.stack([st * np.cos(phi), st * np.sin(phi), np.broadcast_to(ct, (n_lat - 1, n_lon))], axis=-1)
    points = radius * np.concatenate([[[0.0, 0.0, 1.0]], ring.reshape(-1, 3), [[0.0, 0.0, -1.0]]])
    north, south = 0, len(points) - 1
    j = np.arange(n_lon)
    jn = (j + 1) % n_lon
    v = lambda k, jj: 1 + k * n_lon + jj  # noqa: E731  vertex of ring k (0-based), column jj
    faces = [np.stack([np.full(n_lon, north), v(0, j), v(0, jn)], 1).ravel()]
    for k in range(n_lat - 2):
        faces.append(np.stack([v(k, j), v(k + 1, j), v(k + 1, jn), v(k, jn)], 1).ravel())
    faces.append(np.stack([v(n_lat - 2, j), np.full(n_lon, south), v(n_lat - 2, jn)], 1).ravel())
    counts = np.array([3] * n_lon + [4] * (n_lon * (n_lat - 2)) + [3] * n_lon, np.int64)
    return points, counts, np.concatenate(faces)


def _triangulate(ctx: _Context, prim: Usd.Prim, points: np.ndarray, counts: np.ndarray,
                 indices: np.ndarray) -> np.ndarray:
    """Split polygons into triangles that keep each face's winding.

    Faces are grouped by vertex count and handled in bulk: triangles as they
    are, convex polygons by a fan from their first vertex, and concave ones by
    ear clipping in the face's plane. Faces with fewer than 3 vertices are
    skipped.
    """
    starts = np.cumsum(counts) - counts
    out = [np.zeros((0, 3), np.int64)]
    concave_fallback = 0
    for n in np.unique(counts):
        n = int(n)
        if n < 3:
            continue
        idx = indices[starts[counts == n][:, None] + np.arange(n)]  # (F, n)
        if n == 3:
            out.append(idx)
            continue
        convex = _convex_faces(points[idx])
        hub = idx[convex]  # fan (v0, vk, vk+1), k = 1 .. n-2
        k = np.arange(1, n - 1)
        fan = np.stack([np.broadcast_to(hub[:, :1], (len(hub), n - 2)), hub[:, k], hub[:, k + 1]], -1)
        out.append(fan.reshape(-1, 3))
        for face in idx[~convex]:
            local, ok = _ear_clip(points[face])
            concave_fallback += not ok
            out.append(face[local])
    if concave_fallback:
        ctx.warn(f"{prim.GetPath()}: {concave_fallback} self-intersecting or non-planar face(s) fan-triangulated")
    return np.concatenate(out)


def _newell_normal(poly: np.ndarray) -> np.ndarray:
    """Newell's area vector of polygons (..., n, 3): robust for non-planar faces, points along the winding."""
    return 0.5 * np.cross(poly, np.roll(poly, -1, axis=-2)).sum(axis=-2)


def _convex_faces(poly: np.ndarray) -> np.ndarray:
    """True where a polygon (F, n, 3) turns the same way as its area normal at every vertex."""
    normal = _newell_normal(poly)
    edge = np.roll(poly, -1, axis=1) - poly  # e_i = p_{i+1} - p_i
    turn = np.cross(np.roll(edge, 1, axis=1), edge)  # at vertex i: e_{i-1} x e_i
    dots = np.einsum("fni,fi->fn", turn, normal)
    tol = 1e-12 * np.linalg.norm(turn, axis=-1) * np.linalg.norm(normal, axis=-1)[:, None]
    return np.all(dots >= -tol, axis=1)


def _ear_clip(poly: np.ndarray) -> tuple[np.ndarray, bool]:
    """Ear-clip one simple polygon (n, 3); returns local vertex triples and whether it succeeded.

    The polygon is projected on the plane of its Newell normal with a basis
    (u, v, normal) that is right-handed, so its winding is counter-clockwise
    in 2D and each ear (prev, i, next) keeps the face's orientation.
    """
    n_vec = _unit(_newell_normal(poly))
    n = len(poly)
    if n_vec is None:
        return np.array([[0, k, k + 1] for k in range(1, n - 1)]), False
    helper = np.array([1.0, 0.0, 0.0]) if abs(n_vec[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = _unit(np.cross(helper, n_vec))
    v = np.cross(n_vec, u)
    q = np.column_stack([poly @ u, poly @ v])

    def cross2(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    remaining = list(range(n))
    tris = []
    while len(remaining) > 3:
        m = len(remaining)
        for k in range(m):
            i0, i1, i2 = remaining[k - 1], remaining[k], remaining[(k + 1) % m]
            if cross2(q[i0], q[i1], q[i2]) <= 0:  # reflex or collinear: not an ear
                continue
            if any(
                cross2(q[i0], q[i1], q[j]) >= 0 and cross2(q[i1], q[i2], q[j]) >= 0 and cross2(q[i2], q[i0], q[j]) >= 0
                for j in remaining if j not in (i0, i1, i2)
            ):
                continue
            tris.append((i0, i1, i2))
            remaining.pop(k)
            break
        else:  # no ear: not a simple polygon; fan the rest so nothing is lost
            tris += [(remaining[0], remaining[k], remaining[k + 1]) for k in range(1, len(remaining) - 1)]
            return np.array(tris), False
    tris.append(tuple(remaining))
    return np.array(tris), True


def _drop_zero_area(points: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """Remove triangles of exactly zero area (collinear fan slivers): nothing can hit them."""
    if len(tris) == 0:
        return tris
    p = points[tris]
    area2 = np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    return tris[area2 > 0]


# --------------------------------------------------------------------------- #
# materials
# --------------------------------------------------------------------------- #


def _surface(ctx: _Context, prim: Usd.Prim) -> tuple[float, tuple[float, float]] | None:
    """``(albedo, emission pair)`` of a gprim, or None when opacity 0 removes it."""
    inputs = _material_inputs(ctx, prim)
    if inputs is None:
        rgb, source = _display_color(ctx, prim)
        inputs = {"diffuseColor": (rgb, source), "emissiveColor": (_PREVIEW_DEFAULTS["emissiveColor"], ""),
                  "opacity": (1.0, "")}
    opacity = float(inputs["opacity"][0])
    if opacity <= 0.0:
        ctx.warn(f"{prim.GetPath()}: opacity 0; left out (it blocks no light)")
        return None
    if opacity < 1.0:
        ctx.warn(f"{prim.GetPath()}: partial opacity {opacity:g} treated as opaque")
    rgb, source = inputs["diffuseColor"]
    albedo = _grey(ctx, prim, rgb)
    if not (math.isfinite(albedo) and 0.0 <= albedo < 1.0):
        raise ctx.error(prim, f"albedo {albedo:g} from {source} must be in [0, 1) (energy conservation)")
    rgb, source = inputs["emissiveColor"]
    radiance = _grey(ctx, prim, rgb)
    if not (math.isfinite(radiance) and radiance >= 0.0):
        raise ctx.error(prim, f"emission {radiance:g} from {source} must be a non-negative number")
    emission = emission_pair(radiance, ctx.light_units, ctx.default_spectrum) if radiance > 0 else (0.0, 0.0)
    return albedo, emission


def _grey(ctx: _Context, prim: Usd.Prim, rgb) -> float:
    """Luminance grey of a colour (or a scalar); remember prims whose colour was not grey."""
    c = np.atleast_1d(np.asarray(rgb, float))
    if c.size == 1:
        return float(c[0])
    if np.ptp(c) > 1e-6 * max(float(np.max(np.abs(c))), 1e-300):
        ctx.coloured[str(prim.GetPath())] = None
    return luminance_grey(c)


def _material_inputs(ctx: _Context, prim: Usd.Prim) -> dict | None:
    """The bound UsdPreviewSurface's inputs as ``{name: (value, where)}``, None without a usable material."""
    material, _ = UsdShade.MaterialBindingAPI(prim).ComputeBoundMaterial(UsdShade.Tokens.full)
    if not material:
        return None
    key = str(material.GetPath())
    if key not in ctx.materials:
        ctx.materials[key] = _preview_surface_inputs(ctx, material)
    return ctx.materials[key]


def _preview_surface_inputs(ctx: _Context, material: UsdShade.Material) -> dict | None:
    """Read diffuseColor/emissiveColor/opacity off a material's UsdPreviewSurface."""
    shader, _, _ = material.ComputeSurfaceSource()
    if not shader or shader.GetShaderId() != "UsdPreviewSurface":
        ctx.warn(f"{material.GetPath()}: surface is not a UsdPreviewSurface; using displayColor or the default albedo")
        return None
    return {name: _input_value(ctx, shader, name, default) for name, default in _PREVIEW_DEFAULTS.items()}


def _input_value(ctx: _Context, shader: UsdShade.Shader, name: str, default):
    """Value of a shader input, through connections to an authored constant; else the default.

    ``GetValueProducingAttributes`` follows connections through NodeGraph and
    Material interface inputs. A shader output at the end (e.g. a texture)
    is not a constant: warn and use the UsdPreviewSurface default.
    """
    inp = shader.GetInput(name)
    where = f"{shader.GetPath()}.inputs:{name}"
    if not inp:
        return default, f"{where} (default)"
    for attr in inp.GetValueProducingAttributes():
        if UsdShade.Output.IsOutput(attr):
            ctx.warn(f"{where}: connected to {attr.GetPath()}, which is not a constant; using the default")
            return default, f"{where} (default)"
        value = _get(ctx, attr)
        if value is not None:
            return value if isinstance(value, tuple) else float(value), str(attr.GetPath())
    return default, f"{where} (default)"


def _display_color(ctx: _Context, prim: Usd.Prim):
    """``primvars:displayColor`` as albedo when authored (mean of many values), else the default grey."""
    pv = UsdGeom.Gprim(prim).GetDisplayColorPrimvar()
    if pv and pv.HasAuthoredValue():
        values = np.asarray(pv.ComputeFlattened(ctx.time) or [], float).reshape(-1, 3)
        if len(values):
            if len(values) > 1 and np.ptp(values, axis=0).max() > 0:
                ctx.warn(f"{prim.GetPath()}: varying displayColor averaged to one albedo")
            return tuple(values.mean(axis=0)), f"{prim.GetPath()}.primvars:displayColor"
    return _PREVIEW_DEFAULTS["diffuseColor"], "the default albedo"


def _is_geometry_light(ctx: _Context, prim: Usd.Prim) -> bool:
    """True for a gprim with MeshLightAPI (or LightAPI applied directly): geometry that emits."""
    if not prim.HasAPI(UsdLux.LightAPI):
        return False
    if prim.HasAPI(UsdLux.VolumeLightAPI):
        ctx.warn(f"{prim.GetPath()}: VolumeLightAPI ignored (read as a plain surface)")
        return False
    return True


def _geometry_light_surface(ctx: _Context, prim: Usd.Prim) -> tuple[float, tuple[float, float]]:
    """``(albedo, (0, 0))`` of a geometry light; its emission comes from its light inputs.

    The albedo is the bound UsdPreviewSurface's diffuseColor; 0 with no
    (usable) bound material or with ``light:materialSyncMode``
    ``noMaterialResponse``. Opacity is ignored: a light's surface is opaque.
    """
    sync = UsdLux.LightAPI(prim).GetMaterialSyncModeAttr().Get(ctx.time)
    if str(sync) == "noMaterialResponse":
        return 0.0, (0.0, 0.0)
    inputs = _material_inputs(ctx, prim)
    if inputs is None:
        return 0.0, (0.0, 0.0)
    rgb, source = inputs["diffuseColor"]
    albedo = _grey(ctx, prim, rgb)
    if not (math.isfinite(albedo) and 0.0 <= albedo < 1.0):
        raise ctx.error(prim, f"albedo {albedo:g} from {source} must be in [0, 1) (energy conservation)")
    if float(inputs["opacity"][0]) < 1.0:
        ctx.warn(f"{prim.GetPath()}: opacity of a mesh light ignored (its surface is opaque)")
    if _grey(ctx, prim, inputs["emissiveColor"][0]) != 0.0:
        ctx.warn(f"{prim.GetPath()}: emissiveColor of the bound material ignored; "
                 "a mesh light emits what its light inputs (intensity, exposure, color) say")
    return albedo, (0.0, 0.0)


def _geometry_light_emission(ctx: _Context, prim: Usd.Prim, world: np.ndarray,
                             tris: np.ndarray) -> tuple[float, float]:
    """Emission pair of a geometry light: ``intensity * 2**exposure * grey(color)``,
    divided by its world area (one side) when ``normalize`` is on."""
    if prim.HasAPI(UsdLux.ShapingAPI):
        ctx.warn(f"{prim.GetPath()}: UsdLuxShapingAPI (cone, focus, IES) ignored")
    raw, spectrum = _light_value(ctx, prim)
    value = raw
    if bool(UsdLux.LightAPI(prim).GetNormalizeAttr().Get(ctx.time)):
        p = world[tris]
        area = float(0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum())
        if area <= 0.0:
            ctx.warn(f"{prim.GetPath()}: mesh light has zero area and emits nothing")
            return (0.0, 0.0)
        value = raw / area
    return emission_pair(value, ctx.light_units, spectrum) if value > 0 else (0.0, 0.0)


# --------------------------------------------------------------------------- #
# lights
# --------------------------------------------------------------------------- #


def _read_light(ctx: _Context, prim: Usd.Prim) -> Light | None:
    """One UsdLux light resolved to world size and an emission pair (None if unsupported/empty)."""
    kind = next((k for schema, k in _LIGHT_SCHEMAS if prim.IsA(schema)), None)
    if kind is None:
        ctx.warn(f"{prim.GetPath()}: {prim.GetTypeName() or 'light'} is not a supported light; ignored")
        return None
    if prim.HasAPI(UsdLux.ShapingAPI):
        ctx.warn(f"{prim.GetPath()}: UsdLuxShapingAPI (cone, focus, IES) ignored")
    a, t = _world_affine(ctx, prim)
    raw, spectrum = _light_value(ctx, prim)
    normalize = bool(UsdLux.LightAPI(prim).GetNormalizeAttr().Get(ctx.time))
    light = Light(name=str(prim.GetPath()), kind=kind, position=t, frame=_frame(ctx, prim, a), emission=(0.0, 0.0))
    value = _shape_light(ctx, prim, light, a, raw, normalize)
    if value is None:
        return None
    light.emission = emission_pair(value, ctx.light_units, spectrum) if value > 0 else (0.0, 0.0)
    return light


def _light_value(ctx: _Context, prim: Usd.Prim) -> tuple[float, str | float]:
    """``intensity * 2**exposure * grey(color)`` and the emitter's spectrum."""
    api = UsdLux.LightAPI(prim)
    intensity = float(_get(ctx, api.GetIntensityAttr()))
    exposure = float(_get(ctx, api.GetExposureAttr()))
    if not (math.isfinite(intensity) and intensity >= 0):
        raise ctx.error(prim, f"intensity must be a non-negative number, not {intensity:g}")
    if not math.isfinite(exposure):
        raise ctx.error(prim, f"exposure must be finite, not {exposure:g}")
    grey = _grey(ctx, prim, _get(ctx, api.GetColorAttr()))
    if not (math.isfinite(grey) and grey >= 0):
        raise ctx.error(prim, f"color must be non-negative, grey {grey:g}")
    spectrum: str | float = ctx.default_spectrum
    if api.GetEnableColorTemperatureAttr().Get(ctx.time):
        temperature = float(_get(ctx, api.GetColorTemperatureAttr()))
        if not (math.isfinite(temperature) and temperature > 0):
            raise ctx.error(prim, f"colorTemperature must be a positive number of kelvin, not {temperature:g}")
        spectrum = temperature
    return intensity * 2.0 ** exposure * grey, spectrum


def _get(ctx: _Context, attr: Usd.Attribute):
    """An attribute's value with ``float`` (32-bit) numbers read as the decimals authored.

    ``float inputs:width = 1.2`` is stored as 1.2000000476837158; the shortest
    decimal that round-trips in float32 (numpy's ``str``) gives back 1.2, so
    closed-form checks see the numbers the stage states. Other types pass
    through unchanged (tuples for vectors).
    """
    value = attr.Get(ctx.time)
    if value is None:
        return None
    is_f32 = attr.GetTypeName().scalarType.type.typeName in ("float", "GfVec2f", "GfVec3f", "GfVec4f")
    if hasattr(value, "__len__") and not isinstance(value, str):
        return tuple(_decimal_f32(v) if is_f32 else v for v in value)
    return _decimal_f32(value) if is_f32 else value


def _decimal_f32(v) -> float:
    # the shortest decimal that round-trips in float32; format_float_positional
    # with unique=True ignores numpy's global print options (which other
    # packages may switch to a 6-digit legacy mode)
    return float(np.format_float_positional(np.float32(v), unique=True, trim="-"))


def _size_attr(ctx: _Context, prim: Usd.Prim, attr: Usd.Attribute, what: str) -> float:
    """A non-negative light dimension in stage units (before the world scale)."""
    value = float(_get(ctx, attr))
    if not (math.isfinite(value) and value >= 0):
        raise ctx.error(prim, f"{what} must be a non-negative number, not {value:g}")
    return value


def _shape_light(ctx: _Context, prim: Usd.Prim, light: Light, a: np.ndarray, raw: float,
                 normalize: bool) -> float | None:
    """Fill the light's world dimensions; return its emission value (None: drop the light)."""
    scales = _axis_scales(a)
    kind = light.kind
    if kind == LightKind.SPHERE:
        sphere = UsdLux.SphereLight(prim)
        r = _size_attr(ctx, prim, sphere.GetRadiusAttr(), "radius")
        r *= _mean_scale(ctx, prim, scales, "SphereLight") if r > 0 else 1.0
        if sphere.GetTreatAsPointAttr().Get(ctx.time) or r == 0.0:
            light.kind = LightKind.POINT
            # I = L * pi r^2, with L = raw / (4 pi r^2) when normalized -> raw / 4.
            intensity = raw / 4.0 if normalize else raw * math.pi * r * r
            if intensity == 0.0 and raw > 0:
                ctx.warn(f"{prim.GetPath()}: SphereLight of radius 0 without normalize emits nothing")
            return intensity
        light.radius = r
        return raw / (4 * math.pi * r * r) if normalize else raw
    if kind == LightKind.RECT:
        rect = UsdLux.RectLight(prim)
        light.width = float(_size_attr(ctx, prim, rect.GetWidthAttr(), "width") * scales[0])
        light.height = float(_size_attr(ctx, prim, rect.GetHeightAttr(), "height") * scales[1])
        if rect.GetTextureFileAttr().Get(ctx.time):
            ctx.warn(f"{prim.GetPath()}: RectLight texture ignored (uniform radiance)")
        return _per_area(ctx, prim, raw, normalize, light.width * light.height)
    if kind == LightKind.DISK:
        r = _size_attr(ctx, prim, UsdLux.DiskLight(prim).GetRadiusAttr(), "radius")
        light.radius = r * (_mean_scale(ctx, prim, scales[:2], "DiskLight") if r > 0 else 1.0)
        return _per_area(ctx, prim, raw, normalize, math.pi * light.radius ** 2)
    if kind == LightKind.CYLINDER:
        cyl = UsdLux.CylinderLight(prim)
        r = _size_attr(ctx, prim, cyl.GetRadiusAttr(), "radius")
        light.radius = r * (_mean_scale(ctx, prim, scales[1:], "CylinderLight") if r > 0 else 1.0)
        light.length = float(_size_attr(ctx, prim, cyl.GetLengthAttr(), "length") * scales[0])
        if cyl.GetTreatAsLineAttr().Get(ctx.time):
            ctx.warn(f"{prim.GetPath()}: CylinderLight treatAsLine ignored (traced as a cylinder)")
        return _per_area(ctx, prim, raw, normalize, 2 * math.pi * light.radius * light.length)
    if kind == LightKind.DISTANT:
        angle = _size_attr(ctx, prim, UsdLux.DistantLight(prim).GetAngleAttr(), "angle")
        if angle > 180.0:
            raise ctx.error(prim, f"angle must be at most 180 degrees, not {angle:g}")
        light.half_angle = math.radians(angle / 2.0)
        if light.half_angle == 0.0:
            return raw  # delta sun: emission is normal irradiance (the normalized limit)
        return raw / (math.pi * math.sin(light.half_angle) ** 2) if normalize else raw
    if kind == LightKind.DOME:
        light.texture = _dome_texture(ctx, prim)
        light.frame = _dome_texture_frame(ctx, prim, light.frame)
        if light.texture:
            light.texture_map = _dome_texture_map(ctx, prim, light.texture)
        return raw
    raise AssertionError(kind)  # pragma: no cover


def _per_area(ctx: _Context, prim: Usd.Prim, raw: float, normalize: bool, area: float) -> float | None:
    """Radiance of an area light: raw, or raw / world area when normalized; None for zero area."""
    if area <= 0.0:
        ctx.warn(f"{prim.GetPath()}: light has zero area and emits nothing; ignored")
        return None
    return raw / area if normalize else raw


def _dome_texture(ctx: _Context, prim: Usd.Prim) -> str:
    """Resolved absolute path of a DomeLight's ``texture:file``, "" if none is authored."""
    attr = prim.GetAttribute("inputs:texture:file")  # same name on DomeLight and DomeLight_1
    asset = attr.Get(ctx.time) if attr else None
    if not asset or not asset.path:
        return ""
    if not asset.resolvedPath:
        raise ctx.error(prim, f"texture:file {asset.path!r} not found")
    return os.path.abspath(asset.resolvedPath)


def _dome_texture_frame(ctx: _Context, prim: Usd.Prim, frame: np.ndarray) -> np.ndarray:
    """The frame in which the dome's lat-long map follows the OpenEXR convention.

    OpenEXR lat-long: latitude +pi/2 is +Y, (lat 0, lon 0) is +Z and
    (lat 0, lon pi/2) is +X. A DomeLight uses that in its own frame (pole =
    its +Y). A DomeLight_1 whose ``poleAxis`` resolves to Z ("Z", or "scene"
    on a Z-up stage) puts the pole on its +Z and (0, 0) on its -Y: that is the
    prim frame turned +90 degrees about X, columns ``(x, z, -y)``.
    """
    if not prim.IsA(UsdLux.DomeLight_1):
        return frame
    pole = str(UsdLux.DomeLight_1(prim).GetPoleAxisAttr().Get(ctx.time))
    if pole == "scene":
        pole = str(UsdGeom.GetStageUpAxis(prim.GetStage()))
    if pole != "Z":
        return frame
    return np.column_stack([frame[:, 0], frame[:, 2], -frame[:, 1]])


#: ``texture:format`` values a DomeLight may have (``automatic`` only for ``.exr`` files)
DOME_TEXTURE_FORMATS = ("latlong", "automatic")


def _dome_texture_map(ctx: _Context, prim: Usd.Prim, path: str) -> np.ndarray:
    """A dome's lat-long map as luminance grey, shape (H, W), float64 (see :mod:`simulator.latlong`).

    ``texture:format`` must be ``latlong``, or ``automatic`` for a ``.exr``
    file whose header does not declare a cube map. RGB becomes BT.709 Y (the
    weights of :func:`simulator.units.luminance_grey`); a grey ``Y`` image is
    used as is. Values must be finite and non-negative.
    """
    from .. import exr

    attr = prim.GetAttribute("inputs:texture:format")
    fmt = str((attr.Get(ctx.time) if attr else None) or "automatic")
    if fmt not in DOME_TEXTURE_FORMATS:
        raise ctx.error(prim, f"texture:format {fmt!r} of texture:file {path} is not supported "
                              "(only 'latlong', or 'automatic' for a lat-long .exr)")
    if not path.lower().endswith(".exr"):
        raise ctx.error(prim, f"texture:file {path}: only lat-long OpenEXR (.exr) maps are supported")
    try:
        header = exr.read_header(path) if fmt == "automatic" else {}
        rgb = exr.read_rgb(path)
    except UserError as err:  # names the file; add the stage and prim
        raise ctx.error(prim, f"texture:file {err}") from None
    if "CUBE" in str(header.get("envmap", "")).upper():
        raise ctx.error(prim, f"texture:file {path} is a cube map (envmap header); only lat-long maps are supported")
    bad = int(np.sum(~np.isfinite(rgb).all(axis=-1) | (rgb < 0).any(axis=-1)))
    if bad:
        raise ctx.error(prim, f"texture:file {path}: {bad} texel(s) are negative, NaN or Inf")
    weights = np.array([luminance_grey(e) for e in np.eye(3)])  # BT.709 Y per channel
    rgb = rgb.astype(np.float64)
    if np.ptp(rgb, axis=-1).max() > 1e-6 * max(float(rgb.max()), 1e-300):
        ctx.coloured[str(prim.GetPath())] = None
    h, w = rgb.shape[:2]
    if w != 2 * h:
        ctx.warn(f"{prim.GetPath()}: texture:file {path} is {w} x {h}, not 2:1; read as lat-long anyway")
    return rgb @ weights


# --------------------------------------------------------------------------- #
# sensors
# --------------------------------------------------------------------------- #


def _read_sensor(ctx: _Context, prim: Usd.Prim) -> Sensor:
    """A stage-authored sensor: at the prim's world origin, facing its world -Z."""
    kind_name = str(_sensor_attr(ctx, prim, "kind", None)).strip().lower()
    if kind_name not in SENSOR_KINDS:
        raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}kind {kind_name!r} is not one of {', '.join(SENSOR_KINDS)}")
    kind = SENSOR_KINDS[kind_name]
    a, t = _world_affine(ctx, prim)
    normal = _unit(-a[:, 2])
    up = None if normal is None else _unit(a[:, 1] - np.dot(a[:, 1], normal) * normal)
    if normal is None or up is None:
        raise ctx.error(prim, "transform is degenerate (zero scale); cannot orient the sensor")
    sensor = Sensor(
        name=str(_sensor_attr(ctx, prim, "name", str(prim.GetPath()))),
        kind=kind, position=t, normal=normal, up=up, source=str(prim.GetPath()),
    )
    if kind == SensorKind.RADIANCE:
        half = float(_sensor_attr(ctx, prim, "halfAngleDeg", 0.0))
        if not (math.isfinite(half) and 0.0 <= half <= 90.0):
            raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}halfAngleDeg must be in [0, 90], not {half:g}")
        sensor.half_angle = math.radians(half)
    elif kind == SensorKind.PATCH:
        size = _sensor_attr(ctx, prim, "size", None)
        if size is None or len(size) != 2:
            raise ctx.error(prim, f"a patch sensor needs {SENSOR_ATTR_PREFIX}size = (width, height)")
        scales = _axis_scales(a)  # includes metersPerUnit
        w, h = float(size[0] * scales[0]), float(size[1] * scales[1])
        if not (math.isfinite(w) and math.isfinite(h) and w > 0 and h > 0):
            raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}size must be positive, not {tuple(size)}")
        sensor.size = (w, h)
    elif kind == SensorKind.PROBE:
        res = _sensor_attr(ctx, prim, "resolution", DEFAULT_PROBE_RESOLUTION)
        if len(res) != 2 or int(res[0]) < 1 or int(res[1]) < 1:
            raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}resolution must be two positive integers, not {tuple(res)}")
        sensor.resolution = (int(res[0]), int(res[1]))
    return sensor


def _sensor_attr(ctx: _Context, prim: Usd.Prim, name: str, default):
    """Value of ``probesim:sensor:<name>`` if authored, else ``default`` (None default: required)."""
    attr = prim.GetAttribute(SENSOR_ATTR_PREFIX + name)
    value = _get(ctx, attr) if attr and attr.HasAuthoredValue() else None
    if value is None:
        if default is None and name == "kind":
            raise ctx.error(prim, f"{SENSOR_ATTR_PREFIX}kind has no value")
        return default
    return value
