"""The reference cases: one registry for ``probesim verify``, ``probesim
stability``, ``probesim chart`` and the tests.

Each case is declared once (:data:`CASES`): a bundled config (under
``configs/``) and its stage, what it measures, the expected reading of
every receiver (closed forms from :mod:`simulator.reference.closed_forms`;
each expected-value function names its formula and source), the
tolerances a reading is judged by, and the suites that use it:

``verify``
    traced through the normal pipeline and judged per reading
    (:mod:`simulator.commands.verify`);
``stability``
    a hard case of the estimator × case matrix (:mod:`simulator.commands.stability`);
``chart``
    charted by default by ``probesim chart`` (:attr:`Case.chart` is its place
    in that list; the chart runs the config as it is, its own variant selection).

Every photometric verify case of direct light runs again in radiometric
light units (its *radiometric twin*, named ``<name> [W]``), where the
stage's numbers are W m⁻² sr⁻¹ (W/sr, W/m²).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from simulator.reference.cases import direct as D
from simulator.reference.cases import enclosures as E
from simulator.reference.cases import hard as H
from simulator.reference.cases.context import CaseContext, ExpectedFn, NoteFn, no_closed_form, one_light, read_config

__all__ = [
    "REL_TOL", "K_SIGMA", "FLOAT32_SLACK", "REL_TARGET", "REL_TARGET_QUICK", "SUITES",
    "Case", "CASES", "CaseContext", "ExpectedFn", "NoteFn", "suite", "case", "one_light", "no_closed_form", "read_config",
]  # fmt: skip

#: verify: a reading must be within this fraction of the expected value
REL_TOL = 0.01
#: ... and within this many standard errors (plus FLOAT32_SLACK)
K_SIGMA = 4.0
#: float32 arithmetic in the kernels: relative slack on top of K_SIGMA·stderr
FLOAT32_SLACK = 2e-6
#: adaptive stopping: 95% half-width under this fraction of the reading (stderr ≤ 0.1%)
REL_TARGET = 0.002
#: the slow (interreflection) cases, and every case with --quick: stderr ≤ 0.2%,
#: so 1% is still five standard errors
REL_TARGET_QUICK = 0.004

SUITES = ("verify", "stability", "chart")


@dataclass(frozen=True)
class Case:
    """One reference case.

    Attributes
    ----------
    name : str
        Name in tables and on the command line.
    config : str
        Config file, relative to the configs folder (``point.toml``,
        ``stability/leak.toml``).
    measures : str
        What the case measures, one line.
    expected : ExpectedFn
        Expected reading of each receiver.
    suites : tuple of str
        The suites that use it (:data:`SUITES`).
    method : str
        Estimator verify traces it with: light, bsdf, mis or path.
    scale : ExpectedFn or None
        Magnitude the stability verdict's floors are relative to (None: the
        expected reading's own); the unoccluded reading where the truth is 0.
    note : NoteFn or None
        Comment per receiver (published values, model deviations).
    light_units : str or None
        Overrides the config's ``light_units`` (None: as the config says).
    variants : tuple of (str, str)
        Variant selections (set, variant) that replace the config's.
    optional : bool
        The config may be absent (work in progress): verify skips the case
        with a printed note instead of failing it.
    patch_flux : bool
        Verify reports a patch's flux (W, lm); False: its mean irradiance (W/m², lx).
    rel_target : float
        Verify's adaptive target: 95% half-width over the reading.
    quick : bool
        Part of ``verify --quick``.
    chart : int or None
        Place in ``probesim chart``'s default list (with "chart" in ``suites``).
    rel_tol, k_sigma : float
        Verify's pass rule: within ``rel_tol`` of the expected value and
        within ``k_sigma`` standard errors (+ FLOAT32_SLACK relative).
    optics : bool
        The config's sensors name sensor models and verify reads their optics twins (the head's
        ∫ L r dω; :mod:`simulator.sensor_models.readings`), not the ideal sensors.
    """

    name: str
    config: str
    measures: str
    expected: ExpectedFn
    suites: tuple[str, ...] = ("verify",)
    method: str = "light"
    scale: ExpectedFn | None = None
    note: NoteFn | None = None
    light_units: str | None = None
    variants: tuple[tuple[str, str], ...] = ()
    optional: bool = False
    patch_flux: bool = True
    rel_target: float = REL_TARGET
    quick: bool = True
    chart: int | None = None
    rel_tol: float = REL_TOL
    k_sigma: float = K_SIGMA
    optics: bool = False


def _reflectance(rho: str) -> tuple[tuple[str, str], ...]:
    return (("reflectance", rho),)


_VC = ("verify", "chart")

# Direct light: one emitter, closed forms, next-event estimation ("mis" for the
# polygon, whose near-field receivers are noisy under area sampling alone).
_DIRECT: tuple[Case, ...] = (
    Case("cie171_5_2", "cie171_5_2.toml", "CIE 171:2006 5.2: a Lambertian point source over a grid of 10 receivers",
         D.cie171_5_2, _VC, note=D.cie171_5_2_note, chart=8),
    Case("point", "point.toml", "an isotropic point light: inverse-square cosine law, a patch's solid angle", D.point, _VC, chart=0),
    Case("point_cm_yup", "point_cm_yup.toml", "point.usda authored in centimetres with Y up: the same readings",
         D.point_cm_yup),
    Case("sphere", "sphere.toml", "a sphere light above, beside and straddling receivers' horizons", D.sphere, _VC, chart=1),
    Case("rect", "rect.toml", "a one-sided rect light: parallel, tilted, near-field receivers", D.rect, _VC, chart=2),
    Case("cie171_5_3", "cie171_5_3.toml", "CIE 171:2006 5.3's room: a rect light flush with a black ceiling",
         D.rect, note=D.flush_note),
    Case("cie171_5_2_ies", "cie171_5_2_ies.toml", "CIE 171:2006 5.2 with a goniometric (IES) source",
         D.shaped_point, note=D.cie171_5_2_ies_note),
    Case("spot_cone", "spot_cone.toml", "a spot cone's inside, hard edge and soft ramp", D.shaped_point),
    Case("asymmetric_luminaire", "asymmetric_luminaire.toml", "an asymmetric type C distribution, the light turned 90°",
         D.shaped_point),
    Case("disk", "disk.toml", "a disk light on and off its axis, tilted", D.disk, _VC, chart=3),
    Case("disk_perpendicular", "disk_perpendicular.toml", "a disk light seen edge-on and across the horizon", D.disk,
         note=D.disk_note),
    Case("polygon", "polygon.toml", "an emissive one-sided polygon (mesh light), front and back", D.polygon, _VC,
         method="mis", chart=4),
    Case("distant_occluder", "distant_occluder.toml", "a delta sun and a black occluder: shadow and lit edges",
         D.distant_occluder, _VC, chart=5),
    Case("dome", "dome.toml", "a uniform sky over a black ground", D.dome, _VC, chart=6),
    Case("sensor_heads", "sensor_heads.toml", "sensor heads under a uniform sky: 2πL/(n + 1) for cosⁿ θ, L·∫r dω for a "
         "table", D.sensor_heads, method="mis", optics=True),
    Case("sensor_heads_sun", "sensor_heads_sun.toml", "sensor heads tilted under a delta sun: E·r(θ)", D.sensor_heads,
         optics=True),
    Case("cylindrical", "cylindrical.toml", "cylindrical and semi-cylindrical receivers under a point light: I·sinθ(1 + cos φ)/(πd²)",
         D.cylindrical),
    Case("cylindrical_sky", "cylindrical_sky.toml", "cylindrical and semi-cylindrical receivers under a uniform sky: πL/2",
         D.cylindrical, method="mis"),
    Case("cie_overcast", "cie_overcast.toml", "the CIE standard overcast sky as a lat-long map", D.overcast,
         method="mis", note=D.overcast_note),
    Case("radiance_floor", "radiance_floor.toml", "a Lambertian floor under a delta sun, seen by radiance meters",
         D.radiance_floor),
    Case("glazing 0°", "glazing.toml", "a delta sun at the zenith through a clear pane, a 0.70 datasheet pane and a "
         "presence mesh of opacity 0.3", D.glazing, variants=(("sun", "zenith_0"),)),
    Case("glazing 30°", "glazing.toml", "the glazing at 30° from the zenith: E cos T(θ)", D.glazing,
         variants=(("sun", "zenith_30"),)),
    Case("glazing 60°", "glazing.toml", "the glazing at 60° from the zenith", D.glazing,
         variants=(("sun", "zenith_60"),)),
    Case("cutout", "cutout.toml", "a delta sun through a presence grille and a threshold cut-out, opacity read "
         "per texel", D.cutout),
)  # fmt: skip

# Interreflection: path tracing with Russian roulette, several reflectances
# each (the configs' "reflectance" variant set). These are the slow cases, so
# they stop at stderr ≤ 0.2% (still five standard errors inside 1%), and
# --quick runs one reflectance each.
_ENCLOSURES: tuple[Case, ...] = (
    Case("furnace ρ=0.5", "furnace.toml", "a closed emitting furnace of albedo 0.5: L = L_e/(1 − ρ)", E.furnace,
         method="path", note=E.rho_note, optional=True, variants=_reflectance("rho_0_5"), rel_target=REL_TARGET_QUICK),
    Case("furnace ρ=0.9", "furnace.toml", "the furnace at albedo 0.9", E.furnace, method="path", note=E.rho_note,
         optional=True, variants=_reflectance("rho_0_9"), rel_target=REL_TARGET_QUICK, quick=False),
    Case("integrating_sphere", "integrating_sphere.toml", "an integrating sphere of albedo 0.8 with a point source inside",
         E.integrating_sphere, method="path", note=E.rho_note, optional=True, rel_target=REL_TARGET_QUICK),
    Case("cie171_5_8 ρ=0.5", "cie171_5_8.toml", "CIE 171:2006 5.8: indirect illuminance in a closed cube room, ρ = 0.5",
         E.cie171_5_8, _VC, method="path", note=E.cie171_5_8_note, optional=True, variants=_reflectance("rho_0_5"),
         patch_flux=False, rel_target=REL_TARGET_QUICK, chart=9),
    Case("cie171_5_8 ρ=0.8", "cie171_5_8.toml", "CIE 171:2006 5.8 at ρ = 0.8", E.cie171_5_8, method="path",
         note=E.cie171_5_8_note, optional=True, variants=_reflectance("rho_0_8"), patch_flux=False,
         rel_target=REL_TARGET_QUICK, quick=False),
    # charted as the config selects it (ρ = 0.95); not verified at that albedo (slow)
    Case("furnace", "furnace.toml", "the furnace at the config's own albedo (0.95)", E.furnace, ("chart",),
         method="path", note=E.rho_note, chart=7),
)  # fmt: skip


def _radiometric_twin(c: Case) -> Case:
    return dataclasses.replace(c, name=f"{c.name} [W]", light_units="radiometric", suites=("verify",), chart=None)


_ST = ("stability",)

# Hard cases of the stability matrix: configs/stability/, radiometric.
_HARD: tuple[Case, ...] = (
    Case("grazing", "stability/grazing.toml", "receivers 89 and 89.5 deg from a 1 cm sphere light", H.lights, _ST),
    Case("near_rect", "stability/near_rect.toml", "receivers 1 mm under a 2 m rect light", H.lights, _ST),
    Case("near_sphere", "stability/near_sphere.toml", "receivers 1 mm / 1 um off a sphere light, one inside", H.lights, _ST),
    Case("tiny_source", "stability/tiny_source.toml", "a sphere light of radius 1 mm", H.lights, _ST),
    Case("delta_point", "stability/delta_point.toml", "a point light", H.lights, _ST),
    Case("delta_distant", "stability/delta_distant.toml", "an angle-0 distant light", H.lights, _ST),
    Case("leak", "stability/leak.toml", "occluders 1e-4 m below a rect light and an emissive quad", H.leak, _ST,
         scale=H.leak_scale),
    Case("on_surface", "stability/on_surface.toml", "receivers lying on a tilted 10 km plane", H.on_surface, _ST),
    Case("furnace99", "stability/furnace99.toml", "a closed box of albedo 0.99", H.furnace99, _ST),
    Case("hdr", "stability/hdr.toml", "a 1e5 W/m2 sun and a 1 W/m2 lamp", H.lights, _ST),
    Case("degenerate", "stability/degenerate.toml", "zero-area, sliver and duplicate faces", H.degenerate, _ST,
         scale=H.degenerate_unoccluded),
    Case("glass", "stability/glass.toml", "a delta sun at 60 deg through a clear pane, a 0.70 pane and a presence mesh",
         D.glazing, _ST, variants=(("sun", "zenith_60"),)),
    Case("glossy", "stability/glossy.toml", "a brushed-metal (GGX) floor under a uniform sky, meters and a sensor",
         H.glossy, _ST),
)  # fmt: skip

#: every case, each once: direct light, enclosures, the radiometric twins of
#: the direct-light cases, the hard cases
CASES: tuple[Case, ...] = _DIRECT + _ENCLOSURES + tuple(_radiometric_twin(c) for c in _DIRECT) + _HARD


def suite(name: str) -> tuple[Case, ...]:
    """The cases of one suite, in registry order (``chart``: in chart order)."""
    if name not in SUITES:
        raise ValueError(f"no suite {name!r} (one of {', '.join(SUITES)})")
    out = tuple(c for c in CASES if name in c.suites)
    return tuple(sorted(out, key=lambda c: c.chart)) if name == "chart" else out


def case(name: str) -> Case:
    """The case called ``name``."""
    for c in CASES:
        if c.name == name:
            return c
    raise KeyError(name)
