"""The config's ``variants`` table: selections by variant-set name, and by prim path.

::

    [variants]
    reflectance = "rho_0_9"                      # on every prim with a set "reflectance"
    "/World/Car/WheelFL" = { wheelStyle = "sport" }  # on that prim only

A key that starts with ``/`` is a prim path (absolute, ``/Name/Child``) and
its value a table of variant-set name to variant name, selected on that prim
alone; any other key is a variant-set name and its value a variant name,
selected on every prim that has the set. Where both name one prim's set,
the prim path's selection wins. On the command line the same two forms are
``--variant SET=VARIANT`` and ``--variant /PRIM/PATH:SET=VARIANT``
(:func:`parse_flag`).

Whether the stage has the prim, the set and the variant is checked when the
stage is read (:func:`simulator.scene.usd.stage._select_variants`).
"""

from __future__ import annotations

import re
from typing import Annotated, Any

from pydantic import BeforeValidator

from simulator.config.errors import expected, rule

__all__ = ["Variants", "PRIM_PATH", "is_prim_path", "parse_flag"]

#: an absolute prim path: ``/`` then identifiers (letters, digits, ``_``; not starting with a digit)
PRIM_PATH = re.compile(r"(/[^\W\d]\w*)+")


def is_prim_path(key: str) -> bool:
    """True for a ``variants`` key that names a prim (it starts with ``/``)."""
    return key.startswith("/")


def _check_choice(set_name: str, choice: Any, at: tuple) -> None:
    """One ``set = "variant"`` entry; ``at`` is its key path within ``variants``."""
    if not set_name.strip():
        raise rule("empty variant set name", key=at)
    if not isinstance(choice, str):
        raise rule(expected("a string", choice), key=at)
    if not choice.strip():
        raise rule("empty variant name", key=at)


def _check(value: Any) -> dict:
    """``variants`` as given, its keys and values checked (see the module docstring)."""
    if not isinstance(value, dict):
        raise rule(expected("a table", value))
    for key, v in value.items():
        if not is_prim_path(key):
            _check_choice(key, v, (key,))
            continue
        if not PRIM_PATH.fullmatch(key):
            raise rule("not a prim path (expected an absolute path such as /World/Car/WheelFL)", key=key)
        if not isinstance(v, dict):
            raise rule(expected("a table of variant set = variant (the selections on that prim)", v), key=key)
        if not v:
            raise rule("no selections (expected { set = \"variant\" })", key=key)
        for set_name, choice in v.items():
            _check_choice(set_name, choice, (key, set_name))
    return {k: (dict(v) if isinstance(v, dict) else v) for k, v in value.items()}


#: ``variants``: variant-set name -> variant name, or prim path -> {variant-set name -> variant name}
Variants = Annotated[dict, BeforeValidator(_check)]


def parse_flag(item: str) -> tuple[str | None, str, str] | None:
    """``(prim path or None, set, variant)`` of a ``--variant`` value; None when it has no ``=``.

    ``SET=VARIANT`` selects on every prim with the set; ``/PRIM/PATH:SET=VARIANT`` on that prim.
    """
    target, sep, choice = str(item).partition("=")
    if not sep:
        return None
    path = None
    if is_prim_path(target.strip()):
        path, colon, target = target.strip().partition(":")
        if not colon:
            return None
    return path, target.strip(), choice.strip()
