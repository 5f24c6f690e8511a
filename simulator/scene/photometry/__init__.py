"""Luminaire photometry: goniometric (type C) intensity distributions and
the readers of the two file formats lighting engineers exchange them in.

- :mod:`.distribution`: :class:`GoniometricDistribution`, I(θ, φ) in candela
  with bilinear interpolation, total lumens, and a regular table for kernels;
- :mod:`.ies`: IES LM-63 (1986/1991, 1995, 2002, 2019) files;
- :mod:`.ldt`: EULUMDAT (``.ldt``) files;
- :mod:`.files`: :func:`read_photometry`, either format by its suffix.

Pure numpy: no USD, no Warp.

Checked on public photometric files (not bundled), total lumens by
:meth:`GoniometricDistribution.total_lumens` against the file's own figure:

- IES files of the GitHub repository echowuzangye/CU-calculations-based-on-IES-file
  (``ies/1.IES`` … ``8.IES``, LM-63-2002: quadrant, bilateral, asymmetric and
  axial symmetry), against the lumens that repository lists from Photometric
  Toolbox: 9218.26 / 9217.18, 5833.32 / 5834.2, 13348.44 / 13359.57,
  5820.16 / 5821.76, 753.64 / 753.8, 9217.27 / 9230.16, 531.80 / 531.98,
  828.34 / 828.32 lm (within 0.14%; the zonal-lumen method integrates a
  different interpolant);
- holg/eulumdat-rs ``tests/files``: an LM-63-1995 roadway file stating
  9155.7 lm per lamp integrates to 9155.37 lm (its measured 360° plane
  differs from its 0° plane), an LM-63-2002 5300 lm downlight to 5300.82 lm,
  an LM-63-1995 1000 lm file to 999.93 lm;
- holg/eulumdat-rs EULUMDAT templates of real floodlights (Isym 0): lamp
  flux × LORL against the integral, 80419.5 / 80411.2, 120879 / 120981,
  122754 / 122788, 154845 / 154944 lm (within 0.09%); an Isym 4 two-lamp
  fluorescent luminaire 3264.3 / 3262.7 lm; an Isym 3 road luminaire
  28027 / 27934 lm (0.3%).
"""

from .distribution import GoniometricDistribution
from .files import read_photometry
from .ies import read_ies, parse_ies
from .ldt import read_ldt, parse_ldt

__all__ = ["GoniometricDistribution", "read_photometry", "read_ies", "parse_ies", "read_ldt", "parse_ldt"]
