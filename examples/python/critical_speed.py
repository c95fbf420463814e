"""The thesis vehicle's critical speed from Python (as examples/critical_speed.cpp).

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/critical_speed.py
Answer: 111.46 m/s (README; CTest python_example_critical_speed checks it).
"""
import pathlib

import railstab

CASES = pathlib.Path(__file__).resolve().parents[2] / "cases"

r = railstab.critical_speed(CASES / "thesis_vehicle_tangent.toml", from_=100, to=120, step=5)
print(f"{r.scene}: critical speed {r.critical_speed_m_per_s:.2f} m/s, "
      f"{r.hunting_frequency_Hz:.2f} Hz, {r.hunting_mode}")
print(f"loss of stability: {r.loss_of_stability['description']}")
print(f"{len(r.speeds)} grid speeds, {r.eigenvalues.shape[1]} mode tracks")
assert round(r.critical_speed_m_per_s, 2) == 111.46
