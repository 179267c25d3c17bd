"""ellc.dem: the DEM engine of ``ellc dem`` driven from Python.

A :class:`Scenario` is the scenario file of ``ellc dem`` (docs/engine.md, "Scenario file"), read
from a TOML file, from TOML text or from a dict with the same keys, and changed between runs like
a dict. A :class:`Run` is the CLI's own scenario runner: it steps the same protocol (settle, load,
hold, unload, relax, done), writes the same files and gives the same numbers, bit for bit. It runs
to the end (:meth:`Run.run`) or in stages (:meth:`Run.run` with a number of steps,
:meth:`Run.run_until` a phase, a time, a step or a condition), and its state reads as numpy arrays.

Quick start (units: µm, µs, µN, MPa, ng, pJ)::

    from ellc import dem
    scenario = dem.Scenario.from_file("examples/calendering_quick.toml")
    scenario["calendering.target_pressure"] = 100.0      # change one key
    run = dem.Run(scenario, "out")                        # builds the packing
    run.run_until("hold")                                 # to the end of the loading
    print(run.plate_pressure, run.porosity, run.particles.position.shape)
    run.save_checkpoint("out/loaded.bin")
    run.run()                                             # to the end
    series = run.timeseries()                             # the columns of out/timeseries.csv

docs/python.md ("The DEM engine: ellc.dem") is the guide.
"""

import copy
import json
import math
import os
import re
import sys
import time as _clock
import tomllib
import warnings

import numpy as np

from ellc import _ellc

InputError = _ellc.InputError
PHASES = tuple(_ellc._phase_names())  # settle, load, hold, unload, relax, done
REGIMES = ("separated", "elastic", "elastic_plastic", "fully_plastic", "unloading")  # ellc.Regime codes 0..4

__all__ = ["Scenario", "Run", "Particles", "Contacts", "RunFinished", "RunFailed", "InputError", "PHASES",
           "REGIMES", "to_toml", "read_timeseries"]


class RunFinished(RuntimeError):
    """Stepping a run whose protocol has ended (phase ``done``)."""


class RunFailed(RuntimeError):
    """A step failed (a runaway particle, a target the protocol cannot reach); the run cannot go on."""


# ---------------------------------------------------------------------------------------------
# Scenarios
# ---------------------------------------------------------------------------------------------

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _input_error(source, field, value, expected):
    # The sentence of the C++ InputError: source, field = value, what was expected.
    return InputError(f"{source}: {field} = {value!r}: expected {expected}")


def _toml_key(key, source, path):
    if not isinstance(key, str):
        raise _input_error(source, path or "<top level>", key, "table keys that are strings")
    return key if _BARE_KEY.match(key) else json.dumps(key, ensure_ascii=False)


def _toml_value(value, source, field):
    """One TOML value; anything TOML cannot hold raises InputError naming the field."""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        number = float(value)
        if math.isnan(number):
            return "nan"
        if math.isinf(number):
            return "inf" if number > 0 else "-inf"
        return repr(number)  # the shortest text that reads back as the same double
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)  # JSON's escapes are TOML's basic-string escapes
    if isinstance(value, np.ndarray):
        if value.ndim != 1:
            raise _input_error(source, field, value.tolist(), "a number, a string, a boolean, a list or a table")
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(item, source, f"{field}[{index}]") for index, item in enumerate(value)) + "]"
    if isinstance(value, dict):
        items = ", ".join(f"{_toml_key(key, source, field)} = {_toml_value(item, source, f'{field}.{key}')}"
                          for key, item in value.items())
        return "{" + (" " + items + " " if items else "") + "}"
    raise _input_error(source, field, value, "a number, a string, a boolean, a list or a table")


def to_toml(data, source="<dict>"):
    """A dict of TOML tables as TOML text: nested dicts become [tables] (e.g. [walls.material]).

    Values TOML cannot hold (None, objects) raise :class:`ellc.InputError` naming the key.
    """
    if not isinstance(data, dict):
        raise _input_error(source, "<scenario>", data, "a dict of tables ({'packing': {...}, ...})")
    lines = []

    def table(mapping, path):  # path: the keys of the enclosing tables
        scalars = [(key, value) for key, value in mapping.items() if not isinstance(value, dict)]
        tables = [(key, value) for key, value in mapping.items() if isinstance(value, dict)]
        name = ".".join(map(str, path))
        if path and (scalars or not tables):
            lines.append("[" + ".".join(_toml_key(key, source, name) for key in path) + "]")
        for key, value in scalars:
            field = f"{name}.{key}" if name else str(key)
            lines.append(f"{_toml_key(key, source, field)} = {_toml_value(value, source, field)}")
        for key, value in tables:
            table(value, [*path, key])

    table(data, [])
    return "\n".join(lines) + "\n"


def _merge(target, changes):
    for key, value in changes.items():
        if isinstance(value, dict) and isinstance(target.get(key), dict):
            _merge(target[key], value)
        else:
            target[key] = copy.deepcopy(value)


class Scenario:
    """An ``ellc dem`` scenario: the keys of the scenario file as nested dicts.

    Build it with :meth:`from_file`, :meth:`from_toml` or :meth:`from_dict` (the same keys as the
    file: ``{"packing": {"count": 100, ...}, "calendering": {...}}``). Each checks the scenario as
    ``ellc dem`` does, through the same reader: an unknown key or a value of the wrong type raises
    :class:`ellc.InputError` naming the key. Change it like a dict, with dotted keys for the
    tables (``scenario["calendering.target_pressure"] = 100.0``) or :meth:`with_changes`; the
    change is checked when a :class:`Run` starts from it (or by :meth:`check`).

    An unchanged scenario keeps its file's text, so checkpoints written by ``ellc dem`` and by
    Python restart each other (a checkpoint carries the hash of the scenario text).
    """

    def __init__(self, data, source="<dict>", text=None):
        self.source = str(source)
        self.data = data
        self._text = text  # the file's own text, used while the data still writes as it did
        self._original = to_toml(data, self.source) if text is not None else None
        self.check()

    @classmethod
    def from_file(cls, path):
        """Reads SCENARIO.toml (the file ``ellc dem`` takes)."""
        path = os.fspath(path)
        try:
            with open(path, encoding="utf-8") as file:
                text = file.read()
        except OSError as error:
            raise InputError(f"{path}: cannot read the scenario file ({error.strerror})") from None
        return cls.from_toml(text, source=path)

    @classmethod
    def from_toml(cls, text, source="<string>"):
        """A scenario from TOML text."""
        if not isinstance(text, str):
            raise TypeError(f"text: expected TOML text (str), got {type(text).__name__}")
        _ellc._check_scenario(text, source)  # the reader's own message for a syntax error
        try:
            data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as error:
            raise InputError(f"{source}: {error}") from None
        return cls(data, source=source, text=text)

    @classmethod
    def from_dict(cls, data, source="<dict>"):
        """A scenario from a dict with the keys of the scenario file (copied)."""
        if not isinstance(data, dict):
            raise _input_error(source, "<scenario>", data, "a dict of tables ({'packing': {...}, ...})")
        return cls(copy.deepcopy(data), source=source)

    @property
    def text(self):
        """The TOML text a run reads: the file's own while unchanged, else the dict written as TOML."""
        current = to_toml(self.data, self.source)
        return self._text if self._text is not None and current == self._original else current

    def check(self):
        """Reads the scenario as ``ellc dem`` would; raises :class:`ellc.InputError` naming the field."""
        _ellc._check_scenario(self.text, self.source)
        return self

    def copy(self):
        duplicate = Scenario.__new__(Scenario)
        duplicate.source, duplicate.data = self.source, copy.deepcopy(self.data)
        duplicate._original, duplicate._text = self._original, self._text
        return duplicate

    def with_changes(self, changes=None, **tables):
        """A checked copy with nested changes merged in: ``with_changes({"packing": {"count": 50}})``."""
        changed = self.copy()
        _merge(changed.data, dict(changes or {}, **tables))
        return changed.check()

    def _walk(self, key, create):
        parts = key.split(".")
        table = self.data
        for depth, part in enumerate(parts[:-1]):
            if part not in table and create:
                table[part] = {}
            if not isinstance(table.get(part), dict):
                raise KeyError(f"{'.'.join(parts[:depth + 1])}: no such table in the scenario")
            table = table[part]
        return table, parts[-1]

    def __getitem__(self, key):
        table, last = self._walk(key, create=False)
        if last not in table:
            raise KeyError(f"{key}: not set in the scenario (the default applies)")
        return table[last]

    def __setitem__(self, key, value):
        table, last = self._walk(key, create=True)
        table[last] = value

    def __delitem__(self, key):
        table, last = self._walk(key, create=False)
        del table[last]

    def __contains__(self, key):
        try:
            self[key]
        except KeyError:
            return False
        return True

    def __repr__(self):
        return f"ellc.dem.Scenario({self.source!r}, tables={list(self.data)})"


def _as_scenario(scenario):
    if isinstance(scenario, Scenario):
        return scenario
    if isinstance(scenario, dict):
        return Scenario.from_dict(scenario)
    if isinstance(scenario, (str, os.PathLike)):
        return Scenario.from_file(scenario)
    raise TypeError(f"scenario: expected an ellc.dem.Scenario, a dict or a path, got {type(scenario).__name__}")


# ---------------------------------------------------------------------------------------------
# State as arrays
# ---------------------------------------------------------------------------------------------

class Particles:
    """The particles as read-only numpy views onto the engine's arrays (no copies).

    Rows are the engine's slots (``id`` names each particle; slots never move during a run). The
    views show the live state: they change as the run steps, and keep the run alive. Copy what
    you want to keep (``run.particles.position.copy()``). ``species`` indexes
    :attr:`Run.species_names` (the scenario's ``[[species]]`` tables in their order; 0 everywhere
    in a one-species packing).
    """

    FIELDS = ("id", "position", "orientation", "semi_axes", "velocity", "angular_velocity", "force", "torque", "mass",
              "mean_radius", "inertia", "species")

    def __init__(self, core):
        self._core = core

    def __len__(self):
        return self._core.particle_count

    def _field(self, name):
        return self._core.particle_field(name)

    id = property(lambda self: self._field("id"), doc="uint32 (N,): persistent particle ids")
    position = property(lambda self: self._field("position"), doc="(N, 3) centres, µm")
    orientation = property(lambda self: self._field("orientation"),
                           doc="(N, 4) unit quaternions body → world, scalar last (x, y, z, w), as "
                               "scipy.spatial.transform.Rotation.from_quat takes them")
    semi_axes = property(lambda self: self._field("semi_axes"), doc="(N, 3) semi-axes (a, b, c) of the body axes, µm")
    velocity = property(lambda self: self._field("velocity"), doc="(N, 3) µm/µs")
    angular_velocity = property(lambda self: self._field("angular_velocity"),
                                doc="(N, 3) rad/µs, body frame (a sphere's is the world frame: "
                                    "the engine keeps its orientation at the identity)")
    force = property(lambda self: self._field("force"), doc="(N, 3) contact force of the last step, µN, world frame")
    torque = property(lambda self: self._field("torque"), doc="(N, 3) contact torque of the last step, µN µm")
    mass = property(lambda self: self._field("mass"), doc="(N,) ng (after mass scaling)")
    mean_radius = property(lambda self: self._field("mean_radius"), doc="(N,) r̂ = (abc)^(1/3), µm (eq. 50)")
    inertia = property(lambda self: self._field("inertia"), doc="(N, 3) principal moments, body frame, ng µm²")
    species = property(lambda self: self._field("species"),
                       doc="uint16 (N,): each particle's species, an index into Run.species_names")


class Contacts:
    """The contacts of the last force evaluation, as new numpy arrays (one row per contact).

    Pairs first (``wall == -1``, ``id_i < id_j``), then the floor's (``wall == 0``) and the plate's
    (``wall == 1``) contacts, where ``id_j`` is -1. Columns: ``overlap`` δ and ``max_overlap`` δ_*
    (µm), ``regime`` (uint8 codes of ellc.Regime, names in ``REGIMES``), ``normal`` (unit, i → j or
    particle → wall), ``force`` (on j or on the wall, µN), ``normal_force`` (F·n, > 0 pushes the
    bodies apart), ``tangential_force`` (F − (F·n) n), ``size_ratio`` c_c/r̂ (eq. 9 at δ_*, r̂ of
    the smaller particle), ``centre_i`` and ``other`` (j's centre, or the contact point on a wall).
    """

    COLUMNS = ("wall", "id_i", "id_j", "overlap", "max_overlap", "regime", "normal", "force", "normal_force",
               "tangential_force", "size_ratio", "centre_i", "other")

    def __init__(self, columns):
        self.__dict__.update(columns)

    def __len__(self):
        return len(self.wall)

    @property
    def pairs(self):
        """Boolean mask of the particle–particle contacts."""
        return self.wall < 0

    @property
    def regime_name(self):
        """The regimes as strings."""
        return np.array(REGIMES, dtype=object)[self.regime]

    def as_dict(self):
        return {name: getattr(self, name) for name in self.COLUMNS}


def read_timeseries(path):
    """timeseries.csv as a dict: column name → numpy array (``phase`` as str, ``step`` as int64)."""
    with open(path, encoding="utf-8") as file:
        lines = [line.rstrip("\n") for line in file if line.strip()]
    if not lines:
        raise InputError(f"{path}: empty time series")
    header = lines[0].split(",")
    rows = [line.split(",") for line in lines[1:]]
    columns = {}
    for index, name in enumerate(header):
        values = [row[index] for row in rows]
        if name == "phase":
            columns[name] = np.array(values, dtype=str)
        elif name == "step":
            columns[name] = np.array(values, dtype=np.int64)
        else:
            columns[name] = np.array(values, dtype=np.float64)
    return columns


# ---------------------------------------------------------------------------------------------
# Runs
# ---------------------------------------------------------------------------------------------

def _clock_text(seconds):
    total = int(seconds + 0.5)
    return f"{total // 3600}h{total // 60 % 60:02d}m" if total >= 3600 else f"{total // 60}m{total % 60:02d}s"


class _ProgressBar:
    """The CLI's bar on a terminal (stderr), updated between chunks of steps."""

    def __init__(self, enabled):
        self.enabled = enabled if enabled is not None else (hasattr(sys.stderr, "isatty") and sys.stderr.isatty())
        self.start = _clock.monotonic()
        self.drawn = False

    def update(self, run):
        if not self.enabled:
            return
        fraction = run.progress
        elapsed = _clock.monotonic() - self.start
        eta = elapsed * (1.0 - fraction) / fraction if fraction > 1e-3 else 0.0
        filled = int(fraction * 30)
        sys.stderr.write(f"\r[{'#' * filled:<30}] {100 * fraction:5.1f}%  {run.phase:<6} step {run.step}  "
                         f"p = {run.plate_pressure:8.3g} MPa  ETA {_clock_text(eta)}   ")
        sys.stderr.flush()
        self.drawn = True

    def finish(self):
        if self.drawn:
            sys.stderr.write("\n")
            sys.stderr.flush()


_NO_LIMIT = 2 ** 62


class Run:
    """One run of a scenario: ``ellc dem`` stepped from Python.

    ``Run(scenario, output_directory=None)`` builds the packing (or, with ``checkpoint=``, reads
    the state of a checkpoint). ``scenario`` is a :class:`Scenario`, a dict with the file's keys,
    or the path of a scenario file. The run writes what ``ellc dem`` writes (timeseries.csv, vtk/,
    checkpoint.bin, summary.txt when it ends) into ``output_directory``, by default the scenario's
    ``[output] directory``; ``write_files=False`` keeps it in memory (then there is no
    :meth:`timeseries`). ``force=True`` is ``--force`` (a time step above the estimate).

    Stepping releases the GIL. A run that is finished raises :class:`RunFinished` when stepped
    again; a step that fails raises :class:`RunFailed` (a ``RuntimeError``), and so does any later
    step of that run.
    """

    def __init__(self, scenario, output_directory=None, *, checkpoint=None, write_files=True, force=False,
                 parallel_threshold=None):
        self.scenario = _as_scenario(scenario)
        if parallel_threshold is not None and (not isinstance(parallel_threshold, (int, np.integer))
                                               or parallel_threshold < 0):
            raise ValueError(f"parallel_threshold = {parallel_threshold!r}: expected an integer >= 0")
        self.write_files = bool(write_files)
        self._core = _ellc._DemRun(self.scenario.text, self.scenario.source,
                                   os.fspath(output_directory) if output_directory is not None else "",
                                   os.fspath(checkpoint) if checkpoint is not None else "", bool(force),
                                   self.write_files, -1 if parallel_threshold is None else int(parallel_threshold))
        self.warnings = list(self._core.warnings)
        for message in self.warnings:
            warnings.warn(message, RuntimeWarning, stacklevel=2)
        self._summary_written = False

    @classmethod
    def from_checkpoint(cls, scenario, checkpoint, output_directory=None, **options):
        """The run continued from a checkpoint written by :meth:`save_checkpoint` or ``ellc dem``.

        ``scenario`` must be the one that wrote it (InputError otherwise). In the directory of the
        interrupted run, the time series is continued from the checkpoint's step.
        """
        return cls(scenario, output_directory, checkpoint=checkpoint, **options)

    # --- stepping -------------------------------------------------------------------------------

    def _check_steppable(self):
        if self._core.failure:
            raise RunFailed(f"this run failed at step {self.step} ({self._core.failure}); it cannot be stepped "
                            "further: start a new run, or load a checkpoint written before the failure")
        if self._core.done:
            raise RunFinished(f"this run is finished (phase 'done' at step {self.step}); there is nothing left to step")

    def _advance(self, method, *arguments):
        try:
            return method(*arguments)
        except InputError:
            raise
        except RuntimeError as error:
            raise RunFailed(str(error)) from error
        finally:
            if self._core.done and self.write_files and not self._summary_written:
                self._core.write_summary()  # as `ellc dem` does at the end
                self._summary_written = True

    def _stepping(self, max_steps, callback, every, progress, step_chunk):
        """Yields step budgets of at most `every` steps; calls back and draws the bar after each."""
        self._check_steppable()
        if max_steps is not None and (not isinstance(max_steps, (int, np.integer)) or max_steps < 0):
            raise ValueError(f"steps = {max_steps!r}: expected an integer >= 0 or None (to the end)")
        if not isinstance(every, (int, np.integer)) or every < 1:
            raise ValueError(f"every = {every!r}: expected an integer >= 1")
        if callback is not None and not callable(callback):
            raise TypeError(f"callback: expected a callable taking the run, got {type(callback).__name__}")
        bar = _ProgressBar(progress)
        remaining = _NO_LIMIT if max_steps is None else int(max_steps)
        try:
            while remaining > 0 and not self._core.done:
                taken = step_chunk(min(remaining, int(every)))
                remaining -= taken
                bar.update(self)
                if callback is not None:
                    callback(self)
                if taken == 0 or self._stop:
                    break
        finally:
            bar.finish()

    def run(self, steps=None, *, callback=None, every=100, progress=None):
        """Steps to the end of the protocol, or at most `steps` steps. Returns the steps taken.

        ``callback(run)`` is called after every `every` steps (and after the last); ``progress``
        draws a bar on stderr (default: only when stderr is a terminal).
        """
        start = self.step
        self._stop = False
        self._stepping(steps, callback, every, progress, lambda n: self._advance(self._core.advance, n))
        return self.step - start

    def run_until(self, condition=None, *, phase=None, time=None, step=None, max_steps=None, check_every=1,
                  callback=None, every=100, progress=None):
        """Steps until a condition holds; returns True if it does, False if the run ended (or
        `max_steps` ran out) first. Exactly one condition:

        - ``run_until("hold")`` or ``phase="hold"``: until the protocol enters that phase (one of
          ``PHASES``); the run stands at the first step of the phase;
        - ``time=t``: until the simulated time is ≥ t µs;
        - ``step=n``: until step n;
        - ``run_until(predicate)``: until ``predicate(run)`` is true, checked every `check_every`
          steps (a Python call each time: use a phase or a time when one will do).

        A condition that already holds returns True without a step. Callback and bar as in :meth:`run`.
        """
        if isinstance(condition, str):
            phase, condition = condition, None
        chosen = [name for name, value in (("condition", condition), ("phase", phase), ("time", time), ("step", step))
                  if value is not None]
        if len(chosen) != 1:
            raise TypeError("run_until: expected exactly one of a phase name, a predicate, time= or step=, got "
                            + (", ".join(chosen) if chosen else "none"))
        if phase is not None:
            if phase not in PHASES:
                raise ValueError(f"phase = {phase!r}: expected one of {', '.join(map(repr, PHASES))}")
            holds = lambda: self.phase == phase  # noqa: E731
            chunk = lambda n: self._advance(self._core.advance_until_phase, phase, n)  # noqa: E731
        elif time is not None:
            if isinstance(time, bool) or not isinstance(time, (int, float, np.integer, np.floating)) \
                    or not math.isfinite(time):
                raise ValueError(f"time = {time!r}: expected a finite number of µs")
            holds = lambda: self.time >= time  # noqa: E731
            chunk = lambda n: self._advance(self._core.advance_until_time, float(time), n)  # noqa: E731
        elif step is not None:
            if not isinstance(step, (int, np.integer)) or isinstance(step, bool) or step < 0:
                raise ValueError(f"step = {step!r}: expected an integer >= 0")
            holds = lambda: self.step >= step  # noqa: E731
            chunk = lambda n: self._advance(self._core.advance, min(n, step - self.step))  # noqa: E731
        else:
            if not callable(condition):
                raise TypeError(f"run_until: expected a phase name or a callable, got {type(condition).__name__}")
            if not isinstance(check_every, (int, np.integer)) or check_every < 1:
                raise ValueError(f"check_every = {check_every!r}: expected an integer >= 1")
            holds = lambda: bool(condition(self))  # noqa: E731
            every_check = int(check_every)
            counted, met = [0], [False]  # the predicate is called once at each multiple of check_every steps

            def chunk(n):
                taken = 0
                while taken < n and not self._core.done:
                    size = min(every_check - counted[0] % every_check, n - taken)
                    step_taken = self._advance(self._core.advance, size)
                    taken += step_taken
                    counted[0] += step_taken
                    if counted[0] % every_check == 0:
                        met[0] = holds()
                    if step_taken == 0 or met[0]:
                        break
                return taken

        if holds():
            return True
        self._stop = False

        def staged(n):
            taken = chunk(n)
            self._stop = met[0] if condition is not None else holds()
            return taken

        self._stepping(max_steps, callback, every, progress, staged)
        return met[0] if condition is not None else holds()

    # --- state ----------------------------------------------------------------------------------

    step = property(lambda self: self._core.step, doc="steps taken since the start of the run")
    time = property(lambda self: self._core.time, doc="simulated time, µs")
    dt = property(lambda self: self._core.dt, doc="time step, µs")
    phase = property(lambda self: self._core.phase, doc="the protocol's phase (one of PHASES)")
    done = property(lambda self: self._core.done, doc="True once the protocol has ended")
    failed = property(lambda self: bool(self._core.failure), doc="True once a step has failed")
    progress = property(lambda self: self._core.progress, doc="rough fraction done (the CLI's bar)")
    gap = property(lambda self: self._core.gap, doc="plate gap (layer thickness), µm")
    porosity = property(lambda self: self._core.porosity, doc="porosity between the plates")
    plate_pressure = property(lambda self: self._core.plate_pressure, doc="pressure on the top plate, MPa")
    bottom_pressure = property(lambda self: self._core.bottom_pressure, doc="pressure on the floor, MPa")
    kinetic_energy = property(lambda self: self._core.kinetic_energy, doc="pJ")
    plastic_dissipation = property(lambda self: self._core.plastic_dissipation, doc="pJ since the start")
    unbalanced_force_ratio = property(lambda self: self._core.unbalanced_force_ratio,
                                      doc="mean net force over mean contact force (0: static equilibrium)")
    wall_positions = property(lambda self: np.array(self._core.wall_positions), doc="(floor, plate) z, µm")
    wall_velocities = property(lambda self: np.array(self._core.wall_velocities), doc="(floor, plate), µm/µs")
    output_directory = property(lambda self: self._core.output_directory)
    species_names = property(lambda self: list(self._core.species_names),
                             doc="the names of the [[species]] tables, in order; [''] for a one-species packing")

    @property
    def particles(self):
        """:class:`Particles`: read-only views onto the engine's arrays."""
        return Particles(self._core)

    def contacts(self):
        """:class:`Contacts` of the last force evaluation (new arrays)."""
        return Contacts(self._core.contacts())

    def timeseries(self):
        """The time series so far (timeseries.csv): a dict of column → numpy array."""
        if not self.write_files:
            raise RuntimeError("this run writes no files (write_files=False), so it keeps no time series")
        return read_timeseries(os.path.join(self.output_directory, "timeseries.csv"))

    def summary(self):
        """The figures of summary.txt for the current state, as a dict (exact floats; counts as ints).
        summary.txt is a TOML document; this is its table."""
        return tomllib.loads(self._core.summary_text())

    def write_summary(self):
        """Writes summary.txt now (a finished run has written it already); returns its path."""
        if not self.write_files:
            raise RuntimeError("this run writes no files (write_files=False)")
        return self._core.write_summary()

    def save_checkpoint(self, path):
        """Writes the whole state (protocol and engine) to `path`; :meth:`from_checkpoint` continues it."""
        self._core.write_checkpoint(os.fspath(path))
        return os.fspath(path)

    def __repr__(self):
        return (f"ellc.dem.Run({self.scenario.source!r}, step={self.step}, time={self.time:.6g} µs, "
                f"phase={self.phase!r}, particles={self._core.particle_count})")
