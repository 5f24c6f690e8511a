"""Files in and out: the CSV and run record, EXR, lat-long maps, grid and probe maps."""
