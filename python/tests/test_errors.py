"""Hostile input: every error is a Python exception with the command line's
message (file, key, what was expected); none crashes the interpreter."""
import pathlib

import pytest

import railstab
from conftest import case

WHEELSET = case("textbook_wheelset.toml")


def cli_error(cli, *args):
    run = cli(*args, check=False)
    assert run.returncode != 0
    return run.error


def test_missing_file(cli, tmp_path):
    missing = str(tmp_path / "missing.toml")
    with pytest.raises(railstab.InputError) as e:
        railstab.critical_speed(missing)
    assert missing in str(e.value)
    assert isinstance(e.value, ValueError) and isinstance(e.value, railstab.Error)


def test_scene_value_out_of_range_as_the_cli_says(cli):
    with pytest.raises(railstab.InputError) as e:
        railstab.equilibrium(WHEELSET, set={"bodies.wheelset1.mass_kg": -3})
    assert str(e.value) == cli_error(cli, "equilibrium", WHEELSET, "--set", "bodies.wheelset1.mass_kg=-3")
    assert "mass_kg" in str(e.value) and "expected" in str(e.value)


def test_unknown_set_key_as_the_cli_says(cli):
    with pytest.raises(railstab.InputError) as e:
        railstab.eigen(WHEELSET, set={"bodies.nobody.mass_kg": 1.0})
    assert str(e.value) == cli_error(cli, "eigen", WHEELSET, "--set", "bodies.nobody.mass_kg=1.0")


def test_broken_scene_file_as_the_cli_says(cli, tmp_path):
    text = pathlib.Path(WHEELSET).read_text().replace("\nmass_kg =", "\nmass_kilograms =", 1)
    broken = tmp_path / "broken.toml"
    broken.write_text(text)
    with pytest.raises(railstab.InputError) as e:
        railstab.load_scene(str(broken))
    assert str(e.value) == cli_error(cli, "equilibrium", str(broken))
    garbage = tmp_path / "garbage.toml"
    garbage.write_bytes(b"\x00\xff[[[ not toml")
    with pytest.raises(railstab.InputError) as e:
        railstab.critical_speed(str(garbage))
    assert str(e.value) == cli_error(cli, "critical-speed", str(garbage), "--no-plots")
    with pytest.raises(railstab.InputError):
        railstab.critical_speed(str(tmp_path))  # a folder


@pytest.mark.parametrize("call, words", [
    (lambda: railstab.critical_speed(WHEELSET, hunting_band=-1), "hunting_band: expected a finite number in (0, 1000] Hz, got -1"),
    (lambda: railstab.critical_speed(WHEELSET, step=1e-12), "step: expected a finite number in [0.01, 300] m/s"),
    (lambda: railstab.critical_speed(WHEELSET, to=1e12), "to: expected a finite number"),
    (lambda: railstab.critical_speed(WHEELSET, from_=float("nan")), "from_: expected a finite number"),
    (lambda: railstab.critical_speed(WHEELSET, from_=50, to=40), "from_ 50 m/s must be below to 40 m/s"),
    (lambda: railstab.critical_speed(WHEELSET, from_=1, to=300, step=0.01), "would have 29901 points; at most 10000"),
    (lambda: railstab.critical_speed(WHEELSET, solver="magic"), "solver: eigen-solver 'magic': expected one of"),
    (lambda: railstab.eigen(WHEELSET, speed=1e6), "speed: expected a finite number"),
    (lambda: railstab.equilibrium(WHEELSET, arc_length=float("inf")), "arc_length: expected a finite number"),
    (lambda: railstab.simulate(WHEELSET, t_end=1e20), "t_end: expected a finite number"),
    (lambda: railstab.simulate(WHEELSET, rtol=float("nan")), "rtol: expected a finite number"),
    (lambda: railstab.simulate(WHEELSET, integrator="euler"), "integrator:"),
    (lambda: railstab.simulate(WHEELSET, offset={"wheelset1.w_m": 1}), "offset:"),
    (lambda: railstab.verify(WHEELSET, amplitude=0), "amplitude: expected a finite number"),
    (lambda: railstab.verify(WHEELSET, periods=3, settle_periods=5), "settle_periods 5 must be below periods 3"),
    (lambda: railstab.equilibrium(WHEELSET, set={"bodies.wheelset1.mass_kg": "heavy"}), "set:"),
    (lambda: railstab.equilibrium(WHEELSET, set={"bodies.wheelset1.mass_kg": float("nan")}), "set:"),
    (lambda: railstab.equilibrium(WHEELSET, set=["x"]), "set: expected a dict"),
    (lambda: railstab.equilibrium(42), "scene: expected a scene file path"),
    (lambda: railstab.study(WHEELSET, {"bodies.wheelset1.mass_kg": (1, 2)}), "vary: bodies.wheelset1.mass_kg: expected (from, to, step)"),
    (lambda: railstab.study(WHEELSET, {"bodies.wheelset1.mass_kg": (2, 1, 1)}), "vary:"),
    (lambda: railstab.study(WHEELSET, {"bodies.wheelset1.mass_kg": (1000, 2000, 500)}, jobs=0), "jobs: expected a whole number"),
    (lambda: railstab.contact_geometry(WHEELSET), "expected exactly one contact with geometry"),
    (lambda: railstab.bifurcation(WHEELSET, hopf_branch=False), "hopf_branch=False leaves no branch"),
    (lambda: railstab.bifurcation(WHEELSET, cycle_direction="sideways"), "cycle_direction: expected 'down' or 'up'"),
])
def test_arguments_out_of_range(call, words):
    with pytest.raises(railstab.InputError) as e:
        call()
    assert words in str(e.value)


def test_an_analysis_that_fails_is_an_error_not_a_crash(cli):
    # No critical speed in the range: nothing to differentiate.
    with pytest.raises(railstab.Error) as e:
        railstab.sensitivity(WHEELSET, from_=1, to=2, step=0.5)
    assert "there is no stability boundary to differentiate" in str(e.value)
    assert str(e.value) == cli_error(cli, "sensitivity", WHEELSET, "--from", "1", "--to", "2",
                                     "--step", "0.5", "--no-plots").replace("--from/--to", "from_/to")


def test_progress_callback_errors_reach_the_caller():
    def broken(line):
        raise KeyError("from the callback")
    with pytest.raises(KeyError, match="from the callback"):
        railstab.critical_speed(WHEELSET, from_=20, to=40, step=10, progress=broken)
    with pytest.raises(TypeError, match="progress: expected a callable"):
        railstab.critical_speed(WHEELSET, progress=3)


def test_model_warnings_as_the_cli_prints_them(cli):
    key = "bodies.bogie1.mass_kg"
    with pytest.warns(railstab.ModelWarning) as caught:
        r = railstab.equilibrium(case("textbook_bogie.toml"), set={key: 100})
    run = cli("equilibrium", case("textbook_bogie.toml"), "--set", f"{key}=100")
    printed = [line[len("warning: "):] for line in run.stderr.splitlines()
               if line.startswith("warning: ")]
    assert r.model_warnings == printed == [str(w.message) for w in caught]
    assert "mass_kg = 100 is outside" in r.model_warnings[0]


def test_hostile_scene_names_stay_in_the_private_folder(tmp_path, monkeypatch):
    # The report is written into a temporary folder under the file-name rules
    # (io/file_names.hpp): a scene called "../evil" or holding quotes and a
    # comma writes nothing beside it, and the JSON keeps the name.
    monkeypatch.setenv("TMPDIR", str(tmp_path / "tmp"))
    (tmp_path / "tmp").mkdir()
    text = pathlib.Path(WHEELSET).read_text()
    for name in ("../evil", 'a "quoted", name', "/tmp/../../evil"):
        escaped = name.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")
        scene = tmp_path / "scene.toml"
        scene.write_text(text.replace('name = "textbook_wheelset"', f'name = "{escaped}"', 1))
        r = railstab.equilibrium(str(scene))
        assert r.scene == name
        assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml", "tmp"]
        assert list((tmp_path / "tmp").iterdir()) == []  # the private folder is removed


def test_a_named_pipe_is_refused_not_waited_on(tmp_path):
    import os
    fifo = tmp_path / "scene.toml"
    os.mkfifo(fifo)
    with pytest.raises(railstab.InputError, match="scene file"):
        railstab.load_scene(str(fifo))
