"""``microslip.suite(...)`` (issue 45, item 6) without CalculiX: a shell script plays the solver, as
in the Rust suite's tests (tests/suite.rs), handing back real CalculiX results of the deck it was
given (tests/data/suite/) and counting its runs. Its scorecard must be the CLI's ``--format json``,
its exit status data, its refusals ``ValueError``, and Ctrl-C must end the running solver.
"""

from __future__ import annotations

import json
import os
import signal
import stat
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

import microslip

from conftest import ROOT

DATA = ROOT / "tests" / "data" / "suite"

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="a shell-script solver")


def solver(folder: Path, variant: str = "plain", before: str = "") -> Path:
    """A stand-in for ccx in ``folder``: run as ``SCRIPT -i job`` in the run's folder, it reads the
    mesh rung from the deck's header, notes ``start RUNG`` in ``folder/count``, runs ``before``,
    copies the ``VARIANT-RUNG`` results (``plain-RUNG`` where the variant has none), notes
    ``done RUNG``."""
    count = folder / "count"
    body = textwrap.dedent(
        f"""\
        #!/bin/sh
        job="$2"
        mesh=$(sed -n 's/.*microslip-deck: .* mesh=\\([a-z]*\\) .*/\\1/p' "$job.inp")
        echo "start $mesh" >> '{count}'
        {before}
        for ext in dat frd; do
            v={variant}; [ -e '{DATA}/'"$v-$mesh.$ext" ] || v=plain
            cp '{DATA}/'"$v-$mesh.$ext" "$job.$ext"
        done
        echo "done $mesh" >> '{count}'
        """
    )
    path = folder / "fake-ccx"
    path.write_text(body)
    path.chmod(path.stat().st_mode | stat.S_IXUSR)
    return path


def without_times(cases: list) -> list:
    """The scorecard's cases with the solvers' wall times taken out (the one thing that differs
    between two runs of the same suite)."""
    cases = json.loads(json.dumps(cases))
    for case in cases:
        for run in case["runs"]:
            if run["result"] is not None:
                run["result"].pop("solver_seconds")
    return cases


def test_the_scorecard_is_the_cli_s_json_and_its_exit_status_is_data(cli, tmp_path):
    ccx = solver(tmp_path)
    card = microslip.suite(
        "plate-bench", quick=True, jobs=1, workdir=tmp_path / "py", ccx=ccx, html=tmp_path / "s.html"
    )
    done = cli.run(
        "suite", "--cases", "plate-bench", "--quick", "--jobs", "1", "--format", "json",
        "--workdir", str(tmp_path / "cli"), "--ccx", str(ccx),
    )
    assert done.returncode == 0, done.stderr
    assert without_times(card.to_dict()["cases"]) == without_times(json.loads(done.stdout))
    assert card.exit_code == 0 and card.agrees and card.failing == 0
    assert card.solver_failure is None
    assert card.cases[0].verdict == "agrees"
    assert Path(card.workdir) == tmp_path / "py"
    assert (tmp_path / "py" / "plate-bench" / "fine" / "result.json").exists()
    assert "plate-bench" in (tmp_path / "s.html").read_text()
    # The same decks: the Python suite's work folder resumes as the CLI's would, nothing run.
    lines = (tmp_path / "count").read_text().splitlines()
    again = microslip.suite(["plate-bench"], quick=True, workdir=tmp_path / "cli", resume=True, ccx=ccx)
    assert again.exit_code == 0
    assert (tmp_path / "count").read_text().splitlines() == lines


def test_a_case_that_does_not_agree_is_data_with_its_numbers(tmp_path):
    ccx = solver(tmp_path, "off")
    cases = tmp_path / "cases.toml"
    cases.write_text('[[case]]\nname = "stiff"\npreset = "plate-bench"\nmeshes = ["coarse", "fine"]\n')
    card = microslip.suite(cases, workdir=tmp_path / "w", ccx=ccx, junit=tmp_path / "j.xml")
    assert card.exit_code == 1 and not card.agrees and card.failing == 1
    (case,) = card.cases
    assert case.case == "stiff" and case.verdict == "does not agree"
    assert "a stick slope of 11000 MPa/mm, +10.000 %" in case.reason
    assert case.stick_slope.KT_used_MPa_per_mm == 11000
    assert 'failures="1"' in (tmp_path / "j.xml").read_text()


def test_a_failed_solver_is_exit_code_3_not_an_exception(tmp_path):
    ccx = tmp_path / "failing-ccx"
    ccx.write_text("#!/bin/sh\nexit 1\n")
    ccx.chmod(0o755)
    card = microslip.suite("plate-bench", quick=True, workdir=tmp_path / "w", ccx=ccx)
    assert card.exit_code == 3
    assert "ccx failed" in card.solver_failure
    assert card.cases[0].verdict == "not converged"


@pytest.mark.parametrize(
    "kwargs, says",
    [
        ({"cases": "no-such-case"}, "neither a problem"),
        ({"cases": "plate-bench", "executor": "pbs"}, 'must be "local" or "slurm"'),
        ({"cases": "plate-bench", "jobs": 0}, "invalid jobs = 0"),
        ({"cases": "plate-bench", "resume": True, "workdir": None}, "needs the workdir"),
        ({"cases": "plate-bench", "ccx": "/no/such/ccx"}, "--ccx /no/such/ccx"),
    ],
)
def test_usage_errors_raise_value_error(tmp_path, kwargs, says):
    kwargs = {"workdir": tmp_path / "w", **kwargs}
    with pytest.raises(ValueError) as raised:
        microslip.suite(quick=True, **kwargs)
    assert says in str(raised.value), raised.value


def test_a_folder_in_use_is_refused_without_resume(tmp_path):
    (tmp_path / "w").mkdir()
    (tmp_path / "w" / "x").write_text("")
    with pytest.raises(ValueError, match="--resume"):
        microslip.suite("plate-bench", quick=True, workdir=tmp_path / "w", ccx=solver(tmp_path))


def living_in_group(group: int) -> list:
    """The processes of the process group ``group`` that are not zombies."""
    living = []
    for stat_file in Path("/proc").glob("[0-9]*/stat"):
        try:
            text = stat_file.read_text()
        except OSError:
            continue
        # pid (comm) state ppid pgrp ...: comm may hold spaces, so split after its ')'.
        state, _ppid, pgrp = text.rsplit(")", 1)[1].split()[:3]
        if int(pgrp) == group and state != "Z":
            living.append(text.split(" ", 1)[0])
    return living


CHILD = """
import sys, time
import microslip
try:
    microslip.suite("plate-bench", quick=True, jobs=1, workdir=sys.argv[1], ccx=sys.argv[2])
    print("finished", flush=True)
except KeyboardInterrupt:
    print("interrupted", time.monotonic(), flush=True)
print("alive", microslip.TwinBeams().solve(F=100).regularized.regime, flush=True)
"""


def test_ctrl_c_ends_the_running_solver_and_raises_keyboard_interrupt(tmp_path):
    # The solver notes its pid (it leads its own process group) and hangs.
    hang = f"echo $$ > '{tmp_path}/pid.tmp'; mv '{tmp_path}/pid.tmp' '{tmp_path}/pid'; sleep 60"
    ccx = solver(tmp_path, before=hang)
    child = subprocess.Popen(
        [sys.executable, "-c", CHILD, str(tmp_path / "w"), str(ccx)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        started = time.monotonic()
        while not (tmp_path / "pid").exists():
            assert time.monotonic() - started < 60, child.stderr.read()
            time.sleep(0.02)
        pid = int((tmp_path / "pid").read_text())
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=60)
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    lines = out.split("\n")
    assert lines[0].startswith("interrupted"), (out, err)
    assert float(lines[0].split()[1]) - sent < 2.0
    assert lines[1].startswith("alive"), (out, err)
    # The solver's whole group was ended: its `sleep` is gone too (a zombie left for an init
    # that does not reap, as in some containers, runs nothing).
    assert living_in_group(pid) == [], living_in_group(pid)
    # Nothing finished: no result file, so a resumed suite runs the rung again.
    assert not (tmp_path / "w" / "plate-bench" / "coarse" / "result.json").exists()


def test_slurm_without_the_microslip_program_is_refused(tmp_path, monkeypatch):
    # Each array task runs the microslip program: with none to be found, the call says so
    # before anything is written or submitted.
    monkeypatch.delenv("MICROSLIP_BIN", raising=False)
    monkeypatch.setenv("PATH", str(tmp_path))
    with pytest.raises(ValueError, match="runs the microslip program in each array task"):
        microslip.suite("plate-bench", executor="slurm", workdir=tmp_path / "w")
    assert not (tmp_path / "w").exists()


@pytest.mark.skipif(
    os.environ.get("MICROSLIP_SLURM_TEST") != "1",
    reason="needs a running Slurm: .ci/run starts one (.ci/slurm-start) and sets MICROSLIP_SLURM_TEST=1",
)
def test_a_suite_runs_through_a_real_slurm(tmp_path):
    # The Slurm path of microslip.suite(): one job array whose tasks run the microslip program
    # ($MICROSLIP_BIN, which the tests set) on each run's folder; the scorecard comes back as data,
    # each rung solved once.
    program = solver(tmp_path)
    card = microslip.suite(
        "plate-bench", executor="slurm", jobs=2, workdir=tmp_path / "w", ccx=program
    )
    assert card["exit_code"] == 0, card
    assert card["agrees"] and card["failing"] == 0
    assert card["cases"][0]["verdict"] == "agrees"
    assert len(card["cases"][0]["quantities"][0]["rungs_fraction"]) == 3
    done = (tmp_path / "count").read_text().split("\n")
    for rung in ["coarse", "fine", "finest"]:
        assert done.count(f"done {rung}") == 1, done
    assert (tmp_path / "w" / "slurm").is_dir()
