"""critical_speed, eigen, equilibrium and curving against the command line's
files (textbook bogie: 12 states, critical speed 102.46 m/s; the coach on
S1002/UIC60 in its curve for curving)."""
import math

import numpy as np
import pytest

import railstab
from conftest import assert_same_report, case, printed

BOGIE = case("textbook_bogie.toml")
GRID = dict(from_=80.0, to=120.0, step=5.0)
GRID_FLAGS = ["--from", "80", "--to", "120", "--step", "5"]


def test_critical_speed_equals_the_command(cli):
    r = railstab.critical_speed(BOGIE, **GRID)
    run = cli("critical-speed", BOGIE, *GRID_FLAGS, "--no-plots")
    assert_same_report(r, run.json("_critical_speed.json"))
    assert r.critical_speed_m_per_s > 0
    # The eigenvalue arrays are the eigenvalue CSV's numbers at full
    # precision: printed as the CSV prints them (12 digits), the same text.
    rows = run.csv_rows("_eigenvalues.csv")
    header, rows = rows[0], rows[1:]
    t = r.eigenvalue_table
    assert len(rows) == len(t["speed_m_per_s"])
    column = {name: i for i, name in enumerate(header)}
    for k, row in enumerate(rows):
        assert printed(t["speed_m_per_s"][k], 12) == row[column["speed_m_per_s"]]
        assert str(t["mode_track"][k]) == row[column["mode_track"]]
        assert printed(t["eigenvalue_per_s"][k].real, 12) == row[column["eigenvalue_real_per_s"]]
        assert printed(t["eigenvalue_per_s"][k].imag, 12) == row[column["eigenvalue_imag_per_s"]]
        assert printed(t["damping_ratio"][k], 12) == row[column["damping_ratio"]]
        assert t["name"][k] == row[column["name"]]
    # Over speed: one row per grid speed, a column per mode track.
    assert list(r.speeds) == sorted(set(t["speed_m_per_s"]))
    assert r.eigenvalues.shape == (len(r.speeds), max(t["mode_track"]) + 1)
    assert r.eigenvalues.dtype == np.complex128


def test_set_overrides_equal_the_set_flag(cli):
    key, value = "elements.primary_ws1.stiffness_N_per_m[0]", 2.5e6
    scene = railstab.load_scene(BOGIE)
    assert key in scene.parameters
    r = railstab.critical_speed(BOGIE, set={key: value}, **GRID)
    run = cli("critical-speed", BOGIE, *GRID_FLAGS, "--no-plots", "--set", f"{key}=2.5e6")
    assert_same_report(r, run.json("_critical_speed.json"))
    # A Scene carries its overrides into the analysis.
    s = railstab.load_scene(BOGIE, set={key: value})
    assert s.parameters[key] == value
    assert_same_report(railstab.critical_speed(s, **GRID), run.json("_critical_speed.json"))
    # and the override changed the result
    plain = railstab.critical_speed(BOGIE, **GRID)
    assert plain.critical_speed_m_per_s != r.critical_speed_m_per_s


def test_eigen_equals_the_command(cli):
    r = railstab.eigen(BOGIE, speed=30.0)
    run = cli("eigen", BOGIE, "--speed", "30")
    assert_same_report(r, run.json("_eigen_30mps.json"))
    assert [m["name"] for m in r.modes] == r.mode_names
    assert len(r.eigenvalues) == len(r.modes) == r.eigenvectors.shape[1]
    assert r.eigenvectors.shape[0] == len(r.state_names) == r.states
    for k, m in enumerate(r.modes):
        assert printed(r.eigenvalues[k].real, 12) == printed(m["eigenvalue_real_per_s"], 12)
    # A v = lambda v: the vectors are the modes' own.
    A = r.state_matrix
    for k in range(len(r.eigenvalues)):
        v = r.eigenvectors[:, k]
        assert np.linalg.norm(A @ v - r.eigenvalues[k] * v) <= 1e-8 * np.linalg.norm(A) * np.linalg.norm(v)


def test_equilibrium_equals_the_command(cli):
    r = railstab.equilibrium(BOGIE, speed=30.0)
    run = cli("equilibrium", BOGIE, "--speed", "30")
    assert_same_report(r, run.json("_equilibrium_30mps.json"))
    assert r.state.ndim == 1 and np.all(np.isfinite(r.state))


def test_curving_equals_the_command(cli):
    # The coach in its curve over three cant deficiencies (0.3 s CPU).
    coach = case("coach_s1002_curve.toml")
    r = railstab.curving(coach, cant_deficiency=(0.0, 0.1, 0.05))
    run = cli("curving", coach, "--cant-deficiency", "0:0.1:0.05")
    assert_same_report(r, run.json("_curving.json"))
    rows = run.csv_rows("_curving.csv")
    assert list(r.table) == rows[0]
    assert len(rows) - 1 == 3
    for j, name in enumerate(rows[0]):
        column = r.table[name]
        if column.dtype == float:
            assert [printed(v, 10) if not np.isnan(v) else "" for v in column] == \
                [row[j] for row in rows[1:]], name
    np.testing.assert_allclose(r.table["cant_deficiency_m"], [0.0, 0.05, 0.1], atol=1e-12)


def test_curving_bad_requests_name_the_argument():
    coach = case("coach_s1002_curve.toml")
    for kwargs, said in (
            (dict(radius=-250), ["radius", "in [10, 1e6] m", "'-250'"]),
            (dict(cant_deficiency=(0.1, 0.3)), ["cant_deficiency", "(from, to, step)"]),
            (dict(cant_deficiency=(0.1, 0.3, 0)), ["cant_deficiency", "step is not positive"]),
            (dict(cant_deficiency=math.nan), ["cant_deficiency", "not a finite number"]),
            (dict(cant_deficiency=(0, 0.3, 0.1), radius=(1000, 500, 100)), ["two ranges"]),
            (dict(cant_deficiency=-0.2), ["cant_deficiency", "needs a speed of zero or less"]),
            (dict(), ["cant_deficiency (from, to, step)", "radius (from, to, step)"]),
            (dict(radius="250"), ["radius", "expected a number or (from, to, step)"])):
        with pytest.raises(railstab.InputError) as e:
            railstab.curving(coach, **kwargs)
        for s in said:
            assert s in str(e.value), (kwargs, str(e.value))


def test_quasi_linear_critical_speed_equals_the_command(cli):
    # The S1002 bogie's quasi-linear contact at 3 mm (critical-speed --amplitude).
    scene = case("thesis_bogie_s1002_tangent.toml")
    r = railstab.critical_speed(scene, amplitude=0.003, from_=20, to=60, step=5)
    run = cli("critical-speed", scene, "--amplitude", "0.003", "--from", "20", "--to", "60",
              "--step", "5", "--no-plots")
    assert_same_report(r, run.json("_quasi_linear_critical_speed.json"))
    assert r.quasi_linear["amplitude_m"] == 0.003
