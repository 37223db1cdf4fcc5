"""microslip: friction benchmarks under the plain and the regularized Coulomb law.

Units everywhere: mm, N, MPa; the tangential stiffness KT in MPa/mm.

One class per problem of the registry (``TwinBeams``, ``Plate``, ``LapJoint``,
``HertzianCylinder``, ``PressFit``, ``PressFitTwisted``), built with keyword parameters (a parameter not given takes the bundled paper data set's value) or from a preset::

    import microslip
    beams = microslip.preset("paper-beams")          # or microslip.TwinBeams(KT=600, F=100)
    s = beams.solve(F=100)                           # both laws, regimes, zones, quantities
    s.regularized.response                           # w(L), mm
    s.to_dict()                                      # == `microslip beam --format json`
    beams.sweep(F=numpy.linspace(0, 240, 1_000_000))  # dict of numpy arrays

A value outside its domain raises ``ParameterError`` (a ``ValueError``) whose message names the
field, the value and the allowed range, as the command line does.

The classes are generated here from the native registry (``_native.problems()``), so a problem
added to the Rust core appears without binding code; ``_CLASS_NAMES`` only gives the four
first ones their familiar names (a new one is named from its title: ``PressFitTwisted``).
"""

from __future__ import annotations

import os

from . import _native
from ._native import Law, ParameterError, Problem, Solution
from ._report import Report

__version__ = _native.__version__

# The only per-problem text of the Python half: the class names for the registry keys.
# A problem missing here gets its title in CamelCase ("clamped double-lap joint" ->
# "ClampedDoubleLapJoint").
_CLASS_NAMES = {
    "beam": "TwinBeams",
    "plate": "Plate",
    "lap": "LapJoint",
    "cylinder": "HertzianCylinder",
}

PROBLEMS = tuple(_native.problems())
"""The registry: one dict per problem (key, title, params with units and domains, quantities)."""


def _class_name(entry: dict) -> str:
    known = _CLASS_NAMES.get(entry["key"])
    if known:
        return known
    words = entry["title"].replace("-", " ").split()
    return "".join(w[:1].upper() + w[1:] for w in words)


def _docstring(entry: dict) -> str:
    params = "\n".join(
        f"    {p['name']}: {p['meaning']} ({p['unit']}; {p['allowed']}; default {p['default']:g})"
        for p in entry["params"]
    )
    quantities = "\n".join(
        f"    {q['name']}: {q['meaning']} ({q['unit']})" for q in entry["quantities"]
    )
    # The load's name and unit from its parameter: F in N, the cylinder's Q in N/mm, the twisted
    # fit's T in N mm.
    name = entry["load"]
    unit = next((p["unit"] for p in entry["params"] if p["name"] == name), "N")
    load = (
        f"\nIts load is {name} ({unit}): solve({name}=...) and sweep({name}=...) vary it"
        + (" (solve also takes F= for it).\n" if name != "F" and unit in ("N", "N/mm") else ".\n")
        if name
        else "\nIt has no load: solve() takes no argument.\n"
    )
    return (
        f"{entry['summary']}.\n\n"
        f"{_class_name(entry)}(*, name=None, **params): keyword parameters, each defaulting to "
        f"the bundled preset '{entry['paper_preset']}'.\n\nParameters:\n{params}\n"
        f"{load}\nQuantities of solve() (by name, solution[name]):\n{quantities}\n"
    )


def _make_class(entry: dict) -> type:
    name = _class_name(entry)
    return type(
        name,
        (Problem,),
        {
            "_model": entry["key"],
            "__doc__": _docstring(entry),
            "__module__": __name__,
            "__slots__": (),
            "description": entry,
        },
    )


_CLASSES = {entry["key"]: _make_class(entry) for entry in PROBLEMS}
globals().update({cls.__name__: cls for cls in _CLASSES.values()})


def problem_class(model: str) -> type:
    """The class of the problem whose registry key is ``model`` (``"beam"``, ``"plate"``, ``"lap"``)."""
    try:
        return _CLASSES[model]
    except KeyError:
        keys = ", ".join(repr(k) for k in _CLASSES)
        raise ValueError(f"unknown model {model!r}: must be one of {keys}") from None


def preset(name: str) -> Problem:
    """The problem of a preset: a bundled name (``presets()``), a user preset or a TOML path.

    Returns an instance of the preset's problem class (``TwinBeams``, ``Plate``, ``LapJoint``)
    whose ``name`` is the preset's, as ``to_dict()`` reports it.
    """
    model, params, preset_name, _description = _native.preset_values(name)
    return _CLASSES[model](name=preset_name, **params)


def compare(path, problem, *, deck=None) -> Report:
    """An FE code's results against the closed forms, with the verdict, as ``microslip compare
    MODEL RESULT --format json`` reports it.

    ``path``: a CalculiX ``.dat`` (its deck, the ``.inp`` beside it or ``deck``, gives the
    parameters in its header) or a CSV of FE points (``F_N,w_mm`` for the beams, ``KT_MPa_per_mm,u_mm``
    for the plate, ``F_N,Delta_mm`` for the joint), compared at ``problem``'s parameters.
    ``problem``: a problem instance, class or registry key (a class or key means its bundled
    paper data set).
    """
    if isinstance(problem, str):
        problem = problem_class(problem)()
    elif isinstance(problem, type):
        problem = problem()
    return _native.compare(os.fspath(path), problem, None if deck is None else os.fspath(deck))


def suite(
    cases=None,
    *,
    quick: bool = False,
    executor: str = "local",
    jobs=None,
    workdir=None,
    resume: bool = False,
    junit=None,
    html=None,
    ccx="ccx",
    microslip=None,
    progress: bool = False,
) -> Report:
    """``microslip suite``: each case run as its mesh ladder (h, h/2, h/4 and the finest at half the
    load increment; ``quick``: h, h/2), each quantity extrapolated to its converged answer and judged
    against the reference with the reference's accuracy plus the ladder's uncertainty.

    The keywords are the command line's flags: ``cases`` a name (a problem's key means its bundled
    presets, any other name a preset's), a list of names, or the path of a TOML list of cases
    (docs/guide.md, "A verification suite"); default every bundled preset. ``executor`` ``"local"``
    (at most ``jobs`` solver processes at once, default the cores less one) or ``"slurm"`` (one job
    array; each task runs the ``microslip`` program, found as ``microslip``, else
    ``$MICROSLIP_BIN``, else on the PATH). ``workdir`` holds the runs (default: a new temporary
    folder); ``resume`` carries on the suite there. ``junit`` and ``html`` also write the
    scorecard as JUnit XML and as its HTML page. ``ccx``: the solver. ``progress``: the CLI's
    progress lines on stderr.

    Returns the scorecard as data: ``cases`` (the objects of ``--format json``: each case's
    ``verdict``, ``quantities``, ``stick_slope``, ``runs``), ``exit_code`` (the CLI's: 0 every
    case agrees, 1 one does not, 3 a solver failed), ``agrees``, ``failing``, ``solver_failure``,
    ``workdir`` and ``seconds``. Raises ``ValueError`` only for what the CLI refuses (exit 2): an
    unknown case, a bad file, a non-empty ``workdir`` without ``resume``, a solver that cannot be
    found; Ctrl-C ends the running solvers and raises ``KeyboardInterrupt``.
    """
    if cases is not None and not isinstance(cases, (str, os.PathLike)):
        cases = ",".join(cases)
    if executor == "slurm" and microslip is None:
        import shutil

        microslip = os.environ.get("MICROSLIP_BIN") or shutil.which("microslip")
        if microslip is None:
            raise ValueError(
                "executor='slurm' runs the microslip program in each array task: install it, "
                "or name it with microslip=PATH or $MICROSLIP_BIN"
            )
    path = lambda p: None if p is None else os.fspath(p)  # noqa: E731
    return _native.suite(
        path(cases),
        bool(quick),
        executor,
        jobs,
        path(workdir),
        bool(resume),
        path(junit),
        path(html),
        os.fspath(ccx),
        path(microslip),
        bool(progress),
    )


def presets(bundled_only: bool = False) -> list:
    """The names ``preset()`` accepts: the bundled presets, then (unless ``bundled_only``) the
    user's (``microslip presets`` lists the same)."""
    return _native.preset_names(bundled_only)


__all__ = [
    "Law",
    "PROBLEMS",
    "ParameterError",
    "Problem",
    "Report",
    "Solution",
    "compare",
    "preset",
    "presets",
    "problem_class",
    "suite",
    *(cls.__name__ for cls in _CLASSES.values()),
]
