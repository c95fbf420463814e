"""Shared helpers of the Python module's tests (run by CTest: python/CMakeLists.txt
sets RAILSTAB_EXE, RAILSTAB_CASES_DIR and PYTHONPATH).

The reference for every function is the command line: the same analysis is
run with `railstab <command> ... --no-plots --out DIR` and its files are
compared with what the function returns.
"""
import csv
import json
import os
import pathlib
import subprocess

import pytest

CASES = pathlib.Path(os.environ.get("RAILSTAB_CASES_DIR",
                                    pathlib.Path(__file__).resolve().parents[2] / "cases"))
EXE = os.environ.get("RAILSTAB_EXE", str(pathlib.Path(__file__).resolve().parents[2] / "build" / "railstab"))

# Keys whose values are measured times, which differ between any two runs.
TIMING_KEYS = {"wall_s", "cpu_s", "integration_cpu_s", "integration_wall_s", "reference_cpu_s",
               "reference_integration_cpu_s", "reference_integration_wall_s", "reference_wall_s",
               "real_time_factor"}


def case(name):
    return str(CASES / name)


class CliRun:
    def __init__(self, out_dir, completed):
        self.out_dir = pathlib.Path(out_dir)
        self.returncode = completed.returncode
        self.stdout = completed.stdout
        self.stderr = completed.stderr

    def file(self, suffix):
        found = [p for p in self.out_dir.iterdir() if p.name.endswith(suffix)]
        assert len(found) == 1, (suffix, [p.name for p in self.out_dir.iterdir()])
        return found[0]

    def json(self, suffix=".json"):
        return json.loads(self.file(suffix).read_text())

    def csv_rows(self, suffix):
        with open(self.file(suffix), newline="") as f:
            return list(csv.reader(f))

    @property
    def error(self):
        """The message after "railstab: error: " (the first line of it)."""
        marker = "railstab: error: "
        assert marker in self.stderr, self.stderr
        return self.stderr.split(marker, 1)[1].split("\n(the options", 1)[0].rstrip("\n")


@pytest.fixture
def cli(tmp_path):
    """cli("critical-speed", scene, "--from", "40", ...): the command run into a fresh --out."""
    counter = [0]

    def run(*args, check=True):
        counter[0] += 1
        out = tmp_path / f"cli{counter[0]}"
        completed = subprocess.run([EXE, *[str(a) for a in args], "--out", str(out)],
                                   capture_output=True, text=True, cwd=tmp_path)
        if check:
            assert completed.returncode == 0, completed.stderr
        return CliRun(out, completed)

    return run


def assert_same_report(python, cli, path="$"):
    """The Python result's JSON fields equal the command's file, every key
    and value (both are the same writer's text, parsed: equal to the last
    printed digit), measured times excepted."""
    if isinstance(cli, dict):
        assert isinstance(python, dict), path
        assert set(python.keys()) == set(cli.keys()), (path, set(python) ^ set(cli))
        for k in cli:
            if k not in TIMING_KEYS:
                assert_same_report(python[k], cli[k], f"{path}.{k}")
    elif isinstance(cli, list):
        assert isinstance(python, list) and len(python) == len(cli), path
        for i, (p, c) in enumerate(zip(python, cli)):
            assert_same_report(p, c, f"{path}[{i}]")
    else:
        assert python == cli, (path, python, cli)


def printed(value, digits):
    """A number as a railstab CSV prints it (ostream at `digits` significant digits)."""
    return f"{value:.{digits}g}"
