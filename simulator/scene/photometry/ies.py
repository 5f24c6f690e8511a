"""IES LM-63 photometric files (``.ies``): LM-63-1986/1991 (no version
line), ``IESNA:LM-63-1995``, ``IESNA:LM-63-2002`` and ``IES:LM-63-2019``.

Grammar (IES LM-63-2019 §5; the older editions differ only where noted):

1. optional version line (``IESNA:LM-63-1995``, ``IESNA:LM-63-2002``,
   ``IES:LM-63-2019``; older files start with keywords);
2. keyword lines ``[KEYWORD] value`` (``[MORE]`` continues the previous);
3. ``TILT=NONE``, ``TILT=INCLUDE`` (tilt data follow) or ``TILT=<file>``;
4. then whitespace- (or comma-) separated numbers, across lines:
   number of lamps, lumens per lamp (−1: absolute photometry), candela
   multiplier, number of vertical angles, number of horizontal angles,
   photometric type (1 = C, 2 = B, 3 = A), units (1 feet, 2 metres),
   luminous opening width, length, height; ballast factor, a field that is
   the ballast-lamp photometric factor in LM-63-1995 and earlier (1 or
   "future use" later; the 2019 edition's file-generation type, which
   scales nothing), input watts; the vertical angles; the horizontal
   angles; the candela values, all vertical angles of the first horizontal
   angle, then of the next, and so on.

Candela = value × multiplier × ballast factor (× the ballast-lamp factor
for LM-63-1995 and earlier). Only type C photometry is read; ``TILT=INCLUDE``
is accepted when every tilt multiplying factor is 1 (the tilt then changes
nothing), other tilts are refused (one-line :class:`UserError`).
"""

from __future__ import annotations

import re

import numpy as np

from simulator.errors import UserError

from .distribution import GoniometricDistribution, read_file_text, unfold_type_c

__all__ = ["read_ies", "parse_ies"]

_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def read_ies(path) -> GoniometricDistribution:
    """Read an IES LM-63 file; see :func:`parse_ies`."""
    return parse_ies(read_file_text(path), str(path))


def parse_ies(text: str, source: str = "<ies>") -> GoniometricDistribution:
    """Parse the text of an IES LM-63 file into a distribution.

    Returns
    -------
    GoniometricDistribution
        Full type C grid; ``rated_lumens`` = lamps × lumens per lamp, or
        None for absolute photometry (lumens per lamp = −1); ``keywords``
        holds the keyword lines and ``version``.
    """
    lines = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
    version = "LM-63-1986"
    i = 0
    if lines and lines[0].strip().upper().startswith(("IESNA", "IES:")):
        version = lines[0].strip().split(":", 1)[-1].strip() or version
        i = 1
    keywords: dict[str, str] = {"version": version}
    last_key = None
    tilt = None
    while i < len(lines):
        line = lines[i].strip()
        i += 1
        if line.upper().startswith("TILT"):
            tilt = line.split("=", 1)[1].strip() if "=" in line else ""
            break
        m = re.match(r"\[([^\]]+)\]\s*(.*)", line)
        if m:
            key, val = m.group(1).strip().upper(), m.group(2).strip()
            if key == "MORE" and last_key:
                keywords[last_key] += " " + val
            else:
                keywords[key] = val
                last_key = key
    if tilt is None:
        raise UserError(f"{source}: no TILT= line (not an IES LM-63 file?)")
    rest = "\n".join(lines[i:])
    nums = [float(x) for x in _NUMBER.findall(rest.replace(",", " "))]
    pos = 0

    def take(n: int, what: str) -> list[float]:
        nonlocal pos
        if pos + n > len(nums):
            raise UserError(f"{source}: file ends inside {what} (needs {n} more numbers, has {len(nums) - pos})")
        out = nums[pos : pos + n]
        pos += n
        return out

    if tilt.upper() == "INCLUDE":
        _geometry = take(1, "the tilt data")
        (n_pairs,) = take(1, "the tilt data")
        if n_pairs < 0 or n_pairs != int(n_pairs):
            raise UserError(f"{source}: TILT=INCLUDE: bad number of tilt angles {n_pairs:g}")
        take(int(n_pairs), "the tilt angles")
        factors = take(int(n_pairs), "the tilt multiplying factors")
        if any(abs(f - 1.0) > 1e-9 for f in factors):
            raise UserError(f"{source}: TILT=INCLUDE with factors other than 1 is not supported (lamp-tilt corrections)")
    elif tilt.upper() != "NONE":
        raise UserError(f"{source}: TILT={tilt} (a separate tilt file) is not supported; only TILT=NONE")
    head = take(10, "the luminaire line")
    n_lamps, lm_per_lamp, multiplier, n_vert, n_horiz, ptype, _units, _w, _l, _h = head
    ballast, bl_factor, _watts = take(3, "the ballast line")
    if ptype != 1:
        names = {2: "B", 3: "A"}
        raise UserError(f"{source}: photometric type {names.get(int(ptype), int(ptype))} is not supported (only type C)")
    if n_vert < 1 or n_horiz < 1 or n_vert != int(n_vert) or n_horiz != int(n_horiz):
        raise UserError(f"{source}: bad angle counts {n_vert:g} vertical, {n_horiz:g} horizontal")
    nv, nh = int(n_vert), int(n_horiz)
    theta = np.array(take(nv, "the vertical angles"))
    phi = np.array(take(nh, "the horizontal angles"))
    values = np.array(take(nv * nh, "the candela values")).reshape(nh, nv)
    scale = multiplier * ballast
    if version.upper() in ("LM-63-1986", "LM-63-1991", "LM-63-1995"):
        scale *= bl_factor
    if theta[0] < 0 or theta[-1] > 180:
        raise UserError(f"{source}: vertical angles {theta[0]:g}–{theta[-1]:g}° are not type C (0–180°)")
    phi_full, cd_full, symmetry = unfold_type_c(theta, phi, values * scale, source)
    rated = None if lm_per_lamp < 0 else float(n_lamps * lm_per_lamp)
    keywords["tilt"] = tilt
    keywords["multiplier"] = multiplier
    keywords["ballast_factor"] = ballast
    return GoniometricDistribution(theta, phi_full, cd_full, rated_lumens=rated, source=source, symmetry=symmetry, keywords=keywords)
