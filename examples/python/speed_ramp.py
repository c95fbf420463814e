"""Hunting on a falling speed: the textbook wheelset, started hunting at
76 m/s (its Hopf point is 73.1 m/s), decelerated at two rates; where does the
hunting die away?

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/speed_ramp.py
"""
import pathlib

import railstab

CASES = pathlib.Path(__file__).resolve().parents[2] / "cases"

r = railstab.speed_ramp(CASES / "textbook_wheelset.toml", [0.5, 2.0], speed=76.0, ramp_to=60.0,
                        mode="hunting", mode_amplitude=0.001)
for ramp in r.ramps:
    print(f"  {ramp['ramp_rate_m_per_s2']:g} m/s^2: {ramp['outcome']}")
print(r.note)
