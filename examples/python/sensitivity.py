"""Which parameters the textbook bogie's critical speed hangs on: dVc/dp and
the elasticity (p / Vc) dVc/dp of every parameter, largest first.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/sensitivity.py
"""
import pathlib

import railstab

CASES = pathlib.Path(__file__).resolve().parents[2] / "cases"

r = railstab.sensitivity(CASES / "textbook_bogie.toml", from_=80, to=120, step=5)
print(f"{r.scene}: critical speed {r.critical_speed_m_per_s:.4f} m/s")
for p in r.parameters[:5]:
    print(f"  {p['parameter']:45s} dVc/dp {p['critical_speed_derivative_m_per_s_per_unit']:+.4g}, "
          f"elasticity {p['elasticity']:+.4f}")
