"""The failure criteria in Python: the same names as the CLI's --criterion, the same puncture."""

import math

import pytest

import puncture as pu


def test_names_round_trip_and_unknown_names_raise():
    assert pu.criterion_names() == [
        "i1", "max-stretch", "energy-density", "true-stress", "energy-release"]
    for name in pu.criterion_names():
        assert pu.criterion_name(pu.criterion_from_name(name, 7.0)) == name
    assert pu.criterion_from_name("max-stretch", 6.0).critical_stretch == 6.0
    with pytest.raises(ValueError, match="criterion: unknown failure criterion 'bogus'"):
        pu.criterion_from_name("bogus", 1.0)


def test_measures_at_the_equibiaxial_pole():
    m = pu.Material()
    lam = 2.5
    assert pu.measure_at(pu.CriticalFirstInvariant(95.2), m, lam, lam) == pytest.approx(
        2 * lam**2 + lam**-4, rel=1e-15)
    assert pu.measure_at(pu.MaxPrincipalStretch(6.0), m, lam, lam) == lam
    i1 = 2 * lam**2 + lam**-4
    assert pu.measure_at(pu.CriticalEnergyDensity(1.0), m, lam, lam) == pytest.approx(
        -0.5 * 0.06 * 125 * math.log(1 - (i1 - 3) / 125), rel=1e-12)


def test_the_criterion_at_the_i1_puncture_finds_the_same_puncture():
    base = pu.Problem()
    by_i1 = pu.predict_puncture(base)
    assert by_i1.ok and by_i1.criterion == "critical I1 = 95.2"
    stretch = pu.assess(pu.MaxPrincipalStretch(6.0), by_i1.state, base.material).value
    problem = pu.Problem(criteria=[pu.MaxPrincipalStretch(stretch)])
    assert len(problem.criteria) == 1
    by_stretch = pu.predict_puncture(problem)
    assert by_stretch.ok
    assert by_stretch.force_n == pytest.approx(by_i1.force_n, rel=1e-8)
    assert by_stretch.criterion.startswith("maximum principal stretch")


def test_bad_criteria_raise_value_error_naming_the_attribute():
    with pytest.raises(ValueError, match="criteria"):
        pu.predict_puncture(pu.Problem(criteria=[pu.MaxPrincipalStretch(1.0)]))
    with pytest.raises(ValueError, match="criteria"):
        pu.predict_puncture(pu.Problem(criteria=[pu.CriticalEnergyDensity(-1.0)]))


def test_energy_release_on_the_frictionless_flat_punch():
    problem = pu.Problem(friction=0.0, criteria=[pu.CriticalEnergyRelease(1.0)])
    punct = pu.predict_puncture(problem)
    assert punct.ok and punct.criterion == "tearing energy = 1 N/mm"
    balance = pu.energy_release(problem, punct.state, 1.0)
    assert balance.ratio == pytest.approx(1.0, abs=1e-8)
    assert balance.released_energy_mj == pytest.approx(balance.cut_energy_mj, rel=1e-8)
    assert pu.assess(problem.criteria[0], punct.state, problem).ratio == pytest.approx(
        1.0, abs=1e-8)
    with pytest.raises(ValueError, match="no local measure"):
        pu.measure_at(pu.CriticalEnergyRelease(1.0), pu.Material(), 2.0, 2.0)
    # The default contact is lubricated (friction 0.18): refused, friction dissipates.
    with pytest.raises(ValueError, match="friction dissipates"):
        pu.predict_puncture(pu.Problem(criteria=[pu.CriticalEnergyRelease(1.0)]))


def test_critical_values_from_the_papers_bursts():
    tests = [pu.BurstTest(0.5, r) for r in (3.346, 3.407, 3.515, 3.527)]
    est = pu.critical_value_from_inflation(tests, pu.MaxPrincipalStretch(0.0), pole_only=True)
    assert est.ok
    assert est.mean == pytest.approx(sum(r / 0.5 for r in (3.346, 3.407, 3.515, 3.527)) / 4,
                                     rel=1e-15)
    assert est.criterion.critical_stretch == est.mean
