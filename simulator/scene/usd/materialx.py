"""MaterialX surfaces: inline UsdShade networks and referenced ``.mtlx`` documents, as UsdPreviewSurface inputs.

Four surface models (docs/REFERENCES.md §MaterialX surfaces) are mapped onto UsdPreviewSurface's inputs (the dict
:func:`simulator.scene.usd.materials._preview_surface_inputs` returns,
``{input name: (value, where)}``), their inputs read as uniform values
(:mod:`.shading_graph`: constants, texture means, linear math):

``ND_UsdPreviewSurface_surfaceshader``
    Each input is its UsdPreviewSurface namesake.
``ND_standard_surface_surfaceshader`` (Autodesk Standard Surface)
    After MaterialX's own translation graph ``ND_standard_surface_to_UsdPreviewSurface``:
    ``diffuseColor = mix(base·base_color, subsurface_color, subsurface) · mix(1, coat_color, coat)``,
    ``metallic = metalness``, ``roughness = specular_roughness``,
    ``ior = specular_IOR``, ``clearcoat = coat · mean(coat_color)``,
    ``clearcoatRoughness = coat_roughness``,
    ``emissiveColor = emission · emission_color · mix(1, coat_color, coat)``
    (emitted radiance in the stage's light units, as ``emissiveColor``);
    then, beyond the translation graph: ``transmission`` is glazing
    (``opacity = 1 − transmission``, a tinted full transmission a datasheet
    ``probesim:transmittance``, :func:`.surface_mapping.transmission`), the
    geometric ``opacity`` is a cut-out (``opacity = mean(opacity)``,
    ``opacityMode = "presence"``), and a dielectric's ``specular`` weight or
    ``specular_color`` is UsdPreviewSurface's specular workflow with
    ``specularColor = specular · specular_color · F0(specular_IOR)``,
    ``F0(n) = ((n − 1)/(n + 1))²``.
``ND_open_pbr_surface_surfaceshader`` (OpenPBR Surface)
    The same with OpenPBR's names (``base_weight``, ``base_metalness``,
    ``specular_weight``, ``specular_ior``, ``coat_weight``,
    ``transmission_weight``, ``subsurface_weight``, ``geometry_opacity``), and
    ``emission_luminance`` (cd/m², whatever the light units) times
    ``emission_color`` as ``emissiveColor`` in the stage's light units
    (:func:`.surface_mapping.nits_in_light_units`).

``ND_gltf_pbr_surfaceshader`` (glTF 2.0 PBR)
    ``base_color``, ``metallic``, ``roughness``, ``ior``, ``clearcoat``,
    ``emissive · emissive_strength``, ``transmission`` (tinted by
    ``base_color``), ``alpha`` by ``alpha_mode`` (:func:`_map_gltf_pbr`).

Every input authored away from its default that no formula reads (sheen,
fuzz, thin film, anisotropy, normal maps, subsurface radius, ...) is named in
the summary warning.

usd-core from PyPI does not ship the usdMtlx file-format plugin, so a stage
that references a ``.mtlx`` (``references = @look.mtlx@</MaterialX/Materials>``)
composes no prims from it: the reader opens the document itself with the
``MaterialX`` package (:func:`_document`), finds the material the binding
names (``/MaterialX/Materials/<name>``, usdMtlx's layout) and reads its
surface shader the same way. A ``.mtlx`` that cannot be read is an error
naming the file and the prim.
"""

from __future__ import annotations

import os

import numpy as np
from pxr import Sdf, Usd, UsdShade

from simulator.scene.usd.context import _Context, _get, _layer_relative
from simulator.scene.usd.shading_graph import Node, Port
from simulator.scene.usd.surface_mapping import (SurfaceInputs, colour, complete, nits_in_light_units, thin_walled,
                                                 transmission)

_WHITE = (1.0, 1.0, 1.0)

#: ND_UsdPreviewSurface_surfaceshader's inputs and defaults (the UsdPreviewSurface specification's)
PREVIEW_DEFAULTS = {
    "diffuseColor": (0.18, 0.18, 0.18), "emissiveColor": (0.0, 0.0, 0.0), "useSpecularWorkflow": 0,
    "specularColor": (0.0, 0.0, 0.0), "metallic": 0.0, "roughness": 0.5, "clearcoat": 0.0,
    "clearcoatRoughness": 0.01, "opacity": 1.0, "opacityMode": "transparent", "opacityThreshold": 0.0,
    "ior": 1.5, "displacement": 0.0, "occlusion": 1.0,
}

#: ND_standard_surface_surfaceshader's inputs that can change a reading, with the nodedef's defaults
STANDARD_SURFACE_DEFAULTS = {
    "base": 1.0, "base_color": (0.8, 0.8, 0.8), "diffuse_roughness": 0.0, "metalness": 0.0,
    "specular": 1.0, "specular_color": _WHITE, "specular_roughness": 0.2, "specular_IOR": 1.5,
    "specular_anisotropy": 0.0, "specular_rotation": 0.0,
    "transmission": 0.0, "transmission_color": _WHITE, "transmission_depth": 0.0,
    "transmission_scatter": (0.0, 0.0, 0.0), "transmission_scatter_anisotropy": 0.0,
    "transmission_dispersion": 0.0, "transmission_extra_roughness": 0.0,
    "subsurface": 0.0, "subsurface_color": _WHITE, "subsurface_radius": _WHITE, "subsurface_scale": 1.0,
    "subsurface_anisotropy": 0.0, "sheen": 0.0, "sheen_color": _WHITE, "sheen_roughness": 0.3,
    "coat": 0.0, "coat_color": _WHITE, "coat_roughness": 0.1, "coat_anisotropy": 0.0, "coat_rotation": 0.0,
    "coat_IOR": 1.5, "coat_affect_color": 0.0, "coat_affect_roughness": 0.0,
    "thin_film_thickness": 0.0, "thin_film_IOR": 1.5, "emission": 0.0, "emission_color": _WHITE,
    "opacity": _WHITE, "thin_walled": False,
}

#: ND_open_pbr_surface_surfaceshader's inputs that can change a reading, with the nodedef's defaults
OPEN_PBR_DEFAULTS = {
    "base_weight": 1.0, "base_color": (0.8, 0.8, 0.8), "base_diffuse_roughness": 0.0, "base_metalness": 0.0,
    "specular_weight": 1.0, "specular_color": _WHITE, "specular_roughness": 0.3, "specular_ior": 1.5,
    "specular_roughness_anisotropy": 0.0,
    "transmission_weight": 0.0, "transmission_color": _WHITE, "transmission_depth": 0.0,
    "transmission_scatter": (0.0, 0.0, 0.0), "transmission_scatter_anisotropy": 0.0,
    "transmission_dispersion_scale": 0.0, "transmission_dispersion_abbe_number": 20.0,
    "subsurface_weight": 0.0, "subsurface_color": (0.8, 0.8, 0.8), "subsurface_radius": 1.0,
    "subsurface_radius_scale": (1.0, 0.5, 0.25), "subsurface_scatter_anisotropy": 0.0,
    "fuzz_weight": 0.0, "fuzz_color": _WHITE, "fuzz_roughness": 0.5,
    "coat_weight": 0.0, "coat_color": _WHITE, "coat_roughness": 0.0, "coat_roughness_anisotropy": 0.0,
    "coat_ior": 1.6, "coat_darkening": 1.0,
    "thin_film_weight": 0.0, "thin_film_thickness": 0.5, "thin_film_ior": 1.4,
    "emission_luminance": 0.0, "emission_color": _WHITE, "geometry_opacity": 1.0, "geometry_thin_walled": False,
}

#: ND_gltf_pbr_surfaceshader's inputs that can change a reading, with the nodedef's defaults
#: (``attenuation_distance``, default infinite, has no value: authored, it is named)
GLTF_PBR_DEFAULTS = {
    "base_color": _WHITE, "metallic": 1.0, "roughness": 1.0, "occlusion": 1.0, "transmission": 0.0,
    "specular": 1.0, "specular_color": _WHITE, "ior": 1.5, "alpha": 1.0, "alpha_mode": 0, "alpha_cutoff": 0.5,
    "iridescence": 0.0, "iridescence_ior": 1.3, "iridescence_thickness": 100.0, "sheen_color": (0.0, 0.0, 0.0),
    "sheen_roughness": 0.0, "clearcoat": 0.0, "clearcoat_roughness": 0.0, "emissive": (0.0, 0.0, 0.0),
    "emissive_strength": 1.0, "thickness": 0.0, "attenuation_color": _WHITE, "anisotropy_strength": 0.0,
    "anisotropy_rotation": 0.0, "dispersion": 0.0,
}

#: MaterialX node categories named in ``info:id`` (``ND_<category>_<type>``), longest first
_CATEGORIES = sorted(["standard_surface", "open_pbr_surface", "UsdPreviewSurface", "UsdUVTexture", "tiledimage",
                      "image", "constant", "multiply", "add", "subtract", "divide", "mix", "dot", "convert",
                      "extract", "normalmap", "surfacematerial", "gltf_pbr", "disney_principled"],
                     key=len, reverse=True)


def _split_id(ident: str) -> tuple[str, str]:
    """``(category, output type)`` of a MaterialX nodedef name: ``ND_image_color3`` -> ``("image", "color3")``."""
    body = ident[3:] if ident.startswith("ND_") else ident
    for cat in _CATEGORIES:
        if body == cat or body.startswith(cat + "_"):
            return cat, body[len(cat) + 1:].split("_")[0] if body != cat else ""
    head, _, rest = body.partition("_")
    return head, rest.split("_")[0]


# --- UsdShade networks ---------------------------------------------------------------------------------------

def _usd_node(ctx: _Context, shader: UsdShade.Shader, memo: dict) -> Node:
    """A UsdShade shader (``info:id = ND_...``) and what feeds its inputs, as a :class:`Node` graph."""
    key = str(shader.GetPath())
    if key in memo:
        return memo[key]
    category, out_type = _split_id(shader.GetShaderId() or shader.GetSourceAssetSubIdentifier("mdl") or "shader")
    node = memo[key] = Node(category, out_type, key)
    for inp in shader.GetInputs():
        name = inp.GetBaseName()
        where = f"{key}.inputs:{name}"
        port = Port(where)
        for attr in inp.GetValueProducingAttributes():
            if UsdShade.Output.IsOutput(attr):
                src = UsdShade.Shader(attr.GetPrim())
                if src:
                    port = Port(where, node=_usd_node(ctx, src, memo), output=UsdShade.Output(attr).GetBaseName())
                break
            value = _get(ctx, attr)
            if isinstance(value, Sdf.AssetPath):
                path = value.resolvedPath or (_layer_relative(attr, value.path) if value.path else "")
                port = Port(str(attr.GetPath()), value=path, colorspace=str(attr.GetColorSpace() or ""))
            elif value is not None:
                port = Port(str(attr.GetPath()), value=value)
            break
        node.inputs[name] = port
    return node


def _inline_surface(material: UsdShade.Material) -> UsdShade.Shader | None:
    """The MaterialX surface shader of a material (``outputs:mtlx:surface``, else universal), if its id is ``ND_``."""
    for context in ("mtlx", ""):
        shader, _, _ = material.ComputeSurfaceSource(context)
        if shader and (shader.GetShaderId() or "").startswith("ND_"):
            return shader
    return None


# --- .mtlx documents -----------------------------------------------------------------------------------------

def _document(ctx: _Context, path: str, prim: Usd.Prim):
    """The MaterialX document at ``path`` (read once per file).

    Raises
    ------
    UserError
        ``<stage>: <prim>: <file>: not a readable MaterialX document (<why>)``:
        a missing file, malformed XML, or the ``MaterialX`` package missing.
    """
    cache = ctx.materials  # the per-run material cache; a key no prim path can be
    key = f"mtlx document|{os.path.abspath(path)}"
    if key not in cache:
        try:
            import MaterialX as mx
        except ImportError:
            raise ctx.error(prim, f"{path}: reading a .mtlx needs the MaterialX package (pip install MaterialX)") \
                from None
        doc = mx.createDocument()
        try:
            mx.readFromXmlFile(doc, path)
        except Exception as exc:  # ExceptionFileMissing, ExceptionParseError, ...
            reason = " ".join(str(exc).split()) or type(exc).__name__
            raise ctx.error(prim, f"{path}: not a readable MaterialX document ({reason})") from None
        cache[key] = doc
    return cache[key]


def _mtlx_value(value):
    if hasattr(value, "__len__") and not isinstance(value, str):
        return tuple(float(v) for v in value)
    return value


def _mtlx_port(inp, folder: str, memo: dict, where: str) -> Port:
    """A MaterialX input as a :class:`Port`: through ``interfacename`` to the graph's input, through
    ``nodegraph``/``output`` or ``nodename`` to the node feeding it, else its value."""
    for _ in range(64):
        iface = inp.getInterfaceInput() if inp.getInterfaceName() else None
        if iface is None:
            break
        inp = iface
    out = inp.getConnectedOutput()
    if out is not None:
        node = out.getConnectedNode()
        if node is not None:
            return Port(where, node=_mtlx_node(node, folder, memo), output=out.getOutputString() or "out")
    node = inp.getConnectedNode()
    if node is not None:
        return Port(where, node=_mtlx_node(node, folder, memo), output=inp.getOutputString() or "out")
    if inp.getType() == "filename":
        path = inp.getResolvedValueString()
        if path and not os.path.isabs(path):
            path = os.path.normpath(os.path.join(folder, path))
        return Port(where, value=path, colorspace=inp.getActiveColorSpace() or "")
    if not inp.hasValueString():
        return Port(where)
    return Port(where, value=_mtlx_value(inp.getValue()))


def _mtlx_node(node, folder: str, memo: dict) -> Node:
    """A MaterialX node and what feeds it, as a :class:`Node` graph."""
    key = node.getNamePath()
    if key in memo:
        return memo[key]
    out = memo[key] = Node(node.getCategory(), node.getType(), f"{os.path.basename(folder) or '.'}/{key}")
    for inp in node.getInputs():
        out.inputs[inp.getName()] = _mtlx_port(inp, folder, memo, f"{key}.{inp.getName()}")
    return out


def _mtlx_references(prim: Usd.Prim) -> list[tuple[str, Sdf.Path, Sdf.Path]]:
    """``(absolute .mtlx path, target path in it, referencing prim's path)`` of every reference or payload to a
    ``.mtlx`` authored on ``prim`` (variants included), in the order of its prim stack."""
    found = []
    for spec in prim.GetPrimStack():
        for items in (spec.referenceList.GetAddedOrExplicitItems(), spec.payloadList.GetAddedOrExplicitItems()):
            for ref in items:
                if ref.assetPath.lower().endswith(".mtlx"):
                    path = spec.layer.ComputeAbsolutePath(ref.assetPath) if spec.layer else ref.assetPath
                    found.append((path, ref.primPath, prim.GetPath()))
    return found


def _mtlx_binding(ctx: _Context, stage: Usd.Stage, path: Sdf.Path) -> tuple | None:
    """``(.mtlx file, material name, referencing prim)`` of a material path that lies in a referenced ``.mtlx``.

    usdMtlx lays a document out as ``/MaterialX/Materials/<material name>``; a
    reference to ``</MaterialX/Materials>`` on ``/Looks`` makes the material
    ``/Looks/<name>``, one to ``</MaterialX/Materials/M>`` on ``/Looks/M`` makes
    ``/Looks/M``. The first reference (strongest first) whose document holds the
    material wins.
    """
    probe = path
    while probe != Sdf.Path.absoluteRootPath and not probe.isEmpty:
        prim = stage.GetPrimAtPath(probe)
        if prim:
            refs = _mtlx_references(prim)
            for file, target, owner in refs:
                target = target if not target.isEmpty else Sdf.Path("/MaterialX")
                virtual = path.ReplacePrefix(owner, target)
                parts = virtual.pathString.strip("/").split("/")
                if len(parts) == 3 and parts[:2] == ["MaterialX", "Materials"]:
                    node = _document(ctx, file, prim).getNode(parts[2])
                    if node is not None and node.getType() == "material":
                        return file, parts[2], prim
            if refs:
                names = ", ".join(os.path.basename(f) for f, _, _ in refs)
                raise ctx.error(prim, f"material {path.name!r} is not in the MaterialX document(s) it references "
                                      f"({names})")
        probe = probe.GetParentPath()
    return None


def _mtlx_surface(ctx: _Context, file: str, name: str, prim: Usd.Prim) -> Node | None:
    """The surface shader of material ``name`` in ``file`` as a :class:`Node`, None when it has none."""
    import MaterialX as mx

    material = _document(ctx, file, prim).getNode(name)
    shaders = list(mx.getShaderNodes(material))
    if not shaders:
        return None
    return _mtlx_node(shaders[0], os.path.dirname(file), {})


# --- mappings ------------------------------------------------------------------------------------------------

def _specular(out: dict, ins: SurfaceInputs, weight: str, tint: str, metal: float, ior: float) -> None:
    """A dielectric's specular weight and tint: UsdPreviewSurface's specular workflow, ``specularColor`` its F0.

    ``specularColor = weight · tint · ((n − 1)/(n + 1))²``; on a metal (any
    metalness) they tint the metal's edge reflectance, which the metallic
    workflow cannot hold: they are named.
    """
    if ins.is_default(weight) and ins.is_default(tint):
        ins.get(weight), ins.get(tint)
        return
    if metal <= 0.0:
        f0 = ((ior - 1.0) / (ior + 1.0)) ** 2
        out["useSpecularWorkflow"] = (1, f"{ins.where(weight)} / {ins.where(tint)}")
        out["specularColor"] = (colour(ins.get(weight) * ins.get(tint) * f0),
                                f"{ins.where(weight)} x {ins.where(tint)} x F0(ior)")
    else:  # on a metal they tint its edge (F82), which UsdPreviewSurface's metallic Fresnel leaves white
        ins.not_mapped(weight, "a metal's edge tint")
        ins.not_mapped(tint, "a metal's edge tint")


def _coat(out: dict, ins: SurfaceInputs, weight: str, tint: str, rough: str, unused: tuple[str, ...]) -> None:
    """``clearcoat = weight · mean(tint)`` (the translation graph's one-third dot product) and
    ``clearcoatRoughness = rough``, set only where there is a coat; without one its other inputs change
    nothing (and are not named)."""
    coat = float(np.mean(ins.get(weight) * ins.get(tint)))
    if coat > 0.0:
        out["clearcoat"] = (coat, f"{ins.where(weight)} x mean({ins.where(tint)})")
        out["clearcoatRoughness"] = (ins.scalar(rough), ins.where(rough))
    else:
        ins.inert(rough, *unused)


def _cutout(out: dict, ins: SurfaceInputs, name: str) -> None:
    """A geometric (cut-out) opacity: ``opacity = mean(opacity)``, ``opacityMode = "presence"``; beside a
    transmission it is named (UsdPreviewSurface has one opacity)."""
    value = float(np.mean(ins.get(name)))
    if ins.is_default(name):
        return
    if "opacity" in out:
        ins.not_mapped(name, "a cut-out opacity beside transmission")
        return
    out["opacity"] = (value, ins.where(name))
    out["opacityMode"] = ("presence", ins.where(name))


def _map_preview(ctx: _Context, ins: SurfaceInputs) -> dict:
    """ND_UsdPreviewSurface_surfaceshader: each input is its UsdPreviewSurface namesake."""
    out = {}
    for name, default in PREVIEW_DEFAULTS.items():
        if name == "opacityMode":  # a token in UsdShade; MaterialX's nodedef makes it an int (0, 1)
            mode = ins.token(name)
            out[name] = ({"0": "transparent", "1": "presence"}.get(mode, mode), ins.where(name))
            continue
        v = ins.get(name)
        value = colour(v) if isinstance(default, tuple) else (int(v[0]) if isinstance(default, int) else float(v[0]))
        out[name] = (value, ins.where(name))
    return out


#: the input names of the two layered models mapped by :func:`_map_layered` (OpenPBR renames Standard
#: Surface's inputs; its emission is a luminance in cd/m², Standard Surface's is in the stage's light units)
_STANDARD_NAMES = {
    "model": "standard_surface", "base": "base", "base_color": "base_color", "subsurface": "subsurface",
    "subsurface_color": "subsurface_color", "coat": "coat", "coat_color": "coat_color",
    "coat_roughness": "coat_roughness", "coat_extra": ("coat_IOR",), "metalness": "metalness",
    "roughness": "specular_roughness", "ior": "specular_IOR", "specular": "specular",
    "specular_color": "specular_color", "transmission": "transmission", "transmission_color": "transmission_color",
    "emission": "emission", "emission_color": "emission_color", "opacity": "opacity", "thin": "thin_walled",
}
_OPEN_PBR_NAMES = {
    "model": "open_pbr_surface", "base": "base_weight", "base_color": "base_color", "subsurface": "subsurface_weight",
    "subsurface_color": "subsurface_color", "coat": "coat_weight", "coat_color": "coat_color",
    "coat_roughness": "coat_roughness", "coat_extra": ("coat_ior", "coat_darkening"), "metalness": "base_metalness",
    "roughness": "specular_roughness", "ior": "specular_ior", "specular": "specular_weight",
    "specular_color": "specular_color", "transmission": "transmission_weight",
    "transmission_color": "transmission_color", "emission": "emission_luminance", "emission_color": "emission_color",
    "opacity": "geometry_opacity", "thin": "geometry_thin_walled",
}


def _map_standard(ctx: _Context, ins: SurfaceInputs) -> dict:
    """ND_standard_surface_surfaceshader, after MaterialX's standard_surface_to_UsdPreviewSurface (module doc)."""
    return _map_layered(ctx, ins, _STANDARD_NAMES, nits=False)


def _map_open_pbr(ctx: _Context, ins: SurfaceInputs) -> dict:
    """ND_open_pbr_surface_surfaceshader: as standard_surface with OpenPBR's names; emission in cd/m²."""
    return _map_layered(ctx, ins, _OPEN_PBR_NAMES, nits=True)


def _map_layered(ctx: _Context, ins: SurfaceInputs, k: dict, nits: bool) -> dict:
    """Standard Surface or OpenPBR (input names ``k``) onto UsdPreviewSurface's inputs: the coat
    attenuates what lies under it (coat·coat_color + 1 − coat), subsurface blends into the diffuse
    colour, emission is ``emission · emission_color`` (a luminance where ``nits``)."""
    w = ins.where
    coat = ins.get(k["coat"])
    coat_att = coat * ins.get(k["coat_color"]) + (1.0 - coat)
    base = ins.get(k["base"]) * ins.get(k["base_color"])
    ss = ins.get(k["subsurface"])
    dielectric = ss * ins.get(k["subsurface_color"]) + (1.0 - ss) * base
    metal, ior = ins.scalar(k["metalness"]), ins.scalar(k["ior"])
    emitted = ins.get(k["emission"]) * ins.get(k["emission_color"]) * coat_att
    unit = " (cd/m^2)" if nits else ""
    out = {
        "diffuseColor": (colour(dielectric * coat_att), f"{k['model']} {w(k['base'])} x {w(k['base_color'])}"),
        "metallic": (metal, w(k["metalness"])),
        "roughness": (ins.scalar(k["roughness"]), w(k["roughness"])),
        "ior": (ior, w(k["ior"])),
        "emissiveColor": (colour(nits_in_light_units(ctx, emitted) if nits else emitted),
                          f"{k['model']} {w(k['emission'])}{unit} x {w(k['emission_color'])}"),
    }
    ins.products((k["base"], k["base_color"]), (k["subsurface"], k["subsurface_color"]),
                 (k["subsurface"], k["base_color"]), (k["coat"], k["coat_color"]), (k["emission"], k["emission_color"]))
    _coat(out, ins, k["coat"], k["coat_color"], k["coat_roughness"], k["coat_extra"])
    _specular(out, ins, k["specular"], k["specular_color"], metal, ior)
    transmission(out, ins, k["transmission"], k["transmission_color"], ior)
    _cutout(out, ins, k["opacity"])
    thin_walled(out, ins, k["thin"])  # each face a sheet; else a closed mesh is a solid
    return out


def _map_gltf_pbr(ctx: _Context, ins: SurfaceInputs) -> dict:
    """ND_gltf_pbr_surfaceshader (glTF 2.0 metallic-roughness and its extensions).

    ``diffuseColor = base_color``, ``metallic``, ``roughness``, ``ior``,
    ``clearcoat``, ``clearcoatRoughness = clearcoat_roughness``,
    ``emissiveColor = emissive · emissive_strength`` (as ``emissiveColor``);
    KHR_materials_specular's ``specular``/``specular_color`` on a dielectric
    is the specular workflow as for standard_surface
    (``F0 = specular · specular_color · ((n − 1)/(n + 1))²``, the extension's
    own); ``transmission`` is glazing; ``alpha`` with ``alpha_mode`` MASK (1)
    is a cut-out at ``alpha_cutoff``, BLEND (2) a coverage.
    """
    w = ins.where
    metal, ior = ins.scalar("metallic"), ins.scalar("ior")
    out = {
        "diffuseColor": (colour(ins.get("base_color")), w("base_color")),
        "metallic": (metal, w("metallic")),
        "roughness": (ins.scalar("roughness"), w("roughness")),
        "ior": (ior, w("ior")),
        "occlusion": (ins.scalar("occlusion"), w("occlusion")),
        "emissiveColor": (colour(ins.get("emissive") * ins.get("emissive_strength")),
                          f"gltf_pbr {w('emissive')} x {w('emissive_strength')}"),
    }
    ins.products(("emissive", "emissive_strength"))
    if ins.scalar("clearcoat") > 0.0:
        out["clearcoat"] = (ins.scalar("clearcoat"), w("clearcoat"))
        out["clearcoatRoughness"] = (ins.scalar("clearcoat_roughness"), w("clearcoat_roughness"))
    else:
        ins.inert("clearcoat_roughness")
    _specular(out, ins, "specular", "specular_color", metal, ior)
    # KHR_materials_transmission: base_color tints what passes (attenuation_* is a volume: named)
    transmission(out, ins, "transmission", "base_color", ior)
    mode = int(float(ins.token("alpha_mode")))  # 0 OPAQUE (alpha ignored), 1 MASK, 2 BLEND
    if mode == 0:
        ins.inert("alpha", "alpha_cutoff")
    elif not ins.is_default("alpha"):
        if "opacity" in out:
            ins.not_mapped("alpha", "a cut-out alpha beside transmission")
        else:
            out["opacity"] = (ins.scalar("alpha"), w("alpha"))
            out["opacityMode"] = ("presence", w("alpha_mode"))
            if mode == 1:
                out["opacityThreshold"] = (ins.scalar("alpha_cutoff"), w("alpha_cutoff"))
    if mode != 1:
        ins.inert("alpha_cutoff")
    return out


#: surface model -> (defaults, mapping)
_MODELS = {
    "UsdPreviewSurface": (PREVIEW_DEFAULTS, _map_preview),
    "standard_surface": (STANDARD_SURFACE_DEFAULTS, _map_standard),
    "open_pbr_surface": (OPEN_PBR_DEFAULTS, _map_open_pbr),
    "gltf_pbr": (GLTF_PBR_DEFAULTS, _map_gltf_pbr),
}


def _map_surface(ctx: _Context, node: Node) -> dict | None:
    """The UsdPreviewSurface inputs of a MaterialX surface node, None for a model not mapped."""
    if node.category not in _MODELS:
        return None
    defaults, mapping = _MODELS[node.category]
    ins = SurfaceInputs(ctx, node, defaults, node.category)
    out = mapping(ctx, ins)
    ins.finish()
    return complete(ctx, out, node.where)


def _not_mapped(ctx: _Context, what: str) -> None:
    ctx.not_read[f"material(s) with a MaterialX {what} surface, not mapped (displayColor or 0.18 used)"] += 1


def _materialx_inputs(ctx: _Context, material: UsdShade.Material) -> dict | None:
    """UsdPreviewSurface inputs of a material whose surface is MaterialX: an inline ``ND_*`` shader, or a
    ``.mtlx`` the material (or a prim above it) references. None when neither; ``{}`` for a MaterialX model
    that is not mapped (counted in the summary warning)."""
    shader = _inline_surface(material)
    if shader is not None:
        node = _usd_node(ctx, shader, {})
        out = _map_surface(ctx, node)
        if out is None:
            _not_mapped(ctx, node.category)
        return out if out is not None else {}
    if any(o.HasConnectedSource() for o in material.GetSurfaceOutputs()):
        return None  # a surface of its own (MDL, another renderer's): not one a .mtlx failed to compose
    found = _mtlx_binding(ctx, material.GetPrim().GetStage(), material.GetPath())
    return _from_document(ctx, found) if found else None


def _from_document(ctx: _Context, found: tuple) -> dict | None:
    file, name, prim = found
    node = _mtlx_surface(ctx, file, name, prim)
    if node is None:
        _not_mapped(ctx, "shaderless")
        return {}
    out = _map_surface(ctx, node)
    if out is None:
        _not_mapped(ctx, node.category)
    return out if out is not None else {}


def _unresolved_binding(ctx: _Context, prim: Usd.Prim) -> dict | None:
    """Inputs of a material bound to ``prim`` that the stage never composed because it lies in a referenced
    ``.mtlx`` (usd-core has no usdMtlx plugin); None when no binding points into one.

    The nearest direct binding on ``prim`` or an ancestor (full purpose, then all-purpose) is the one a
    render would use (ignoring ``bindMaterialAs`` strength; collection bindings into a ``.mtlx`` are not
    followed): if its target is a composed Material, that material was simply unusable, so None.
    """
    stage = prim.GetStage()
    p = prim
    while p and not p.IsPseudoRoot():
        api = UsdShade.MaterialBindingAPI(p)
        for purpose in (UsdShade.Tokens.full, UsdShade.Tokens.allPurpose):
            targets = api.GetDirectBindingRel(purpose).GetTargets()
            if not targets:
                continue
            target = stage.GetPrimAtPath(targets[0])
            if target and target.IsA(UsdShade.Material):
                return None
            key = f"mtlx binding|{targets[0]}"
            if key not in ctx.materials:
                found = _mtlx_binding(ctx, stage, targets[0])
                ctx.materials[key] = (_from_document(ctx, found) or None) if found else None
            return ctx.materials[key]
        p = p.GetParent()
    return None
