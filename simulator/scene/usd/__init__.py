"""Read a USD stage into a :class:`~simulator.scene.model.Scene`.

This package is the only code in probesim that imports ``pxr``. It turns a
stage into numpy arrays and small records in the *probesim world frame*
(metres, right-handed, Z up), so nothing downstream needs to know about USD.

One job per module: :mod:`.stage` opens the stage, applies variants, sets
the world frame and walks the prims; :mod:`.geometry` (with the pure-numpy
:mod:`.tessellation`) turns gprims into triangles; :mod:`.instancers` places
PointInstancer prototypes; :mod:`.materials` reads surfaces and
:mod:`.textures` the textures they use; :mod:`.lights` reads UsdLux and
geometry lights; :mod:`.sensors` reads stage-authored sensors.
:mod:`.context` holds what they share and :mod:`.transforms` the world
transforms.

What is read
------------
Geometry
    ``UsdGeom.Mesh`` (any polygon counts), ``Cube``, ``Sphere``, ``Capsule``
    (and ``Capsule_1`` with equal radii), ``Cone``, ``Cylinder`` (and the
    ``Cylinder_1`` frustum) with their ``axis``, and ``Plane`` (``width``,
    ``length``, ``axis``; double-sided by its fallback), merged into one
    triangle soup. Faces are wound so that ``cross(p1 - p0, p2 - p0)`` is the
    front face in world space: a ``leftHanded`` prim is re-wound, and so is a
    prim whose world transform has a negative determinant (a mirror swaps
    handedness); both together cancel. Other gprims (curves, points, NURBS,
    volumes) are not read: one summary warning counts them by type.
    A Sphere becomes a UV sphere of :data:`SPHERE_SEGMENTS` (longitude
    segments, latitude rings), vertices on the surface, so its facets lie
    inside it by up to about r·((pi/n_lon)^2 + (pi/(2 n_lat))^2)/2: 0.24% of
    r at 64 x 32. Where that matters (an integrating sphere) author
    ``int2 probesim:tessellation = (512, 256)`` on the prim: 261,120
    triangles, within 3.8e-5·r of the sphere. Cylinders and cones use the
    first number (segments around), capsules both; their inscribed polygons
    have up to 2 (2 pi/n)^2/6 less area and volume (0.32% at n = 64).
    A Mesh with an authored ``subdivisionScheme`` other than ``none`` is
    read as its control cage (one summary warning), as Hydra draws it at
    refinement level 0; ``holeIndices`` are counted as ignored.
Instancing
    Scene-graph instances (``instanceable = true``) are read through their
    instance proxies. A ``PointInstancer`` draws its prototypes where its
    instances stand (positions, orientations, scales, the prototype's own
    transform, the instancer's transform; ``invisibleIds`` and inactive ids
    left out; nested instancers too), never in the prototypes' own place:
    see :mod:`.instancers`.
Materials
    The bound material's ``UsdPreviewSurface``: ``diffuseColor`` is the
    Lambertian albedo, ``emissiveColor`` the front-face emitted radiance in
    the stage's light units, ``opacity`` 0 removes the prim (it blocks
    nothing). The binding is resolved for the ``full`` purpose (a final
    render), falling back to the all-purpose one, collection bindings
    included; ``GeomSubset`` s of the ``materialBind`` family give their faces
    their own material. Inputs are followed through connections to authored
    constant values (e.g. a Material interface input); an input connected to
    a ``UsdUVTexture`` reads the texture's mean (sRGB-decoded for 8-bit
    textures, then ``scale`` and ``bias``; one summary warning), anything else
    falls back to the UsdPreviewSurface default and is counted as ignored.
    With no bound material, ``primvars:displayColor`` is the albedo if
    authored, else UsdPreviewSurface's default 0.18. ``probesim:reflectance``
    (an asset or string path, relative to the layer authoring it) on the
    Material or its shader names a measured reflectance CSV that replaces
    ``diffuseColor`` (:func:`.materials._measured_reflectance`): its faces
    keep the curve for spectral transport and, as albedo, its luminance
    under D65. Colours become their
    luminance-weighted grey (BT.709 Y), with one warning naming the prims
    whose colour was not grey. An albedo must lie in [0, 1]; exactly 1 is
    accepted with a warning (paths end there only by escaping the scene, so
    a closed albedo-1 enclosure has no finite reading). Inputs probesim does
    not model (``roughness``, ``metallic``, ``specularColor``, ...), when
    authored away from their fallback, are counted in the summary warning.
Lights
    UsdLux Sphere, Rect, Disk, Distant, Dome (and DomeLight_1) and Cylinder
    lights, resolved to world size and emission as described in
    :func:`load_stage`. Lights emit but are not geometry: they neither
    reflect nor block. ``Light.frame`` is the orthonormal frame of the prim's
    world rotation, left-handed where the transform mirrors (a negative
    scale: a luminaire's web is then mirrored, not rotated; see
    :func:`.transforms._frame`), except for domes, where it is the frame of
    the lat-long texture in the OpenEXR convention: latitude +pi/2 along
    ``frame[:, 1]``, (lat 0, lon 0) along ``frame[:, 2]``, (lat 0, lon pi/2)
    along ``frame[:, 0]`` (UsdLux DomeLight: the prim's own frame;
    DomeLight_1 with a Z ``poleAxis``: the prim frame turned +90 deg about X).
    A dome's ``texture:file`` is a lat-long image (``texture:format``
    ``latlong`` or ``automatic``): OpenEXR or Radiance ``.hdr`` (linear), or
    an 8/16-bit PNG, JPEG, ... read as sRGB relative radiance, linearised,
    with a warning that it clips bright sources. It is read into
    ``Light.texture_map`` as luminance grey (BT.709 Y) and scales the dome's
    emission texel by texel (see :mod:`simulator.io.latlong` for the pixel
    <-> direction map). A PortalLight (``inputs:width`` x ``inputs:height``
    in its local XY plane, times the transform's X and Y scales, passing
    light toward its local -Z) is read onto the DomeLights whose ``portals``
    relationship targets it (``Light.portals``, see
    :mod:`simulator.scene.usd.portals`): it guides the dome's sampling and
    changes no reading. A portal no dome targets, or of zero size, is
    ignored with a warning; a negative size, or a ``portals`` target that is
    missing or not a PortalLight, is an error. Plugin lights are not read
    (counted in the summary warning). A stage with no light at all (no UsdLux light, no
    emitting triangle), or whose every light emits 0, is refused: every reading would be zero. Inputs
    authored under their legacy names (no ``inputs:`` prefix, before USD
    21.05) are read where the ``inputs:`` name is not authored, and named
    once in the summary warning (:mod:`.legacy`).
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
Collections
    Every ``UsdCollectionAPI`` collection is resolved to the lights it
    includes (``Scene.collections``, :mod:`.collections`), so a study's light
    group can name one.
Variants
    ``load_stage(..., variants={"reflectance": "rho_0_9"})`` (a config's
    ``variants`` table) selects that variant on every prim that has the
    variant set, in the stage's in-memory override layer, before anything is read: one stage can
    serve a whole parameter sweep. ``variants={"/Car/WheelFL": {"wheelStyle":
    "sport"}}`` selects on that prim only (it wins over a by-set selection
    there). An unknown prim, set or variant is an error that lists what the
    stage offers.
Skinned meshes
    A gprim bound to a ``Skeleton`` under a ``SkelRoot`` is posed at the
    time read by pxr's UsdSkel skinning and placed by the skeleton's world
    transform (:mod:`.skinning`); blend shapes are named as ignored.

Prims are traversed through instance proxies, so instanceable prims count.
Inactive prims are skipped (with their subtrees). Geometry and lights are
skipped when their computed visibility is ``invisible`` or their computed
purpose is ``guide`` or ``proxy``; sensors are measurement points, not
rendered things, so visibility and purpose do not hide them (deactivate a
sensor prim to drop it). Time-varying attributes are read at the ``time``
given (a config's ``time``, ``--time``), else at
``Usd.TimeCode.EarliestTime()`` (each attribute's first time sample, or its
default value), and then the summary line names the animated prims
(:mod:`.animation`).

Summary warnings
----------------
What is not read comes back as one line per kind, with counts, not one
line per prim: ``stage.usda: not read: 3 BasisCurves, 12 Points; ignored:
5 x inputs:roughness``; likewise the texture means, albedo-1 surfaces,
subdivision cages and colours reduced to grey. The same stage line counts
the legacy light attributes read, the animated prims read with no time
given, the composition errors and pxr's own diagnostics (caught while the
stage is read instead of printed on stderr, :mod:`.diagnostics`), each
with its first example. Attributes that change
nothing in a Lambertian reading (``doc``, ``kind``, extents, normals,
``primvars:st``, inputs at their fallback) are not named.

World frame
-----------
Stage coordinates are scaled by ``UsdGeom.GetStageMetersPerUnit``; a stage
that does not author ``metersPerUnit`` is read in centimetres (UsdGeom's
fallback, 0.01) with a warning. A Y-up
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
``probesim:sensor:kind``         token/string ``irradiance``, ``radiance``, ``patch``,
                                              ``probe``, ... or ``glare`` (required)
``probesim:sensor:name``         string       name in results (default: the prim path)
``probesim:sensor:halfAngleDeg`` float        radiance: cone half-angle, degrees, in
                                              [0, 90] (default 0: one direction)
``probesim:sensor:size``         float2       patch: (width, height) in stage units along
                                              the prim's local X and Y (required); the
                                              world transform's scale applies too
``probesim:sensor:resolution``   int2         probe: lat-long map (width, height) in
                                              pixels (default (64, 32)); glare: its half
                                              map in front of the eye (default (128, 128))
``probesim:sensor:evalglare``    string       glare: source finding as evalglare options
                                              (``-b``, ``-r``, ``-y``/``-x``/``-Y``, ``-C``)
``probesim:sensor:dgpStderr``    float        glare: DGP's standard error to trace to (0.005)
``probesim:sensor:model``        string       irradiance: a sensor model, bundled or a
                                              .toml beside the stage (docs/sensors.md)
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

import os

import numpy as np

from pxr import Usd, UsdGeom, UsdLux

from simulator.errors import UserError
from simulator.scene.model import Geometry, Light, LightKind, Scene, Sensor
from simulator.scene.surfaces import curved_mirrors, curved_notes, mirror_limits, shaded_faces
from simulator.scene.usd.facets import faceted_note, faceted_reflectors
from simulator.scene.usd.collections import light_collections
from simulator.scene.usd.context import _Context

# The public constants live with the code that uses them and are re-exported
# here; so are TESSELLATION_ATTR, MAX_SPHERE_FACES and DOME_TEXTURE_FORMATS.
from simulator.scene.usd.geometry import MAX_SPHERE_FACES, SPHERE_SEGMENTS, TESSELLATION_ATTR  # noqa: F401
from simulator.scene.usd.geometry import _GeometryBuilder, _read_gprim
from simulator.scene.usd.animation import note_animated
from simulator.scene.usd.diagnostics import PxrDiagnostics
from simulator.scene.enclosures import sealed_light
from simulator.scene.usd.instancers import _read_instancer
from simulator.scene.usd.lights import DOME_TEXTURE_FORMATS, _is_supported_light, _read_light, _require_light  # noqa: F401
from simulator.scene.usd.materials import DEFAULT_ALBEDO, _finish_warnings
from simulator.scene.usd.portals import attach_portals, is_portal, read_portal
from simulator.scene.usd.sensors import DEFAULT_PROBE_RESOLUTION, SENSOR_ATTR_PREFIX, SENSOR_KINDS, _is_sensor, _read_sensor
from simulator.scene.usd.stage import (
    _check_options,
    _collect_composition_errors,
    _is_rendered,
    _mtlx_references_quiet,
    _open_stage,
    _reading_context,
    _select_variants,
    _traverse,
    _warn_unauthored_units,
    _world_frame,
)

__all__ = [
    "usd_version",
    "load_stage",
    "SENSOR_ATTR_PREFIX",
    "SENSOR_KINDS",
    "DEFAULT_PROBE_RESOLUTION",
    "DEFAULT_ALBEDO",
    "SPHERE_SEGMENTS",
]


def usd_version() -> str:
    """The OpenUSD version in use (for run records)."""
    from pxr import Usd

    return ".".join(map(str, Usd.GetVersion()))


def load_stage(
    path: str | os.PathLike,
    light_units: str = "photometric",
    radiometric_spectrum: str | float = "E",
    variants: dict | None = None,
    require_light: bool = False,
    time: float | None = None,
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
    variants : dict, optional
        Variant selections (a config's ``variants`` table), applied before
        anything is read: variant-set name to variant name (every prim with
        the set), or prim path to ``{set: variant}`` (that prim); see
        :func:`_select_variants`.
    require_light : bool
        Refuse a stage with nothing that emits (no UsdLux light, no emitting
        geometry): every reading would be zero. A run asks for this
        (:func:`simulator.pipeline.load_scene`); ``False`` (the default)
        reads geometry alone, for tools that only look at the surfaces.
    time : float, optional
        USD time code to read the stage at (a config's ``time``). None:
        ``Usd.TimeCode.EarliestTime()``, each attribute's first time sample;
        the summary line then names the prims that are animated.

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
        [0, 1], NaN/Inf transform, unknown sensor kind, ...), or it has no
        light (with ``require_light``). The message names the file and the prim.

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
    the prim's ``probesim:spectrum`` when authored (an illuminant name, a
    temperature or an SPD CSV relative to its layer; it wins over
    ``colorTemperature``, with a warning), else the blackbody temperature
    when enabled, else ``"D65"`` (photometric) or ``radiometric_spectrum``
    (radiometric). Sizes are world sizes: the
    transform's scale (and metersPerUnit) applies to width, height, radius
    and length; a non-uniform scale on a round shape uses the mean scale of
    the affected axes, with a warning.
    """
    _check_options(path, light_units, radiometric_spectrum, time)
    with PxrDiagnostics() as pxr_said:  # pxr's own warnings: into the summary line, not onto stderr
        with _mtlx_references_quiet():  # usd-core composes no .mtlx; the material reader opens them
            stage = _open_stage(path)
            _select_variants(stage, str(path), variants or {})
        mpu, up_axis = _world_frame(stage, path)
        ctx = _reading_context(path, mpu, up_axis, light_units, radiometric_spectrum, time)
        _collect_composition_errors(stage, ctx)
        _warn_unauthored_units(stage, ctx)
        geometry, lights, sensors = _read_prims(ctx, stage)
        if require_light:
            _require_light(ctx, lights, geometry)
        _refuse_sealed_light(ctx, geometry, lights)
        if geometry.solid_side is not None and np.any(geometry.solid_side != 0):
            closed = sorted({geometry.prim_names[i] for i in np.unique(geometry.prim[geometry.solid_side != 0])})
            ctx.ignored[f"refraction's bend in closed transparent mesh(es) {', '.join(closed[:3])}"
                        f"{' ...' if len(closed) > 3 else ''} (read as slabs entered once, no offset)"] += len(closed)
        delta_lights = [l.name for l in lights if l.is_delta]
        shaded = shaded_faces(geometry)
        curves = curved_mirrors(geometry, shaded)
        for note in (mirror_limits(geometry.points, geometry.triangles, geometry.surface_id, geometry.surfaces,
                                   delta_lights, shaded, curves.n + curves.left_out)
                     + curved_notes(curves, delta_lights + [l.name for l in lights if l.kind == LightKind.DISTANT
                                                            and not l.is_delta])):
            ctx.warn(f"{os.path.basename(str(path))}: {note}")
        faceted = faceted_reflectors(geometry)
        if faceted:
            ctx.warn(f"{os.path.basename(str(path))}: {faceted_note(faceted)}")
        ctx.pxr_messages += pxr_said.collect()
        _finish_warnings(ctx)
    return Scene(
        geometry=geometry,
        lights=lights,
        sensors=sensors,
        path=str(path),
        meters_per_unit=mpu,
        up_axis=up_axis,
        warnings=ctx.warnings,
        collections=light_collections(stage, lights),
        time_code=time,
        animated=tuple(ctx.animated),
        sources=_sources(stage, ctx, lights),
    )


def _sources(stage: Usd.Stage, ctx: _Context, lights: list[Light]) -> tuple[str, ...] | None:
    """The files this reading depended on that pxr or a C++ reader opened (Python ``open`` calls are
    seen by the caller's audit hook): every layer composed, texture files, dome maps and MaterialX
    documents; None after a composition error (what failed to resolve is not a file to watch)."""
    if ctx.composition_errors:
        return None
    files = [layer.realPath for layer in stage.GetUsedLayers() if layer.realPath]
    files += [k.rsplit("|", 1)[0] for k in ctx.textures if isinstance(k, str) and k.rsplit("|", 1)[0]]  # "path|colour space"
    files += [l.texture for l in lights if l.texture]
    files += [k.split("|", 1)[1] for k in ctx.materials if isinstance(k, str) and k.startswith("mtlx document|")]
    # a layer inside a package (``scene.usdz[inner.usdc]``) changes with the package file
    files = [f.split("[", 1)[0] if f.endswith("]") else f for f in files]
    return tuple(dict.fromkeys(os.path.abspath(f) for f in files))


def _refuse_sealed_light(ctx: _Context, geometry: Geometry, lights: list[Light]) -> None:
    """Refuse light sealed in a closed albedo-1 surface: nothing absorbs it, every reading there diverges.

    See :mod:`simulator.scene.enclosures`. Lights at infinity (distant, dome) are outside everything.
    """
    if not ctx.white:
        return
    placed = [(l.name, l.position) for l in lights if l.kind not in (LightKind.DISTANT, LightKind.DOME)]
    found = sealed_light(geometry.points, geometry.triangles, geometry.albedo, geometry.emission, placed)
    if found is not None:
        name, tri = found
        wall = geometry.prim_names[geometry.prim[tri]]
        raise UserError(f"{ctx.path}: {name} is sealed inside a closed surface of albedo 1 ({wall}): nothing "
                        "absorbs its light, so the readings diverge (a trace would stop only at max_depth or "
                        "65536 bounces); make the albedo less than 1 or open the enclosure")


def _read_prims(ctx: _Context, stage: Usd.Stage) -> tuple[Geometry, list[Light], list[Sensor]]:
    """Walk every active prim, instance proxies included, and sort it into geometry, lights, sensors.

    A PointInstancer's subtree is not walked: its prototypes are drawn where
    its instances stand (:mod:`.instancers`), not in their own place.
    """
    geo = _GeometryBuilder()
    lights: list[Light] = []
    sensors: list[Sensor] = []
    domes: list[tuple[Light, Usd.Prim]] = []
    portals = {}
    walk = _traverse(stage)
    for prim in walk:
        if _is_sensor(prim):
            sensors.append(_read_sensor(ctx, prim))  # sensors ignore visibility and purpose
        if not _is_rendered(ctx, prim):
            continue
        if prim.IsA(UsdGeom.PointInstancer):
            walk.PruneChildren()
            note_animated(ctx, prim)
            _read_instancer(ctx, prim, geo)
        elif prim.IsA(UsdGeom.Gprim):
            note_animated(ctx, prim)
            _read_gprim(ctx, prim, geo)  # MeshLightAPI prims too: geometry that emits
        elif is_portal(prim):
            if (portal := read_portal(ctx, prim)) is not None:
                portals[portal.name] = portal
        elif prim.HasAPI(UsdLux.LightAPI):
            if not _is_supported_light(prim):
                ctx.not_read[prim.GetTypeName() or "untyped light"] += 1
                continue
            note_animated(ctx, prim)
            light = _read_light(ctx, prim)
            if light is not None:
                lights.append(light)
                if light.kind == LightKind.DOME:
                    domes.append((light, prim))
    attach_portals(ctx, stage, domes, portals)
    return geo.build(ctx.reflectances, ctx.emissive_spectra, ctx.surfaces, ctx.coverage_textures), lights, sensors
