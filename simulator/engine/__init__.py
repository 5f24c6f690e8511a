"""The engine: uploads a scene to a Warp device, launches the estimator
kernels in batches, accumulates float64 statistics and stops each sensor
when its error target is met. Only this package and :mod:`simulator.kernels`
import ``warp``, and only when a run starts."""
