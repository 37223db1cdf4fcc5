"""The Python numbers are the CLI's, to the last bit: `Solution.to_dict()` equals `json.loads` of
`microslip <model> --format json` (dict equality compares floats exactly), for every problem of
the registry on every bundled preset and on random valid parameters; and a parameter set the
CLI refuses, Python refuses with the CLI's message."""

from __future__ import annotations

import random

import pytest

import microslip
from conftest import random_params, set_flags

# Only the bundled presets: a user's preset directory must not change the suite.
BUNDLED = microslip.presets(bundled_only=True)


def test_every_problem_has_a_bundled_preset_checked():
    checked = {microslip.preset(name).model for name in BUNDLED}
    assert checked == {e["key"] for e in microslip.PROBLEMS}


@pytest.mark.parametrize("name", BUNDLED)
def test_bundled_presets_equal_the_cli_json(cli, name):
    problem = microslip.preset(name)
    assert problem.solve().to_dict() == cli.json(problem.model, "--preset", name)


@pytest.mark.parametrize("entry", microslip.PROBLEMS, ids=lambda e: e["key"])
def test_random_parameters_equal_the_cli_json(cli, entry):
    rng = random.Random(35)
    cls = microslip.problem_class(entry["key"])
    base = entry["paper_preset"]
    accepted = 0
    for _ in range(8):
        params = random_params(entry, rng)
        args = [entry["key"], "--preset", base, *set_flags(params)]
        try:
            problem = cls(name=f"{base} (modified by --set)", **params)
        except microslip.ParameterError as refused:
            done = cli.run(*args, "--format", "json")
            assert done.returncode == 2
            assert done.stderr.strip() == f"microslip: {refused}"
            continue
        accepted += 1
        solution = problem.solve()
        report = cli.json(*args)
        assert solution.to_dict() == report
        # The solution's own numbers are the report's too.
        assert solution.regularized.response == _response(report, "regularized", entry)
        assert solution.coulomb.response == _response(report, "coulomb", entry)
    assert accepted >= 4


def _response(report: dict, law: str, entry: dict) -> float:
    """The response in a point report: the one key of the law that is the problem's response
    quantity (its first) with its unit (`w_..._mm`, `Delta_mm`, `sa_mm`, the twisted fit's
    `theta_rad`)."""
    response = entry["quantities"][0]
    name, unit = response["name"], response["unit"]
    # A key drops the parentheses of its name: `w(L)` is `w_...`, `s(a)` is `sa_...`.
    stems = {name.split("(")[0], name.replace("(", "").replace(")", "")}
    keys = [k for k in report[law] if k.split("_")[0] in stems and k.endswith("_" + unit)]
    assert len(keys) == 1, (keys, stems, unit)
    return report[law][keys[0]]


def test_the_done_when_one_liner_prints_the_cli_digits(cli):
    """The issue's acceptance line: regularized w(L) of paper-beams at 100 N, same digits."""
    import subprocess
    import sys

    line = "import microslip; print(microslip.preset('paper-beams').solve(F=100).regularized.response)"
    printed = subprocess.run([sys.executable, "-c", line], capture_output=True, text=True, check=True)
    report = cli.run("beam", "--preset", "paper-beams", "--format", "json").stdout
    digits = printed.stdout.strip()
    assert f'"w_tip_mm": {digits}' in report.split('"regularized"')[1]
