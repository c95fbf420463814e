"""The README's root-locus plot of the thesis vehicle, with matplotlib from
the arrays critical_speed returns (the command draws it with gnuplot:
plots/thesis_vehicle_tangent_root_locus.png).

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/root_locus.py [OUT.png]
(default thesis_vehicle_tangent_root_locus_matplotlib.png in the current folder)
"""
import math
import pathlib
import sys

import matplotlib
matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt
import numpy as np

import railstab

CASES = pathlib.Path(__file__).resolve().parents[2] / "cases"
out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "thesis_vehicle_tangent_root_locus_matplotlib.png")

r = railstab.critical_speed(CASES / "thesis_vehicle_tangent.toml")
band = r.hunting_band_Hz
fig, ax = plt.subplots(figsize=(8, 6))
# One curve per mode track (the same mode over the speed grid), the upper
# half plane below the hunting band: real part against frequency.
lam = r.eigenvalues
# The hunting track: the least stable in the band at the highest speed.
last = np.where(np.isfinite(lam[-1]) & (lam[-1].imag > 0) & (lam[-1].imag / (2 * math.pi) <= band),
                lam[-1].real, -np.inf)
hunting_track = int(np.argmax(last))
for j in range(lam.shape[1]):
    f = lam[:, j].imag / (2 * math.pi)
    keep = np.isfinite(lam[:, j]) & (f > 0) & (f <= band) & (lam[:, j].real >= -20)
    if keep.sum() < 2:
        continue
    hunting = j == hunting_track
    ax.plot(lam[keep, j].real, f[keep], lw=2.5 if hunting else 0.8,
            color="#d55e00" if hunting else "0.55", label=r.hunting_mode if hunting else None,
            zorder=3 if hunting else 2)
ax.axvline(0.0, color="k", lw=0.8)
ax.set_xlabel("real part (1/s)")
ax.set_ylabel("frequency (Hz)")
ax.set_title(f"{r.scene}: root locus {r.speeds[0]:g}-{r.speeds[-1]:g} m/s, "
             f"critical speed {r.critical_speed_m_per_s:.2f} m/s")
ax.legend(loc="upper left")
fig.tight_layout()
fig.savefig(out, dpi=100)
print(f"wrote {out}")
assert out.stat().st_size > 10000
