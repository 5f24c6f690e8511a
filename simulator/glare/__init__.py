"""Discomfort glare at an eye: DGP, DGPs and UGR from a view of the stage.

A glare sensor (``kind = "glare"``) is an eye position, a view direction and
an up vector. probesim traces the luminance of the hemisphere in front of
the eye with the probe kernel (a lat-long map of the front half only, see
:mod:`.view`), adds each sun as its true disk (its luminance and visibility
through glazing read by a cone meter the size of the disk, never spread over
a pixel), finds the glare sources as evalglare does (:mod:`.sources`) and
evaluates the indices with their standard errors (:mod:`.evaluate`, formulas
in :mod:`.indices`). The engine side is :mod:`simulator.engine.glare`; the
fisheye images are written by :mod:`simulator.io.glare_maps`.

Pure numpy here: no Warp, no USD.
"""
