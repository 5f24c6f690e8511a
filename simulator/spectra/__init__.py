"""Spectra: the wavelength grid, emission and reflectance spectra, sensor responses.

Everything here is host-side numpy. CIE tables come from ``colour-science``,
imported lazily by :mod:`simulator.spectra.tables` the first time a table is
needed, so a grey run that asks for no response never pays its import
(about 1 s). Modules:

``grid``         the reduction grid (380–780 nm, 1 nm) and transport bands
``tables``       CIE tables sampled on the grid (cached)
``csvfile``      the two-column spectral CSV reader every measured file uses
``sources``      emission spectra: blackbody, CIE illuminants, RGB, SPD files
``reflectance``  RGB → reflectance uplift (Mallett & Yuksel 2019), CSV files
``responses``    the response registry (photopic, PAR, α-opic, custom, …)
``reduce``       spectral or per-band estimates → responses with stderr
``posthoc``      responses of a grey scene from its radiometric readings
``transport``    grey, per-emitter or hero-wavelength transport, and why
``hero``         the tables hero-wavelength transport uploads (reflectance, emission, response weights)
``traced``       a spectrally traced run's response columns and record
``config``       how a run names its responses (TOML piece and loader)
``schema``       the same TOML piece as pydantic models

What spectral tracing costs against one channel is measured by a script
beside the package, ``benchmarks/spectral_cost.py``, not in it.
"""
