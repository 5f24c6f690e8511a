"""Surface materials: UsdPreviewSurface albedo, emission and opacity, displayColor, greys.

A gprim's bound ``UsdPreviewSurface`` gives its Lambertian albedo
(``diffuseColor``), its front-face emitted radiance (``emissiveColor``) and
how much of it is there (``opacity``: in ``presence`` mode or under an
``opacityThreshold`` its coverage, 0 removes it; in the default
``transparent`` mode a clear pane of its ``ior`` over 1 − opacity of it). The binding is the
one ``UsdShadeMaterialBindingAPI.ComputeBoundMaterial`` resolves for the
``full`` purpose (a final render), which falls back to the all-purpose
binding and honours collection bindings (``material:binding:collection:*``)
and ``bindMaterialAs`` strength; a ``GeomSubset`` of the ``materialBind``
family resolves its own binding the same way (see
:func:`simulator.scene.usd.geometry._face_surfaces`).

Inputs are followed through connections to authored constants; an input
connected to a ``UsdUVTexture`` reads the texture's mean value
(:mod:`.textures`). With no usable material, ``primvars:displayColor`` or
the UsdPreviewSurface default is the albedo. Colours become luminance greys
(BT.709 Y), each kept beside its grey for spectral transport (the albedo
colour, and ``emissiveColor``'s where it is not grey); a material's ``probesim:reflectance`` names a measured curve
that replaces ``diffuseColor`` (:func:`_measured_reflectance`). Summary warnings, one line each, name the prims whose colour was
not grey, the inputs read as a texture mean, the albedo-1 surfaces, and the
inputs that would change the reading but are ignored (``roughness``,
``metallic``, ``specularColor``, ... authored away from the UsdPreviewSurface
fallback, counted by name).
"""

from __future__ import annotations

import math
import os

import numpy as np
from pxr import Sdf, Usd, UsdGeom, UsdShade

from simulator.errors import UserError
from simulator.units import luminance_grey
from simulator.scene.usd.context import _Context, _get, _layer_relative, _name_list, _not_uniform
from simulator.scene.usd.surface_mapping import IGNORED_PREVIEW_DEFAULTS
from simulator.scene.usd.textures import _texture_mean

#: UsdPreviewSurface's fallback diffuseColor (0.18, 0.18, 0.18), used when nothing is authored
DEFAULT_ALBEDO = 0.18
#: a material's measured reflectance: ``asset`` (or ``string``) path of a reflectance CSV, on the
#: Material or its UsdPreviewSurface shader (the shader's wins), relative to the layer that authors it
REFLECTANCE_ATTR = "probesim:reflectance"

#: a glazing datasheet's normal-incidence visible transmittance, ``float``, on the Material or its
#: UsdPreviewSurface shader (the shader's wins): the material is then an absorbing thin slab
TRANSMITTANCE_ATTR = "probesim:transmittance"

# UsdPreviewSurface input fallbacks (from its specification). Every input here is read into the
# inputs dict (``{name: (value, where)}``) that :func:`_preview_surface_inputs` returns, and from
# that dict alone into the face's surface (:func:`_surface_row`), whatever wrote the dict.
_PREVIEW_DEFAULTS = {
    "diffuseColor": (DEFAULT_ALBEDO,) * 3,
    "emissiveColor": (0.0, 0.0, 0.0),
    "opacity": 1.0,
    "opacityThreshold": 0.0,
    "opacityMode": "transparent",
    "roughness": 0.5,
    "metallic": 0.0,
    "specularColor": (0.0, 0.0, 0.0),
    "useSpecularWorkflow": 0,
    "ior": 1.5,
    "clearcoat": 0.0,
    "clearcoatRoughness": 0.01,
}

# inputs of the specular and clearcoat lobes: authored away from the fallback, they give the face the
# UsdPreviewSurface BSDF (a face with all of them at their fallbacks stays Lambertian: the fallback's 4%
# specular at roughness 0.5 is read as part of its matte albedo)
_UNMODELLED = ("roughness", "metallic", "specularColor", "useSpecularWorkflow", "clearcoat", "clearcoatRoughness")

# UsdPreviewSurface inputs probesim does not read, with their fallbacks: an
# input authored (or connected) away from its fallback is counted as ignored
# (declared beside the MaterialX/MDL mappings, which count them the same way).
_IGNORED_DEFAULTS = IGNORED_PREVIEW_DEFAULTS


def _surface(ctx: _Context, prim: Usd.Prim,
             bind_prim: Usd.Prim | None = None) -> tuple[float, tuple[float, float], np.ndarray, int, np.ndarray, int] | None:
    """``(albedo, emission pair, albedo colour (3,), reflectance id, emission colour (3,), surface id)`` of a
    gprim, or None when presence opacity 0 (or a cut-out threshold above it) removes it.

    The surface id indexes ``ctx.surfaces`` (:func:`_surface_row`), -1 for a
    matte face.

    ``bind_prim`` (default ``prim``) is where the material binding is
    resolved: a GeomSubset of ``prim`` for the subset's faces. The
    reflectance id indexes ``ctx.reflectances`` (a measured curve, whose
    grey is then the albedo), -1 without one. The emission colour is the
    linear sRGB ``emissiveColor`` whose grey the pair carries, (1, 1, 1)
    where it is grey (:func:`_emission_colour`).
    """
    inputs = _material_inputs(ctx, prim if bind_prim is None else bind_prim)
    if inputs is None:
        rgb, source = _display_color(ctx, prim)
        inputs = {"diffuseColor": (rgb, source), "emissiveColor": (_PREVIEW_DEFAULTS["emissiveColor"], ""),
                  "opacity": (1.0, ""), "_surface_key": "displayColor"}
    sid = _surface_row(ctx, prim if bind_prim is None else bind_prim, inputs)
    if sid is None:
        return None
    curve = inputs.get("reflectance", (-1, ""))[0]
    albedo = _albedo(ctx, prim, inputs) if curve < 0 else ctx.reflectances[curve][2]
    rgb, source = inputs["emissiveColor"]
    radiance = _grey(ctx, prim, rgb)
    if not (math.isfinite(radiance) and radiance >= 0.0):
        raise ctx.error(prim, f"emission {radiance:g} from {source} must be a non-negative number")
    if radiance > 0.0:
        ctx.emissive_spectra[(None, False)] = None
    emission_colour = _emission_colour(rgb, radiance)
    if np.any(emission_colour < 0.0) or not np.all(np.isfinite(emission_colour)):
        raise ctx.error(prim, f"emissiveColor {tuple(float(v) for v in emission_colour)} from {source} must have "
                              "non-negative channels")
    colour = _albedo_colour(inputs, albedo) if curve < 0 else np.full(3, albedo)
    return albedo, ctx.emission(radiance), colour, curve, emission_colour, sid


def _in_unit(ctx: _Context, prim: Usd.Prim, inputs: dict, name: str) -> float:
    """A scalar input that must lie in [0, 1]; one line naming the prim and input otherwise."""
    value, source = inputs.get(name, (_PREVIEW_DEFAULTS[name], "the default"))
    v = float(np.mean(value)) if isinstance(value, tuple) else float(value)
    if not (math.isfinite(v) and 0.0 <= v <= 1.0):
        raise ctx.error(prim, f"inputs:{name} {v:g} from {source} must be in [0, 1]")
    return v


def _surface_row(ctx: _Context, prim: Usd.Prim, inputs: dict) -> int | None:
    """The ``ctx.surfaces`` index of the surface these material inputs make (-1: matte), None when the
    face is left out (opacity 0 in presence mode, or a cut-out threshold above it).

    Reads and validates, from the inputs dict only (so any reader that fills
    it, UsdPreviewSurface or another network mapped onto its inputs, is read
    alike): ``opacity``, ``opacityThreshold``, ``opacityMode``, ``ior``,
    :data:`TRANSMITTANCE_ATTR`, and ``roughness``, ``metallic``,
    ``specularColor``, ``useSpecularWorkflow``, ``clearcoat``,
    ``clearcoatRoughness`` (the BSDF's lobes, modelled where any is authored
    away from its fallback). Rules: :mod:`simulator.scene.surfaces`; in the
    default ``transparent`` mode opacity 0 is a clear pane of the ``ior`` and
    0 < opacity < 1 a translucent layer, and only ``presence`` mode or an
    ``opacityThreshold`` removes a face.

    Raises
    ------
    UserError
        ``<stage>: <prim>: inputs:<name> <value> from <where> ...``: a value
        in [0, 1] outside it, an ior below 1, an opacityMode other than
        ``transparent`` or ``presence``, a transmittance outside (0, 1] or
        above what a clear slab of that ior transmits.
    """
    from simulator.scene.surfaces import OPACITY_MODES, Surface, clear_slab_transmittance, internal_transmittance

    key = inputs.get("_surface_key", None)
    if key is None:
        key = id(inputs)
    if key in ctx.surface_index:
        sid = ctx.surface_index[key]
        if isinstance(sid, str):  # left out: say so for every prim
            ctx.warn(f"{prim.GetPath()}: {sid}; left out (it blocks no light)")
            return None
        return sid
    opacity = _in_unit(ctx, prim, inputs, "opacity")
    threshold = _in_unit(ctx, prim, inputs, "opacityThreshold")
    values = {n: _in_unit(ctx, prim, inputs, n) for n in ("roughness", "metallic", "clearcoat", "clearcoatRoughness")}
    mode, mode_src = inputs.get("opacityMode", ("transparent", "the default"))
    mode = str(mode)
    if mode not in OPACITY_MODES:
        raise ctx.error(prim, f"inputs:opacityMode {mode!r} from {mode_src} must be one of {', '.join(OPACITY_MODES)}")
    ior, ior_src = inputs.get("ior", (_PREVIEW_DEFAULTS["ior"], "the default"))
    ior = float(np.mean(ior)) if isinstance(ior, tuple) else float(ior)
    if not (math.isfinite(ior) and ior >= 1.0):
        raise ctx.error(prim, f"inputs:ior {ior:g} from {ior_src} must be at least 1")
    spec, spec_src = inputs.get("specularColor", (_PREVIEW_DEFAULTS["specularColor"], "the default"))
    spec = tuple(float(v) for v in np.broadcast_to(np.asarray(spec, float), (3,)))
    if not all(math.isfinite(v) and 0.0 <= v <= 1.0 for v in spec):
        raise ctx.error(prim, f"inputs:specularColor {spec} from {spec_src} must have channels in [0, 1]")
    workflow = bool(int(float(np.mean(inputs.get("useSpecularWorkflow", (0, ""))[0]))))
    t0, t0_src = inputs.get(TRANSMITTANCE_ATTR, (None, ""))
    tau = 1.0
    if t0 is not None:
        t0 = float(t0)
        if not (math.isfinite(t0) and 0.0 < t0 <= 1.0):
            raise ctx.error(prim, f"{TRANSMITTANCE_ATTR} {t0:g} from {t0_src} must be in (0, 1]")
        try:
            tau = internal_transmittance(t0, ior)
        except ValueError as e:
            raise ctx.error(prim, f"{TRANSMITTANCE_ATTR} {t0:g} from {t0_src}: {e}") from None
    spectrum = inputs.get("_transmittance_spectrum")
    if spectrum is not None:
        peak = float(np.max(spectrum[1]))
        clear = clear_slab_transmittance(ior)
        if peak > clear + 1e-12:
            raise ctx.error(prim, f"{TRANSMITTANCE_ATTR} {spectrum[0]}: its peak {peak:.4g} is above the "
                                  f"{clear:.4f} a clear slab of ior {ior:g} transmits")
    tex, tex_why = inputs.get("_opacity_texture", (-1, ""))
    # transparent mode (no threshold): opacity 0 is clear glass of the ior ("even a fully transparent
    # object still receives lighting as, for example, perfectly clear glass still has a specular
    # response", UsdPreviewSurface spec), 0 < o < 1 a translucent layer (matte over o, the clear pane
    # over 1 - o; scene.surfaces); only presence mode or a threshold removes a surface
    transparent = threshold == 0.0 and mode == "transparent"
    layered = transparent and 0.0 < opacity < 1.0 and t0 is None
    per_texel = tex >= 0 and (threshold > 0.0 or mode == "presence" or layered) and t0 is None
    coverage, pane = 1.0, False
    if threshold > 0.0:  # a cut-out: opacity below the threshold is not there, at or above it is opaque
        coverage = 1.0 if opacity >= threshold else 0.0
    elif mode == "presence":
        coverage = opacity
    elif opacity <= 0.0:  # wholly transparent: a clear pane of the ior
        pane = True
    elif layered:
        coverage, pane = opacity, True
    if t0 is not None:
        pane = True
        if coverage <= 0.0 or transparent:
            coverage = 1.0  # a datasheet pane: its transmittance, not its opacity, lets light through
    if coverage <= 0.0 and not per_texel:
        why = f"opacity {opacity:g} below opacityThreshold {threshold:g}" if threshold > 0 else "opacity 0 in presence mode"
        ctx.warn(f"{prim.GetPath()}: {why}; left out (it blocks no light)")
        ctx.surface_index[key] = why
        return None
    fallback = {n: _PREVIEW_DEFAULTS[n] for n in _UNMODELLED}
    got = dict(values, specularColor=spec, useSpecularWorkflow=int(workflow))
    authored = tuple(n for n in _UNMODELLED
                     if not np.allclose(np.asarray(got[n], float), np.asarray(fallback[n], float), rtol=0, atol=1e-6))
    # a face with any of these away from its fallback gets the UsdPreviewSurface BSDF (kernels.bsdf); on a
    # pane they are read but not modelled (the slab is what it is), counted in the summary warning
    glossy = bool(authored) and not pane  # (a translucent layer's opaque share is matte)
    unmodelled = authored if pane else ()
    for n in unmodelled:
        ctx.ignored[f"inputs:{n}"] += 1  # read and validated; not modelled on a pane
    if per_texel:  # read per texel, not as the mean the summary's textured inputs count
        ctx.textured["opacity"] -= 1
        if ctx.textured["opacity"] <= 0:
            del ctx.textured["opacity"]
    if (coverage < 1.0 or threshold > 0.0) and not per_texel and "mean of the texture" in inputs.get("opacity", ("", ""))[1]:
        how = f"{tex_why}: " if tex_why else ""
        ctx.ignored[f"inputs:opacity from a texture ({how}coverage is its mean, not per texel)"] += 1
    row = Surface(name=str(prim.GetPath()), coverage=coverage, pane=pane, layered=layered, ior=ior, tau=tau, transmittance=t0,
                  roughness=values["roughness"], metallic=values["metallic"], clearcoat=values["clearcoat"],
                  clearcoat_roughness=values["clearcoatRoughness"], specular_color=spec,
                  use_specular_workflow=workflow, opacity=opacity, opacity_threshold=threshold, opacity_mode=mode,
                  unmodelled=unmodelled, glossy=glossy, opacity_texture=tex if per_texel else -1,
                  thin_walled=bool(inputs.get("_thin_walled", (False, ""))[0]) and pane,
                  transmittance_spectrum=spectrum if pane else None)
    sid = -1
    if row.modelled:
        sid = len(ctx.surfaces)
        ctx.surfaces.append(row)
    ctx.surface_index[key] = sid
    return sid


def _emission_colour(rgb, radiance: float) -> np.ndarray:
    """The linear sRGB ``emissiveColor`` of a face, shape (3,), for spectral transport: the colour itself
    where it is not grey (its BT.709 grey is the face's radiance), else (1, 1, 1), the shared spectrum."""
    c = np.atleast_1d(np.asarray(rgb, float))
    if c.size != 3 or radiance <= 0.0 or not _not_uniform(np.ptp(c), float(np.max(np.abs(c)))):
        return np.ones(3)
    return c.copy()


def _measured_reflectance(ctx: _Context, material: UsdShade.Material, shader: UsdShade.Shader) -> int:
    """Index into ``ctx.reflectances`` of the curve a material names (:data:`REFLECTANCE_ATTR`), -1 if none.

    The file is read once per resolved path
    (:func:`simulator.spectra.reflectance.measured_reflectance`); a file
    that does not cover 380–780 nm is warned about (its end values are
    held). An authored ``diffuseColor`` beside it is counted as ignored.

    Raises
    ------
    UserError
        ``<stage>: <prim>: probesim:reflectance: <what is wrong>``: not an
        asset or string, an empty path, or the file's own error (missing
        file, bad header, a row outside [0, 1), ...) naming file and line.
    """
    from simulator.spectra.reflectance import measured_reflectance

    attr = next((a for a in (p.GetAttribute(REFLECTANCE_ATTR) for p in (shader.GetPrim(), material.GetPrim()))
                 if a and a.HasAuthoredValue()), None)
    if attr is None:
        return -1
    owner = attr.GetPrim()
    value = attr.Get(ctx.time)
    if isinstance(value, Sdf.AssetPath):
        authored, path = value.path, value.resolvedPath or _layer_relative(attr, value.path)
    elif isinstance(value, str):
        authored, path = value, _layer_relative(attr, value)
    else:
        raise ctx.error(owner, f"{REFLECTANCE_ATTR} must be an asset (or string) path of a reflectance .csv, "
                               f"not a {attr.GetTypeName()}")
    if not authored.strip():
        raise ctx.error(owner, f"{REFLECTANCE_ATTR} is empty (expected the path of a reflectance .csv)")
    key = os.path.abspath(path)
    if key not in ctx.reflectance_index:
        try:
            rho, grey, notes = measured_reflectance(key)
        except UserError as e:
            raise ctx.error(owner, f"{REFLECTANCE_ATTR}: {e}") from None
        for note in notes:
            ctx.warn(f"{owner.GetPath()}: {REFLECTANCE_ATTR}: {note}")
        ctx.reflectance_index[key] = len(ctx.reflectances)
        ctx.reflectances.append((os.path.basename(key), rho, grey))
    diffuse = shader.GetInput("diffuseColor")
    if diffuse and (diffuse.HasConnectedSource() or diffuse.GetAttr().HasAuthoredValue()):
        ctx.ignored[f"inputs:diffuseColor beside {REFLECTANCE_ATTR} (the measured curve is used)"] += 1
    return ctx.reflectance_index[key]


def _albedo_colour(inputs: dict, albedo: float) -> np.ndarray:
    """The linear sRGB ``diffuseColor`` whose grey is ``albedo``, shape (3,): ``(a, a, a)`` for a scalar
    or grey input, and exactly (1, 1, 1) where the grey was read as 1 (spectral transport uplifts it)."""
    c = np.atleast_1d(np.asarray(inputs["diffuseColor"][0], float))
    if c.size != 3 or albedo == 1.0 or np.ptp(c) == 0.0:
        return np.full(3, albedo)
    return c.copy()


def _albedo(ctx: _Context, prim: Usd.Prim, inputs: dict) -> float:
    """Grey ``diffuseColor`` of material inputs, which must lie in [0, 1] (energy conservation).

    An albedo of 1 (to 1e-9: ``(1, 1, 1)``'s BT.709 grey rounds to
    1 + 2e-16) is read as exactly 1 and named in a summary warning: such a
    surface absorbs nothing, so a path ends only when it escapes the scene
    (see :func:`_finish_warnings`).
    """
    rgb, source = inputs["diffuseColor"]
    albedo = _grey(ctx, prim, rgb)
    if math.isfinite(albedo) and 1.0 <= albedo <= 1.0 + 1e-9:
        ctx.white[str(prim.GetPath())] = None
        return 1.0
    if not (math.isfinite(albedo) and 0.0 <= albedo < 1.0):
        raise ctx.error(prim, f"albedo {albedo:g} from {source} must be in [0, 1] (energy conservation)")
    return albedo


def _grey(ctx: _Context, prim: Usd.Prim, rgb) -> float:
    """Luminance grey of a colour (or a scalar); remember prims whose colour was not grey."""
    c = np.atleast_1d(np.asarray(rgb, float))
    if c.size == 1:
        return float(c[0])
    if _not_uniform(np.ptp(c), float(np.max(np.abs(c)))):
        ctx.coloured[str(prim.GetPath())] = None
    return luminance_grey(c)


def _finish_warnings(ctx: _Context) -> None:
    """The summary warnings, one line each: greys, texture means, albedo 1, subdivision, what was not read.

    Notes
    -----
    Albedo 1: the kernels multiply a path's throughput by the albedo at each
    bounce and play Russian roulette only once it falls below 0.1, so on an
    albedo-1 surface nothing ends a path but escaping the scene. In an open
    scene that is the right reading (E/pi off a white floor); in an
    enclosure no light escapes from, the true reading is infinite and the
    estimate is cut at ``max_depth`` bounces (65,536 vertices when
    unlimited), finite but meaningless and slow (measured: a closed 4 m
    albedo-1 cube around a sphere light read 26,964 lx where albedo 0.99
    reads 44 lx, at 65,536 rays per sample). Light sealed in a watertight
    albedo-1 surface is refused (:mod:`simulator.scene.enclosures`); the warning covers
    the enclosures that check cannot see.
    """
    if ctx.coloured:
        ctx.warn(f"coloured albedo/emission/light colour reduced to luminance grey: {_name_list(list(ctx.coloured))}")
    if ctx.textured:
        inputs = ", ".join(f"{n} x inputs:{name}" for name, n in sorted(ctx.textured.items()))
        ctx.warn(f"textured inputs read as their texture's mean value (a uniform surface): {inputs} "
                 f"({len(ctx.textures)} texture file(s))")
    if ctx.white:
        ctx.warn(f"albedo 1 (no absorption) on {_name_list(list(ctx.white))}: paths end there only by escaping "
                 "the scene; in an enclosure no light leaves the reading diverges, and unless the enclosure is "
                 "watertight (then the stage is refused) it is cut at max_depth (65536 bounces when unlimited)")
    if ctx.subdivided:
        meshes = ", ".join(f"{n} {scheme}" for scheme, n in sorted(ctx.subdivided.items()))
        ctx.warn(f"subdivision surfaces read as their control cage (not refined; glossy and mirror faces shaded by "
                 f"the cage's smooth normals): {meshes} mesh(es)")
    parts = []
    if ctx.not_read:
        parts.append("not read: " + ", ".join(f"{n} {what}" for what, n in sorted(ctx.not_read.items())))
    if ctx.ignored:
        parts.append("ignored: " + ", ".join(f"{n} x {what}" for what, n in sorted(ctx.ignored.items())))
    parts += ctx.summary_parts()
    if parts:
        ctx.warn(f"{os.path.basename(ctx.path)}: " + "; ".join(parts))


def _material_inputs(ctx: _Context, prim: Usd.Prim) -> dict | None:
    """The bound UsdPreviewSurface's inputs as ``{name: (value, where)}``, None without a usable material."""
    material, _ = UsdShade.MaterialBindingAPI(prim).ComputeBoundMaterial(UsdShade.Tokens.full)
    if not material:  # a binding into a referenced .mtlx composes no prim (no usdMtlx in usd-core)
        from simulator.scene.usd.materialx import _unresolved_binding
        return _unresolved_binding(ctx, prim)
    key = str(material.GetPath())
    if key not in ctx.materials:
        ctx.materials[key] = _preview_surface_inputs(ctx, material)
    return ctx.materials[key]


def _preview_surface_inputs(ctx: _Context, material: UsdShade.Material) -> dict | None:
    """Read diffuseColor/emissiveColor/opacity off a material's UsdPreviewSurface (or, without one, its
    MaterialX or Omniverse MDL surface mapped onto UsdPreviewSurface's inputs: :mod:`.materialx`, :mod:`.mdl`)."""
    shader, _, _ = material.ComputeSurfaceSource()
    if not shader or shader.GetShaderId() != "UsdPreviewSurface":
        from simulator.scene.usd.materialx import _materialx_inputs
        from simulator.scene.usd.mdl import _mdl_inputs
        # None: neither MaterialX nor Omniverse MDL; {}: one of them, not mapped (named by its reader)
        mapped = _materialx_inputs(ctx, material)
        mapped = _mdl_inputs(ctx, material) if mapped is None else mapped
        ident = shader.GetShaderId() if shader else None
        if not ident:  # e.g. only an outputs:mdl:surface or outputs:mtlx:surface
            contexts = sorted({o.GetBaseName().rpartition(":")[0] or "universal" for o in material.GetSurfaceOutputs()
                               if o.HasConnectedSource()})
            ident = "/".join(contexts) or "no"
        if mapped is None:
            ctx.not_read[f"material(s) with a {ident} surface, not UsdPreviewSurface (displayColor or 0.18 used)"] += 1
        attr = material.GetPrim().GetAttribute(REFLECTANCE_ATTR)
        if attr and attr.HasAuthoredValue():
            ctx.ignored[f"{REFLECTANCE_ATTR} on a material with no UsdPreviewSurface"] += 1
        return mapped or None
    _count_ignored_inputs(ctx, shader)
    curve = _measured_reflectance(ctx, material, shader)
    inputs = {name: _input_value(ctx, shader, name, default) for name, default in _PREVIEW_DEFAULTS.items()
              if curve < 0 or name != "diffuseColor"}
    inputs["opacityMode"] = _opacity_mode(ctx, material, shader, inputs["opacityMode"])
    inputs["_opacity_texture"] = _opacity_texture(ctx, shader)
    t0 = _transmittance(ctx, (shader.GetPrim(), material.GetPrim()))
    if t0 is not None:
        inputs[TRANSMITTANCE_ATTR] = t0[:2]
        if t0[2] is not None:
            inputs["_transmittance_spectrum"] = t0[2]
    if curve >= 0:
        inputs["diffuseColor"] = ((ctx.reflectances[curve][2],) * 3, f"{REFLECTANCE_ATTR} {ctx.reflectances[curve][0]}")
        inputs["reflectance"] = (curve, inputs["diffuseColor"][1])
    return inputs


def _opacity_texture(ctx: _Context, shader: UsdShade.Shader) -> tuple[int, str]:
    """``(index into ctx.coverage_textures, "")`` of the texture ``inputs:opacity`` reads per texel, or
    ``(-1, why not)`` (:func:`.textures._coverage_texture`; a file that cannot be read is an error)."""
    from simulator.scene.usd.textures import _coverage_texture

    where = f"{shader.GetPath()}.inputs:opacity"
    inp = shader.GetInput("opacity")
    if not inp or not inp.HasConnectedSource():
        return -1, "not connected"
    for attr in inp.GetValueProducingAttributes():
        if UsdShade.Output.IsOutput(attr):
            return _coverage_texture(ctx, attr, where)
    return -1, "not connected"


def _opacity_mode(ctx: _Context, material: UsdShade.Material, shader: UsdShade.Shader, read):
    """``opacityMode`` as ``(token, where)``: the shader's input (through connections), else an
    ``inputs:opacityMode`` on the Material itself (some exporters author it there), else the fallback."""
    inp = shader.GetInput("opacityMode")
    if inp and (inp.HasConnectedSource() or inp.GetAttr().HasAuthoredValue()):
        return str(read[0]), read[1]
    attr = material.GetPrim().GetAttribute("inputs:opacityMode")
    if attr and attr.HasAuthoredValue():
        return str(_get(ctx, attr)), str(attr.GetPath())
    return str(read[0]), read[1]


def _transmittance(ctx: _Context, prims):
    """``(T0, where, spectrum)`` of the first prim's authored :data:`TRANSMITTANCE_ATTR`, None if none
    authors it: a number (``spectrum`` None), or an asset (or string) path of a transmittance CSV
    (:func:`simulator.spectra.transmittance.measured_transmittance`), relative to the layer that
    authors it, whose grey is T0 and ``spectrum`` ``(file name, T0(λ) (401,))``.

    Raises
    ------
    UserError
        ``<stage>: <prim>: probesim:transmittance: <what is wrong>``: neither a number nor a path, an
        empty path, or the file's own error (missing, bad header, a value outside [0, 1], ...).
    """
    from simulator.spectra.transmittance import measured_transmittance

    for p in prims:
        attr = p.GetAttribute(TRANSMITTANCE_ATTR)
        if not (attr and attr.HasAuthoredValue()):
            continue
        value = _get(ctx, attr)
        if isinstance(value, (Sdf.AssetPath, str)):
            authored = value.path if isinstance(value, Sdf.AssetPath) else value
            path = (value.resolvedPath if isinstance(value, Sdf.AssetPath) else "") or _layer_relative(attr, authored)
            if not authored.strip():
                raise ctx.error(p, f"{TRANSMITTANCE_ATTR} is empty (expected a number or the path of a "
                                   "transmittance .csv)")
            try:
                spectrum, grey, notes = measured_transmittance(os.path.abspath(path))
            except UserError as e:
                raise ctx.error(p, f"{TRANSMITTANCE_ATTR}: {e}") from None
            for note in notes:
                ctx.warn(f"{p.GetPath()}: {TRANSMITTANCE_ATTR}: {note}")
            return grey, f"{attr.GetPath()} ({os.path.basename(path)})", (os.path.basename(path), spectrum)
        try:
            return float(value), str(attr.GetPath()), None
        except (TypeError, ValueError):
            raise ctx.error(p, f"{TRANSMITTANCE_ATTR} must be a number or the path of a transmittance .csv, "
                               f"not a {attr.GetTypeName()}") from None
    return None


def _count_ignored_inputs(ctx: _Context, shader: UsdShade.Shader) -> None:
    """Count the UsdPreviewSurface inputs that would change the reading but are not modelled."""
    for name, default in _IGNORED_DEFAULTS.items():
        inp = shader.GetInput(name)
        if not inp:
            continue
        if inp.HasConnectedSource():
            ctx.ignored[f"inputs:{name} (connected)"] += 1
            continue
        value = _get(ctx, inp.GetAttr())
        if value is not None and not np.allclose(np.asarray(value, float), np.asarray(default, float),
                                                 rtol=0, atol=1e-6):
            ctx.ignored[f"inputs:{name}"] += 1


def _input_value(ctx: _Context, shader: UsdShade.Shader, name: str, default):
    """Value of a shader input, through connections to an authored constant; else the default.

    ``GetValueProducingAttributes`` follows connections through NodeGraph and
    Material interface inputs. A UsdUVTexture output at the end gives the
    texture's mean value (:func:`.textures._texture_mean`, counted for the
    summary warning); any other shader output is not a constant: the
    UsdPreviewSurface default is used and the input counted as ignored.
    """
    inp = shader.GetInput(name)
    where = f"{shader.GetPath()}.inputs:{name}"
    if not inp:
        return default, f"{where} (default)"
    for attr in inp.GetValueProducingAttributes():
        if UsdShade.Output.IsOutput(attr):
            value, why = _texture_mean(ctx, attr)
            if value is None:
                ctx.ignored[f"inputs:{name} {why} (default used)"] += 1
                return default, f"{where} (default)"
            ctx.textured[name] += 1
            return (value if len(value) > 1 else float(value[0])), f"{where} (mean of the texture at {attr.GetPath()})"
        value = _get(ctx, attr)
        if value is not None:
            if isinstance(value, (tuple, str)):
                return value, str(attr.GetPath())
            return float(value), str(attr.GetPath())
    return default, f"{where} (default)"


def _display_color(ctx: _Context, prim: Usd.Prim):
    """``primvars:displayColor`` as albedo when authored (mean of many values), else the default grey."""
    pv = UsdGeom.Gprim(prim).GetDisplayColorPrimvar()
    if pv and pv.HasAuthoredValue():
        values = np.asarray(pv.ComputeFlattened(ctx.time) or [], float).reshape(-1, 3)
        if len(values):
            if len(values) > 1 and np.ptp(values, axis=0).max() > 0:
                ctx.ignored["varying primvars:displayColor (averaged to one albedo)"] += 1
            return tuple(values.mean(axis=0)), f"{prim.GetPath()}.primvars:displayColor"
    return _PREVIEW_DEFAULTS["diffuseColor"], "the default albedo"
