"""Shading networks as a small graph, and the uniform value each node output gives.

MaterialX networks reach the reader two ways: as UsdShade prims authored in
the stage (``info:id = "ND_standard_surface_surfaceshader"``, ``ND_image_color3``,
...) and as ``.mtlx`` documents a stage references. Both become the same
:class:`Node` graph here, so one evaluator reads them: a node output's value
is the *uniform* value probesim gives a surface (its surfaces are uniform), so

- a constant is itself (``constant`` nodes, authored values);
- an ``image`` / ``tiledimage`` (or ``UsdUVTexture``) is its texture's mean
  (:mod:`.textures`: the mean over texels, sRGB-decoded where the node's colour
  space says ``srgb_texture``);
- the linear math nodes pass means through exactly: ``add``, ``subtract``,
  ``multiply`` and ``divide`` by a constant, ``mix`` with a constant weight,
  ``dot`` (a pass-through), ``convert``, ``extract``. ``mean(a * b)`` is not
  ``mean(a) * mean(b)`` when both vary, so a product (or a ``mix`` weight, or
  a divisor) that is itself a texture is read as the product of the means and
  named in the summary warning;
- any other node (noise, ramps, normal maps, geometric properties, ...) has
  no uniform value: the input it feeds is named and read as its default.

Values are float arrays of 1 to 4 channels; a float broadcasts against a
colour as in MaterialX.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np

from simulator.scene.usd.context import _Context
from simulator.scene.usd.textures import _OUTPUT_CHANNELS, _mean_rgba

#: channels of the RGBA texel mean an image node of each MaterialX output type gives
_IMAGE_CHANNELS = {"float": [0], "vector2": [0, 1], "color3": [0, 1, 2], "vector3": [0, 1, 2],
                   "color4": [0, 1, 2, 3], "vector4": [0, 1, 2, 3]}

#: MaterialX colour spaces whose 8-bit or float texels are sRGB-encoded (decoded before the mean)
_SRGB_SPACES = {"srgb_texture", "sRGB", "srgb"}
#: colour spaces read as they are (linear Rec. 709 primaries, the working space, or data)
_LINEAR_SPACES = {"", "lin_rec709", "raw", "none", "linear", "lin_srgb"}

#: math nodes whose missing inputs take these MaterialX standard-library defaults
_MATH_DEFAULTS = {
    "add": {"in1": 0.0, "in2": 0.0}, "subtract": {"in1": 0.0, "in2": 0.0},
    "multiply": {"in1": 0.0, "in2": 1.0}, "divide": {"in1": 0.0, "in2": 1.0},
    "mix": {"fg": 0.0, "bg": 0.0, "mix": 0.0}, "dot": {"in": 0.0}, "convert": {"in": 0.0},
    "constant": {"value": 0.0}, "extract": {"in": 0.0, "index": 0},
}


@dataclass
class Port:
    """One input of a node: an authored constant, or a link to ``node``'s ``output``.

    ``value`` is a float array (numbers and colours), a ``str`` (a file path,
    already resolved, for ``filename`` inputs) or another Python value
    (booleans, ints, tokens). ``colorspace`` is the colour space a filename
    input states (MaterialX ``colorspace``, USD ``colorSpace`` metadata).
    """

    where: str
    value: object = None
    node: "Node | None" = None
    output: str = "out"
    colorspace: str = ""


@dataclass
class Node:
    """A shading node: its MaterialX category (``standard_surface``, ``image``, ...), output type, inputs."""

    category: str
    type: str
    where: str
    inputs: dict[str, Port] = field(default_factory=dict)


@dataclass
class Value:
    """A uniform value read from a port: ``value`` (float array), where it came from, whether a texture
    mean is in it, and notes (why it is approximate) for the summary warning."""

    value: np.ndarray
    where: str
    textured: bool = False
    notes: tuple[str, ...] = ()


class NotUniform(Exception):
    """A port has no uniform value probesim can read; the message says why (for the summary warning)."""


def as_array(v) -> np.ndarray:
    """A number, colour or vector as a float array of its channels."""
    return np.atleast_1d(np.asarray(v, float)).astype(float)


def port_value(ctx: _Context, port: Port, depth: int = 0) -> Value:
    """The uniform value of a port (an authored constant, or the node output it links to).

    Raises
    ------
    NotUniform
        The port links to a node with no uniform value, a texture that cannot
        be read, or a graph deeper than 64 nodes (a cycle).
    """
    if port.node is None:
        if port.value is None:
            raise NotUniform("no value")
        try:
            return Value(as_array(port.value), port.where)
        except (TypeError, ValueError):
            raise NotUniform(f"a {type(port.value).__name__} value") from None
    if depth > 64:
        raise NotUniform("a network deeper than 64 nodes")
    return _node_value(ctx, port.node, port.output, depth + 1)


def _input(ctx: _Context, node: Node, name: str, depth: int) -> Value:
    port = node.inputs.get(name)
    if port is None or (port.node is None and port.value is None):
        default = _MATH_DEFAULTS.get(node.category, {}).get(name)
        if default is None:
            raise NotUniform(f"a {node.category} node without inputs:{name}")
        return Value(as_array(default), f"{node.where} (default {name})")
    return port_value(ctx, port, depth)


def _node_value(ctx: _Context, node: Node, output: str, depth: int) -> Value:
    cat = node.category
    if cat in ("image", "tiledimage"):
        return _image_mean(ctx, node, _IMAGE_CHANNELS.get(node.type, [0, 1, 2]))
    if cat == "UsdUVTexture":
        return _uv_texture_mean(ctx, node, output, depth)
    if cat == "constant":
        return _input(ctx, node, "value", depth)
    if cat in ("dot", "convert"):
        v = _input(ctx, node, "in", depth)
        if cat == "convert" and node.type in ("color3", "vector3") and v.value.size == 1:
            v = Value(np.repeat(v.value, 3), v.where, v.textured, v.notes)
        return v
    if cat == "extract":
        v = _input(ctx, node, "in", depth)
        index = int(_input(ctx, node, "index", depth).value[0])
        if not 0 <= index < v.value.size:
            raise NotUniform(f"an extract node with index {index} outside its input")
        return Value(v.value[index:index + 1], v.where, v.textured, v.notes)
    if cat in ("add", "subtract", "multiply", "divide"):
        a, b = _input(ctx, node, "in1", depth), _input(ctx, node, "in2", depth)
        notes = a.notes + b.notes
        if cat in ("multiply", "divide") and b.textured and (a.textured or cat == "divide"):
            notes += (f"a {cat} node of two textures (read as the {cat} of their means)",)
        try:
            with np.errstate(divide="raise", invalid="raise"):
                out = {"add": np.add, "subtract": np.subtract, "multiply": np.multiply,
                       "divide": np.divide}[cat](a.value, b.value)
        except (ValueError, FloatingPointError):
            raise NotUniform(f"a {cat} node of {a.value.size} and {b.value.size} channels (or a division by 0)") \
                from None
        return Value(out, node.where, a.textured or b.textured, notes)
    if cat == "mix":
        fg, bg, w = (_input(ctx, node, n, depth) for n in ("fg", "bg", "mix"))
        notes = fg.notes + bg.notes + w.notes
        if w.textured and (fg.textured or bg.textured):
            notes += ("a mix node whose weight and layers are textures (read as a mix of means)",)
        try:
            out = w.value * fg.value + (1.0 - w.value) * bg.value
        except ValueError:
            raise NotUniform("a mix node of mismatched channels") from None
        return Value(out, node.where, fg.textured or bg.textured or w.textured, notes)
    raise NotUniform(f"connected to a {cat} node, which has no uniform value")


def _texture_space(ctx: _Context, node: Node, colorspace: str) -> str:
    """``sRGB`` or ``raw`` (the decoding :func:`.textures._mean_rgba` applies) for a MaterialX colour space."""
    if colorspace in _SRGB_SPACES:
        return "sRGB"
    if colorspace not in _LINEAR_SPACES:
        ctx.ignored[f"texture colour space {colorspace!r} (read as linear Rec. 709)"] += 1
    return "raw"


def _image_mean(ctx: _Context, node: Node, channels: list[int]) -> Value:
    """Mean of a MaterialX ``image``/``tiledimage`` node's texture (its ``file`` input), the channels of its type."""
    port = node.inputs.get("file")
    if port is None or port.node is not None or not isinstance(port.value, str) or not port.value:
        raise NotUniform("connected to an image node without a file")
    if "<UDIM>" in port.value or "<UVTILE>" in port.value:
        raise NotUniform("connected to an image node of UDIM tiles")
    rgba = _mean_rgba(ctx, port.value, _texture_space(ctx, node, port.colorspace))
    if rgba is None:
        raise NotUniform(f"connected to an image whose file {os.path.basename(port.value)} is missing or unreadable")
    return Value(np.asarray([rgba[c] for c in channels], float), f"{node.where} (mean of {port.value})", True)


def _uv_texture_mean(ctx: _Context, node: Node, output: str, depth: int) -> Value:
    """A MaterialX ``UsdUVTexture`` node: ``scale * mean + bias`` per channel of its output (as :mod:`.textures`)."""
    port = node.inputs.get("file")
    if port is None or port.node is not None or not isinstance(port.value, str) or not port.value:
        raise NotUniform("connected to a UsdUVTexture node without a file")
    space_port = node.inputs.get("sourceColorSpace")
    space = str(space_port.value) if space_port is not None and space_port.value else "auto"
    rgba = _mean_rgba(ctx, port.value, space)
    if rgba is None:
        raise NotUniform(f"connected to a UsdUVTexture whose file {os.path.basename(port.value)} is missing or "
                         "unreadable")
    chans = _OUTPUT_CHANNELS.get(output)
    if chans is None:
        raise NotUniform(f"connected to a UsdUVTexture output {output!r}, which it has not")

    def four(name, default):
        p = node.inputs.get(name)
        if p is None or (p.node is None and p.value is None):
            return np.full(4, default)
        v = port_value(ctx, p, depth)
        return v.value if v.value.size == 4 else np.full(4, float(v.value[0]))

    scale, bias = four("scale", 1.0), four("bias", 0.0)
    return Value(np.asarray([scale[c] * rgba[c] + bias[c] for c in chans], float),
                 f"{node.where} (mean of {port.value})", True)
