"""Figures as people read them: a value with its error at a sane precision, and its unit.

One rule for every figure a report prints (tables, plan titles, colour bars):

- a value with a standard error ``s > 0``: the error rounded to **2
  significant digits**, the value rounded to the same decimal place
  (``22161.3 ± 736.2`` → ``22,160 ± 740``; ``0.7312 ± 0.007362`` →
  ``0.7312 ± 0.0074``);
- a value with no error (a requirement, a count, an exact figure): 3
  significant digits, never fewer than its whole digits (``12345.6`` →
  ``12,346``; ``0.61234`` → ``0.612``);
- never an exponent: thousands grouped with commas, so ``2.216e+04`` reads
  ``22,160``;
- the unit after a no-break space (SI brochure §5.4.3), ``%`` included.

The decimal place of a rounded error ``s`` is ``d = 1 − ⌊log10 s⌋``
(negative d rounds to tens, hundreds, …).
"""

from __future__ import annotations

import math

__all__ = ["NBSP", "error_decimals", "plain", "with_error", "number"]

#: between a number and its unit, and around ±: the pair never breaks over lines
NBSP = "\u00a0"
#: significant digits of a rounded error, and of a value shown alone
ERROR_DIGITS = 2
VALUE_DIGITS = 3


def error_decimals(stderr: float, digits: int = ERROR_DIGITS) -> int:
    """Decimal places that keep ``digits`` significant digits of ``stderr`` (> 0): 1 − ⌊log10 s⌋ for 2 digits.

    The rounding may carry (0.0996 to 2 digits is 0.10): the place is taken
    from the rounded error so that 0.0996 keeps 2 decimals, not 3.
    """
    d = digits - 1 - math.floor(math.log10(abs(stderr)))
    r = round(abs(stderr), d)
    if r > 0 and digits - 1 - math.floor(math.log10(r)) < d:  # 0.0996 → 0.10: one place fewer
        d -= 1
    return d


def number(v: float, decimals: int) -> str:
    """``v`` rounded to ``decimals`` places (negative: to tens, hundreds, …), thousands grouped, no exponent."""
    if not math.isfinite(v):
        return "n/a" if math.isnan(v) else ("∞" if v > 0 else "−∞")
    if decimals < 0:
        v = round(v, decimals)
        decimals = 0
    s = f"{v:,.{decimals}f}"
    if s.lstrip("-").strip("0.,") == "":  # −0.00 reads 0.00
        s = s.lstrip("-")
    return s.replace("-", "−")


def _unit(s: str, unit: str) -> str:
    return f"{s}{NBSP}{unit}" if unit else s


def plain(v: float, unit: str = "", digits: int = VALUE_DIGITS) -> str:
    """A value with no error: ``digits`` significant digits (never fewer than its whole digits), and its unit."""
    v = float(v)
    if not math.isfinite(v) or v == 0.0:
        return _unit(number(v, 0), unit)
    d = max(0, digits - 1 - math.floor(math.log10(abs(v))))
    s = number(v, d)
    if "." in s:  # 0.600 reads 0.6: trailing zeros of a value alone say nothing
        s = s.rstrip("0").rstrip(".")
    return _unit(s, unit)


def with_error(v: float, stderr: float, unit: str = "") -> str:
    """``value ± error unit`` by the module's rule; an error of 0: the value alone (:func:`plain`), an
    unknown (NaN) error: ``value ± n/a``."""
    v, stderr = float(v), float(stderr)
    if math.isnan(stderr) and math.isfinite(v):
        return _unit(f"{plain(v)}{NBSP}±{NBSP}n/a", unit)
    if not (math.isfinite(stderr) and stderr > 0) or not math.isfinite(v):
        return plain(v, unit)
    d = error_decimals(stderr)
    return _unit(f"{number(v, d)}{NBSP}±{NBSP}{number(stderr, d)}", unit)
