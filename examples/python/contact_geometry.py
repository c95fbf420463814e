"""S1002 wheel on UIC60 rail: equivalent conicity over amplitude (EN 15302).

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/contact_geometry.py
"""
import pathlib

import numpy as np

import railstab

CASES = pathlib.Path(__file__).resolve().parents[2] / "cases"

r = railstab.contact_geometry(CASES / "s1002_uic60_contact.toml")
print(f"{r.wheel_profile} on {r.rail_profile}: equivalent conicity at 3 mm "
      f"{r.equivalent_conicity_at_reference_amplitude:.4f}")
a, c = r.conicity["amplitude_m"], r.conicity["equivalent_conicity"]
for A in (0.001, 0.002, 0.003, 0.004, 0.005):
    print(f"  amplitude {A * 1e3:.0f} mm: {np.interp(A, a, c):.4f}")
