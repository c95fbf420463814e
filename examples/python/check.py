"""The model checks of the thesis vehicle before a run: masses, axle loads,
static deflections, natural frequencies at rest, warnings.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/check.py
"""
import pathlib

import railstab

CASES = pathlib.Path(__file__).resolve().parents[2] / "cases"

r = railstab.check(CASES / "thesis_vehicle_tangent.toml")
print(f"{r.scene}: {len(r.warnings)} warnings, {len(r.errors)} errors")
print("report fields:", ", ".join(r.keys()))
assert not r.errors
