"""Planck's law: blackbody spectral radiance, and the constants it takes.

A module of its own (it needs only numpy) so that the wide grid
(:mod:`simulator.spectra.wide`) and the light sources
(:mod:`simulator.spectra.sources`) both read it without importing each other.

Notes
-----
.. math:: B_λ(T) = \\frac{2 h c^2}{λ^5} \\frac{1}{e^{c_2/(λT)} − 1}

with c₂ = h c / k exactly, or CIE 15's 1.4388·10⁻² m K for colour
temperatures (the CIE's illuminant A and blackbody tables use it).
"""

import numpy as np

__all__ = ["C2_CIE_M_K", "C_M_S", "H_J_S", "K_B_J_K", "planck_W_m2_sr_nm"]

#: Planck constant, J s (exact, SI 2019)
H_J_S = 6.62607015e-34
#: speed of light in vacuum, m/s (exact)
C_M_S = 299792458.0
#: Boltzmann constant, J/K (exact, SI 2019)
K_B_J_K = 1.380649e-23
#: second radiation constant for colour temperatures, m K (CIE 15:2004, ITS-90)
C2_CIE_M_K = 1.4388e-2


def planck_W_m2_sr_nm(temperature_K: float, wavelength_nm, c2_m_K: float | None = None) -> np.ndarray:
    """Blackbody spectral radiance B_λ(T), W m⁻² sr⁻¹ nm⁻¹ (see module Notes).

    Parameters
    ----------
    temperature_K : float
        > 0.
    wavelength_nm : array_like
        Wavelengths in vacuum, nm.
    c2_m_K : float, optional
        Second radiation constant; default the exact h c / k.
    """
    lam = np.asarray(wavelength_nm, float) * 1e-9
    c2 = H_J_S * C_M_S / K_B_J_K if c2_m_K is None else float(c2_m_K)
    x = c2 / (lam * float(temperature_K))
    return 2.0 * H_J_S * C_M_S**2 / lam**5 / np.expm1(x) * 1e-9
