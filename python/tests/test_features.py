"""cycle, fe_defaults, kt_tolerance, fit, deck and compare give what the matching CLI command
gives (its JSON parsed, or the deck's text), and continuum the number the CLI's report holds."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

import microslip

DATA = Path(__file__).resolve().parents[2] / "tests" / "data"
LOADED = [e for e in microslip.PROBLEMS if e["load"]]


@pytest.mark.parametrize("entry", LOADED, ids=lambda e: e["key"])
def test_cycle_equals_the_cli(cli, entry):
    problem = microslip.preset(entry["paper_preset"])
    amplitude = 0.8 * problem.regime_scale
    report = problem.cycle(amplitude)
    assert isinstance(report, microslip.Report)
    expected = cli.json("cycle", "--preset", entry["paper_preset"], "--amplitude", repr(amplitude))
    assert report.to_dict() == expected
    assert report.regularized.D_Nmm == expected["regularized"]["D_Nmm"]


def test_the_plate_has_no_cycle():
    with pytest.raises(ValueError, match="no load to cycle"):
        microslip.preset("paper-plate").cycle(1.0)


@pytest.mark.parametrize("entry", microslip.PROBLEMS, ids=lambda e: e["key"])
def test_fe_defaults_equal_the_cli(cli, entry):
    name = entry["paper_preset"]
    assert microslip.preset(name).fe_defaults().to_dict() == cli.json("kt", "--preset", name)
    assert microslip.preset(name).fe_defaults(element_size=0.5).to_dict() == cli.json(
        "kt", "--preset", name, "--element-size", "0.5"
    )


@pytest.mark.parametrize("entry", microslip.PROBLEMS, ids=lambda e: e["key"])
@pytest.mark.parametrize("of", ["coulomb", "current"])
def test_kt_tolerance_equals_the_cli(cli, entry, of):
    name = entry["paper_preset"]
    got = microslip.preset(name).kt_tolerance("1%", of=of).to_dict()
    assert got == cli.json("kt", "--preset", name, "--tolerance", "1%", "--of", of)
    assert microslip.preset(name).kt_tolerance(0.01, of=of).to_dict() == got


def test_kt_tolerance_over_a_force_range_equals_the_cli(cli):
    got = microslip.preset("paper-beams").kt_tolerance("2%", F_from=50.0, F_to=150.0).to_dict()
    assert got == cli.json("kt", "--preset", "paper-beams", "--tolerance", "2%", "--from", "50", "--to", "150")
    with pytest.raises(ValueError, match="invalid F_to = 10: must not be below F_from = 50 N"):
        microslip.preset("paper-beams").kt_tolerance("2%", F_from=50.0, F_to=10.0)


def _paper_fe_curve(tmp_path: Path):
    """The independent FE reference of the paper's beams at K_T = 600 (tests/data), as F and w,
    and as the `F_N,w_mm` file the CLI's fit reads."""
    with open(DATA / "twin-beams-paper-fe.csv") as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    rows = [r for r in rows if float(r["KT_MPa_per_mm"]) == 600.0]
    forces = [float(r["F_N"]) for r in rows]
    w = [float(r["w_regularized_mm"]) for r in rows]
    path = tmp_path / "measured.csv"
    path.write_text("F_N,w_mm\n" + "".join(f"{a!r},{b!r}\n" for a, b in zip(forces, w)))
    return forces, w, path


def test_fit_equals_the_cli(cli, tmp_path):
    forces, w, path = _paper_fe_curve(tmp_path)
    beams = microslip.preset("paper-beams")
    got = beams.fit(forces, w).to_dict()
    expected = cli.json("fit", "beam", str(path), "--preset", "paper-beams")
    assert got.pop("data") == "<arrays>" and expected.pop("data") == str(path)
    assert got == expected
    held = beams.fit(forces, w, fix_mu=0.3).to_dict()
    expected = cli.json("fit", "beam", str(path), "--preset", "paper-beams", "--fix", "mu=0.3")
    held.pop("data"), expected.pop("data")
    assert held == expected


def test_fit_of_the_cylinder_equals_the_cli(cli, tmp_path):
    """The cylinder's s(a) against its line load Q (N/mm): the bundled curve, read as the CLI
    reads it (`Q_N_per_mm,sa_mm`), fitted to the same report."""
    source = DATA / "reports" / "inputs" / "fit-cylinder.csv"
    with open(source) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    loads = [float(r["Q_N_per_mm"]) for r in rows]
    slips = [float(r["sa_mm"]) for r in rows]
    got = microslip.preset("cylinder-steel-pad").fit(loads, slips).to_dict()
    expected = cli.json("fit", "cylinder", str(source))
    assert got.pop("data") == "<arrays>" and expected.pop("data") == str(source)
    assert got == expected
    assert "Q_gross_N_per_mm" in got and "F_1_N" not in got


def test_fit_refuses_bad_points_with_the_cli_words():
    beams = microslip.preset("paper-beams")
    with pytest.raises(ValueError, match="one value per point"):
        beams.fit([1.0, 2.0], [0.1])
    with pytest.raises(ValueError, match="<arrays>"):
        beams.fit([10.0, 20.0, 30.0, float("nan")], [0.001, 0.002, 0.003, 0.004])
    with pytest.raises(ValueError, match="no force-response curve"):
        microslip.preset("paper-plate").fit([1.0], [1.0])


@pytest.mark.parametrize("entry", microslip.PROBLEMS, ids=lambda e: e["key"])
def test_deck_equals_the_cli(cli, entry):
    name = entry["paper_preset"]
    done = cli.run("deck", "ccx", entry["key"], "--preset", name)
    if "has no CalculiX deck" in done.stderr:
        # A problem without a deck (the twisted press fit) is refused alike, with why.
        assert done.returncode == 2, done.stderr
        with pytest.raises(ValueError, match="has no CalculiX deck"):
            microslip.preset(name).deck("ccx")
        return
    assert done.returncode == 0, done.stderr
    assert microslip.preset(name).deck("ccx") == done.stdout
    fine = cli.run("deck", "ccx", entry["key"], "--preset", name, "--mesh", "fine")
    assert microslip.preset(name).deck(mesh="fine") == fine.stdout


def test_deck_with_loads_equals_the_cli(cli):
    done = cli.run("deck", "ccx", "beam", "--preset", "paper-beams", "--loads", "10,50,90")
    assert microslip.preset("paper-beams").deck(loads=[10, 50, 90]) == done.stdout
    with pytest.raises(ValueError, match="must increase"):
        microslip.preset("paper-beams").deck(loads=[50, 10])


RUNS = [
    e for e in microslip.PROBLEMS if (DATA / "calculix" / f"{e['paper_preset']}.dat").exists()
]


@pytest.mark.parametrize("entry", RUNS, ids=lambda e: e["key"])
def test_compare_of_a_calculix_run_equals_the_cli(cli, entry):
    """Every CalculiX run of a bundled preset kept in tests/data/calculix (`<preset>.dat`): the
    whole report of `microslip compare`, with the stick slope the run used, its kinematics and
    the verdicts they turn. (The cylinder's run is 6 MB and not kept: the test below compares
    every problem's, the cylinder's too, on a CSV result.)"""
    path = DATA / "calculix" / f"{entry['paper_preset']}.dat"
    got = microslip.compare(path, entry["key"])
    assert isinstance(got, microslip.Report)
    expected = cli.json("compare", entry["key"], str(path))
    assert "stick_slope" in expected and "kinematics" in expected
    assert got.to_dict() == expected


def test_the_kept_runs_are_the_problems_of_the_calculix_validation():
    assert [e["key"] for e in RUNS] == ["beam", "plate", "lap"]


@pytest.mark.parametrize("entry", microslip.PROBLEMS, ids=lambda e: e["key"])
def test_compare_of_a_csv_result_equals_the_cli(cli, entry, tmp_path):
    """Every problem's FE points as a CSV (its own sweep table, which `compare` reads as FE
    results): the report of `microslip compare MODEL CSV --preset P` with its stick-slope and
    kinematics sections ("not stated" for a CSV) and the continuum verdict where there is one."""
    name = entry["paper_preset"]
    problem = microslip.preset(name)
    if entry["load"]:
        scale = problem.regime_scale
        span = ["--from", repr(0.2 * scale), "--to", repr(0.8 * scale)]
    else:
        span = ["--from", repr(0.5 * problem.KT), "--to", repr(2.0 * problem.KT)]
    table = cli.run("sweep", "--preset", name, *span, "--points", "4")
    assert table.returncode == 0, table.stderr
    path = tmp_path / "fe.csv"
    path.write_text(table.stdout)
    got = microslip.compare(path, problem).to_dict()
    expected = cli.json("compare", entry["key"], str(path), "--preset", name)
    assert expected["kinematics"]["kinematics"] == "not stated"
    assert "stick_slope" in expected
    assert got == expected


def test_compare_refuses_another_problems_results():
    with pytest.raises(ValueError, match="plate"):
        microslip.compare(DATA / "calculix" / "paper-plate.dat", microslip.TwinBeams)


@pytest.mark.parametrize(
    "name, change",
    [("paper-plate", ["tp", 2.0]), ("lap-aluminium", ["KT", 300.0]), ("paper-beams", ["KT", 300.0])],
)
def test_continuum_is_the_number_of_the_cli_report(cli, name, change):
    """`continuum()` is the continuum's response that `<model> --continuum` reports (the plate's
    mean end displacement, the joint's Delta), from the same solve."""
    problem = microslip.preset(name).replace(**{change[0]: change[1]})
    model = problem.model
    report = cli.json(model, "--preset", name, "--set", f"{change[0]}={change[1]!r}", "--continuum")
    key = {"plate": "u_end_mean_mm", "lap": "Delta_mm", "beam": "w_mm"}[model]
    assert problem.continuum() == report["continuum"][key]


def test_the_cylinder_has_no_continuum_yet():
    with pytest.raises(ValueError, match="no continuum reference"):
        microslip.preset("cylinder-steel-pad").continuum()
