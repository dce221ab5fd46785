"""SurfaceTopography's side of examples/read_speed.rs: the same work.

    /work/venvs/readers/bin/python tests/reference/read_speed.py FILE [--fill]

Reads FILE with read_topography (with --fill, then
interpolate_undefined_data()), prints the grid and the rms of the defined
heights about their mean in the file's unit.
"""
import sys

import numpy as np
from SurfaceTopography import read_topography

t = read_topography(sys.argv[1])
if "--fill" in sys.argv and t.has_undefined_data:
    t = t.interpolate_undefined_data()
h = np.ma.compressed(np.ma.masked_invalid(np.ma.masked_array(t.heights(), dtype=float)))
print(t.nb_grid_pts, f"rms {np.sqrt(np.mean((h - h.mean()) ** 2)):e} {t.unit}")
