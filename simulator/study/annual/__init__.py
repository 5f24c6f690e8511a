"""A year of daylight: weather, the Perez sky by patch, the exact sun, hourly recombination, metrics, control."""
