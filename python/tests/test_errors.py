"""Refusals: a value outside its domain raises ParameterError (a ValueError) whose message is the
CLI's, naming the field, the value and the range; its attributes say the same."""

from __future__ import annotations

import math

import pytest

import microslip


@pytest.mark.parametrize("entry", microslip.PROBLEMS, ids=lambda e: e["key"])
def test_every_parameter_out_of_its_domain_is_refused_by_name(cli, entry):
    cls = microslip.problem_class(entry["key"])
    for p in entry["params"]:
        for bad in (p["min"] - 1.0, p["max"] * 10.0, math.inf, math.nan):
            with pytest.raises(microslip.ParameterError) as e:
                cls(**{p["name"]: bad})
            message = str(e.value)
            assert isinstance(e.value, ValueError)
            assert e.value.field == p["name"]
            assert e.value.value == bad or math.isnan(bad)
            assert message.startswith(f"invalid {p['name']} = "), message
            assert message.endswith(f": {e.value.allowed}") and "must" in e.value.allowed
            if math.isfinite(bad):
                # The command line's words, to the character.
                flag = f"{p['name']}={bad!r}"
                done = cli.run(entry["key"], "--preset", entry["paper_preset"], "--set", flag)
                assert done.returncode == 2
                assert done.stderr.strip() == f"microslip: {message}"


def test_issue_example_and_a_named_refusal():
    beams = microslip.TwinBeams(L=200, b=20, h=10, E=210000, P=1, mu=0.3, KT=600)
    assert beams.KT == 600.0 and beams.nu == 0.3  # nu defaults to the paper's
    # The message documented in the core (problems/inputs.rs, `Inputs` example).
    with pytest.raises(ValueError, match=r"^invalid L = -1: must be > 0 and finite \(mm\)$"):
        beams.replace(L=-1)


def test_unknown_keywords_and_non_numbers_are_type_errors():
    with pytest.raises(TypeError, match=r"unknown key 'Kt' for the beam model \(allowed: L b h E nu P mu KT F\)"):
        microslip.TwinBeams(Kt=600)
    with pytest.raises(TypeError, match="KT must be a number, got str"):
        microslip.TwinBeams(KT="600")
    with pytest.raises(TypeError, match="has no load"):
        microslip.Plate().solve(F=1.0)


def test_objects_are_frozen_and_replace_copies():
    beams = microslip.preset("paper-beams")
    with pytest.raises(AttributeError):
        beams.KT = 5
    softer = beams.replace(KT=120)
    assert softer.KT == 120 and beams.KT == 600
    assert type(softer) is microslip.TwinBeams
    assert softer.name == "paper-beams (modified)"
    assert beams.replace(KT=600) == beams and beams.replace(KT=600).name == "paper-beams"


def test_unknown_preset_says_so():
    with pytest.raises(ValueError, match="no-such-preset"):
        microslip.preset("no-such-preset")


def test_a_preset_s_setting_the_api_cannot_carry_is_refused_by_its_key(tmp_path):
    # A preset that sets a problem's choice away from its default is refused, naming the key and
    # the value it sets, rather than silently solved with the default.
    path = tmp_path / "timo.toml"
    path.write_text(
        'model = "beam"\nbeam_theory = "timoshenko"\nL = 200.0\nb = 20.0\nh = 10.0\n'
        "E = 210000.0\nP = 1.0\nmu = 0.3\nKT = 600.0\nF = 100.0\n"
    )
    with pytest.raises(ValueError, match="beam_theory = timoshenko, not the default"):
        microslip.preset(str(path))


def test_problems_pickle_for_process_pools():
    import pickle

    joint = microslip.preset("lap-aluminium").replace(KT=250.0)
    back = pickle.loads(pickle.dumps(joint))
    assert type(back) is microslip.LapJoint and back == joint and back.name == joint.name
    assert back.solve().to_dict() == joint.solve().to_dict()


def test_solve_takes_each_problem_s_load_by_its_own_name():
    # The cylinder's load is Q (N/mm): solve(Q=...) sets it; F= is its documented alias, and a
    # positional value is the load too. The answer is that of the data set with Q replaced.
    pad = microslip.preset("cylinder-steel-pad")
    by_name = pad.solve(Q=120.0).to_dict()
    replaced = pad.replace(Q=120.0).solve().to_dict()
    assert by_name == {**replaced, "preset": "cylinder-steel-pad"}
    assert by_name != pad.solve().to_dict()
    assert pad.solve(F=120.0).to_dict() == by_name
    assert pad.solve(120.0).to_dict() == by_name
    # The beams' load is F (N); Q is not theirs.
    beams = microslip.preset("paper-beams")
    assert beams.solve(F=50.0).to_dict() == {**beams.replace(F=50.0).solve().to_dict(), "preset": "paper-beams"}
    with pytest.raises(TypeError, match=r"unexpected keyword 'Q': solve\(\) of the twin cantilever beams takes its load F \(N\)"):
        beams.solve(Q=50.0)
    # A bool is not a load (Python would take True as 1), and a load is given once.
    with pytest.raises(TypeError, match="not a bool"):
        pad.solve(True)
    with pytest.raises(TypeError, match="given twice"):
        pad.solve(120.0, Q=120.0)
