"""A short time-domain run of the textbook wheelset above its critical speed (73.1 m/s):
the lateral motion as a numpy array, and the run's error estimate.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/simulate.py
"""
import pathlib

import numpy as np

import railstab

CASES = pathlib.Path(__file__).resolve().parents[2] / "cases"

r = railstab.simulate(CASES / "textbook_wheelset.toml", speed=80.0, t_end=2.0,
                      offset={"wheelset1.y_m": 0.001})
y = r.channels["wheelset1.y_m"]
if r.stopped_early:
    print("stopped early:", r.stopped_early)
print(f"{r.scene}: {len(r.time)} output times to {r.time[-1]} s, {len(r.channels)} channels")
print(f"wheelset1 lateral: from {y[0] * 1e3:.3f} mm, largest {np.abs(y).max() * 1e3:.3f} mm")
e = r.error_estimate
print(f"estimated error {e['position_error']:.3g} at {e['position_error_at']} "
      f"({e['method']})")
