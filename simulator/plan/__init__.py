"""The planner: per sensor, which estimator reads it and why."""

from simulator.plan.planner import *  # noqa: F401,F403
from simulator.plan.planner import __all__  # noqa: F401
