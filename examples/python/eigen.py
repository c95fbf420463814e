"""Eigenvalues and modes of the textbook bogie at 30 m/s.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/eigen.py
"""
import pathlib

import numpy as np

import railstab

CASES = pathlib.Path(__file__).resolve().parents[2] / "cases"

r = railstab.eigen(CASES / "textbook_bogie.toml", speed=30.0)
print(f"{r.scene} at {r.speed_m_per_s} m/s: {r.states} states")
for lam, f, zeta, name in zip(r.eigenvalues, r.frequency_Hz, r.damping_ratio, r.mode_names):
    if lam.imag > 0 and f < 20:
        print(f"  {lam.real:10.4f} {f:8.3f} Hz  damping {zeta:7.4f}  {name}")
# The vectors are the state matrix's: A v = lambda v.
k = int(np.argmax(r.eigenvalues.real))
v = r.eigenvectors[:, k]
assert np.allclose(r.state_matrix @ v, r.eigenvalues[k] * v, atol=1e-8 * np.abs(v).max() * np.abs(r.state_matrix).max())
