"""The textbook wheelset's periodic hunting orbits from the Hopf point
(amplitude against speed: the bifurcation diagram's numbers).

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/bifurcation.py
"""
import pathlib

import railstab

CASES = pathlib.Path(__file__).resolve().parents[2] / "cases"

r = railstab.bifurcation(CASES / "textbook_wheelset.toml", from_=50, to=100, max_amplitude=0.003)
print(f"{r.scene}: linear critical speed {r['linear_critical_speed_m_per_s']:.3f} m/s")
b = r.orbits
print(f"{len(next(iter(b.values())))} orbits; columns: {', '.join(b)}")
