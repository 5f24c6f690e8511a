"""Per-asset MDL materials that only set an Omniverse template's parameters, read from the ``.mdl`` file.

Omniverse assets often carry their own module, ``Steel.mdl``, whose whole body
is one call of a template with literal arguments::

    export material Steel(*)
     = OmniPBR::OmniPBR(
        diffuse_color_constant: color(0.5f, 0.5f, 0.5f),
        diffuse_texture: texture_2d("./Steel_BaseColor.png", ::tex::gamma_srgb),
        metallic_constant: 1.0f);

The ``(*)`` makes the wrapper's parameters the template's own, so the stage's
authored inputs (same names) win over these arguments, which win over the
template's defaults. This reader understands only that shape and only literal
arguments: numbers (``1.0f``), booleans, ``color(…)``/``float3(…)`` of
numbers, ``texture_2d("path", ::tex::gamma_*)`` (the path relative to the
``.mdl`` file) and enum values, which are kept as their names. Anything else
(a call, an expression, a cross-module reference) is named in the summary
warning and the template's default is used. No MDL is compiled.
"""

from __future__ import annotations

import os
import re

from simulator.scene.usd.context import _Context

#: ``export material Name(*) [[annotations]] = [ns::]Template(`` with the template named
_WRAPPER = re.compile(r"export\s+material\s+\w+\s*\(\s*\*\s*\)(?:\s*\[\[.*?\]\])?\s*=\s*(?:::)?((?:\w+::)*)(\w+)\s*\(",
                      re.S)
_NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?[fFdD]?$")
_GAMMA = {"gamma_srgb": "sRGB", "gamma_linear": "raw", "gamma_default": "auto"}


def _strip_comments(text: str) -> str:
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def _balanced(text: str, start: int) -> str | None:
    """The text inside the parenthesis opened just before ``start``, None when it never closes."""
    depth, i = 1, start
    quote = False
    while i < len(text):
        c = text[i]
        if c == '"':
            quote = not quote
        elif not quote and c == "(":
            depth += 1
        elif not quote and c == ")":
            depth -= 1
            if depth == 0:
                return text[start:i]
        i += 1
    return None


def _split_top(text: str) -> list[str]:
    """``text`` split at the commas outside parentheses and quotes."""
    parts, depth, quote, cur = [], 0, False, []
    for c in text:
        if c == '"':
            quote = not quote
        elif not quote and c in "([":
            depth += 1
        elif not quote and c in ")]":
            depth -= 1
        if c == "," and depth == 0 and not quote:
            parts.append("".join(cur))
            cur = []
        else:
            cur.append(c)
    if "".join(cur).strip():
        parts.append("".join(cur))
    return [p.strip() for p in parts]


def _literal(value: str, folder: str):
    """A Python value for an MDL literal: float, bool, tuple, ``("texture", path, colour space)`` or an enum
    name; None when it is not a literal."""
    v = value.strip()
    if _NUMBER.match(v):
        return float(v.rstrip("fFdD"))
    if v in ("true", "false"):
        return v == "true"
    m = re.fullmatch(r"(?:::)?(?:color|float3|float4|float2)\s*\((.*)\)", v, re.S)
    if m:
        items = [s.strip() for s in m.group(1).split(",") if s.strip()]
        if items and all(_NUMBER.match(s) for s in items):
            nums = tuple(float(s.rstrip("fFdD")) for s in items)
            return nums * 3 if len(nums) == 1 and v.lstrip(":").startswith("color") else nums
        return None
    m = re.fullmatch(r"(?:::)?texture_2d\s*\((.*)\)", v, re.S)
    if m:
        args = _split_top(m.group(1))
        if not args:
            return ("texture", "", "auto")
        path = re.fullmatch(r'"(.*)"', args[0])
        if path is None:
            return None
        space = "auto"
        if len(args) > 1:
            space = _GAMMA.get(args[1].split("::")[-1], "auto")
        p = path.group(1)
        if p and not os.path.isabs(p):
            p = os.path.normpath(os.path.join(folder, p))
        return ("texture", p, space)
    if re.fullmatch(r"(?:::)?(?:\w+::)*\w+", v):
        return v.split("::")[-1]  # an enum value, kept by name
    return None


def wrapper_arguments(ctx: _Context, path: str) -> tuple[str, dict[str, object], list[str]] | None:
    """``(template, {parameter: value}, parameters not literal)`` of a wrapper module, None if it is not one.

    ``path`` is the resolved ``.mdl`` file; a file that cannot be read, or
    whose material is not a single call of a template, gives None.
    """
    key = f"mdl wrapper|{os.path.abspath(path)}"
    if key in ctx.materials:
        return ctx.materials[key]
    found = None
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            text = _strip_comments(f.read())
    except OSError:
        text = ""
    m = _WRAPPER.search(text)
    body = _balanced(text, m.end()) if m else None
    if body is not None:
        folder = os.path.dirname(path)
        args, odd = {}, []
        for part in _split_top(body):
            name, sep, value = part.partition(":")
            name = name.strip()
            if not sep or not re.fullmatch(r"\w+", name):
                continue
            lit = _literal(value, folder)
            if lit is None:
                odd.append(name)
            else:
                args[name] = lit
        found = (m.group(2), args, odd)
    ctx.materials[key] = found
    return found
