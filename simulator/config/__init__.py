"""Run configs: TOML files read into validated :class:`RunConfig` objects."""

import os as _os

# The schema's pydantic validators are compiled here, once, without pydantic
# plugins: looking for them reads every installed distribution's entry points
# (about 5 ms). A PYDANTIC_DISABLE_PLUGINS the user set is left as it is, and
# the variable is restored afterwards, so other pydantic models are untouched.
_PLUGINS = "PYDANTIC_DISABLE_PLUGINS"
_user_setting = _os.environ.get(_PLUGINS)
if _user_setting is None:
    _os.environ[_PLUGINS] = "__all__"
try:
    from simulator.config.loader import *  # noqa: F401,F403,E402
    from simulator.config.loader import __all__  # noqa: F401,E402
finally:
    if _user_setting is None:
        del _os.environ[_PLUGINS]
