"""EULUMDAT photometric files (``.ldt``).

A line-oriented format (EULUMDAT, Stockmar 1990; the layout DIALux and
Relux read): one field per line,

====  ==============================================================
line  field
====  ==============================================================
1     manufacturer / company
2     type indicator Ityp (0 point source with no symmetry, 1 point
      source symmetric about the vertical axis, 2 linear, 3 point
      source with other symmetry)
3     symmetry indicator Isym (see below)
4     number of C-planes Mc between 0° and 360°
5     distance between C-planes Dc (degrees; 0 for non-equidistant)
6     number of luminous intensities in each C-plane Ng
7     distance between them Dg (degrees; 0 for non-equidistant)
8–12  measurement report, luminaire name and number, file name, date
13–21 luminaire and luminous-area dimensions (mm)
22    downward flux fraction DFF (%)
23    light output ratio LORL (%)
24    conversion factor for luminous intensities CFLI
25    tilt of the luminaire during measurement (degrees)
26    number n of standard sets of lamps, then per set six lines:
      number of lamps (negative: absolute photometry, see below), type,
      total luminous flux (lm), colour temperature, colour rendering,
      wattage (W)
      then 10 direct ratios (room indices k = 0.6 … 5)
      then Mc angles C (degrees), Ng angles γ (degrees)
      then the luminous intensities, cd per 1000 lm of lamp flux, Ng
      values for each C-plane that the symmetry leaves
====  ==============================================================

Isym: 0 no symmetry (Mc planes, C 0 … 360 − Dc); 1 symmetry about the
vertical axis (1 plane); 2 symmetry to the C0–C180 plane (Mc/2 + 1 planes,
C0 … C180); 3 symmetry to the C90–C270 plane (Mc/2 + 1 planes, C270 …
C360/0 … C90); 4 symmetry to both (Mc/4 + 1 planes, C0 … C90).

Candela = value × CFLI × Φ/1000, Φ the first lamp set's total flux. A
negative number of lamps marks absolute photometry (the convention for
LED luminaires): the file's flux is then the luminaire's, and the
distribution is marked absolute (``rated_lumens`` None) though scaled the
same way. γ = 0° is the nadir as in type C; EULUMDAT's C-planes are the
type C horizontal angles.
"""

from __future__ import annotations


import numpy as np

from simulator.errors import UserError

from .distribution import GoniometricDistribution, read_file_text, unfold_type_c

__all__ = ["read_ldt", "parse_ldt"]


def read_ldt(path) -> GoniometricDistribution:
    """Read a EULUMDAT file; see :func:`parse_ldt`."""
    return parse_ldt(read_file_text(path), str(path))


def parse_ldt(text: str, source: str = "<ldt>") -> GoniometricDistribution:
    """Parse the text of a EULUMDAT file into a full type C distribution."""
    lines = [ln.strip() for ln in text.replace("\r\n", "\n").replace("\r", "\n").split("\n")]
    pos = 0

    def line(what: str) -> str:
        nonlocal pos
        if pos >= len(lines):
            raise UserError(f"{source}: file ends at line {pos + 1} ({what})")
        pos += 1
        return lines[pos - 1]

    def num(what: str) -> float:
        s = line(what)
        try:
            return float(s.replace(",", "."))
        except ValueError:
            raise UserError(f"{source}: line {pos}: {what}: {s!r} is not a number") from None

    def integer(what: str) -> int:
        v = num(what)
        if v != int(v):
            raise UserError(f"{source}: line {pos}: {what}: {v:g} is not an integer")
        return int(v)

    line("company")
    ityp = integer("Ityp")
    isym = integer("Isym")
    mc = integer("Mc, number of C-planes")
    num("Dc")
    ng = integer("Ng, intensities per C-plane")
    num("Dg")
    for what in ("measurement report", "luminaire name", "luminaire number", "file name", "date/user"):
        line(what)
    for what in ("length", "width", "height", "luminous length", "luminous width", "h C0", "h C90", "h C180", "h C270"):
        num(what)
    num("DFF")
    num("LORL")
    cfli = num("conversion factor CFLI")
    num("tilt")
    n_sets = integer("number of lamp sets")
    if n_sets < 1:
        raise UserError(f"{source}: line {pos}: no lamp set")
    sets = []
    for _ in range(n_sets):
        n_lamps = integer("number of lamps")
        line("lamp type")
        flux = num("lamp flux")
        line("colour temperature")
        line("colour rendering")
        num("wattage")
        sets.append((n_lamps, flux))
    for k in range(10):
        num(f"direct ratio {k + 1}")
    if isym not in (0, 1, 2, 3, 4):
        raise UserError(f"{source}: Isym {isym} is not 0–4")
    if mc < 1 or ng < 1:
        raise UserError(f"{source}: Mc {mc}, Ng {ng}: need at least one plane and one angle")
    c_all = np.array([num("C angle") for _ in range(mc)])
    g = np.array([num("gamma angle") for _ in range(ng)])
    if isym == 1:
        first, count = 0, 1
    elif isym == 2:
        first, count = 0, mc // 2 + 1
    elif isym == 3:
        first, count = 3 * mc // 4, mc // 2 + 1
    elif isym == 4:
        first, count = 0, mc // 4 + 1
    else:
        first, count = 0, mc
    vals = np.array([num("luminous intensity") for _ in range(count * ng)]).reshape(count, ng)
    idx = (first + np.arange(count)) % mc
    c = c_all[idx].copy()
    if isym == 3:
        # C270 … C350, C0 … C90 → 270 … 450 → reorder to the 90–270 convention (I(180 − C) = I(C))
        c = np.where(np.arange(count) >= (mc - first), c + 360.0, c)  # unwrap past 360
        c_mirror = np.mod(180.0 - c, 360.0)  # the measured half reflected: 90 … 270
        order = np.argsort(c_mirror)
        c, vals = c_mirror[order], vals[order]
    n_lamps, flux = sets[0]
    scale = cfli * abs(flux) / 1000.0
    cd = vals * scale
    if isym == 1:
        c = np.array([0.0])
    phi_full, cd_full, symmetry = unfold_type_c(g, c, cd, source)
    rated = None if n_lamps < 0 else float(abs(flux))
    kw = {"Ityp": ityp, "Isym": isym, "CFLI": cfli, "lamp_sets": sets}
    return GoniometricDistribution(g, phi_full, cd_full, rated_lumens=rated, source=source, symmetry=symmetry, keywords=kw)
