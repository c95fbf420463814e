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


@pytest.mark.parametrize("key", KEYS)
def test_gradient_against_central_differences(key):
    # Central differences of the critical speed with h = 1e-3 relative: the
    # truncation error is O(h^2) and the bisection's 1e-6 m/s tolerance adds
    # ~1e-6 / (2 h p dVc/dp). Measured: 1.8e-7 (stiffness) and 4.0e-8 (mass)
    # relative (h = 1e-2: 2.9e-5 and 6.0e-6, the O(h^2) term); asserted to 1e-5.
    base = railstab.critical_speed(BOGIE, gradient=[key], **GRID)
    p = railstab.load_scene(BOGIE).parameters[key]
    h = 1e-3 * p
    up = railstab.critical_speed(BOGIE, set={key: p + h}, gradient=[key], **GRID)
    down = railstab.critical_speed(BOGIE, set={key: p - h}, gradient=[key], **GRID)
    fd = (up.critical_speed_m_per_s - down.critical_speed_m_per_s) / (2 * h)
    assert base.gradient[key] == pytest.approx(fd, rel=1e-5)


def test_gradient_key_that_is_no_parameter():
    with pytest.raises(railstab.InputError, match="gradient key no.such: no such parameter of textbook_bogie"):
        railstab.critical_speed(BOGIE, gradient=["no.such"], **GRID)
