"""sensitivity and critical_speed(gradient=...): the command's numbers, and
the derivative against central differences of the critical speed."""
import pytest

import railstab
from conftest import assert_same_report, case

BOGIE = case("textbook_bogie.toml")
KEYS = ["elements.primary_ws1.stiffness_N_per_m[0]", "bodies.bogie1.mass_kg"]
GRID = dict(from_=80.0, to=120.0, step=5.0)
GRID_FLAGS = ["--from", "80", "--to", "120", "--step", "5"]


def test_sensitivity_equals_the_command(cli):
    r = railstab.sensitivity(BOGIE, keys=KEYS, **GRID)
    run = cli("sensitivity", BOGIE, *GRID_FLAGS, "--no-plots", "--key", KEYS[0], "--key", KEYS[1])
    report = run.json("_sensitivity.json")
    assert_same_report(r, report)
    assert set(r.gradient) == set(KEYS)


def test_gradient_is_the_sensitivity_commands(cli):
    r = railstab.critical_speed(BOGIE, gradient=KEYS, **GRID)
    s = railstab.sensitivity(BOGIE, keys=KEYS, **GRID)
    assert r.gradient == s.gradient  # the same computation, bit for bit
    # The search is the sensitivity command's: to 1e-6 m/s.
    assert r.speed_tolerance_requested_m_per_s == 1e-6
    assert r.critical_speed_m_per_s == pytest.approx(s.critical_speed_m_per_s, abs=0)


def test_gradient_against_central_differences():
    # h = 1e-3 relative (~ cbrt(eps) scaled up: the critical speed is found to
    # 1e-6 m/s, so a smaller h would difference the bisection's tolerance).
    # Central difference error O(h^2) plus 2e-6 m/s / (2 h p): measured
    # agreement ~1e-5 relative; asserted to 1e-3.
    key = KEYS[0]
    base = railstab.critical_speed(BOGIE, gradient=[key], **GRID)
    p = railstab.load_scene(BOGIE).parameters[key]
    h = 1e-3 * p
    up = railstab.critical_speed(BOGIE, set={key: p + h}, gradient=[key], **GRID)
    down = railstab.critical_speed(BOGIE, set={key: p - h}, gradient=[key], **GRID)
    fd = (up.critical_speed_m_per_s - down.critical_speed_m_per_s) / (2 * h)
    assert base.gradient[key] == pytest.approx(fd, rel=1e-3)


def test_gradient_key_that_is_no_parameter():
    with pytest.raises(railstab.InputError, match="gradient key no.such: no such parameter of textbook_bogie"):
        railstab.critical_speed(BOGIE, gradient=["no.such"], **GRID)
