"""The engine: uploads a scene to a Warp device (:mod:`.device`), launches
the estimator kernels in batches for every sensor kind, probes included
(:mod:`.driver`, over CPU threads by :mod:`.fanout`), accumulates float64
statistics (:mod:`.stats`) and stops each reading when its error target is
met (:mod:`.adaptive`). Only this package and :mod:`simulator.kernels`
import ``warp``, and only when a run starts."""
