"""UsdLux lights and geometry lights: shapes in world size, the emission rule, dome maps.

A UsdLux light becomes a :class:`~simulator.scene.model.Light` whose
emission follows the UsdLux "Quantities and units" rule (see
:func:`simulator.scene.usd.load_stage`)::

    value = intensity * 2**exposure * grey(color) / sizeFactor

with its sizes in world metres, or, where the prim states its lumens
(``probesim:flux_lm``, or ``probesim:power_W`` × ``probesim:efficacy_lm_per_W``),
the emission that sends those lumens out (:mod:`simulator.scene.usd.flux`).
A textured DomeLight carries its lat-long
OpenEXR map as luminance grey. A gprim with ``MeshLightAPI`` (or
``LightAPI`` applied directly) is geometry that emits: the same light
inputs give its radiance, and its bound material gives only its albedo.
"""

from __future__ import annotations

import math
import os

import numpy as np
from pxr import Sdf, Usd, UsdGeom, UsdLux

from simulator.errors import UserError
from simulator.units import luminance_grey
from simulator.scene.model import Light, LightKind
from simulator.scene.usd.legacy import lux_get
from simulator.scene.usd.context import _Context, _layer_relative, _not_uniform
from simulator.scene.usd.materials import _albedo, _albedo_colour, _grey, _material_inputs
from simulator.scene.usd.flux import apply_stated_output, stated_output
from simulator.scene.usd.shaping import has_shaping, read_shaping
from simulator.scene.usd.tessellation import _parallelogram_areas
from simulator.scene.usd.transforms import _axis_scales, _frame, _mean_scale, _world_affine

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

#: a light's own spectral shape: an illuminant name ("D65", "A", "LED-B3"), a temperature (a number
#: of kelvin or "3000K") or an SPD CSV (a string ending .csv, or an asset), relative to its layer
SPECTRUM_ATTR = "probesim:spectrum"

#: ``texture:format`` values a DomeLight may have (``automatic``: a lat-long map unless an EXR header says cube)
DOME_TEXTURE_FORMATS = ("latlong", "automatic")


def _is_supported_light(prim: Usd.Prim) -> bool:
    """True for the UsdLux light types probesim reads (see ``_LIGHT_SCHEMAS``)."""
    return any(prim.IsA(schema) for schema, _ in _LIGHT_SCHEMAS)


def _require_light(ctx: _Context, lights: list[Light], geometry) -> None:
    """Refuse a stage in which nothing emits: every reading would be a silent zero.

    A light that was read but emits nothing (``intensity`` 0, an ``exposure``
    of -inf, a black ``color``) counts as no light: a stage whose every
    light is at 0 is refused as one without lights, naming them.

    Raises
    ------
    UserError
        No UsdLux light was read and no triangle emits (``emissiveColor`` or
        a mesh light), or every light read emits 0.
    """
    emits = geometry.n_triangles > 0 and bool(np.any(geometry.emission > 0))
    if not lights and not emits:
        raise UserError(f"{ctx.path}: no light in the stage (no UsdLux light and no emissive geometry); "
                        "every reading would be zero")
    if not emits and not any(max(l.emission) > 0.0 for l in lights):
        names = ", ".join(l.name for l in lights[:3]) + (f" and {len(lights) - 3} more" if len(lights) > 3 else "")
        raise UserError(f"{ctx.path}: every light emits 0 ({names}: intensity, exposure or color at 0) and no geometry "
                        "emits; every reading would be zero")


def _read_light(ctx: _Context, prim: Usd.Prim) -> Light | None:
    """One UsdLux light resolved to world size and an emission pair (None if unsupported/empty)."""
    kind = next((k for schema, k in _LIGHT_SCHEMAS if prim.IsA(schema)), None)
    if kind is None:
        ctx.warn(f"{prim.GetPath()}: {prim.GetTypeName() or 'light'} is not a supported light; ignored")
        return None
    a, t = _world_affine(ctx, prim)
    raw, spectrum, normalize, source = _light_inputs(ctx, prim)
    stated = stated_output(ctx, prim)
    light = Light(name=str(prim.GetPath()), kind=kind, position=t, frame=_frame(ctx, prim, a, right_handed=False),
                  emission=(0.0, 0.0))
    value = _shape_light(ctx, prim, light, a, raw, normalize)
    if value is None:
        return None
    light.emission = ctx.emission(value, spectrum)
    light.spectrum = spectrum
    light.spectrum_authored = source == "own"
    colour = np.atleast_1d(np.asarray(lux_get(ctx, prim, UsdLux.LightAPI(prim).GetColorAttr()), float))
    if colour.size == 3 and np.ptp(colour) > 0.0:
        light.color = tuple(float(c) for c in colour)
    read_shaping(ctx, prim, light)
    if stated is not None:  # lumens (or W × lm/W): the emission that sends them out, after size and shaping
        apply_stated_output(ctx, prim, light, stated, spectrum)
        light.authored = dict(stated)
        return light
    light.authored = _authored_inputs(ctx, prim, normalize)
    if light.shaping is not None and light.shaping.absolute:  # the file's candelas × LLF: intensity is not used
        light.authored = {"ies_absolute": True, "light_loss_factor": light.shaping.light_loss_factor}
    if light.kind == LightKind.POINT and light.emission[1] == 0.0 and raw > 0:
        # a radius-0 sphere without normalize has I = L pi r^2 = 0, unless absolute photometry
        # (probesim:ies:absolute) set its candelas from the file: warn only when nothing is left
        ctx.warn(f"{prim.GetPath()}: SphereLight of radius 0 without normalize emits nothing")
    return light


def _authored_inputs(ctx: _Context, prim: Usd.Prim, normalize: bool) -> dict:
    """The inputs that set a light's output as the run record states them: intensity, exposure,
    normalize and the grey of its colour (``intensity × 2**exposure × grey`` before any size factor)."""
    api = UsdLux.LightAPI(prim)
    return {"intensity": float(lux_get(ctx, prim, api.GetIntensityAttr())),
            "exposure": float(lux_get(ctx, prim, api.GetExposureAttr())), "normalize": bool(normalize),
            "color_grey": float(_grey(ctx, prim, lux_get(ctx, prim, api.GetColorAttr())))}


def _light_inputs(ctx: _Context, prim: Usd.Prim) -> tuple[float, str | float, bool, str]:
    """``(value, spectrum, normalize, source)`` of any light: :func:`_light_value` and its ``normalize``
    flag.

    Shaping (cone, focus, IES profile) is read by :mod:`simulator.scene.usd.shaping`.
    """
    raw, spectrum, source = _light_value(ctx, prim)
    return raw, spectrum, bool(lux_get(ctx, prim, UsdLux.LightAPI(prim).GetNormalizeAttr())), source


def _light_value(ctx: _Context, prim: Usd.Prim) -> tuple[float, str | float, str]:
    """``intensity * 2**exposure * grey(color)``, the emitter's spectrum and where it came from:
    ``"own"`` (the prim's :data:`SPECTRUM_ATTR`, which wins over ``colorTemperature``, with a warning
    when both are on), ``"temperature"`` (``colorTemperature`` enabled) or ``""`` (the run's default)."""
    api = UsdLux.LightAPI(prim)
    intensity = float(lux_get(ctx, prim, api.GetIntensityAttr()))
    exposure = float(lux_get(ctx, prim, api.GetExposureAttr()))
    if not (math.isfinite(intensity) and intensity >= 0):
        raise ctx.error(prim, f"intensity must be a non-negative number, not {intensity:g}")
    if not math.isfinite(exposure):
        raise ctx.error(prim, f"exposure must be finite, not {exposure:g}")
    grey = _grey(ctx, prim, lux_get(ctx, prim, api.GetColorAttr()))
    if not (math.isfinite(grey) and grey >= 0):
        raise ctx.error(prim, f"color must be non-negative, grey {grey:g}")
    value = intensity * 2.0 ** exposure * grey
    own = _own_spectrum(ctx, prim)
    on = bool(lux_get(ctx, prim, api.GetEnableColorTemperatureAttr()))
    if own is not None:
        if on:
            ctx.warn(f"{prim.GetPath()}: colorTemperature ignored: {SPECTRUM_ATTR} names its spectrum")
        return value, own, "own"
    if not on:
        return value, ctx.default_spectrum, ""
    temperature = float(lux_get(ctx, prim, api.GetColorTemperatureAttr()))
    if not (math.isfinite(temperature) and temperature > 0):
        raise ctx.error(prim, f"colorTemperature must be a positive number of kelvin, not {temperature:g}")
    return value, temperature, "temperature"


def _own_spectrum(ctx: _Context, prim: Usd.Prim) -> str | float | None:
    """A light's :data:`SPECTRUM_ATTR` as :func:`simulator.spectra.sources.emitter_spectrum` reads it
    (an SPD path made absolute against the authoring layer), None when not authored.

    Raises
    ------
    UserError
        ``<stage>: <prim>: probesim:spectrum: ...``: a value of another
        type, an unknown illuminant, a temperature that is not positive, or
        the SPD file's own error (naming file and line).
    """
    from simulator.spectra.sources import emitter_spectrum

    attr = prim.GetAttribute(SPECTRUM_ATTR)
    if not attr or not attr.HasAuthoredValue():
        return None
    value = attr.Get(ctx.time)
    if isinstance(value, Sdf.AssetPath):
        spec = value.resolvedPath or _layer_relative(attr, value.path)
        if not value.path.lower().endswith(".csv"):
            raise ctx.error(prim, f"{SPECTRUM_ATTR}: asset {value.path!r} is not a .csv SPD file")
    elif isinstance(value, str):
        spec = value.strip()
        if spec.lower().endswith(".csv"):
            spec = _layer_relative(attr, spec)
    elif isinstance(value, (int, float)) and not isinstance(value, bool):
        spec = float(value)
    else:
        raise ctx.error(prim, f"{SPECTRUM_ATTR} must be a string (illuminant, '3000K', SPD .csv), a number of "
                              f"kelvin or an asset, not a {attr.GetTypeName()}")
    try:
        emitter_spectrum(spec)
    except UserError as e:
        raise ctx.error(prim, f"{SPECTRUM_ATTR}: {e}") from None
    return spec


def _size_attr(ctx: _Context, prim: Usd.Prim, attr: Usd.Attribute, what: str) -> float:
    """A non-negative light dimension in stage units (before the world scale)."""
    value = float(lux_get(ctx, prim, attr))
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
            return raw / 4.0 if normalize else raw * math.pi * r * r
        light.radius = r
        return raw / (4 * math.pi * r * r) if normalize else raw
    if kind == LightKind.RECT:
        rect = UsdLux.RectLight(prim)
        light.width = float(_size_attr(ctx, prim, rect.GetWidthAttr(), "width") * scales[0])
        light.height = float(_size_attr(ctx, prim, rect.GetHeightAttr(), "height") * scales[1])
        if lux_get(ctx, prim, rect.GetTextureFileAttr()):
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
    asset = lux_get(ctx, prim, "inputs:texture:file")  # same name on DomeLight and DomeLight_1
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


def _dome_texture_map(ctx: _Context, prim: Usd.Prim, path: str) -> np.ndarray:
    """A dome's lat-long map as luminance grey, shape (H, W), float64 (see :mod:`simulator.io.latlong`).

    ``texture:format`` must be ``latlong``, or ``automatic`` (read as
    lat-long, unless an OpenEXR header declares a cube map). The file may be
    OpenEXR or Radiance ``.hdr`` (RGBE, :mod:`simulator.io.hdr`): linear
    radiance, used as is. An 8-bit (or 16-bit) PNG, JPEG, ... is read as
    sRGB-encoded relative radiance and linearised
    (:func:`simulator.io.images.srgb_to_linear`), with a warning: such a map
    stops at 1, so a bright source in it (the sun) is clipped and the dome
    gives too little light. RGB becomes BT.709 Y (the weights of
    :func:`simulator.units.luminance_grey`); a grey image is used as is.
    Values must be finite and non-negative.
    """
    from simulator.io import exr
    from simulator.io.images import read_image, srgb_to_linear

    fmt = str(lux_get(ctx, prim, "inputs:texture:format") or "automatic")
    if fmt not in DOME_TEXTURE_FORMATS:
        raise ctx.error(prim, f"texture:format {fmt!r} of texture:file {path} is not supported "
                              "(only 'latlong', or 'automatic' for a lat-long map)")
    is_exr = path.lower().endswith(".exr")
    try:
        header = exr.read_header(path) if fmt == "automatic" and is_exr else {}
        if is_exr:
            rgb = exr.read_rgb(path)
        else:
            image = read_image(path, _texture_bytes(path))
            rgb = image.rgb
            if image.integer_bits:
                rgb = srgb_to_linear(rgb)
                ctx.warn(f"{prim.GetPath()}: texture:file {os.path.basename(path)} is a {image.integer_bits}-bit "
                         "image: read as sRGB relative radiance (linearised); it clips bright sources such as "
                         "the sun, so the dome's light is too low where it clips: prefer an .exr or .hdr map")
    except UserError as err:  # names the file; add the stage and prim
        raise ctx.error(prim, f"texture:file {err}") from None
    if "CUBE" in str(header.get("envmap", "")).upper():
        raise ctx.error(prim, f"texture:file {path} is a cube map (envmap header); only lat-long maps are supported")
    bad = int(np.sum(~np.isfinite(rgb).all(axis=-1) | (rgb < 0).any(axis=-1)))
    if bad:
        raise ctx.error(prim, f"texture:file {path}: {bad} texel(s) are negative, NaN or Inf")
    rgb = rgb.astype(np.float64)
    if _not_uniform(np.ptp(rgb, axis=-1).max(), float(rgb.max())):
        ctx.coloured[str(prim.GetPath())] = None
    h, w = rgb.shape[:2]
    if w != 2 * h:
        ctx.warn(f"{prim.GetPath()}: texture:file {path} is {w} x {h}, not 2:1; read as lat-long anyway")
    return luminance_grey(rgb)  # a grey texel keeps its value exactly


def _texture_bytes(path: str) -> bytes | None:
    """Bytes of a resolved texture inside a package (``pkg.usdz[tex.hdr]``); None for a plain file."""
    if "[" not in path:
        return None
    from simulator.scene.usd.textures import _asset_data

    return _asset_data(path)


def _is_geometry_light(ctx: _Context, prim: Usd.Prim) -> bool:
    """True for a gprim with MeshLightAPI (or LightAPI applied directly): geometry that emits."""
    if not prim.HasAPI(UsdLux.LightAPI):
        return False
    if prim.HasAPI(UsdLux.VolumeLightAPI):
        ctx.warn(f"{prim.GetPath()}: VolumeLightAPI ignored (read as a plain surface)")
        return False
    return True


def _geometry_light_surface(ctx: _Context, prim: Usd.Prim) -> tuple[float, tuple[float, float], np.ndarray, int]:
    """``(albedo, (0, 0), albedo colour (3,), reflectance id)`` of a geometry light; its emission comes from
    its light inputs (the reflectance id as :func:`simulator.scene.usd.materials._surface` gives it).

    The albedo is the bound UsdPreviewSurface's diffuseColor; 0 with no
    (usable) bound material or with ``light:materialSyncMode``
    ``noMaterialResponse``. Opacity is ignored: a light's surface is opaque.
    """
    sync = UsdLux.LightAPI(prim).GetMaterialSyncModeAttr().Get(ctx.time)
    if str(sync) == "noMaterialResponse":
        return 0.0, (0.0, 0.0), np.zeros(3), -1
    inputs = _material_inputs(ctx, prim)
    if inputs is None:
        return 0.0, (0.0, 0.0), np.zeros(3), -1
    albedo = _albedo(ctx, prim, inputs)
    if float(inputs["opacity"][0]) < 1.0:
        ctx.warn(f"{prim.GetPath()}: opacity of a mesh light ignored (its surface is opaque)")
    if _grey(ctx, prim, inputs["emissiveColor"][0]) != 0.0:
        ctx.warn(f"{prim.GetPath()}: emissiveColor of the bound material ignored; "
                 "a mesh light emits what its light inputs (intensity, exposure, color) say")
    return albedo, (0.0, 0.0), _albedo_colour(inputs, albedo), inputs.get("reflectance", (-1, ""))[0]


def _geometry_light_emission(ctx: _Context, prim: Usd.Prim, world: np.ndarray,
                             tris: np.ndarray) -> tuple[float, float]:
    """Emission pair of a geometry light: ``intensity * 2**exposure * grey(color)``,
    divided by its world area (one side) when ``normalize`` is on."""
    raw, spectrum, normalize, source = _light_inputs(ctx, prim)
    stated_output(ctx, prim, "mesh light")  # lumens are not read on a mesh light: refused if authored
    if has_shaping(prim):
        ctx.warn(f"{prim.GetPath()}: UsdLuxShapingAPI on a mesh light ignored")
    value = raw
    if normalize:
        area = float(0.5 * _parallelogram_areas(world, tris).sum())
        if area <= 0.0:
            ctx.warn(f"{prim.GetPath()}: mesh light has zero area and emits nothing")
            return (0.0, 0.0)
        value = raw / area
    if value > 0:
        ctx.emissive_spectra[(spectrum if source else None, source == "own")] = None
    return ctx.emission(value, spectrum)
