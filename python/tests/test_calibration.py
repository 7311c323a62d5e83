"""The calibrations from Python: the same numbers and the same messages as the CLI's `calibrate`
and `fit` commands, the paper's critical I1 reproduced, synthetic data recovered, errors raised."""

import math
from pathlib import Path

import numpy as np
import pytest

import puncture as pu

DATA = Path(__file__).resolve().parents[2] / "tests" / "cli"
PAPER_BURSTS = [3.346, 3.407, 3.515, 3.527]  # mm, a 0.5 mm mark: the paper's 95.2 +- 4.8


# The CLI writes JSON with nlohmann's shortest round-trip representation of the same doubles
# the bindings return, and both run the same deterministic code: equal to the last bit, so any
# tolerance would only hide a difference in the inputs.  rel=1e-15 allows a last-digit change.
def same(a, b):
    if b is None:
        return a is None
    return a == pytest.approx(b, rel=1e-15, abs=0.0)


def cli_error(cli, *args):
    """The message of a failed CLI run and its exit code, without the 'puncture: ...: ' prefix."""
    rc, out, err = cli.run(*args)
    assert rc in (1, 2) and out == "", err
    prefix = "puncture: error: " if rc == 1 else "puncture: solver failure: "
    assert err.startswith(prefix), err
    message = err[len(prefix):]
    if rc == 2:  # the failure kind follows on its own line
        message, kind = message.split("\n  failure kind: ")
        assert kind.split(":")[0] in ("physical", "numerical", "outside the model"), kind
    return rc, message.strip()


def without_flag(message):
    """'--flag: text' -> 'text' (the CLI names the flag, the bindings the argument)."""
    return message.split(": ", 1)[1]


# ----- critical I1 ------------------------------------------------------------------------------

def test_paper_critical_i1_reproduced():
    e = pu.critical_i1_from_inflation(PAPER_BURSTS, mark_radius_mm=0.5)
    # The paper's §2.3: 95.2 +- 4.8 from four tests.
    assert round(e.mean, 1) == 95.2
    assert round(e.standard_deviation, 1) == 4.8
    assert e.standard_error == pytest.approx(e.standard_deviation / 2, rel=1e-15)
    # Each test's I1 from its stretch, by the equibiaxial formula written out here.
    lam = np.array(PAPER_BURSTS) / 0.5
    np.testing.assert_allclose(e.stretches, lam, rtol=1e-15)
    np.testing.assert_allclose(e.first_invariants, 2 * lam**2 + lam**-4, rtol=1e-14)
    assert e.mean == pytest.approx(np.mean(2 * lam**2 + lam**-4), rel=1e-14)
    assert e.standard_deviation == pytest.approx(np.std(2 * lam**2 + lam**-4, ddof=1), rel=1e-12)


def test_critical_i1_matches_cli(cli):
    e = pu.critical_i1_from_inflation(PAPER_BURSTS, 0.5)
    c = cli.json("calibrate", "critical-i1", "--mark-radius", "0.5", "--burst-radii",
                 ",".join(map(str, PAPER_BURSTS)))
    assert same(e.mean, c["critical_i1"]["mean"])
    assert same(e.standard_deviation, c["critical_i1"]["sd"])
    assert same(e.standard_error, c["critical_i1"]["standard_error"])
    assert [t["i1"] for t in c["inputs"]["tests"]] == list(e.first_invariants)


def test_burst_tests_from_csv_match_cli(cli):
    tests = pu.burst_tests_from_csv(str(DATA / "bursts.csv"))
    e = pu.critical_i1_from_inflation(tests)
    c = cli.json("calibrate", "critical-i1", str(DATA / "bursts.csv"))
    assert [t.burst_radius_mm for t in tests] == [t["burst_radius_mm"] for t in c["inputs"]["tests"]]
    assert same(e.mean, c["critical_i1"]["mean"])
    assert same(e.standard_deviation, c["critical_i1"]["sd"])
    one = pu.critical_i1_from_inflation([pu.BurstTest(0.5, 3.45)])
    assert one.standard_deviation is None and one.standard_error is None


@pytest.mark.parametrize("radii,mark,name", [
    ("3.4,0.4", 0.5, "burst_radii_mm"),
    ("nan", 0.5, "burst_radii_mm"),
    ("3.4", -1.0, "mark_radius_mm"),
])
def test_critical_i1_errors_match_cli(cli, radii, mark, name):
    rc, message = cli_error(cli, "calibrate", "critical-i1", "--mark-radius", mark,
                            "--burst-radii", radii)
    assert rc == 1
    with pytest.raises(ValueError) as info:
        pu.critical_i1_from_inflation([float(r) for r in radii.split(",")], mark)
    assert str(info.value) == f"{name}: {without_flag(message)}"


def test_burst_csv_errors_match_cli(cli):
    rc, message = cli_error(cli, "calibrate", "critical-i1", str(DATA / "bursts_bad.csv"))
    with pytest.raises(ValueError, match="bursts_bad.csv:4: column 2") as info:
        pu.burst_tests_from_csv(str(DATA / "bursts_bad.csv"))
    assert str(info.value) == message
    rc, message = cli_error(cli, "calibrate", "critical-i1", str(DATA / "bursts.csv"),
                            "--mark-radius", "0.5")
    with pytest.raises(ValueError) as info:
        pu.burst_tests_from_csv(str(DATA / "bursts.csv"), mark_radius_mm=0.5)
    assert str(info.value) == "mark_radius_mm: " + without_flag(message)
    with pytest.raises(ValueError, match="at least one inflation test"):
        pu.critical_i1_from_inflation([])


# ----- friction from the hole ---------------------------------------------------------------

DRY_1MM = dict(indenter=pu.FlatPunch(radius_mm=1.0))


def test_friction_matches_cli(cli):
    problem = pu.Problem(**DRY_1MM)
    c = cli.json("calibrate", "friction", "--indenter-radius", "1", "--puncture-force", "1.72",
                 "--hole-ratio", "1.58", "--hole-ratio-sd", "0.14")
    for method, key in [("at-measured-force", "at_measured_force"),
                        ("at-predicted-puncture", "at_predicted_puncture")]:
        e = pu.friction_from_hole(problem, 1.58, 0.14, puncture_force_n=1.72, method=method)
        theirs = c[key]
        assert e.method.token == theirs["method"] == method
        assert same(e.friction.value, theirs["friction"]["value"])
        assert same(e.friction_for_ratio_plus_sd.value, theirs["friction_ratio_plus_sd"]["value"])
        assert same(e.friction_for_ratio_minus_sd.value,
                    theirs["friction_ratio_minus_sd"]["value"])
        assert same(e.stretch_at_zero_friction, theirs["stretch_at_zero_friction"])
        assert [s.model for s in e.scan] == [s["part_three_stretch"] for s in theirs["scan"]]
    # The default method follows the CLI's: the paper's when a force is given.
    assert pu.friction_from_hole(problem, 1.58, puncture_force_n=1.72).method == \
        pu.HoleMethod.AtMeasuredForce
    assert pu.friction_from_hole(problem, 1.58).method == pu.HoleMethod.AtPredictedPuncture


def test_friction_recovered_from_a_predicted_hole():
    # The force-free method inverts predict_puncture: the Part III stretch the solver predicts
    # with mu' = 1.2 must give mu' = 1.2 back (to the 1e-9 absolute of the root refinement,
    # amplified by the ~1e-8 relative accuracy of each puncture solve: 1e-6 leaves a margin).
    ratio = pu.predict_puncture(pu.Problem(friction=1.2, **DRY_1MM)).part_three_stretch
    e = pu.friction_from_hole(pu.Problem(**DRY_1MM), ratio)
    assert e.friction.value == pytest.approx(1.2, abs=1e-6)
    assert e.friction_for_ratio_plus_sd.value is None  # no sd given
    assert "no standard deviation" in e.friction_for_ratio_plus_sd.message


def test_friction_errors_match_cli(cli):
    rc, message = cli_error(cli, "calibrate", "friction", "--indenter-radius", "1",
                            "--puncture-force", "1.72", "--hole-ratio", "9")
    assert rc == 2
    with pytest.raises(pu.SolverError) as info:
        pu.friction_from_hole(pu.Problem(**DRY_1MM), 9.0, puncture_force_n=1.72)
    assert str(info.value) == message and info.value.message == message
    for flags, kwargs, name in [(["--hole-ratio", "1.5", "--hole-ratio-sd", "-1"],
                                 dict(hole_ratio=1.5, hole_ratio_sd=-1.0), "hole_ratio_sd"),
                                (["--hole-ratio", "1.5", "--puncture-force", "0"],
                                 dict(hole_ratio=1.5, puncture_force_n=0.0), "puncture_force_n"),
                                (["--hole-ratio", "nan"], dict(hole_ratio=math.nan), "hole_ratio")]:
        rc, message = cli_error(cli, "calibrate", "friction", *flags)
        assert rc == 1
        with pytest.raises(ValueError) as info:
            pu.friction_from_hole(pu.Problem(), **kwargs)
        assert str(info.value) == f"{name}: {without_flag(message)}"
    with pytest.raises(ValueError, match="method: expected"):
        pu.friction_from_hole(pu.Problem(), 1.5, method="guess")


# ----- J_lim from a puncture force ----------------------------------------------------------

def test_j_lim_matches_cli(cli):
    e = pu.j_lim_from_puncture_force(pu.Problem(), 0.7)
    c = cli.json("calibrate", "jlim", "--puncture-force", "0.7")["estimate"]
    assert same(e.j_lim.value, c["j_lim"]["value"])
    assert list(e.j_lim.solutions) == c["j_lim"]["solutions"]
    assert same(e.puncture.force_n, c["puncture"]["force_n"])
    assert same(e.neo_hookean_force_n, c["neo_hookean_force_n"])
    assert same(e.max_first_invariant_at_force, c["max_i1_at_force"])
    assert [s.model for s in e.scan] == [s["puncture_force_n"] for s in c["scan"]]


def test_j_lim_recovered_from_a_predicted_force():
    # The default membrane's predicted force has J_lim = 125; the inversion (1e-10 in log space,
    # each force to ~1e-8) gives it back to far better than 1e-6 relative.
    force = pu.predict_puncture(pu.Problem()).force_n
    e = pu.j_lim_from_puncture_force(pu.Problem(material=pu.Material.gent(j_lim=300)), force)
    assert e.j_lim.value == pytest.approx(125.0, rel=1e-6)
    assert e.puncture.force_n == pytest.approx(force, rel=1e-8)


def test_j_lim_errors_match_cli(cli):
    rc, message = cli_error(cli, "calibrate", "jlim", "--puncture-force", "0.1")
    assert rc == 2
    with pytest.raises(pu.SolverError) as info:
        pu.j_lim_from_puncture_force(pu.Problem(), 0.1)
    assert str(info.value) == message
    rc, message = cli_error(cli, "calibrate", "jlim", "--puncture-force", "0")
    with pytest.raises(ValueError) as info:
        pu.j_lim_from_puncture_force(pu.Problem(), 0.0)
    assert str(info.value) == "puncture_force_n: " + without_flag(message)
    with pytest.raises(ValueError, match="^material: J_lim is a parameter of the Gent law"):
        pu.j_lim_from_puncture_force(pu.Problem(material=pu.Material.neo_hookean()), 0.7)
    with pytest.raises(ValueError, match="^invalid input:\n  critical_i1: "):
        pu.j_lim_from_puncture_force(pu.Problem(critical_i1=2.0), 0.7)


# ----- uniaxial fit -------------------------------------------------------------------------

def test_uniaxial_fit_matches_cli(cli):
    stretch, stress = pu.uniaxial_points_from_csv(str(DATA / "uniaxial_gent.csv"))
    fit = pu.fit_uniaxial(stretch, stress, "gent")
    c = cli.json("fit", "uniaxial", str(DATA / "uniaxial_gent.csv"))
    assert [p["stretch"] for p in c["points"]] == list(stretch)
    assert [p["fitted_stress_mpa"] for p in c["points"]] == list(fit.fitted_stress_mpa)
    for ours, theirs in zip(fit.parameters, c["fit"]["parameters"]):
        assert ours.name == theirs["name"]
        assert same(ours.value, theirs["value"])
        assert same(ours.standard_error, theirs["standard_error"])
        assert ours.identifiable == theirs["identifiable"]
    assert same(fit.rms_residual_mpa, c["fit"]["rms_residual_mpa"])
    assert same(fit.material.law.j_lim, c["fit"]["material"]["j_lim"])
    assert fit.iterations == c["fit"]["iterations"]


def test_uniaxial_points_from_forces_match_cli(cli):
    specimen = pu.SpecimenGeometry(10.0, 0.2, 60.0)
    stretch, stress = pu.uniaxial_points_from_csv(str(DATA / "uniaxial_force.csv"), specimen)
    c = cli.json("fit", "uniaxial", str(DATA / "uniaxial_force.csv"), "--specimen-width", "10",
                 "--specimen-thickness", "0.2", "--gauge-length", "60")
    assert [p["stretch"] for p in c["points"]] == list(stretch)
    assert [p["nominal_stress_mpa"] for p in c["points"]] == list(stress)
    # The same conversion from arrays, against the formulas written out.
    raw = np.loadtxt(DATA / "uniaxial_force.csv", delimiter=",", comments="#", skiprows=2)
    s2, p2 = pu.uniaxial_points(raw[:, 1], raw[:, 0], specimen)
    np.testing.assert_array_equal(s2, stretch)
    np.testing.assert_allclose(s2, 1 + raw[:, 0] / 60.0, rtol=1e-15)
    np.testing.assert_allclose(p2, raw[:, 1] / (10.0 * 0.2), rtol=1e-15)


@pytest.mark.parametrize("law,material", [
    ("gent", pu.Material.gent(shear_modulus_mpa=0.05, j_lim=60.0)),
    ("neo-hookean", pu.Material.neo_hookean(shear_modulus_mpa=0.3)),
    (pu.FitLaw.MooneyRivlin, pu.Material.mooney_rivlin(shear_modulus_mpa=0.1, alpha=0.2)),
])
def test_synthetic_uniaxial_data_recovered(law, material):
    stretch = np.linspace(1.0, 7.0, 40)
    stress = material.uniaxial_stress_mpa(stretch)  # the law itself, not the fit
    fit = pu.fit_uniaxial(stretch, stress, law)
    # Exact data: the least-squares minimum is the generating material, found to the
    # optimiser's tolerance (~1e-10 relative); 1e-7 leaves a margin.
    assert fit.parameter("G").value == pytest.approx(material.shear_modulus_mpa, rel=1e-7)
    if isinstance(material.law, pu.Gent):
        assert fit.parameter("J_lim").value == pytest.approx(material.law.j_lim, rel=1e-7)
    if isinstance(material.law, pu.MooneyRivlin):
        assert fit.parameter("alpha").value == pytest.approx(material.law.alpha, rel=1e-7)
    assert fit.rms_residual_mpa < 1e-9 * stress.max()


def test_noisy_uniaxial_data_within_standard_errors():
    material = pu.Material.gent(shear_modulus_mpa=0.06, j_lim=70.0)
    stretch = np.linspace(1.0, 7.0, 60)
    rng = np.random.default_rng(20180102)  # fixed seed: the test is deterministic
    stress = material.uniaxial_stress_mpa(stretch) + rng.normal(0.0, 0.002, stretch.size)
    fit = pu.fit_uniaxial(stretch, stress)
    for name, true in [("G", 0.06), ("J_lim", 70.0)]:
        p = fit.parameter(name)
        assert p.identifiable
        # Four standard errors: a 1-in-15000 event for a correct standard error.
        assert abs(p.value - true) < 4 * p.standard_error, (name, p.value, p.standard_error)
    assert fit.residual_sd_mpa == pytest.approx(0.002, rel=0.25)  # 60 points: sd of sd ~ 9 %


def test_uniaxial_errors_match_cli(cli):
    for name in ["uniaxial_bad.csv", "uniaxial_wrong_columns.csv"]:
        rc, message = cli_error(cli, "fit", "uniaxial", str(DATA / name))
        assert rc == 1
        with pytest.raises(ValueError) as info:
            pu.uniaxial_points_from_csv(str(DATA / name))
        assert str(info.value) == message
    rc, message = cli_error(cli, "fit", "uniaxial", str(DATA / "uniaxial_gent.csv"),
                            "--specimen-width", "10", "--specimen-thickness", "0.2",
                            "--gauge-length", "60")
    with pytest.raises(ValueError) as info:
        pu.uniaxial_points_from_csv(str(DATA / "uniaxial_gent.csv"),
                                    pu.SpecimenGeometry(10, 0.2, 60))
    assert str(info.value) == message
    with pytest.raises(ValueError, match="need as many values"):
        pu.fit_uniaxial([1.0, 1.1], [0.0])
    with pytest.raises(ValueError, match="law: expected"):
        pu.fit_uniaxial([1.0, 1.1, 1.2], [0.0, 0.1, 0.2], "rubber")
    with pytest.raises(ValueError):
        pu.fit_uniaxial([1.0, 1.1], [0.0, 0.01], "gent")  # fewer points than 2 parameters + 1


# ----- every law, the comparison by AIC, the presets ------------------------------------------

TRELOAR = Path(__file__).resolve().parents[2] / "tests" / "data" / "treloar_1944_uniaxial.csv"


@pytest.mark.parametrize("law,material,values", [
    ("yeoh", pu.Material.yeoh(c10_mpa=0.03, c20_mpa=0.002, c30_mpa=1e-4), [0.03, 0.002, 1e-4]),
    ("arruda-boyce", pu.Material(shear_modulus_mpa=0.06, law=pu.ArrudaBoyce(8.0)), [0.06, 8.0]),
    ("gent-gent", pu.Material(shear_modulus_mpa=0.06, law=pu.GentGent(40.0, 0.1)),
     [0.06, 40.0, 0.1]),
    (pu.FitLaw.Ogden, pu.Material.ogden(mu_mpa=[0.05, -0.01], alpha=[2.5, -1.5]),
     [0.05, -0.01, 2.5, -1.5]),
])
@pytest.mark.parametrize("test", ["uniaxial", "equibiaxial"])
def test_every_law_recovered_in_both_tests(law, material, values, test):
    stretch = np.linspace(1.1, 4.0 if test == "uniaxial" else 2.2, 30)
    stress = (material.uniaxial_stress_mpa(stretch) if test == "uniaxial"
              else material.equibiaxial_stress_mpa(stretch))
    fit = pu.fit_uniaxial(stretch, stress, law, test=test, ogden_alpha=[3.0, -2.0])
    assert fit.test.token == test
    # Exact data: the generating parameters, to the optimiser's tolerance (1e-8 in C++).
    assert [p.value for p in fit.parameters] == pytest.approx(values, rel=1e-7)
    assert len(fit.correlation) == len(values)


def test_ogden_terms_and_bad_exponents():
    stretch = np.linspace(1.1, 3.0, 20)
    stress = pu.Material.neo_hookean(shear_modulus_mpa=0.1).uniaxial_stress_mpa(stretch)
    one = pu.fit_uniaxial(stretch, stress, "ogden", ogden_terms=1)
    assert [p.name for p in one.parameters] == ["mu_1", "alpha_1"]
    assert one.parameter("alpha_1").value == pytest.approx(2.0, rel=1e-7)  # neo-Hookean
    with pytest.raises(ValueError, match="ogden_alpha_start"):
        pu.fit_uniaxial(stretch, stress, "ogden", ogden_alpha=[0.5])
    with pytest.raises(ValueError, match="test: expected"):
        pu.fit_uniaxial(stretch, stress, "gent", test="biaxial")


def test_information_criteria_by_hand():
    c = pu.information_criteria(10, 2, 0.5)
    n_log = 10 * math.log(0.05)
    assert c.parameters == 3
    assert c.aic == pytest.approx(n_log + 6, rel=1e-14)
    assert c.aicc == pytest.approx(n_log + 6 + 4, rel=1e-14)
    assert c.bic == pytest.approx(n_log + 3 * math.log(10), rel=1e-14)
    with pytest.raises(ValueError):
        pu.information_criteria(10, 2, 0.0)


def test_treloar_compare_matches_cli(cli):
    stretch, stress = pu.uniaxial_points_from_csv(str(TRELOAR))
    ranked = pu.compare_uniaxial_fits(stretch, stress, ["neo-hookean", "ogden", "yeoh"])
    assert ranked[0].law == pu.FitLaw.Ogden
    assert ranked[-1].law == pu.FitLaw.NeoHookean
    aics = [f.information.aic for f in ranked]
    assert aics == sorted(aics)
    rc, out, err = cli.run("fit", "uniaxial", str(TRELOAR), "--compare",
                           "neo-hookean,ogden,yeoh", "--format", "json")
    assert rc == 0, err
    import json
    data = json.loads(out)
    for fit, row in zip(ranked, data["ranking"]):
        assert row["law"] == fit.law.token
        assert same(row["aic"], fit.information.aic)
    for fit, full in zip(ranked, data["fits"]):
        for p, q in zip(fit.parameters, full["parameters"]):
            assert same(p.value, q["value"]) and same(p.standard_error, q["standard_error"])


def test_presets():
    names = [p.name for p in pu.material_presets()]
    assert names == ["liu2018-silicone", "ogden-1972-treloar"]
    ogden = pu.material_preset("ogden-1972-treloar")
    assert "doi:10.1098/rspa.1972.0026" in ogden.source
    stretch = np.array([1.5, 3.0, 6.0])
    mu = np.array([6.3, 0.012, -0.1]) * 0.0980665  # kgf/cm^2 -> MPa
    alpha = np.array([1.3, 5.0, -2.0])
    by_hand = sum(m * (stretch ** (a - 1) - stretch ** (-a / 2 - 1)) for m, a in zip(mu, alpha))
    assert ogden.material.uniaxial_stress_mpa(stretch) == pytest.approx(by_hand, rel=1e-13)
    silicone = pu.material_preset("liu2018-silicone").material
    assert silicone.shear_modulus_mpa == 0.06 and silicone.j_lim == 125.0
    with pytest.raises(ValueError, match="preset: unknown material preset 'rubber'"):
        pu.material_preset("rubber")


# ----- the puncture band --------------------------------------------------------------------

def test_band_matches_cli(cli):
    band = pu.puncture_band(pu.Problem(), critical_i1=pu.plus_minus(95.2, 4.8),
                            friction=pu.plus_minus(0.18, 0.05), j_lim=(115.0, 135.0),
                            shear_modulus_mpa=pu.ParameterRange(0.05975, 0.06025))
    c = cli.json("calibrate", "band", "--critical-i1-sd", "4.8", "--friction-sd", "0.05",
                 "--jlim-range", "115,135", "--shear-modulus-range", "0.05975,0.06025")
    assert same(band.nominal.force_n, c["nominal"]["force_n"])
    for key in ["force_min_n", "force_max_n", "depth_min_mm", "depth_max_mm",
                "force_half_range_rss_n", "force_min_corner", "force_max_corner"]:
        assert same(getattr(band, key), c["band"][key]), key
    assert band.dominant.token == c["band"]["dominant"]
    assert band.ok and c["band"]["complete"]
    assert [x.force_n for x in band.corners] == [x["force_n"] for x in c["corners"]]
    for ours, theirs in zip(band.sensitivities, c["sensitivities"]):
        assert ours.parameter.token == theirs["parameter"]
        assert same(ours.force_change_n, theirs["force_change_n"])
        assert ours.force_direction == theirs["force_direction"] == \
            pu.documented_force_direction(ours.parameter)
        assert [s.depth_mm for s in ours.samples] == [s["depth_mm"] for s in theirs["samples"]]


def test_band_against_independent_predictions():
    # The band's ends are the predictions at the corners the documented directions give.
    problem = pu.Problem()
    band = pu.puncture_band(problem, critical_i1=pu.plus_minus(95.2, 4.8),
                            friction=pu.plus_minus(0.18, 0.05))
    low = pu.predict_puncture(pu.Problem(critical_i1=95.2 - 4.8, friction=0.18 - 0.05))
    high = pu.predict_puncture(pu.Problem(critical_i1=95.2 + 4.8, friction=0.18 + 0.05))
    assert band.force_min_n == low.force_n and band.force_max_n == high.force_n
    assert band.force_min_n < band.nominal.force_n < band.force_max_n
    assert band.dominant == pu.BandParameter.CriticalI1
    collapsed = pu.puncture_band(problem, friction=(0.18, 0.18))
    assert collapsed.force_min_n == collapsed.force_max_n == collapsed.nominal.force_n


def test_band_errors_match_cli(cli):
    for flags, kwargs in [(["--friction-sd", "0.3"], dict(friction=pu.plus_minus(0.18, 0.3))),
                          (["--friction-range", "0.2,0.3"], dict(friction=(0.2, 0.3))),
                          (["--critical-i1-range", "95,120", "--jlim-range", "110,130"],
                           dict(critical_i1=(95.0, 120.0), j_lim=(110.0, 130.0)))]:
        rc, message = cli_error(cli, "calibrate", "band", *flags)
        assert rc == 1
        with pytest.raises(ValueError) as info:
            pu.puncture_band(pu.Problem(), **kwargs)
        assert str(info.value) == message
    with pytest.raises(ValueError, match="^J_lim range: J_lim is a parameter of the Gent law"):
        pu.puncture_band(pu.Problem(material=pu.Material.neo_hookean()), j_lim=(100, 150))
    with pytest.raises(ValueError, match="^friction: expected a ParameterRange or"):
        pu.puncture_band(pu.Problem(), friction="wide")
    with pytest.raises(ValueError, match="^invalid input:\n  friction: "):
        pu.puncture_band(pu.Problem(friction=-1), critical_i1=(90, 100))


def test_uniaxial_fit_takes_the_loaders_pair_as_it_comes():
    points = pu.uniaxial_points_from_csv(str(DATA / "uniaxial_gent.csv"))
    whole = pu.fit_uniaxial(points, law="gent")
    unpacked = pu.fit_uniaxial(*points, law="gent")
    assert [p.value for p in whole.parameters] == [p.value for p in unpacked.parameters]
    assert list(whole.fitted_stress_mpa) == list(unpacked.fitted_stress_mpa)


def test_no_function_documents_its_result_as_a_bare_object():
    # pybind11 writes "-> object" for a py::object result: give it a real type instead.
    bare = [name for name in dir(pu) if callable(getattr(pu, name)) and
            "-> object" in (getattr(pu, name).__doc__ or "")]
    assert bare == []


def test_uniaxial_fit_on_a_bound_matches_cli(cli):
    # Stiffening Gent data fitted with Mooney-Rivlin: the best fit in 0 <= alpha <= 1 is on
    # alpha = 0, a physical failure with the CLI's message (which ran away unbounded before).
    rc, message = cli_error(cli, "fit", "uniaxial", str(DATA / "uniaxial_gent.csv"),
                            "--material", "mooney-rivlin")
    assert rc == 2
    points = pu.uniaxial_points_from_csv(str(DATA / "uniaxial_gent.csv"))
    with pytest.raises(pu.SolverError) as info:
        pu.fit_uniaxial(points[0], points[1], "mooney-rivlin")
    assert str(info.value) == message
    assert info.value.status == pu.Status.OnBound
    assert info.value.failure_kind == pu.FailureKind.Physical
    assert "alpha = 0" in message


# ----- fit_curves: force-depth records (`puncture fit curve`) ------------------------------------

def test_fit_curves_recovers_an_exact_curve():
    """The model's own curve, started 33 % and 28 % off, gives back G and J_lim (to the
    optimiser's stop, 1e-6), with numpy arrays of the points and the model."""
    truth = pu.Problem()
    curve = pu.loading_curve(truth, points=41, max_depth_mm=30.0)
    start = pu.Problem(material=pu.Material(shear_modulus_mpa=0.08, law=pu.Gent(j_lim=160.0)))
    test = pu.CurveTest(start, curve.depth_mm[1:], curve.force_n[1:], name="exact")
    fit = pu.fit_curves([test], ["shear-modulus", "jlim"])
    assert fit.ok
    assert fit.parameter("shear-modulus").value == pytest.approx(0.06, rel=1e-6)
    assert fit.parameter("jlim").value == pytest.approx(125.0, rel=1e-6)
    assert fit.correlation.shape == (2, 2)
    t = fit.tests[0]
    assert isinstance(t.model_force_n, np.ndarray) and t.model_force_n.shape == (40,)
    assert np.allclose(t.model_force_n - t.force_n, t.residual_n, rtol=0, atol=1e-15)


def test_fit_curves_from_a_record_as_the_cli(cli):
    """read_force_depth_record + fit_curves give the CLI's numbers for the same record."""
    record = pu.read_force_depth_record(str(DATA / "indentation_record.csv"), contact_depth=2.0)
    assert record["puncture"] is not None and not record["contact_found"]
    test = pu.CurveTest(pu.Problem(), record["depth_mm"], record["force_n"],
                        puncture=record["puncture"])
    fit = pu.fit_curves([test], ["shear-modulus", "jlim"])
    rc, out, err = cli.run("fit", "curve", DATA / "indentation_record.csv", "--free",
                           "shear-modulus,jlim", "--contact-depth", "2", "--format", "json")
    assert rc == 0, err
    import json
    free = json.loads(out)["fit"]["free"]
    for p, q in zip(fit.parameters, free):
        assert same(p.value, q["value"]) and same(p.standard_error, q["standard_error"])


def test_fit_curves_errors():
    test = pu.CurveTest(pu.Problem(), [1.0, 2.0, 3.0], [0.1, 0.2, 0.3])
    with pytest.raises(ValueError, match="unknown parameter 'modulus'"):
        pu.fit_curves([test], ["modulus"])
    with pytest.raises(ValueError, match="no test has a puncture point"):
        pu.fit_curves([test], ["critical-i1"])
    with pytest.raises(ValueError, match="bad_cell.csv:4: column 2"):
        pu.read_force_depth_record(str(DATA / "indentation_bad_cell.csv"), contact_depth=0.0)


def test_fit_curves_contact_offset_and_stick_threshold(cli):
    """Each test's contact offset (model depth = depth - offset) and the stick threshold's
    profile give the CLI's numbers, with the offset's test and the threshold's profile interval
    named."""
    record = pu.read_force_depth_record(str(DATA / "indentation_record.csv"))
    assert record["contact_found"]
    test = pu.CurveTest(pu.Problem(), record["depth_mm"], record["force_n"],
                        puncture=record["puncture"], name="found")
    fit = pu.fit_curves([test], ["shear-modulus", "jlim", "contact-offset"])
    rc, out, err = cli.run("fit", "curve", DATA / "indentation_record.csv", "--free",
                           "shear-modulus,jlim,contact-offset", "--format", "json")
    assert rc == 0, err
    import json
    free = json.loads(out)["fit"]["free"]
    offset = fit.parameter("contact-offset")
    assert offset.test == "found" and free[2]["test"].endswith("indentation_record.csv")
    assert same(offset.value, free[2]["value"])
    assert not offset.profile_interval and free[2]["interval"] == "t"
    # Found 3.17 mm late (the contact is at 2 mm): the offset's interval holds -3.17 mm.
    late = record["contact_depth_mm"] - 2.0
    assert offset.ci_lower <= -late <= offset.ci_upper

    stick = pu.read_force_depth_record(str(DATA / "indentation_record_stick.csv"),
                                       contact_depth=2.0)
    held = pu.Problem(stick=pu.StickCriterion(pu.StickRule.Force, 0.25))
    fit = pu.fit_curves([pu.CurveTest(held, stick["depth_mm"], stick["force_n"])],
                        ["shear-modulus", "stick-threshold"])
    tau = fit.parameter("stick-threshold")
    assert fit.ok and tau.profile_interval and tau.standard_error is None
    assert tau.ci_lower <= 0.3 <= tau.ci_upper
