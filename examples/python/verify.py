"""The textbook wheelset's least stable mode checked in the time domain:
fitted growth rate and frequency against the eigenvalue.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/verify.py
"""
import pathlib

import railstab

CASES = pathlib.Path(__file__).resolve().parents[2] / "cases"

r = railstab.verify(CASES / "textbook_wheelset.toml", speed=20.0, periods=8, settle_periods=2)
print(f"{r.scene} at 20 m/s: {r.mode}")
print({k: v for k, v in r.items() if isinstance(v, (int, float)) and not isinstance(v, bool)})
