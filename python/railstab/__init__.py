"""railstab: lateral stability of railway vehicles, from Python.

The analyses of the ``railstab`` command line, in-process: each function takes
a scene (a file path or a :class:`Scene` from :func:`load_scene`) and ``set``,
the command line's ``--set`` overrides as a dict::

    import railstab
    r = railstab.critical_speed("cases/thesis_vehicle_tangent.toml",
                                set={"elements.yaw_damper.damping_N_s_per_m[0]": 2.5e5})
    r.critical_speed_m_per_s      # a field of the critical-speed JSON
    r.speeds, r.eigenvalues       # numpy: the eigenvalues over speed

Every function returns a :class:`Result`: the command's JSON report as a dict
(the same keys and numbers: the command's own writer renders it, see
docs/outputs.md), with its keys also readable as attributes, plus numpy arrays
of the numbers behind it at full precision (listed in each function's doc).
The keyword arguments are the command's flags (``--hunting-band`` is
``hunting_band``; ``--from`` is ``from_``, ``from`` being a Python keyword),
checked against the same ranges.

Errors raise :class:`InputError` (also a ValueError: a scene file's key, an
argument out of range; the message is the command line's) or :class:`Error`
(also a RuntimeError: the analysis failed). The model check's warnings,
which the command prints before an analysis, are issued as
:class:`ModelWarning` and kept in ``result.model_warnings``. The analyses run without the GIL:
Python threads run them side by side. ``progress`` takes a callable that gets
the command's progress lines (simulate: the simulated time in s); an exception
it raises stops its calls and is raised when the analysis returns.

docs/python.md has the whole interface.
"""
import csv
import io
import json
import math
import numbers
import os
import warnings

import numpy as np

from railstab import _railstab
from railstab._railstab import Error, InputError

__all__ = ["Error", "InputError", "ModelWarning", "Result", "Scene", "load_scene", "check",
           "critical_speed", "eigen", "equilibrium", "curving", "simulate", "speed_ramp", "verify",
           "assess",
           "sensitivity",
           "contact_geometry", "track", "study", "bifurcation"]
__version__ = _railstab.__version__


class Result(dict):
    """An analysis's JSON report as a dict; keys readable as attributes too.

    The numpy arrays a function adds are plain attributes (documented per
    function); they are not keys, so ``dict(result)`` is the JSON report.
    """

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(
                f"{type(self).__name__} has no field or array '{name}' "
                f"(fields: {', '.join(self.keys())})") from None

    def __dir__(self):
        return list(super().__dir__()) + list(self.keys())

    def __setattr__(self, name, value):
        # An array named like a report field would hide the field from
        # attribute access: refused, so the two never disagree silently.
        if name in self:
            raise AttributeError(f"'{name}' is a field of the report; name the attribute otherwise")
        super().__setattr__(name, value)


class Scene:
    """A scene file read and checked with its overrides (see load_scene).

    Attributes: path, set (the overrides, a dict), name, speed_m_per_s,
    bodies (names), parameters (every parameter key with its value: the keys
    ``set``, ``sensitivity`` and ``critical_speed(gradient=...)`` take).
    Passing a Scene to an analysis reads the file again with these overrides
    (and the call's own ``set`` after them).
    """

    def __init__(self, path, settings, info):
        self.path = path
        self.set = dict(settings)
        self.name = info["name"]
        self.speed_m_per_s = info["speed_m_per_s"]
        self.bodies = list(info["bodies"])
        self.parameters = dict(info["parameters"])

    def __repr__(self):
        extra = f", set={self.set!r}" if self.set else ""
        return f"railstab.Scene({self.path!r}{extra})"


def _number_text(value):
    """A --set value: a real number in its shortest exact form (repr reads
    back as the same double); anything else as text, for the C++ parser to
    refuse with its message."""
    if isinstance(value, bool):
        return str(value)  # refused: True is no number
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    return str(value)


def _settings_dict(settings):
    if settings is None:
        return {}
    if not hasattr(settings, "items"):
        raise InputError("set: expected a dict of scene keys and numbers, e.g. "
                         "{'bodies.carbody.mass_kg': 32000}, got " + type(settings).__name__)
    return dict(settings)


def _scene_and_overrides(scene, settings):
    """(path, {key: value}): the scene's own overrides, then the call's (a
    later setting of a key wins, as a repeated --set)."""
    if isinstance(scene, Scene):
        merged = dict(scene.set)
        path = scene.path
    elif isinstance(scene, (str, os.PathLike)):
        merged = {}
        path = os.fspath(scene)
    else:
        raise InputError("scene: expected a scene file path or a railstab.Scene, got "
                         + type(scene).__name__)
    merged.update(_settings_dict(settings))
    return path, merged


def _scene_and_settings(scene, settings):
    """(path, ["KEY=VALUE", ...]): the overrides in --set's form."""
    path, merged = _scene_and_overrides(scene, settings)
    return path, [f"{k}={_number_text(v)}" for k, v in merged.items()]


def _pairs(name, values):
    """{"wheelset1.y_m": 0.005} as ["wheelset1.y_m=0.005"] (--offset's form)."""
    if values is None:
        return []
    if not hasattr(values, "items"):
        raise InputError(f"{name}: expected a dict, e.g. {{'wheelset1.y_m': 0.005}}, got "
                         + type(values).__name__)
    return [f"{k}={_number_text(v)}" for k, v in values.items()]


def _column(values):
    """A CSV column as a numpy array: floats (empty cells NaN) when every cell
    is a number or empty, else strings."""
    try:
        return np.array([float(v) if v != "" else math.nan for v in values], dtype=float)
    except ValueError:
        return np.array(values, dtype=str)


def _table(csv_text):
    """A CSV file's columns (RFC 4180, as railstab writes them) as a dict of
    numpy arrays, in the file's column order."""
    rows = list(csv.reader(io.StringIO(csv_text)))
    header, body = rows[0], rows[1:]
    return {name: _column([row[i] for row in body]) for i, name in enumerate(header)}


class ModelWarning(UserWarning):
    """The model check's warning about a scene (a wheelset placed off its
    rails, a spring far from its length, an unusual mass...), as the command
    line prints it before an analysis; also in the result's model_warnings."""


def _result(out):
    r = Result(json.loads(out["json"]))
    r.model_warnings = list(out.get("model_warnings", []))
    for message in r.model_warnings:
        warnings.warn(message, ModelWarning, stacklevel=3)
    return r


def load_scene(path, set=None):
    """Read and check a scene file with ``set`` overrides; returns a Scene.

    Raises InputError naming the file, the key and what was expected, as the
    command line does.
    """
    path, merged = _scene_and_overrides(path, set)
    _, settings = _scene_and_settings(path, merged)
    return Scene(path, merged, _railstab.load_scene(path, settings))


def check(scene, set=None, *, speed=None, arc_length=None, natural_frequencies=True):
    """The model checks before a run: ``railstab check``.

    Returns the check JSON as a Result (masses, axle loads, static
    deflections, natural frequencies at rest, warnings, errors). The command
    fails when ``errors`` is not empty; this returns the report all the same.
    """
    path, settings = _scene_and_settings(scene, set)
    return _result(_railstab.check(path, settings, speed, arc_length, bool(natural_frequencies)))


def critical_speed(scene, set=None, *, from_=5.0, to=150.0, step=2.5, solver="auto",
                   hunting_band=20.0, min_damping_ratio=None, arc_length=None, gradient=None,
                   amplitude=None, progress=None):
    """The critical (hunting) speed: ``railstab critical-speed``.

    Returns the critical-speed JSON as a Result, plus
      speeds        the grid speeds (m/s), shape (n,)
      eigenvalues   the eigenvalues (1/s, complex) over speed, shape (n, tracks):
                    column j is mode track j (the same mode followed over the
                    grid), NaN where the track has no mode at that speed
      track_names   each track's mode name at its first speed
      eigenvalue_table  the eigenvalue CSV's columns as arrays (one row per
                    speed and mode: speed_m_per_s, mode_track,
                    eigenvalue_per_s, frequency_Hz, damping_ratio, neutral,
                    residual, name)
    With ``gradient=[keys]`` (keys of Scene.parameters) also
      gradient      {key: dVc/dp}, the exact derivative ``railstab
                    sensitivity`` computes; the search is then that command's
                    (bisection to 1e-6 m/s instead of 0.01), so the value and
                    its gradient belong together (for scipy.optimize).
    ``amplitude`` (m): the quasi-linear critical speed, the profile contacts
    replaced by their harmonic linearisation at that wheelset amplitude
    (``--amplitude``; the JSON's ``quasi_linear`` object).
    """
    path, settings = _scene_and_settings(scene, set)
    keys = None if gradient is None else [str(k) for k in gradient]
    out = _railstab.critical_speed(path, settings, arc_length, from_, to, step, solver,
                                   hunting_band, min_damping_ratio, keys, amplitude, progress)
    r = _result(out)
    table = out["eigenvalues"]
    r.eigenvalue_table = table
    speeds = np.unique(table["speed_m_per_s"])
    tracks = int(table["mode_track"].max()) + 1 if len(table["mode_track"]) else 0
    eigenvalues = np.full((len(speeds), tracks), complex(math.nan, math.nan))
    names = [""] * tracks
    rows = np.searchsorted(speeds, table["speed_m_per_s"])
    for i, j, lam, name in zip(rows, table["mode_track"], table["eigenvalue_per_s"],
                               table["name"]):
        eigenvalues[i, j] = lam
        if not names[j]:
            names[j] = name
    r.speeds, r.eigenvalues, r.track_names = speeds, eigenvalues, names
    if keys is not None:
        r.gradient = dict(out["gradient"])
    return r


def eigen(scene, set=None, *, speed=None, arc_length=None, solver="auto", hunting_band=20.0):
    """Eigenvalues and modes at one speed: ``railstab eigen``.

    Returns the eigen JSON as a Result (its ``modes`` with names and shapes),
    plus
      eigenvalues    complex (1/s), shape (modes,), in the JSON's order
      frequency_Hz, damping_ratio   shape (modes,)
      mode_names     list of names
      eigenvectors   complex, shape (states, modes): column k is mode k's
                     vector on the linear model's states
      state_names    the linear model's states (cyclic ones removed)
      state_matrix   A, shape (states, states) (dense solver only)
    """
    path, settings = _scene_and_settings(scene, set)
    out = _railstab.eigen(path, settings, speed, arc_length, solver, hunting_band)
    r = _result(out)
    for name in ("eigenvalues", "frequency_Hz", "damping_ratio", "eigenvectors"):
        setattr(r, name, out[name])
    r.mode_names = list(out["mode_names"])
    r.state_names = list(out["state_names"])
    r.state_matrix = out.get("state_matrix")
    return r


def equilibrium(scene, set=None, *, speed=None, arc_length=None):
    """The steady rolling / curving state: ``railstab equilibrium``.

    Returns the equilibrium JSON as a Result (every body's offsets, every
    wheel's load, creepages and forces), plus
      state   the equilibrium state vector (numpy)
    """
    path, settings = _scene_and_settings(scene, set)
    out = _railstab.equilibrium(path, settings, speed, arc_length)
    r = _result(out)
    r.state = out["state"]
    return r


def _value_or_range(name, value):
    """A number or (from, to, step) as the list of fields curving takes ([]: not given)."""
    if value is None:
        return []
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        return [float(value)]
    if isinstance(value, (tuple, list)) and len(value) == 3 and all(
            isinstance(v, numbers.Real) and not isinstance(v, bool) for v in value):
        return [float(v) for v in value]
    raise InputError(f"{name}: expected a number or (from, to, step) in metres, got {value!r}")


def curving(scene, set=None, *, cant_deficiency=None, radius=None, arc_length=None):
    """Steady curving over cant deficiency or radius: ``railstab curving``.

    ``cant_deficiency`` and ``radius`` (m) are each a number or a range
    ``(from, to, step)``, a range in one of them at most; the one not given
    is the scene's at its reference point. Returns the curving JSON as a
    Result (every condition's wheel forces Y, Q, Y/Q, Sum Y, angles of
    attack, flange contact, and where the sweep stopped at a physical
    limit, the statement), plus
      table    the curving CSV's columns (one row per condition)
    """
    path, settings = _scene_and_settings(scene, set)
    out = _railstab.curving(path, settings, arc_length,
                            _value_or_range("cant_deficiency", cant_deficiency),
                            _value_or_range("radius", radius))
    r = _result(out)
    r.table = _table(out["csv"])
    return r


def simulate(scene, set=None, *, speed=None, t_end=None, arc_length=None, offset=None, mode=None,
             mode_amplitude=None, integrator=None, rtol=None, atol=None, estimate_error=True,
             stop_on_lift_off=False, progress=None):
    """The nonlinear model in time: ``railstab simulate``.

    Returns the run summary JSON (``<stem>_run.json``: integrator, steps,
    contact events, ride extremes and ``error_estimate``, the same run at 100x
    tighter tolerances) as a Result, plus
      time       output times (s), shape (n,)
      channels   {column: array (n,)}: every column of the command's CSVs
                 (trajectory <body>.<coordinate>, <body>.absolute_roll_rad,
                 wheel forces, accelerations; docs/outputs.md), at full
                 precision; a lifted wheel's Y/Q is NaN
      warnings   the run check's warnings (the command prints them)
    ``offset``: {"wheelset1.y_m": 0.005} (--offset); ``mode="hunting"`` with
    ``mode_amplitude`` (m) starts on a mode (--mode, --mode-amplitude).
    ``progress`` gets the simulated time (s).
    """
    path, settings = _scene_and_settings(scene, set)
    out = _railstab.simulate(path, settings, speed, arc_length, t_end, _pairs("offset", offset),
                             mode, mode_amplitude, integrator or "", rtol, atol,
                             bool(estimate_error), bool(stop_on_lift_off), progress)
    r = _result(out)
    channels = {}
    for name in ("trajectory_csv", "absolute_roll_csv", "wheel_forces_csv", "accelerations_csv"):
        table = _table(out[name])
        time = table.pop("time_s")
        channels.update(table)
    r.time = time
    r.channels = channels
    r.warnings = list(out["warnings"])
    return r


def speed_ramp(scene, rates, set=None, *, speed=None, ramp_to=None, hunting_threshold=None,
               arc_length=None, offset=None, mode=None, mode_amplitude=None, integrator=None,
               rtol=None, atol=None, progress=None):
    """Hunting on a falling speed: ``railstab simulate --ramp-rate``.

    From ``speed`` (the scene's by default) the vehicle decelerates at each of
    ``rates`` (m/s^2; one number or several) down to ``ramp_to`` (default
    half the start speed); each ramp reports the speed where the hunting dies
    away (the leading wheelset's peak-to-peak lateral motion over a period
    below ``hunting_threshold``, m). Returns the ramp JSON as a Result, plus
      envelope   the envelope CSV's columns (per ramp: time, speed, amplitude)
    """
    path, settings = _scene_and_settings(scene, set)
    if isinstance(rates, numbers.Real):
        rates = [rates]
    out = _railstab.speed_ramp(path, settings, speed, arc_length, _pairs("offset", offset), mode,
                               mode_amplitude, integrator or "", rtol, atol,
                               [float(a) for a in rates], ramp_to, hunting_threshold, progress)
    r = _result(out)
    r.envelope = _table(out["envelope_csv"])
    return r


def verify(scene, set=None, *, speed=None, arc_length=None, amplitude=1e-4, periods=15.0,
           settle_periods=2.0, any_mode=False, scene_offsets=False, offset=None, mode=None,
           mode_amplitude=None):
    """Time-domain check of the least stable mode: ``railstab verify``.

    Returns the verification JSON as a Result (fitted rate and frequency
    against the eigenvalue).
    """
    path, settings = _scene_and_settings(scene, set)
    return _result(_railstab.verify(path, settings, speed, arc_length, amplitude, periods,
                                    settle_periods, bool(any_mode), bool(scene_offsets),
                                    _pairs("offset", offset), mode, mode_amplitude))


def assess(scene, set=None, *, speed=None, t_end=None, arc_length=None, offset=None, mode=None,
           mode_amplitude=None, progress=None):
    """EN 14363 running stability from a time-domain run: ``railstab assess``.

    The run starts from the scene's initial offsets (``offset`` replaces some,
    as ``--offset``) or on a mode (``mode``, ``mode_amplitude``), on the
    scene's track irregularities where it has them. Returns the assessment
    JSON as a Result (Sum Y rms and bogie frame acceleration rms against
    their limits, the 2 m safety quantities, passed or not), plus
      windows   the windows CSV's columns (each quantity's rms over distance)
    ``progress`` gets the simulated time (s).
    """
    path, settings = _scene_and_settings(scene, set)
    out = _railstab.assess(path, settings, speed, arc_length, t_end, _pairs("offset", offset),
                           mode, mode_amplitude, progress)
    r = _result(out)
    r.windows = _table(out["windows_csv"])
    return r


def sensitivity(scene, set=None, *, keys=None, from_=5.0, to=150.0, step=2.5, hunting_band=20.0,
                progress=None):
    """dVc/dp of scene parameters: ``railstab sensitivity``.

    Returns the sensitivity JSON as a Result (ranked by elasticity), plus
      gradient   {key: dVc/dp}
    ``keys``: parameter keys (Scene.parameters); None: all.
    """
    path, settings = _scene_and_settings(scene, set)
    out = _railstab.sensitivity(path, settings, [str(k) for k in (keys or [])], from_, to, step,
                                hunting_band, progress)
    r = _result(out)
    r.gradient = dict(out["gradient"])
    return r


def contact_geometry(scene, set=None, *, contact=None):
    """Wheel-rail contact geometry of a profile pair: ``railstab contact-geometry``.

    Returns the contact-geometry JSON as a Result (equivalent conicity at
    3 mm, flange contact), plus
      characteristic   the characteristic functions CSV's columns (y_m, delta_r_m, ...)
      conicity         the conicity CSV's columns (amplitude_m, wavelength_m,
                       equivalent_conicity)
    """
    path, settings = _scene_and_settings(scene, set)
    out = _railstab.contact_geometry(path, settings, contact or "")
    r = _result(out)
    r.characteristic = _table(out["characteristic_csv"])
    r.conicity = _table(out["conicity_csv"])
    return r


def _vary_text(key, values):
    if isinstance(key, (tuple, list)):
        key = ",".join(key)  # linked keys take one value together
    try:
        first, last, step = values
    except (TypeError, ValueError):
        raise InputError(f"vary: {key}: expected (from, to, step), got {values!r}") from None
    return f"{key}={_number_text(first)}:{_number_text(last)}:{_number_text(step)}"


def track(scene, set=None):
    """The scene's track irregularities: ``railstab track``.

    Returns the irregularities JSON as a Result (every channel's target and
    sample rms over its wavelength band), plus
      samples    the channels CSV's columns (the arc length and each channel, m)
      spectra    the PSD CSV's columns (each channel's Welch estimate and
                 its target over wavelength)
    No plots. The scene must have a [track.irregularities] table.
    """
    path, settings = _scene_and_settings(scene, set)
    out = _railstab.track(path, settings)
    r = _result(out)
    r.samples = _table(out["channels_csv"])
    r.spectra = _table(out["psd_csv"])
    return r


def study(scene, vary, set=None, *, from_=5.0, to=150.0, step=2.5, solver="auto",
          hunting_band=20.0, jobs=None, progress=None, dataframe=None):
    """The critical speed over combinations of scene values: ``railstab study``.

    ``vary``: {key: (from, to, step)}; a tuple of keys as the key links them
    (one value for all). Returns the study JSON as a Result, plus
      table   the study CSV's columns (index, each varied key, status,
              critical_speed_m_per_s, ...) as a pandas DataFrame where pandas
              is installed, else as a dict of numpy arrays; ``dataframe=True``
              insists on the DataFrame (an ImportError without pandas),
              ``dataframe=False`` asks for the dict
    ``jobs``: threads (default: the machine's cores, as the command).
    """
    path, settings = _scene_and_settings(scene, set)
    if not hasattr(vary, "items"):
        raise InputError("vary: expected a dict {key: (from, to, step)}, got " + type(vary).__name__)
    texts = [_vary_text(k, v) for k, v in vary.items()]
    if jobs is None:
        jobs = os.cpu_count() or 1
    if isinstance(jobs, bool) or not isinstance(jobs, numbers.Integral) or not 1 <= jobs <= 1024:
        raise InputError(f"jobs: expected a whole number of threads in [1, 1024], got {jobs!r}")
    if dataframe is None or dataframe:
        try:
            import pandas
            dataframe = True
        except ImportError:
            if dataframe:
                raise ImportError("study(dataframe=True) needs pandas (Debian: apt-get install "
                                  "python3-pandas); without it the table is a dict of arrays") from None
            dataframe = False
    out = _railstab.study(path, settings, texts, from_, to, step, solver, hunting_band, int(jobs),
                          progress)
    r = _result(out)
    table = _table(out["csv"])
    r.table = pandas.DataFrame(table) if dataframe else table
    return r


def bifurcation(scene, set=None, *, from_=5.0, to=150.0, step=2.5, cycle_speed=None,
                cycle_direction="down", hopf_branch=True, stop_at_fold=False, max_amplitude=0.01,
                max_orbits=200, solver="auto", hunting_band=20.0, arc_length=None, progress=None):
    """Periodic hunting orbits and the nonlinear critical speed: ``railstab bifurcation``.

    Returns the bifurcation JSON as a Result (``branches``: each branch with
    its orbits), plus
      orbits     the branches CSV's columns (one row per orbit) as arrays
    """
    path, settings = _scene_and_settings(scene, set)
    out = _railstab.bifurcation(path, settings, arc_length, from_, to, step, cycle_speed,
                                cycle_direction, bool(hopf_branch), bool(stop_at_fold), max_amplitude,
                                int(max_orbits), solver, hunting_band, progress)
    r = _result(out)
    r.orbits = _table(out["csv"])
    return r
