"""Run configs: TOML files read into validated :class:`RunConfig` objects."""

from simulator.config.loader import *  # noqa: F401,F403
from simulator.config.loader import __all__  # noqa: F401
