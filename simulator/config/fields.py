"""Value types of the config schema: each an ``Annotated`` pydantic type with its rule.

TOML values arrive typed, so every type here is strict: an integer key
takes a TOML integer (not ``10.0``, not ``true``); a number key takes a
float or an integer (converted to float) but never a boolean, and never
``nan`` or ``inf``. Ranges with one bound are pydantic constraints
(``Field(ge=1)``); the rest (choices, intervals, shapes, unit vectors) are
small validators raising :func:`~simulator.config.errors.rule` errors with
their wording.

Vectors are in the probesim world frame (metres, right-handed, Z up) and
come out as float64 arrays.
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Union

import numpy as np
from pydantic import AfterValidator, BeforeValidator, Discriminator, Field, Strict, Tag, ValidationInfo
from pydantic.types import AllowInfNan

from simulator.config.errors import expected, rule, toml_type
from simulator.config.records import MAX_PROBE_PIXELS

__all__ = [
    "Integer",
    "Number",
    "Text",
    "Count",
    "Positive",
    "one_of",
    "choice",
    "interval",
    "nonblank",
    "tables",
    "Point",
    "Direction",
    "UpDirection",
    "Size",
    "Resolution",
    "Spacing",
    "orthogonal_up",
]

#: below this sine of the angle between two directions they count as parallel
PARALLEL_SIN = 1e-6

Integer = Annotated[int, Strict()]
Number = Annotated[float, Strict(), AllowInfNan(False)]
Text = Annotated[str, Strict()]
#: an integer >= 1 (sample counts, pixels)
Count = Annotated[Integer, Field(ge=1)]
#: a finite number > 0
Positive = Annotated[Number, Field(gt=0.0)]


# --------------------------------------------------------------------------- rules


def one_of(value: str, values: tuple[str, ...], noun: str, key: str | None = None) -> str:
    """``value`` if it is one of ``values``, else an error naming it as ``noun``."""
    if value not in values:
        raise rule(f"unknown {noun} {value!r} (expected one of: {', '.join(values)})", key=key)
    return value


def choice(values: tuple[str, ...], noun: str) -> AfterValidator:
    """A string that must be one of ``values``; ``noun`` names it in the message."""
    return AfterValidator(lambda value: one_of(value, values, noun))


def interval(lo: float, hi: float, *, closed_lo: bool = False, unit: str = "") -> AfterValidator:
    """A number in ``(lo, hi)``, or ``[lo, hi)`` with ``closed_lo``; ``unit`` is named in the message."""
    unit = f" {unit}" if unit else ""

    def check(x: float) -> float:
        if closed_lo and not lo <= x < hi:
            raise rule(f"must be >= {lo:g} and < {hi:g}{unit}, got {x:g}")
        if not closed_lo and not lo < x < hi:
            raise rule(f"must be between {lo:g} and {hi:g}{unit} (exclusive), got {x:g}")
        return x

    return AfterValidator(check)


def nonblank(message: str) -> AfterValidator:
    """A string with something besides white space; ``message`` when it has not."""

    def check(text: str) -> str:
        if not text.strip():
            raise rule(message)
        return text

    return AfterValidator(check)


def tables(name: str) -> BeforeValidator:
    """An array of tables, ``[[name]]`` in TOML."""

    def check(value: Any) -> Any:
        if not isinstance(value, list):
            raise rule(f"expected an array of tables ([[{name}]]), got {toml_type(value)}")
        for k, item in enumerate(value):
            if not isinstance(item, dict):
                raise rule(f"expected a table ([[{name}]]), got {toml_type(item)}", key=k)
        return value

    return BeforeValidator(check)


def _array(n: int, what: str = "numbers") -> BeforeValidator:
    """An array of exactly ``n`` elements (their own type is checked after)."""

    def check(value: Any) -> Any:
        if not isinstance(value, list):
            raise rule(f"expected an array of {n} {what}, got {toml_type(value)}")
        if len(value) != n:
            raise rule(f"expected an array of {n} {what}, got {len(value)} element(s)")
        return value

    return BeforeValidator(check)


def _float64(values: list[float]) -> np.ndarray:
    return np.array(values, dtype=np.float64)


def _unit(v: np.ndarray) -> np.ndarray:
    """``v / |v|``; a zero or overflowing length is an error."""
    length = float(np.linalg.norm(v))
    if not length > 0.0 or not math.isfinite(length):
        raise rule("zero-length vector" if length == 0.0 else "vector length is not finite")
    return v / length


def _pixels(res: list[int]) -> tuple[int, int]:
    w, h = res
    if w * h > MAX_PROBE_PIXELS:
        raise rule(f"{w} x {h} pixels is more than the {MAX_PROBE_PIXELS} a probe map may hold")
    return int(w), int(h)


def _number_or_pair(value: Any) -> Any:
    if isinstance(value, list) or (isinstance(value, (int, float)) and not isinstance(value, bool)):
        return value
    raise rule(expected("a number or an array of 2 numbers", value))


def _pair(value: tuple[float, float] | float) -> tuple[float, float]:
    return value if isinstance(value, tuple) else (value, value)


def orthogonal_up(up: np.ndarray, normal: np.ndarray | None) -> np.ndarray:
    """Unit ``up`` made orthogonal to unit ``normal`` (Gram–Schmidt).

    For a validator of ``up`` beside ``normal``; ``normal`` None (it failed
    its own check) leaves ``up`` as it is. ``up`` parallel to ``normal``
    (sine of their angle below :data:`PARALLEL_SIN`) is an error.
    """
    if normal is None:
        return up
    ortho = up - float(np.dot(up, normal)) * normal
    length = float(np.linalg.norm(ortho))
    if length < PARALLEL_SIN:
        raise rule("parallel to {sibling}; up must point along the height side", sibling="normal")
    return ortho / length


# --------------------------------------------------------------------------- shapes

#: a position, metres: float64 array, shape (3,)
Point = Annotated[list[Number], _array(3), AfterValidator(_float64)]
#: a direction, normalised: float64 array, shape (3,)
Direction = Annotated[Point, AfterValidator(_unit)]


def _up_beside_normal(up: np.ndarray, info: ValidationInfo) -> np.ndarray:
    return orthogonal_up(up, info.data.get("normal"))


#: ``up`` of a table whose ``normal`` is declared before it: a direction, then
#: made orthogonal to ``normal`` (:func:`orthogonal_up`)
UpDirection = Annotated[Direction, AfterValidator(_up_beside_normal)]
#: ``(width, height)``, metres, both > 0
Size = Annotated[list[Positive], _array(2), AfterValidator(tuple)]
#: lat-long map ``(width, height)`` in pixels, at most :data:`MAX_PROBE_PIXELS`
Resolution = Annotated[list[Count], _array(2, "integers (width, height)"), AfterValidator(_pixels)]
#: grid spacing ``(sx, sy)``, metres: one number for both, or a pair
Spacing = Annotated[
    Union[Annotated[Size, Tag("pair")], Annotated[Positive, Tag("one")]],
    Discriminator(lambda v: "pair" if isinstance(v, list) else "one"),
    BeforeValidator(_number_or_pair),
    AfterValidator(_pair),
]
