"""Config problems as one line: pydantic's errors translated into :class:`UserError`.

Every message has the form ``"<file>: <key path>: <what is wrong>"``, e.g.
``configs/a.toml: sensor[2].normal: zero-length vector``; for command-line
flags the file is left out and the key path is the flag (``--samples``).

The schema raises two kinds of error:

* pydantic's own (a wrong type, a bound, a missing key), worded here from
  the error's type, input and bound (:func:`_message`);
* :func:`rule` errors (a choice, an interval, a zero-length vector, an
  unknown key), which carry their final wording, and optionally the key
  they are about when raised for a whole table.

Of all the errors in a file the first in file order is reported
(:func:`_locate` maps pydantic's location onto the parsed TOML, dropping
the union tags pydantic adds).
"""

from __future__ import annotations

import difflib
from typing import Any

from pydantic_core import PydanticCustomError, ValidationError

from simulator.errors import UserError

__all__ = ["RULE", "MISSING", "rule", "expected", "unknown_key", "toml_type", "user_error", "translate"]

#: pydantic error type of every :func:`rule` error
RULE = "probesim"
#: the message of a required key that is absent
MISSING = "required key is missing"

#: what a type error expected, by pydantic error type
_EXPECTED = {
    "int_type": "an integer",
    "float_type": "a number",
    "string_type": "a string",
    "bool_type": "a boolean",
    "model_type": "a table",
    "model_attributes_type": "a table",
    "dict_type": "a table",
    "list_type": "an array",
}
#: comparison and context key of each bound error
_BOUNDS = {
    "greater_than": (">", "gt"),
    "greater_than_equal": (">=", "ge"),
    "less_than": ("<", "lt"),
    "less_than_equal": ("<=", "le"),
}

#: TOML's name of each parsed Python type, first match wins (bool before int: a bool is an int)
_TOML_TYPES = ((bool, "boolean"), (int, "integer"), (float, "float"), (str, "string"), (list, "array"), (dict, "table"))


def toml_type(value: Any) -> str:
    """TOML's name for the type of a parsed value (``"integer"``, ``"table"``, ...)."""
    for cls, name in _TOML_TYPES:
        if isinstance(value, cls):
            return name
    return "date/time" if value is not None else "nothing"


def expected(what: str, value: Any) -> str:
    """``"expected <what>, got <TOML type of value>"``."""
    return f"expected {what}, got {toml_type(value)}"


def rule(message: str, *, key: str | int | None = None, sibling: str | None = None) -> PydanticCustomError:
    """An error worded by the schema, to raise from a validator.

    Parameters
    ----------
    message : str
        The final wording, e.g. ``"zero-length vector"``.
    key : str, int or tuple, optional
        Key (or array index) within the value being validated that the
        message is about: raised for a whole table, it lands on
        ``<table>.<key>``; a tuple is a key path (``<table>.<a>.<b>``).
    sibling : str, optional
        A key beside the one at fault; ``{sibling}`` in ``message`` becomes
        its full path (``sensor[0].normal``).
    """
    ctx: dict[str, Any] = {"message": message}
    if key is not None:
        ctx["key"] = key
    if sibling is not None:
        ctx["sibling"] = sibling
    return PydanticCustomError(RULE, "{message}", ctx)


def unknown_key(key: str, allowed: tuple[str, ...]) -> PydanticCustomError:
    """``<key>: unknown key (did you mean ...? expected one of: ...)``."""
    hint = difflib.get_close_matches(key, allowed, n=1)
    did = f"did you mean {hint[0]!r}? " if hint else ""
    return rule(f"unknown key ({did}expected one of: {', '.join(allowed)})", key=key)


def user_error(file: str | None, key: str, message: str) -> UserError:
    """``UserError("<file>: <key>: <message>")`` on one line; empty parts left out."""
    parts = [p for p in (file, key) if p] + [" ".join(str(message).split())]
    return UserError(": ".join(parts))


def translate(
    exc: ValidationError, raw: Any, file: str | None = None, rename: dict[str, str] | None = None
) -> UserError:
    """The first problem (in file order) of a failed validation, as one line.

    Parameters
    ----------
    exc : pydantic_core.ValidationError
        From validating ``raw`` against a schema model.
    raw : object
        What was validated (the parsed TOML), to order the errors by and to
        tell keys from pydantic's union tags.
    file : str, optional
        Config file as the user named it; None for command-line flags.
    rename : dict of str to str, optional
        Key path to the name to show instead (``{"samples": "--samples"}``).

    Returns
    -------
    UserError
    """
    best: tuple[list[int], str, str] | None = None
    for err in exc.errors(include_url=False):
        ctx = err.get("ctx") or {}
        loc = tuple(err["loc"])
        if err["type"] == RULE and "key" in ctx:  # a key, or a key path (a tuple) within the value
            loc += tuple(ctx["key"]) if isinstance(ctx["key"], tuple) else (ctx["key"],)
        names, order = _locate(raw, loc)
        message = _message(err)
        if err["type"] == RULE and "sibling" in ctx:
            message = message.replace("{sibling}", _render(names[:-1] + [ctx["sibling"]]))
        if best is None or order < best[0]:
            best = (order, _render(names), message)
    assert best is not None, "a ValidationError has at least one error"
    _, path, message = best
    if rename:
        path = rename.get(path, path)
    return user_error(file, path, message)


def _locate(raw: Any, loc: tuple) -> tuple[list, list[int]]:
    """Key path and file-order position of a pydantic error location.

    Pydantic's location also names the union member it tried (a sensor's
    kind, a grid spacing's form) and marks dict keys with ``"[key]"``; the
    key path keeps only what is in the file. The position is the index of
    each key within its table (tomllib keeps file order) and of each array
    element; a missing key sorts after the keys present.
    """
    node, names, order = raw, [], []
    for part in loc:
        if part == "[key]":
            continue
        if isinstance(node, dict):
            if part in node:
                order.append(list(node).index(part))
                node = node[part]
            elif isinstance(part, str) and node.get("kind") == part:
                continue  # the tag of the sensor-kind union
            else:
                order.append(len(node))
                node = None
        elif isinstance(node, list) and isinstance(part, int):
            order.append(part)
            node = node[part] if 0 <= part < len(node) else None
        elif isinstance(part, str) and node is not None:
            continue  # a union tag inside a value that is not a table
        else:
            order.append(0)
        names.append(part)
    return names, order


def _render(names: list) -> str:
    """``["sensor", 2, "normal"]`` -> ``"sensor[2].normal"``."""
    out = ""
    for part in names:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += f".{part}" if out else str(part)
    return out


def _num(x: Any) -> str:
    """A bound or value as today's messages print it: floats ``%g``, ints exact."""
    return f"{x:g}" if isinstance(x, float) else str(x)


def _message(err: dict) -> str:
    """Today's wording of one pydantic error."""
    kind = err["type"]
    ctx = err.get("ctx") or {}
    value = err.get("input")
    if kind == RULE:
        return str(ctx["message"])
    if kind in _EXPECTED:
        return expected(_EXPECTED[kind], value)
    if kind in _BOUNDS:
        op, key = _BOUNDS[kind]
        bound = ctx[key]
        if isinstance(bound, float) and isinstance(value, int):
            value = float(value)  # an integer given for a number
        return f"must be {op} {_num(bound)}, got {_num(value)}"
    if kind == "finite_number":
        return f"must be a finite number, got {value}"
    if kind == "missing":
        return MISSING
    if kind == "extra_forbidden":
        return "unknown key"
    return str(err["msg"])
