"""The textbook bogie's critical speed against its primary longitudinal
stiffness: a study grid as numpy arrays (a pandas DataFrame with dataframe=True).

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/study.py
"""
import pathlib

import railstab

CASES = pathlib.Path(__file__).resolve().parents[2] / "cases"
KEY = "elements.primary_ws1.stiffness_N_per_m[0]"

r = railstab.study(CASES / "textbook_bogie.toml", {KEY: (2.5e6, 2e7, 2.5e6)}, from_=10, to=200,
                   step=5, jobs=2)
t = r.table
for k, v in zip(t[KEY], t["critical_speed_m_per_s"]):
    print(f"  k_x = {k / 1e6:5.1f} MN/m: {v:7.3f} m/s")
