"""From readings to figures: zone figures and calibration, EN 12464-1 areas, placement, score names."""
