"""probesim: a radiometric light-probe sensor simulator."""

__version__ = "0.1.0"

