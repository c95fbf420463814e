"""The steady state of the textbook bogie at 30 m/s: body offsets and wheel loads.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/equilibrium.py
"""
import pathlib

import railstab

CASES = pathlib.Path(__file__).resolve().parents[2] / "cases"

r = railstab.equilibrium(CASES / "textbook_bogie.toml", speed=30.0)
print(f"{r.scene} at {r.speed_m_per_s} m/s: {r.newton_iterations} Newton iterations")
for body in r.bodies:
    print(f"  {body['name']:10s} lateral {body['y_offset_m'] * 1e3:8.4f} mm, "
          f"yaw {body['yaw_offset_rad'] * 1e3:8.4f} mrad")
print(f"state vector: {len(r.state)} states")
