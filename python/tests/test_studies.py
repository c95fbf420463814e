"""load_scene, contact_geometry, track, study and bifurcation against the command line."""
import numpy as np
import pytest

import railstab
from conftest import assert_same_report, case, printed

BOGIE = case("textbook_bogie.toml")
S1002 = case("s1002_uic60_contact.toml")


def test_load_scene():
    s = railstab.load_scene(BOGIE)
    assert s.name == "textbook_bogie"
    assert s.bodies == ["wheelset1", "wheelset2", "bogie1"]
    assert s.parameters["bodies.bogie1.mass_kg"] > 0
    assert repr(s) == f"railstab.Scene({BOGIE!r})"
    # A Scene read from a Scene keeps the first one's overrides under the new ones.
    key = "bodies.bogie1.mass_kg"
    s1 = railstab.load_scene(BOGIE, set={key: 2000.0})
    s2 = railstab.load_scene(s1, set={"bodies.wheelset1.mass_kg": 1400.0})
    assert s2.set == {key: 2000.0, "bodies.wheelset1.mass_kg": 1400.0}
    assert s2.parameters[key] == 2000.0 and s2.parameters["bodies.wheelset1.mass_kg"] == 1400.0


def test_contact_geometry_equals_the_command(cli):
    r = railstab.contact_geometry(S1002)
    run = cli("contact-geometry", S1002, "--no-plots")
    assert_same_report(r, run.json(".json"))
    for suffix, table in (("_characteristic.csv", r.characteristic), ("_conicity.csv", r.conicity)):
        rows = run.csv_rows(suffix)
        assert list(table) == rows[0]
        for j, name in enumerate(rows[0]):
            assert [printed(v, 10) if not np.isnan(v) else "" for v in table[name]] == \
                [row[j] for row in rows[1:]], name


def test_track_equals_the_command(cli, tmp_path):
    # 600 m of ERRI B176 low irregularities under the thesis vehicle.
    scene = tmp_path / "irregular.toml"
    scene.write_text(open(case("thesis_vehicle_tangent.toml")).read() +
                     '\n[track.irregularities]\npsd = "erri_b176_low"\nseed = 5\nlength_m = 600.0\n')
    r = railstab.track(str(scene))
    run = cli("track", scene, "--no-plots")
    assert_same_report(r, run.json("_irregularities.json"))
    for suffix, table in (("_irregularities.csv", r.samples), ("_irregularity_psd.csv", r.spectra)):
        rows = run.csv_rows(suffix)
        assert list(table) == rows[0]
        assert len(table[rows[0][0]]) == len(rows) - 1
    # The same irregularities set from Python, as --set does.
    table = '{psd = "erri_b176_low", seed = 5, length_m = 600.0}'
    r2 = railstab.track(case("thesis_vehicle_tangent.toml"), set={"track.irregularities": table})
    np.testing.assert_array_equal(r2.samples["alignment_m"], r.samples["alignment_m"])
    # A perfect track has nothing to show: said, naming the key.
    with pytest.raises(railstab.InputError, match="track.irregularities"):
        railstab.track(case("thesis_vehicle_tangent.toml"))


def test_study_equals_the_command(cli):
    key = "elements.primary_ws1.stiffness_N_per_m[0]"
    lines = []  # called from the study's two worker threads, one at a time
    r = railstab.study(BOGIE, {key: (5e6, 1.5e7, 5e6)}, from_=20, to=200, step=5, jobs=2,
                       progress=lines.append, dataframe=False)
    assert len(lines) == 3, lines
    run = cli("study", BOGIE, "--vary", f"{key}=5e6:1.5e7:5e6", "--from", "20", "--to", "200",
              "--step", "5", "--jobs", "2", "--no-plots")
    assert_same_report(r, run.json("_study.json"))
    rows = run.csv_rows("_study.csv")
    assert list(r.table) == rows[0]
    assert len(r.table["index"]) == 3
    for j, name in enumerate(rows[0]):
        column = r.table[name]
        text = [printed(v, 12) if column.dtype.kind == "f" else str(v) for v in column]
        assert len(text) == len(rows) - 1


def test_study_as_a_dataframe():
    pandas = pytest.importorskip("pandas")
    key = "elements.primary_ws1.stiffness_N_per_m[0]"
    r = railstab.study(BOGIE, {key: (5e6, 1e7, 5e6)}, from_=20, to=200, step=5, jobs=1,
                       dataframe=True)
    assert isinstance(r.table, pandas.DataFrame)
    assert list(r.table[key]) == [5e6, 1e7]


def test_bifurcation_equals_the_command(cli):
    # The textbook wheelset's Hopf branch to 3 mm (0.1-0.3 s CPU: as the
    # CLI's own bifurcation test).
    wheelset = case("textbook_wheelset.toml")
    lines = []
    r = railstab.bifurcation(wheelset, from_=50, to=100, max_amplitude=0.003, progress=lines.append)
    run = cli("bifurcation", wheelset, "--from", "50", "--to", "100", "--max-amplitude", "0.003",
              "--no-plots")
    assert_same_report(r, run.json("_bifurcation.json"))
    rows = run.csv_rows("_bifurcation_branches.csv")
    assert list(r.orbits) == rows[0]
    assert len(r.orbits[rows[0][0]]) == len(rows) - 1
    assert lines


def test_check_equals_the_command(cli):
    r = railstab.check(BOGIE, speed=30.0)
    run = cli("check", BOGIE, "--speed", "30")
    assert_same_report(r, run.json("_check_30mps.json"))


def test_study_table_is_a_dataframe_where_pandas_is_installed():
    key = "elements.primary_ws1.stiffness_N_per_m[0]"
    r = railstab.study(BOGIE, {key: (5e6, 1e7, 5e6)}, from_=20, to=200, step=5, jobs=1)
    try:
        import pandas
    except ImportError:
        assert isinstance(r.table, dict)
    else:
        assert isinstance(r.table, pandas.DataFrame)
    assert list(r.table[key]) == [5e6, 1e7]
