"""Omniverse MDL surfaces read from their authored inputs (no MDL compiler), as UsdPreviewSurface inputs.

A material whose ``outputs:mdl:surface`` is a shader with
``info:mdl:sourceAsset = @OmniPBR.mdl@`` (``OmniGlass.mdl``, ``OmniSurface*.mdl``)
and ``info:mdl:sourceAsset:subIdentifier`` naming the material is read from
the inputs the stage authors; an input not authored takes the module's
default. The formulas follow each module's own (OmniPBR.mdl, OmniGlass.mdl,
OmniSurfaceBase.mdl; docs/REFERENCES.md §Omniverse MDL materials);
``lerp(a, b, t) = (1 − t) a + t b`` and ``mean(tex)`` is
a texture's mean (:mod:`.textures`, ``colorSpace`` ``auto``/``sRGB``/``raw``):

OmniPBR (``OmniPBR``, ``OmniPBR_Opacity``, ``OmniPBR_ClearCoat*``)
    ``c = diffuse_texture ? lerp(t, Y(t), albedo_desaturation)`` with
    ``t = albedo_brightness · mean(diffuse_texture) + albedo_add``, else
    ``diffuse_color_constant``; ``diffuseColor = c · diffuse_tint``;
    ``roughness = lerp(reflection_roughness_constant, mean(roughness map),
    reflection_roughness_texture_influence)`` and
    ``metallic = lerp(metallic_constant, mean(metallic map), metallic_texture_influence)``
    (the ORM map's G and B channels when ``enable_ORM_texture``);
    ``ior = n(F0)`` with ``F0 = 0.08 · specular_level`` (the module's
    dielectric reflectivity at normal incidence, 0.04 = ior 1.5 at the default
    0.5); with ``enable_emission``,
    ``emissiveColor = emissive_intensity · c_e · mean(emissive_mask_texture) / π``
    with ``c_e = emissive_color`` (or ``mean(emissive_color_texture)``):
    MDL's ``material_emission`` defaults to radiant exitance, read as a
    luminous exitance in lm/m², so luminance is exitance / π (a Lambertian
    emitter), in cd/m² converted to the stage's light units; with
    ``enable_opacity``, ``opacity = opacity_constant`` (or
    ``opacity_texture`` per texel, the value ``opacity_mode`` selects: 0
    alpha, 1 the mean of RGB, 2 their luminance, 3 their maximum, MDL's
    ``base::mono_mode``), ``opacityMode = "presence"`` (MDL's
    ``cutout_opacity``), ``opacityThreshold = opacity_threshold``.
OmniGlass (``OmniGlass``, ``OmniGlass_Opacity``)
    A dielectric: ``opacity = 0``, ``diffuseColor = 0``, ``ior = glass_ior``,
    ``roughness = frosting_roughness`` (or the roughness map's mean by its
    influence); a tinted ``glass_color`` (grey ``τ < 1``, times the colour map's
    mean) is a datasheet ``probesim:transmittance`` of a thin slab with
    internal transmittance ``τ`` (:func:`.surface_mapping.slab_transmittance`).
OmniSurface (``OmniSurface``, ``OmniSurfaceBase``, ``OmniSurfaceLite*``)
    Autodesk Standard Surface with Omniverse's names, mapped as
    :mod:`.materialx` maps standard_surface: ``diffuseColor =
    diffuse_reflection_weight · diffuse_reflection_color · mix(1, coat_color, coat_weight)``,
    ``metallic = metalness``, ``roughness = specular_reflection_roughness``,
    ``ior = specular_reflection_ior``, ``clearcoat = coat_weight · mean(coat_color)``,
    ``specular_transmission_weight`` glazing; emission
    ``emission_weight · emission_intensity · emission_color`` in cd/m² for
    ``emission_mode`` 1 (nit), and / π for 0 (lux, the default: an exitance).

A per-asset module (``Steel.mdl``) whose material only calls one of these
templates with literal arguments is read through those arguments
(:mod:`.mdl_wrapper`); the stage's authored inputs win over them.

Inputs that only place a texture (tiling, rotation, UV set, projection) do
not change a uniform reading and are not named; every other input authored
away from its default that no formula reads (normal maps, anisotropy,
subsurface, sheen, ...) is named in the summary warning.
"""

from __future__ import annotations

import math
import os

import numpy as np
from pxr import UsdShade

from simulator.units import luminance_grey
from simulator.scene.usd.context import _Context
from simulator.scene.usd.materialx import _coat, _specular, _usd_node
from simulator.scene.usd.mdl_wrapper import wrapper_arguments
from simulator.scene.usd.shading_graph import Port
from simulator.scene.usd.surface_mapping import (SurfaceInputs, colour, complete, ior_of_f0,
                                                 nits_in_light_units, slab_transmittance, thin_walled,
                                                 transmission)
from simulator.scene.usd.textures import MONO_MODES, _mean_rgba

_WHITE = (1.0, 1.0, 1.0)

#: inputs that place a texture on the surface; they cannot change a texture's mean
_PLACEMENT = ("texture_translate", "texture_rotate", "texture_scale", "project_uvw", "world_or_object",
              "uv_space_index", "diffuse_wrapmode_u", "diffuse_wrapmode_v", "vertexcolor_coordinate_index",
              "uvw_", "texture_coordinate", "wrap_")

#: OmniPBR.mdl's inputs that can change a reading, with the module's defaults (textures: "")
OMNIPBR_DEFAULTS = {
    "diffuse_color_constant": (0.2, 0.2, 0.2), "diffuse_texture": "", "albedo_desaturation": 0.0,
    "albedo_add": 0.0, "albedo_brightness": 1.0, "diffuse_tint": _WHITE,
    "reflection_roughness_constant": 0.5, "reflection_roughness_texture_influence": 0.0,
    "reflectionroughness_texture": "", "reflection_roughness_texture": "",
    "metallic_constant": 0.0, "metallic_texture_influence": 0.0, "metallic_texture": "",
    "specular_level": 0.5, "enable_ORM_texture": False, "ORM_texture": "",
    "ao_to_diffuse": 0.0, "ao_texture": "",
    "enable_emission": False, "emissive_color": (1.0, 0.1, 0.1), "emissive_color_texture": "",
    "emissive_mask_texture": "", "emissive_intensity": 40.0,
    "enable_opacity": False, "enable_opacity_texture": False, "opacity_constant": 1.0, "opacity_texture": "",
    "opacity_mode": 1, "opacity_threshold": 0.0,
    "bump_factor": 1.0, "normalmap_texture": "", "detail_bump_factor": 0.3, "detail_normalmap_texture": "",
    "flip_tangent_u": False, "flip_tangent_v": True,
}

#: OmniGlass.mdl's inputs that can change a reading, with the module's defaults
OMNIGLASS_DEFAULTS = {
    "glass_color": _WHITE, "glass_color_texture": "", "depth": 0.001, "frosting_roughness": 0.0,
    "roughness_texture_influence": 1.0, "roughness_texture": "", "glass_ior": 1.491, "thin_walled": False,
    "reflection_color": _WHITE, "reflection_color_texture": "", "enable_opacity": False,
    "cutout_opacity": 1.0, "cutout_opacity_texture": "", "normal_map_texture": "", "normal_map_strength": 1.0,
}

#: OmniSurfaceBase.mdl's inputs that can change a reading, with the module's defaults
OMNISURFACE_DEFAULTS = {
    "diffuse_reflection_weight": 0.8, "diffuse_reflection_color": _WHITE, "diffuse_reflection_roughness": 0.0,
    "metalness": 0.0, "specular_reflection_weight": 1.0, "specular_reflection_color": _WHITE,
    "specular_reflection_roughness": 0.2, "specular_reflection_ior": 1.5,
    "specular_reflection_anisotropy": 0.0, "specular_reflection_anisotropy_rotation": 0.0,
    "specular_transmission_weight": 0.0, "specular_transmission_color": _WHITE,
    "specular_transmission_scattering_depth": 0.0, "specular_transmission_scattering_color": (0.0, 0.0, 0.0),
    "specular_transmission_scatter_anisotropy": 0.0, "specular_transmission_dispersion_abbe": 0.0,
    "specular_retro_reflection_weight": 0.0, "subsurface_weight": 0.0, "sheen_weight": 0.0,
    "coat_weight": 0.0, "coat_color": _WHITE, "coat_roughness": 0.1, "coat_ior": 1.5,
    "coat_affect_color": 0.0, "coat_affect_roughness": 0.0, "thin_film_weight": 0.0,
    "emission_weight": 0.0, "emission_mode": 0, "emission_intensity": 1.0, "emission_color": _WHITE,
    "emission_use_temperature": False, "emission_temperature": 6500.0,
    "enable_opacity": False, "geometry_opacity": 1.0, "geometry_opacity_threshold": 0.0, "thin_walled": False,
}


def _texture(ctx: _Context, ins: SurfaceInputs, name: str) -> np.ndarray | None:
    """Mean RGBA (4,) of a ``texture_2d`` input, None when not authored; a file that cannot be read is named
    (the module then uses its constant, as MDL does for an invalid texture)."""
    port = ins.asset(name)
    if port is None:
        return None
    rgba = _mean_rgba(ctx, port.value, port.colorspace or "auto")
    if rgba is None:
        ctx.ignored[f"inputs:{name} of {ins.model}: texture {os.path.basename(port.value)} not found or "
                    "unreadable (the constant used)"] += 1
        return None
    ctx.textured[name] += 1
    return rgba


def _mono_mode(ctx: _Context, ins: SurfaceInputs, mode_name: str) -> int:
    """The ``base::mono_mode`` input ``mode_name`` as 0–3 (:data:`.textures.MONO_MODES`): an int or the
    enum's name (``base::mono_alpha``, as wrapper modules and some exporters write it).

    Raises
    ------
    UserError
        ``<stage>: <prim>: inputs:<mode_name> <value> must be one of ...``: not one of the four modes.
    """
    ins.inert(mode_name)
    port = ins.node.inputs.get(mode_name)
    raw = port.value if port is not None and port.node is None and port.value is not None else ins.defaults[mode_name]
    if isinstance(raw, str):
        name = raw.strip().rpartition("::")[2]
        mode = MONO_MODES.index(name) if name in MONO_MODES else (int(name) if name.isdigit() else -1)
    else:
        mode = int(np.asarray(raw).ravel()[0])
    if not 0 <= mode < len(MONO_MODES):
        raise ctx.error(ins.node.where, f"inputs:{mode_name} {raw!r} must be one of "
                                        f"{', '.join(f'{k} ({v})' for k, v in enumerate(MONO_MODES))}")
    return mode


def _opacity_map(ctx: _Context, ins: SurfaceInputs, mode_name: str, texture: str) -> tuple[float, str, tuple]:
    """An MDL opacity map read as the material selects it: ``(mean opacity, where, (coverage texture index,
    why not))``. The mono value per texel is the one ``base::mono_mode`` ``mode_name`` selects
    (:func:`.textures.mono_texels`: alpha, the mean of RGB, their luminance or their maximum); it is kept
    per texel (:mod:`simulator.kernels.coverage`, read at the hit through ``primvars:st``) unless an
    input that places the texture (tiling, rotation, projection, another uv set) is authored, then its
    mean is the coverage and that is named. None when the map is not authored or cannot be read."""
    from simulator.scene.usd.textures import _file_coverage, _read_rgba, mono_texels

    port = ins.asset(texture)
    if port is None or _texture(ctx, ins, texture) is None:
        return None
    mode = _mono_mode(ctx, ins, mode_name)
    where = f"{MONO_MODES[mode]} of {ins.where(texture)}"
    placed = sorted(k for k in ins.node.inputs if k.startswith(_PLACEMENT) and ins.authored(k))
    space = port.colorspace or "auto"
    if placed:
        rgba = _read_rgba(port.value, space)
        return float(np.mean(mono_texels(rgba, mode))), where, (-1, f"placed by {', '.join(placed)}")
    idx = _file_coverage(ctx, port.value, space, mode, f"{ins.node.where}.inputs:{texture} "
                                                       f"({os.path.basename(port.value)}, {MONO_MODES[mode]})")
    ctx.textured[texture] -= 1  # read per texel, not as the mean the summary's textured inputs count
    if ctx.textured[texture] <= 0:
        del ctx.textured[texture]
    return float(ctx.coverage_textures[idx].mean), where, (idx, "")


def _lerp_map(ctx, ins, constant: str, influence: str, texture: str, channel=None) -> float:
    """``lerp(constant, mean(texture), influence)``: a map's mean blended over a constant."""
    c = ins.scalar(constant)
    t = ins.scalar(influence)
    rgba = _texture(ctx, ins, texture) if channel is None else channel
    if rgba is None:
        return c
    m = float(rgba) if np.ndim(rgba) == 0 else float(np.mean(rgba[:3]))
    return (1.0 - t) * c + t * m


def _map_omnipbr(ctx: _Context, ins: SurfaceInputs) -> dict:
    w = ins.where
    tex = _texture(ctx, ins, "diffuse_texture")
    if tex is not None:
        t = ins.scalar("albedo_brightness") * tex[:3] + ins.scalar("albedo_add")
        d = ins.scalar("albedo_desaturation")
        base, src = (1.0 - d) * t + d * float(luminance_grey(t)), f"mean of {w('diffuse_texture')}"
    else:
        base, src = ins.get("diffuse_color_constant"), w("diffuse_color_constant")
        for name in ("albedo_brightness", "albedo_add", "albedo_desaturation"):
            ins.get(name)  # these act on the texture only
    orm = _texture(ctx, ins, "ORM_texture") if ins.flag("enable_ORM_texture") else None
    rough_map = "reflectionroughness_texture" if ins.authored("reflectionroughness_texture") \
        else "reflection_roughness_texture"
    ins.asset("reflectionroughness_texture"), ins.asset("reflection_roughness_texture")
    out = {
        "diffuseColor": (colour(base * ins.get("diffuse_tint")), f"OmniPBR {src} x {w('diffuse_tint')}"),
        "roughness": (_lerp_map(ctx, ins, "reflection_roughness_constant", "reflection_roughness_texture_influence",
                                rough_map, None if orm is None else orm[1]), w("reflection_roughness_constant")),
        "metallic": (_lerp_map(ctx, ins, "metallic_constant", "metallic_texture_influence", "metallic_texture",
                               None if orm is None else orm[2]), w("metallic_constant")),
        "ior": (ior_of_f0(0.08 * ins.scalar("specular_level")), f"0.08 x {w('specular_level')} as F0"),
    }
    if ins.flag("enable_emission"):
        ce = _texture(ctx, ins, "emissive_color_texture")
        ce = ins.get("emissive_color") if ce is None else ce[:3]
        mask = _texture(ctx, ins, "emissive_mask_texture")
        mask = 1.0 if mask is None else mask[:3]
        lux = ins.scalar("emissive_intensity") * np.asarray(ce) * mask
        out["emissiveColor"] = (colour(nits_in_light_units(ctx, lux / math.pi)),
                                f"OmniPBR {w('emissive_intensity')} x {w('emissive_color')} / pi")
    else:
        ins.inert("emissive_color", "emissive_intensity", "emissive_color_texture", "emissive_mask_texture")
    if ins.flag("enable_opacity") or ins.flag("enable_opacity_texture"):
        m = _opacity_map(ctx, ins, "opacity_mode", "opacity_texture") if ins.flag("enable_opacity_texture") else None
        if m is None:
            op, src = ins.scalar("opacity_constant"), w("opacity_constant")
            ins.inert("opacity_mode")  # the channel of a map there is none of
        else:
            op, src, out["_opacity_texture"] = m
        out["opacity"] = (op, src)
        out["opacityMode"] = ("presence", "OmniPBR cutout_opacity")
        out["opacityThreshold"] = (ins.scalar("opacity_threshold"), w("opacity_threshold"))
    else:
        ins.inert("opacity_constant", "opacity_texture", "opacity_mode", "opacity_threshold")
    return out


def _map_omniglass(ctx: _Context, ins: SurfaceInputs) -> dict:
    w = ins.where
    ior = ins.scalar("glass_ior")
    rough = _lerp_map(ctx, ins, "frosting_roughness", "roughness_texture_influence", "roughness_texture")
    out = {
        "diffuseColor": ((0.0, 0.0, 0.0), "OmniGlass (a dielectric: no diffuse lobe)"),
        "opacity": (0.0, "OmniGlass (a dielectric)"),
        "ior": (ior, w("glass_ior")),
        "roughness": (rough, w("frosting_roughness")),
    }
    tint = np.asarray(ins.get("glass_color"), float)
    tex = _texture(ctx, ins, "glass_color_texture")
    if tex is not None:
        tint = tint * tex[:3]
    tau = float(luminance_grey(tint)) if tint.size == 3 else float(tint[0])
    if tau < 1.0 - 1e-6:
        out["probesim:transmittance"] = (slab_transmittance(max(tau, 0.0), ior),
                                         f"a thin slab of internal transmittance {tau:g} ({w('glass_color')})")
    ins.not_mapped("depth", "the distance the glass colour is reached at; the colour is read as one pass")
    thin_walled(out, ins, "thin_walled")  # each face a sheet; else a closed mesh is a solid
    if ins.flag("enable_opacity"):
        op = _texture(ctx, ins, "cutout_opacity_texture")
        out["opacity"] = (ins.scalar("cutout_opacity") if op is None else float(np.mean(op[:3])),
                          w("cutout_opacity"))
        out["opacityMode"] = ("presence", "OmniGlass cutout_opacity")
        ins.not_mapped("glass_color", "glazing beside a cut-out")
    else:
        ins.inert("cutout_opacity", "cutout_opacity_texture")
    return out


def _map_omnisurface(ctx: _Context, ins: SurfaceInputs) -> dict:
    w = ins.where
    coat = ins.get("coat_weight")
    coat_att = coat * ins.get("coat_color") + (1.0 - coat)
    base = ins.get("diffuse_reflection_weight") * ins.get("diffuse_reflection_color")
    metal, ior = ins.scalar("metalness"), ins.scalar("specular_reflection_ior")
    out = {
        "diffuseColor": (colour(base * coat_att), f"OmniSurface {w('diffuse_reflection_weight')} x "
                                                  f"{w('diffuse_reflection_color')}"),
        "metallic": (metal, w("metalness")),
        "roughness": (ins.scalar("specular_reflection_roughness"), w("specular_reflection_roughness")),
        "ior": (ior, w("specular_reflection_ior")),
    }
    ins.products(("diffuse_reflection_weight", "diffuse_reflection_color"), ("coat_weight", "coat_color"),
                 ("emission_weight", "emission_color"), ("emission_intensity", "emission_color"))
    _coat(out, ins, "coat_weight", "coat_color", "coat_roughness", ("coat_ior", "coat_affect_color",
                                                                   "coat_affect_roughness"))
    weight = ins.scalar("emission_weight")
    if weight > 0.0:
        nit_mode = ins.token("emission_mode") in ("1", "emission_nt")  # an int enum (0 lx, 1 nt) or its name
        value = weight * ins.scalar("emission_intensity") * ins.get("emission_color") * coat_att
        nits = value if nit_mode else value / math.pi
        out["emissiveColor"] = (colour(nits_in_light_units(ctx, nits)),
                                f"OmniSurface {w('emission_weight')} x {w('emission_intensity')} x "
                                f"{w('emission_color')} ({'nit' if nit_mode else 'lux / pi'})")
        ins.not_mapped("emission_use_temperature", "a temperature colour")
        if not ins.flag("emission_use_temperature"):
            ins.inert("emission_temperature")
    else:
        ins.inert("emission_mode", "emission_intensity", "emission_color", "emission_use_temperature",
                  "emission_temperature")
    _specular(out, ins, "specular_reflection_weight", "specular_reflection_color", metal, ior)
    transmission(out, ins, "specular_transmission_weight", "specular_transmission_color", ior)
    if ins.flag("enable_opacity"):
        op = ins.scalar("geometry_opacity")
        if "opacity" in out:
            ins.not_mapped("geometry_opacity", "a cut-out opacity beside transmission")
        else:
            out["opacity"] = (op, w("geometry_opacity"))
            out["opacityMode"] = ("presence", "OmniSurface geometry_opacity")
            out["opacityThreshold"] = (ins.scalar("geometry_opacity_threshold"), w("geometry_opacity_threshold"))
    else:
        ins.inert("geometry_opacity", "geometry_opacity_threshold")
    thin_walled(out, ins, "thin_walled")
    return out


#: MDL material name -> (defaults, mapping)
_MODELS = {
    "OmniPBR": (OMNIPBR_DEFAULTS, _map_omnipbr), "OmniPBR_Opacity": (OMNIPBR_DEFAULTS, _map_omnipbr),
    "OmniPBRBase": (OMNIPBR_DEFAULTS, _map_omnipbr),
    "OmniPBR_ClearCoat": (OMNIPBR_DEFAULTS, _map_omnipbr),
    "OmniPBR_ClearCoat_Opacity": (OMNIPBR_DEFAULTS, _map_omnipbr),
    "OmniGlass": (OMNIGLASS_DEFAULTS, _map_omniglass), "OmniGlass_Opacity": (OMNIGLASS_DEFAULTS, _map_omniglass),
    "OmniSurface": (OMNISURFACE_DEFAULTS, _map_omnisurface),
    "OmniSurfaceBase": (OMNISURFACE_DEFAULTS, _map_omnisurface),
    "OmniSurfaceLite": (OMNISURFACE_DEFAULTS, _map_omnisurface),
    "OmniSurfaceLiteBase": (OMNISURFACE_DEFAULTS, _map_omnisurface),
}

def _add_wrapper_arguments(ctx: _Context, node, module: str, wrapped: tuple) -> None:
    """A wrapper module's literal arguments as the node's inputs, under the stage's own authored ones."""
    _, args, odd = wrapped
    for arg, value in args.items():
        port = node.inputs.get(arg)
        if port is not None and (port.node is not None or port.value is not None):
            continue  # the stage's opinion wins
        if isinstance(value, tuple) and value and value[0] == "texture":
            node.inputs[arg] = Port(f"{module}: {arg}", value=value[1] or None, colorspace=value[2])
        else:
            node.inputs[arg] = Port(f"{module}: {arg}", value=value)
    for arg in odd:
        ctx.ignored[f"{arg} of {module} (not a literal: the template's default used)"] += 1


def _mdl_shader(material: UsdShade.Material) -> tuple[UsdShade.Shader, str, str] | None:
    """``(shader, module file name, material name)`` of a material's MDL surface, None without one."""
    shader, _, _ = material.ComputeSurfaceSource("mdl")
    if not shader:
        return None
    asset = shader.GetSourceAsset("mdl")
    if asset is None or not asset.path:
        return None
    module = os.path.basename(asset.path)
    name = shader.GetSourceAssetSubIdentifier("mdl") or os.path.splitext(module)[0]
    return shader, module, name


def _mdl_inputs(ctx: _Context, material: UsdShade.Material) -> dict | None:
    """UsdPreviewSurface inputs of a material whose surface is an Omniverse OmniPBR/OmniGlass/OmniSurface MDL
    material; None for no MDL surface; ``{}`` for another MDL material (counted in the summary warning)."""
    found = _mdl_shader(material)
    if found is None:
        return None
    shader, module, name = found
    wrapped = None
    if name not in _MODELS:  # a per-asset module that calls a template with literal arguments?
        asset = shader.GetSourceAsset("mdl")
        wrapped = wrapper_arguments(ctx, asset.resolvedPath) if asset.resolvedPath else None
        if wrapped is None or wrapped[0] not in _MODELS:
            ctx.not_read[f"material(s) with an MDL surface other than OmniPBR/OmniGlass/OmniSurface ({module}), "
                         "not mapped (displayColor or 0.18 used)"] += 1
            return {}
        name = wrapped[0]
    defaults, mapping = _MODELS[name]
    node = _usd_node(ctx, shader, {})
    if wrapped is not None:
        _add_wrapper_arguments(ctx, node, module, wrapped)
    for key in [k for k in node.inputs if k.startswith(_PLACEMENT)]:
        del node.inputs[key]
    ins = SurfaceInputs(ctx, node, defaults, name)
    out = mapping(ctx, ins)
    ins.finish()
    return complete(ctx, out, str(shader.GetPath()))
