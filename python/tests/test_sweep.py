"""Vectorized sweeps equal the scalar loop bit for bit, over the load and over other parameters,
for every problem (the cylinder's load sweep continues along its family, issue 47: to 1e-9, and
the same sweep twice gives the same bits); refusals name the element; shapes are kept."""

from __future__ import annotations

import numpy as np
import pytest

import microslip

PROBLEMS = microslip.PROBLEMS


def _bits(a) -> np.ndarray:
    """A float array as its bit patterns, so NaN == NaN and -0 != 0: 'equal' means identical."""
    return np.ascontiguousarray(a, dtype=np.float64).view(np.int64)


def _scalar_loop(problem, key, xs, quantity_names):
    rows = []
    for x in xs:
        s = problem.replace(**{key: float(x)}).solve()
        rows.append(s)
    return rows


def _same(got, expected, tolerance):
    """Identical bits (tolerance None), or each within `tolerance` of the expected value relative
    to it, NaN where it is NaN."""
    got, expected = np.asarray(got, dtype=np.float64), np.asarray(expected, dtype=np.float64)
    if tolerance is None:
        return (_bits(got) == _bits(expected)).all()
    nan = np.isnan(expected)
    return (np.isnan(got) == nan).all() and (
        np.abs(got - expected)[~nan] <= tolerance * np.abs(expected)[~nan]
    ).all()


def _check_against_loop(problem, key, xs, tolerance=None):
    entry = problem.description
    names = [q["name"] for q in entry["quantities"]]
    out = problem.sweep(quantities="all", **{key: xs})
    rows = _scalar_loop(problem, key, xs, names)
    symbol = entry["response_symbol"]
    for law in ("coulomb", "regularized"):
        expected = [getattr(r, law).response for r in rows]
        assert _same(out[f"{symbol}_{law}"], expected, tolerance), law
        expected = [getattr(r, law).zone_end for r in rows]
        assert _same(out[f"zone_end_{law}"], expected, tolerance), law
        labels = [out["regimes"][code] for code in out[f"regime_{law}"]]
        assert labels == [getattr(r, law).regime for r in rows]
    for name in names:
        expected = [np.nan if r[name] is None else r[name] for r in rows]
        assert _same(out[name], expected, tolerance), name
    assert (_bits(out[key]) == _bits(xs)).all()


@pytest.mark.parametrize("entry", PROBLEMS, ids=lambda e: e["key"])
def test_sweeping_the_stiffness_equals_the_scalar_loop(entry):
    problem = microslip.preset(entry["paper_preset"])
    _check_against_loop(problem, "KT", np.logspace(-2, 8, 97))


@pytest.mark.parametrize("entry", [e for e in PROBLEMS if e["load"]], ids=lambda e: e["key"])
def test_sweeping_the_load_equals_the_scalar_loop(entry):
    problem = microslip.preset(entry["paper_preset"])
    # A load bounded by gross slip (the regime scale: the lap joint's, the cylinder's, the press
    # fit's) is swept up to it; the beams' slide on, to 3 regime scales.
    try:
        problem.replace(**{entry["load"]: 1.5 * problem.regime_scale})
        top = 3.0 * problem.regime_scale
    except microslip.ParameterError:
        top = problem.regime_scale
    # The cylinder's rows continue from each other (one family of loads, issue 47): each the
    # scalar solve's root to its stop, 1e-9 of what it answers; the closed forms bit for bit.
    tolerance = 1e-9 if entry["key"] == "cylinder" else None
    _check_against_loop(problem, entry["load"], np.linspace(0.0, top, 101), tolerance)


def test_a_cylinder_sweep_is_its_own_and_leaves_solve_cold():
    """The same sweep twice gives the same bits, and a scalar solve after it (at one of its
    loads) gives the bits it gave before: the continuation lives in the sweep only."""
    pad = microslip.preset("cylinder-steel-pad")
    loads = np.linspace(0.0, pad.regime_scale, 201)
    before = pad.solve(Q=float(loads[100]))
    first = pad.sweep(Q=loads, quantities="all")
    again = pad.sweep(Q=loads, quantities="all")
    assert first.keys() == again.keys()
    for name in first:
        if isinstance(first[name], np.ndarray) and first[name].dtype == np.float64:
            assert (_bits(first[name]) == _bits(again[name])).all(), name
    after = pad.solve(Q=float(loads[100]))
    for law in ("coulomb", "regularized"):
        assert _bits(getattr(after, law).response) == _bits(getattr(before, law).response)
        assert _bits(getattr(after, law).zone_end) == _bits(getattr(before, law).zone_end)


@pytest.mark.parametrize("entry", PROBLEMS, ids=lambda e: e["key"])
def test_every_parameter_can_be_swept(entry):
    problem = microslip.preset(entry["paper_preset"])
    for p in entry["params"]:
        value = getattr(problem, p["name"])
        xs = np.array([value, value])
        out = problem.sweep(**{p["name"]: xs})
        assert out[f"{entry['response_symbol']}_regularized"][0] == problem.solve().regularized.response


def test_a_refused_element_is_named_with_its_index():
    beams = microslip.preset("paper-beams")
    with pytest.raises(microslip.ParameterError, match=r"^F\[2\]: invalid F = -1: must be") as e:
        beams.sweep(F=[0.0, 1.0, -1.0, 3.0])
    assert e.value.field == "F" and e.value.value == -1.0


def test_a_refusal_deep_in_a_long_sweep_names_its_own_index():
    """Long sweeps are split across threads: the index is still the array's, and the first."""
    forces = np.linspace(0.0, 240.0, 1_000_000)
    forces[900_001] = -2.0
    forces[700_000] = -3.0
    with pytest.raises(microslip.ParameterError, match=r"^F\[700000\]: invalid F = -3"):
        microslip.preset("paper-beams").sweep(F=forces)


def test_a_long_sweep_equals_the_scalar_loop_where_threads_split_it():
    beams = microslip.preset("paper-beams")
    forces = np.linspace(0.0, 240.0, 200_001)
    out = beams.sweep(F=forces)
    for i in (0, 1, 65_535, 100_000, 100_001, 150_000, 200_000):
        s = beams.solve(F=float(forces[i]))
        assert out["w_regularized"][i] == s.regularized.response
        assert out["regimes"][out["regime_regularized"][i]] == s.regularized.regime
        assert out["regimes"][out["regime_coulomb"][i]] == s.coulomb.regime


def test_the_joint_refuses_a_load_past_gross_slip_by_index():
    joint = microslip.preset("lap-aluminium")
    with pytest.raises(ValueError, match=r"^F\[1\]: invalid F = 7000: must be in \[0, 6000\] N"):
        joint.sweep(F=[100.0, 7000.0])


def test_shape_is_kept_and_lists_are_accepted():
    beams = microslip.preset("paper-beams")
    grid = np.linspace(1, 200, 12).reshape(3, 4)
    out = beams.sweep(F=grid)
    assert out["w_regularized"].shape == (3, 4)
    assert out["regime_coulomb"].dtype == np.int8
    flat = beams.sweep(F=list(grid.ravel()))
    assert (flat["w_regularized"] == out["w_regularized"].ravel()).all()


def test_sweep_takes_one_known_parameter():
    beams = microslip.preset("paper-beams")
    with pytest.raises(TypeError, match="exactly one parameter"):
        beams.sweep(F=[1.0], KT=[2.0])
    with pytest.raises(TypeError, match="unknown key 'Kt' for the beam model"):
        beams.sweep(Kt=[1.0])
    with pytest.raises(KeyError, match="no quantity"):
        beams.sweep(F=[1.0], quantities=["nope"])
