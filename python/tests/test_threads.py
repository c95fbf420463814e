"""The analyses release the GIL: Python threads run them side by side with
the same results as serial calls."""
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import railstab
from conftest import case

BOGIE = case("textbook_bogie.toml")
KEY = "elements.primary_ws1.stiffness_N_per_m[0]"
VALUES = [5e6, 1e7, 1.5e7, 2e7]


def speed(value):
    return railstab.critical_speed(BOGIE, set={KEY: value}, from_=80, to=120, step=5).critical_speed_m_per_s


def test_threads_give_the_serial_results():
    serial = [speed(v) for v in VALUES]
    with ThreadPoolExecutor(max_workers=2) as pool:
        parallel = list(pool.map(speed, VALUES))
    assert parallel == serial


def test_python_runs_while_an_analysis_runs():
    # While a thread is inside the analysis, this thread keeps running Python
    # code: it could not if the call held the GIL (it would get at most one
    # switch interval, 5 ms, before the call starts). Counted against this
    # thread's own rate alone, over the call's duration.
    def count_for(seconds):
        n, end = 0, time.perf_counter() + seconds
        while time.perf_counter() < end:
            n += 1
        return n
    rate = count_for(0.05) / 0.05
    state = {"inside": False, "done": False}

    def work():
        state["start"] = time.perf_counter()
        state["inside"] = True
        railstab.critical_speed(case("thesis_vehicle_tangent.toml"))
        state["done"] = True
        state["end"] = time.perf_counter()

    t = threading.Thread(target=work)
    ticks = 0
    t.start()
    while not state["done"]:
        if state["inside"]:
            ticks += 1
    t.join()
    duration = state["end"] - state["start"]
    assert duration > 0.05
    # Released: ~ rate x duration (less on a busy machine); held: < rate x 0.005.
    assert ticks > 0.1 * rate * duration, (ticks, rate, duration)
