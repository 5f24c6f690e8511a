"""Placement studies (``probesim study``): candidates × scenarios, zone figures, the best K sensors.

One job per module: :mod:`.schema` (the study file), :mod:`.en12464` (the
grid rule), :mod:`.candidates` (sensor sets on the stage), :mod:`.sun`
(solar position), :mod:`.scenarios` (dimming vectors, trace groups),
:mod:`.groups` (one pass tallying every light group, and the linear recombination),
:mod:`.chunks` (units of work, their store and resume), :mod:`.distributed`
(in-process or dask), :mod:`.objectives` (zone figures, calibration),
:mod:`.placement` (greedy selection), :mod:`.runner` (a study end to end)
and :mod:`.report` (CSVs, heat maps, JSON).
"""
