"""Sensor models: what a real sensor reads where the ideal one reads the irradiance.

A model is a head's angular response (:mod:`.angular`), a spectral
responsivity with its calibration, and the electronics that turn the
signal into counts and a reported value. A ``[[sensor]]`` or ``[[grid]]``
names one with ``model = "..."``: the run then reads the ideal quantity as
before and, beside it, the signal through the model's optics and the
device's reading (docs/DESIGN.md §Sensor models).
"""
