"""The Python module's cost against the command line (issue 26's targets):

1. one call: railstab.critical_speed on the thesis vehicle against
   `railstab critical-speed --no-plots` (the same analysis in C++: scene
   set-up, search, Hopf assessment, JSON and CSV written); CPU time, median
   of ROUNDS. The command's time includes its process start (~10 ms of
   loading), the Python call's the temporary folder it writes the report
   into; both include everything else alike.
2. a 100-point study: 100 critical_speed calls from two Python threads
   against `railstab study --jobs 2` over the same 100 values; wall and CPU
   time.

Run after building (not a test: timings, nothing asserted):
  PYTHONPATH=build/python /usr/bin/python3 analysis/python_overhead.py [ROUNDS]
Results: docs/python.md, "Cost".
"""
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

import railstab

ROOT = pathlib.Path(__file__).resolve().parents[1]
EXE = os.environ.get("RAILSTAB_EXE", str(ROOT / "build" / "railstab"))
VEHICLE = str(ROOT / "cases" / "thesis_vehicle_tangent.toml")
BOGIE = str(ROOT / "cases" / "textbook_bogie.toml")
ROUNDS = int(sys.argv[1]) if len(sys.argv) > 1 else 10


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def python_call_cpu():
    start = time.process_time()
    railstab.critical_speed(VEHICLE)
    return time.process_time() - start


def command_cpu(out):
    start = children_cpu()
    subprocess.run([EXE, "critical-speed", VEHICLE, "--no-plots", "--out", out], check=True,
                   capture_output=True)
    return children_cpu() - start


with tempfile.TemporaryDirectory() as tmp:
    python_call_cpu()  # first call: pages the module in
    py = statistics.median(python_call_cpu() for _ in range(ROUNDS))
    cli = statistics.median(command_cpu(tmp) for _ in range(ROUNDS))
    print(f"thesis vehicle critical speed, CPU median of {ROUNDS}: Python call {py * 1e3:.1f} ms, "
          f"command {cli * 1e3:.1f} ms: Python / command = {py / cli:.3f}")

    key = "elements.primary_ws1.stiffness_N_per_m[0]"
    values = [5e6 + i * 0.1e6 for i in range(100)]
    start, start_cpu = time.perf_counter(), time.process_time()
    with ThreadPoolExecutor(max_workers=2) as pool:
        speeds = list(pool.map(lambda v: railstab.critical_speed(
            BOGIE, set={key: v}, from_=20, to=200, step=5).critical_speed_m_per_s, values))
    threads, threads_cpu = time.perf_counter() - start, time.process_time() - start_cpu
    start, start_cpu = time.perf_counter(), children_cpu()
    subprocess.run([EXE, "study", BOGIE, "--vary", f"{key}=5e6:14.9e6:0.1e6", "--from", "20",
                    "--to", "200", "--step", "5", "--jobs", "2", "--no-plots", "--out", tmp],
                   check=True, capture_output=True)
    study, study_cpu = time.perf_counter() - start, children_cpu() - start_cpu
    print(f"100-point study of the textbook bogie: two Python threads {threads:.2f} s wall, "
          f"{threads_cpu:.2f} s CPU; railstab study --jobs 2 {study:.2f} s wall, {study_cpu:.2f} s "
          f"CPU: threads / study = {threads / study:.3f} wall, {threads_cpu / study_cpu:.3f} CPU")
