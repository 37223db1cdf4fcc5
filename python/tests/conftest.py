"""Shared fixtures: the command-line binary the Python numbers are checked against, and random
valid parameter sets drawn from the registry's usual ranges.

The CLI is found in $MICROSLIP_BIN, else the workspace's target/debug or target/release (CI builds
the debug one before pytest runs). Missing, the parity tests fail with what to run: they are the
point of the suite, and a skip would hide that they did not run.
"""

from __future__ import annotations

import json
import math
import os
import random
import subprocess
from pathlib import Path

import pytest

import microslip

ROOT = Path(__file__).resolve().parents[2]


def _binary() -> Path | None:
    given = os.environ.get("MICROSLIP_BIN")
    if given:
        return Path(given)
    for profile in ("debug", "release"):
        path = ROOT / "target" / profile / "microslip"
        if path.exists():
            return path
    return None


class Cli:
    """Runs the `microslip` binary."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def run(self, *args: str) -> subprocess.CompletedProcess:
        return subprocess.run(
            [str(self.path), *args], capture_output=True, text=True, timeout=300, check=False
        )

    def json(self, *args: str):
        done = self.run(*args, "--format", "json")
        if args and args[0] in ("compare", "bench"):
            # Exit 0 only when the verdict agrees, 1 when it does not or could not judge; the
            # report is printed either way.
            assert done.returncode in (0, 1), done.stderr
            data = json.loads(done.stdout)
            assert (done.returncode == 0) == data["verdict"]["agrees"], done.stderr
            return data
        assert done.returncode == 0, done.stderr
        return json.loads(done.stdout)


@pytest.fixture(scope="session")
def cli() -> Cli:
    path = _binary()
    if path is None or not path.exists():
        pytest.fail(
            "the microslip CLI is needed to check the Python numbers against it: run `cargo build` "
            "at the repository root, or set MICROSLIP_BIN"
        )
    return Cli(path)


def set_flags(params: dict) -> list:
    """`--set K=V` for every parameter, each value written so that it parses back to the same f64."""
    flags = []
    for key, value in params.items():
        flags += ["--set", f"{key}={value!r}"]
    return flags


def random_params(entry: dict, rng: random.Random) -> dict:
    """One parameter set of the problem `entry` (a `microslip.PROBLEMS` item): each value
    log-uniform over its usual range (uniform where the range starts at 0, as nu), drawn again
    where the keys' mutual bounds refuse the structure; the load,
    where there is one, uniform up to 1.2 times the force where the regimes change (F_thre,
    F_gross), so every regime and, for the lap joint, some refusals occur."""
    cls = microslip.problem_class(entry["key"])
    load = entry["load"]

    def draw() -> dict:
        params = {}
        for p in entry["params"]:
            low, high = p["usual"]
            u = rng.random()
            params[p["name"]] = math.exp(math.log(low) + u * math.log(high / low)) if low > 0 else low + u * (high - low)
        return params

    def structure(params: dict):
        try:
            return cls(**({**params, load: 0.0} if load is not None else params))
        except microslip.ParameterError:
            return None

    # Keys drawn each over its own range may break a bound between them (the press fit's
    # ri < r < ro): such a structure is drawn again, so that most sets reach the closed forms.
    params = draw()
    for _ in range(1000):
        if structure(params) is not None:
            break
        params = draw()
    built = structure(params)
    if load is not None and built is not None:
        params[load] = 1.2 * built.regime_scale * rng.random()
    return params
