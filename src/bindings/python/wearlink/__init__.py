# SPDX-License-Identifier: LGPL-2.1-or-later
"""wearlink from Python: read a scene, change its entries, run it, get arrays back.

    import wearlink
    scene = wearlink.Scene("params/nine_bar_wear.prm")
    scene["Joint B/Clearance/Radial clearance"] = 2e-4      # checked at once
    result = wearlink.run(scene)                           # the C++ runs, the GIL released
    result.summary["clearance_joints"]["B"]               # summary.json as a dict
    result.wear_history["B_max_depth_bushing_um"]          # a column as a numpy array
    result.profiles["B"]["bore"]                           # the worn bore's radii [m]

A scene is checked as the program checks it: a bad entry raises InputError (a
ValueError) with the program's message, which names the file, the entry and the allowed
range. A run that the numerics cannot carry raises NumericalError (a RuntimeError); an
output that cannot be written raises EnvironmentFault (an OSError); Ctrl-C stops a run
and raises Interrupted (a KeyboardInterrupt), its unfinished files removed.

The manual's page doc/python.md has a parameter study; `help(wearlink.run)` and
`help(wearlink.Scene)` say the rest.
"""

import json as _json
import os as _os
import re as _re
import shutil as _shutil
import tempfile as _tempfile
import threading as _threading


from ._wearlink import (EnvironmentFault, EstimationError, InputError, Interrupted,
                        NumericalError)
from . import _wearlink

__all__ = ["Scene", "Result", "Table", "run", "life", "compare_contact", "calibrate", "contact", "study",
           "InputError", "EstimationError", "NumericalError",
           "EnvironmentFault", "Interrupted"]

_INCLUDE = _re.compile(r"^(\s*include\s+)(\S+)(.*)$", _re.IGNORECASE)


def _located(error):
    """Add file, line and entry to an InputError from its message (None where it names none)."""
    text = str(error)
    match = (_re.search(r"of file <([^>]+)>", text) or _re.search(r"scene file '([^']+)'", text)
             or _re.search(r"\bIn ([^\s,:]+)", text))
    error.file = match.group(1) if match else None
    match = _re.search(r"\b[Ll]ine <?(\d+)", text)
    error.line = int(match.group(1)) if match else None
    match = _re.search(r"--set ([^'=]+/[^'=]+)=", text) or _re.search(r"'([^'=\s][^'=]*/[^'=]+)'", text)
    error.entry = match.group(1) if match else None
    return error


def _call(function, *args):
    """Call the C++ part; an InputError gets its file, line and entry as attributes."""
    try:
        return function(*args)
    except (InputError, EstimationError) as error:
        raise _located(error) from None


def _format(value):
    """A Python value as a scene entry: lists and tuples comma-separated, booleans true/false."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple)):
        return ", ".join(_format(v) for v in value)
    return repr(value) if isinstance(value, float) else str(value)


def _absolute_includes(text, base):
    """Scene text with its relative `include` paths made absolute from the folder `base`."""
    lines = []
    for line in text.splitlines():
        match = _INCLUDE.match(line)
        if match and not _os.path.isabs(match.group(2)):
            line = match.group(1) + _os.path.abspath(_os.path.join(base, match.group(2))) + match.group(3)
        lines.append(line)
    return "\n".join(lines) + "\n"


def _scene_file(text):
    """A temporary folder holding `text` as its scene.prm: (folder, path)."""
    folder = _tempfile.mkdtemp(prefix="wearlink-scene-")
    path = _os.path.join(folder, "scene.prm")
    with open(path, "w") as out:
        out.write(text)
    return folder, path


class Scene:
    """A wearlink scene (a .prm file) and the entries set on top of it.

    Scene(path, set=None): the scene in the file `path`; `set` a dict of entries to change,
    {"Joint B/Clearance/Radial clearance": 2e-4, ...}. The scene is read and checked at once,
    and again at every change: a bad entry raises InputError and leaves the scene as it was.

    scene["Section/Entry"] reads an entry as the scene has it (text, as in the file);
    scene["Section/Entry"] = value sets it (numbers, booleans, lists are written as the
    file would). scene.set(...) sets several at once; scene.copy() is an independent copy.
    """

    def __init__(self, path, set=None, _owned=None):
        self._path, self._sets, self._owned, self._info = _os.fspath(path), {}, _owned, None
        try:
            self.set(set or {})
        except BaseException:
            if _owned:  # a scene from text that does not read: its file goes
                _shutil.rmtree(_owned, ignore_errors=True)
            raise

    @classmethod
    def from_string(cls, text, base=".", set=None):
        """A scene from its text. Relative `include` lines are read from the folder `base`."""
        folder, path = _scene_file(_absolute_includes(text, base))
        return cls(path, set, _owned=folder)

    def __del__(self):
        if getattr(self, "_owned", None):
            _shutil.rmtree(self._owned, ignore_errors=True)

    @property
    def path(self):
        """The scene file."""
        return self._path

    @property
    def overrides(self):
        """The entries set, as the program's --set arguments ("Section/Entry=value")."""
        return [f"{k}={v}" for k, v in self._sets.items()]

    @property
    def title(self):
        return self._info["title"]

    @property
    def bodies(self):
        return list(self._info["bodies"])

    @property
    def clearance_joints(self):
        """The clearance joints (a sliced joint's slices by their names, "B.s01", ...)."""
        return list(self._info["clearance_joints"])

    @property
    def wearing_joints(self):
        """The clearance joints that wear (a run of the scene is then a wear run)."""
        return list(self._info["wearing_joints"])

    def set(self, entries):
        """Set several entries {"Section/Entry": value}; checked together, all or none."""
        sets = dict(self._sets)
        for key, value in (entries or {}).items():
            sets[key] = _format(value)
        info = _call(_wearlink.describe, self._path, [f"{k}={v}" for k, v in sets.items()])
        self._sets, self._info = sets, info
        return self

    def __getitem__(self, path):
        return _call(_wearlink.entry, self._path, self.overrides, path)

    def __setitem__(self, path, value):
        self.set({path: value})

    def copy(self):
        """An independent copy (changing it leaves this one as it is)."""
        folder, path = None, self._path
        if self._owned:  # a scene from text: the copy gets its own file
            with open(self._path) as f:
                folder, path = _scene_file(f.read())
        other = Scene.__new__(Scene)
        other._path, other._sets, other._owned, other._info = path, dict(self._sets), folder, self._info
        return other

    def __repr__(self):
        changed = f", {len(self._sets)} entries set" if self._sets else ""
        return f"<wearlink.Scene {self._path!r}: {self.title!r}{changed}>"


class Table:
    """A CSV table of numbers: columns by name as numpy arrays.

    table["t_s"] is a column (a view into table.values, no copy); table.columns the names;
    table.values the rows × columns float64 array; len(table) the rows;
    table.to_pandas() a pandas DataFrame (when pandas is installed).
    """

    def __init__(self, columns, values, path=None):
        self.columns = list(columns)
        self.values = values
        self.path = path
        self._index = {name: k for k, name in enumerate(self.columns)}

    @classmethod
    def read(cls, path):
        columns, values = _call(_wearlink.read_csv, _os.fspath(path))
        return cls(columns, values, _os.fspath(path))

    def __getitem__(self, name):
        try:
            return self.values[:, self._index[name]]
        except KeyError:
            raise KeyError(f"no column {name!r}; the columns are {', '.join(self.columns)}") from None

    def __contains__(self, name):
        return name in self._index

    def __len__(self):
        return self.values.shape[0]

    def __iter__(self):
        return iter(self.columns)

    def to_pandas(self):
        import pandas
        return pandas.DataFrame(self.values, columns=self.columns)

    def __repr__(self):
        return f"<wearlink.Table {self.values.shape[0]} rows × {len(self.columns)} columns>"


class Result:
    """What a run hands back.

    summary         summary.json as a dict (units in the key names: _m, _N, _s, ...)
    time_series     time_series.csv as a Table (None if the run wrote none)
    wear_history    wear_history.csv as a Table, one row per wear iteration (wear runs)
    life, life_history  summary["life"] and life_history.csv as a Table (life())
    members         an ensemble's ensemble.csv as a Table, one row per member (ensemble=N)
    tables          every CSV table the command wrote into its folder, by name ("deviations", ...)
    report          the table the program prints (compare_contact, calibrate)
    profiles        {joint: {"angle_rad", "bore", "pin", "initial_bore", "initial_pin"}}:
                    the worn surfaces' radii [m] at the angles of their samples (wear runs)
    files           the files the run wrote, relative to output_directory
    output_directory  where they are (None once a temporary folder was removed)
    warnings        the results beyond their models' validity (summary["warnings"])
    """

    def __init__(self, summary, profiles, directory, keep, report=""):
        self.summary = summary
        self.profiles = profiles
        self.report = report
        self.warnings = list(summary.get("warnings", []))
        self.files = sorted(_os.path.relpath(_os.path.join(d, f), directory)
                            for d, _, names in _os.walk(directory) for f in names)
        ts = _os.path.join(directory, "time_series.csv")
        self.time_series = Table.read(ts) if _os.path.exists(ts) else None
        wh = _os.path.join(directory, "wear_history.csv")
        self.wear_history = Table.read(wh) if _os.path.exists(wh) else None
        members = _os.path.join(directory, "ensemble.csv")
        self.members = Table.read(members) if _os.path.exists(members) else None
        lh = _os.path.join(directory, "life_history.csv")
        self.life_history = Table.read(lh) if _os.path.exists(lh) else None
        self.life = summary.get("life")
        self.tables = {name[:-4]: Table.read(_os.path.join(directory, name))
                       for name in sorted(_os.listdir(directory)) if name.endswith(".csv")}
        self.output_directory = directory if keep else None

    def __repr__(self):
        kind = "wear run" if self.wear_history is not None else "run"
        where = self.output_directory or "a removed temporary folder"
        return f"<wearlink.Result of a {kind}: {len(self.files)} files in {where}>"


def _in_folder(output, keep, call):
    """call(directory) into `output` (or a temporary folder, removed unless kept); its Result."""
    temporary = output is None
    directory = _tempfile.mkdtemp(prefix="wearlink-run-") if temporary else _os.path.abspath(_os.fspath(output))
    keep = (not temporary) if keep is None else keep
    try:
        raw = call(directory)
        summary = _json.loads(raw["summary"]) if raw["summary"] else {}
        for name in ("summary.json", "convergence.json"):  # the command's own summary file
            path = _os.path.join(directory, name)
            if not summary and _os.path.exists(path):
                with open(path) as f:
                    summary = _json.load(f)
        result = Result(summary, raw["profiles"], directory, keep, raw.get("report", ""))
    except BaseException:
        if temporary:
            _shutil.rmtree(directory, ignore_errors=True)
        raise
    if temporary and not keep:
        _shutil.rmtree(directory, ignore_errors=True)
    return result


def compare_contact(scene, worn=None, cycles=100, effects=True, output=None, keep=None, overwrite=False):
    """The simplified contact laws against the FE model of each joint, as `wearlink compare-contact`.

    worn      None, or the folder of a wear run (its bore_<J>.csv, pin_<J>.csv): the worn
              joints too
    cycles    driving cycles of each law's effect run (> 0, at most 1e4)
    effects   False: no effect runs (force–approach curves and pressures only)

    The Result's `report` is the table of deviations the program prints, its `tables` the
    CSVs (force_approach, deviations, effects, pressure); output, keep and overwrite are
    run()'s.
    """
    if not isinstance(scene, Scene):
        scene = Scene(scene)
    in_main = _threading.current_thread() is _threading.main_thread()
    worn = "" if worn is None else _os.path.abspath(_os.fspath(worn))
    return _in_folder(output, keep, lambda d: _call(_wearlink.compare_contact, scene.path, scene.overrides, d,
                                                    overwrite, worn, float(cycles), bool(effects), in_main))


def contact(case, set=None, output=None, keep=None, overwrite=False):
    """The FE contact of one pin–bushing pair under given loads, as `wearlink contact`.

    case   a contact case file (params/pin_bushing.prm: geometry, materials, loads, FE
           model; not a mechanism scene); set a dict of its entries to change
    The Result's `summary` is summary.json (per load state the contact force, the
    approach, the contact arc and the peak pressure), its `tables` the pressure on both
    surfaces per load state; output, keep and overwrite are run()'s. The reference solver
    goes over the MPI ranks under `mpirun` (output=DIR then).
    """
    sets = [f"{k}={_format(v)}" for k, v in (set or {}).items()]
    if output is None and _wearlink.mpi_ranks()[1] > 1:
        raise _located(InputError("A contact case over several MPI ranks needs output=DIR, a folder every rank "
                                  "sees."))
    in_main = _threading.current_thread() is _threading.main_thread()
    path = _os.path.abspath(_os.fspath(case))
    return _in_folder(output, keep, lambda d: _call(_wearlink.contact, path, sets, d, overwrite, in_main))


def study(kind, scene, output=None, keep=None, overwrite=False, quick=False, knobs=None, study_file=None,
          refinements=(1, 2, 4), ensemble=4, seed=1, perturbation=1e-9):
    """What accuracy costs in time, or whether the worn profiles converge, as `wearlink study`.

    kind          "accuracy": every accuracy knob of the scene in turn (quick=True a shortened
                  study; knobs a list of knob names; study_file a study .prm), each run's cost
                  and its change of the result beside the chaos floor; "convergence": the wear
                  run at the refinement factors `refinements`, the worn profiles' change level
                  by level against the floor
    ensemble      the chaos floor's perturbed runs (accuracy: 0 for none, or 2 … 100;
                  convergence: 2 … 100 per level); seed, perturbation as for run()

    The Result's `report` is the study's Markdown (accuracy.md, convergence.md), its
    `tables` the CSVs (accuracy, accuracy_floor; convergence, ...) and, for convergence,
    its `summary` convergence.json. The runs go over the MPI ranks under `mpirun`
    (output=DIR then).
    """
    if not isinstance(scene, Scene):
        scene = Scene(scene)
    if output is None and _wearlink.mpi_ranks()[1] > 1:
        raise _located(InputError("A study over several MPI ranks needs output=DIR, a folder every rank sees."))
    in_main = _threading.current_thread() is _threading.main_thread()
    study_file = "" if study_file is None else _os.path.abspath(_os.fspath(study_file))
    return _in_folder(output, keep, lambda d: _call(
        _wearlink.study, kind, scene.path, scene.overrides, d, overwrite, bool(quick), list(knobs or []), study_file,
        [float(r) for r in refinements], float(ensemble), float(seed), float(perturbation), in_main))


def calibrate(scene, measurements, ensemble=4, seed=1, perturbation=1e-9, tolerance=1e-3, max_runs=10, output=None,
              keep=None, overwrite=False):
    """The wear coefficients that reproduce measured mass losses or profiles, as `wearlink calibrate`.

    measurements  the measurements file (a .prm; doc/tutorials/calibration.md)
    ensemble      members of the ensemble at the calibrated coefficients (1: none), for
                  the 95 % intervals; seed, perturbation as for run()
    tolerance     the relative residual the secant runs stop at; max_runs their limit

    The Result's `summary` is calibration.json (each coefficient with its interval), its
    `report` the table the program prints. The forward runs go over the MPI ranks under
    `mpirun` (output=DIR then).
    """
    if not isinstance(scene, Scene):
        scene = Scene(scene)
    if output is None and _wearlink.mpi_ranks()[1] > 1:
        raise _located(InputError("A calibration over several MPI ranks needs output=DIR, a folder every rank sees."))
    in_main = _threading.current_thread() is _threading.main_thread()
    meas = _os.path.abspath(_os.fspath(measurements))
    return _in_folder(output, keep, lambda d: _call(_wearlink.calibrate, scene.path, scene.overrides, meas, d,
                                                    overwrite, float(ensemble), float(seed), float(perturbation),
                                                    float(tolerance), float(max_runs), in_main))


def _command(command, scene, output, keep, overwrite, progress, ensemble=None, seed=1, perturbation=1e-9,
             sensitivity=None):
    """Run a command of the C++ part into `output` (or a temporary folder) and read its Result."""
    if not isinstance(scene, Scene):
        scene = Scene(scene)
    if ensemble is None and (seed != 1 or perturbation != 1e-9 or sensitivity is not None):
        raise _located(InputError("seed, perturbation and sensitivity belong to an ensemble: add ensemble=N "
                                  "(2 … 1000)."))
    if sensitivity not in (None, "saltelli"):
        raise _located(InputError(f"sensitivity={sensitivity!r}: the only layout is 'saltelli' (a Saltelli design "
                                  "for Sobol indices); leave it out for rank correlations over Sobol points."))
    ranks = _wearlink.mpi_ranks()[1] if ensemble is not None else 1
    if output is None and ranks > 1:
        raise _located(InputError(f"An ensemble over {ranks} MPI ranks needs output=DIR, a folder every rank "
                                  "sees (a temporary folder is each rank's own)."))
    in_main = _threading.current_thread() is _threading.main_thread()

    def call(directory):
        if ensemble is None:
            return _call(_wearlink.execute, command, scene.path, scene.overrides, directory, overwrite, progress,
                         in_main)
        return _call(_wearlink.ensemble, command, scene.path, scene.overrides, directory, overwrite,
                     float(ensemble), float(seed), float(perturbation), sensitivity == "saltelli", in_main)

    return _in_folder(output, keep, call)


_ENSEMBLE_DOC = """
    ensemble=N (2 … 1000) runs N members instead, each with the angle drivers' initial angles
    perturbed by `perturbation` rad (seed `seed`) and the scene's uncertain inputs drawn
    (section Uncertainty; sensitivity="saltelli" lays them out for Sobol indices), as
    `--ensemble N` does: the members run over the MPI ranks when the script runs under
    `mpirun -np R python3 ...` (every rank gets the same Result; output=DIR is then needed),
    else one after the other. The Result's summary is the ensemble's (each figure's mean,
    spread and interval), its `members` the table ensemble.csv (a row per member), and the
    members' own files are in output/member_*/. progress is not told for an ensemble.
"""


def run(scene, output=None, keep=None, overwrite=False, progress=None, ensemble=None, seed=1, perturbation=1e-9,
        sensitivity=None):
    """Run a scene as `wearlink run` does and return a Result.

    scene      a Scene, or the path of a .prm file
    output     the folder to write into (created; it must not hold an earlier run's files
               unless overwrite=True, which removes those files first, and only them);
               None: a temporary folder
    keep       keep the folder (default: keep `output`, remove a temporary one after the
               run; the Result holds its arrays in memory either way)
    progress   None, or a callable progress(fraction, line) told at each tenth of a run or
               after each wear iteration (fraction 0 … 1, line as the program prints it)

    A scene with a wearing joint runs the wear loop (and writes what `wearlink run` writes
    for it); any other scene one simulation with its plots. The C++ runs without the GIL.
    In the main thread Ctrl-C stops the run cleanly and raises Interrupted; a second
    Ctrl-C ends the process at once, as it does the program.
    """
    return _command("run", scene, output, keep, overwrite, progress, ensemble, seed, perturbation, sensitivity)


def life(scene, output=None, keep=None, overwrite=False, progress=None, ensemble=None, seed=1, perturbation=1e-9,
         sensitivity=None):
    """Run a wear scene until its Life criteria are decided, as `wearlink life` does.

    The arguments are run()'s; progress is told after every iteration with the largest
    criterion's share of its limit. The Result's `life` is summary["life"] (the life in
    revolutions and hours, each criterion with its bracket or interval) and its
    `life_history` the table of every criterion's value per iteration. The scene must
    switch on a criterion of its section Life (InputError otherwise, before any file is
    written).
    """
    return _command("life", scene, output, keep, overwrite, progress, ensemble, seed, perturbation, sensitivity)


run.__doc__ += _ENSEMBLE_DOC
life.__doc__ += _ENSEMBLE_DOC.replace("(each figure's mean,\n    spread and interval)",
                                      "(each figure's mean, spread and interval; ensemble_life the life's percentiles)")
