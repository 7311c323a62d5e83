"""The bindings give the C++ results: the same numbers as the CLI, consistent arrays."""

import copy
import math
import threading

import numpy as np
import pytest

import puncture as pu

CURVE_COLUMNS = ["depth_mm", "force_n", "normalized_force", "stage", "configuration",
                 "part_three_stretch", "part_two_length_mm", "corner_slope_rad", "max_i1",
                 "beyond_puncture"]
FIELD_COLUMNS = ["part", "R_mm", "r_mm", "z_mm", "slope_rad", "lambda1", "lambda2", "lambda3",
                 "s1_mpa", "s2_mpa", "I1", "contact_pressure_mpa", "friction_traction_mpa"]


def rel(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def test_default_puncture_force_matches_cli(cli):
    prediction = pu.predict_puncture(pu.Problem())
    from_cli = cli.json("puncture")["puncture"]
    assert prediction.ok
    assert rel(prediction.force_n, from_cli["force_n"]) < 1e-6
    assert rel(prediction.depth_mm, from_cli["depth_mm"]) < 1e-6
    assert rel(prediction.part_three_stretch, from_cli["part_three_stretch"]) < 1e-6
    assert prediction.crack_location == from_cli["crack_location"]
    assert prediction.configuration.token == from_cli["configuration"]
    assert round(prediction.force_n, 4) == 0.6994  # README, docs/model.md


def test_energy_to_puncture_matches_cli(cli):
    plain = pu.predict_puncture(pu.Problem())
    assert plain.energy_to_puncture_mj is None  # off unless asked: it costs a curve's solves
    options = pu.SolverOptions()
    options.energy_to_puncture = True
    prediction = pu.predict_puncture(pu.Problem(), options)
    from_cli = cli.json("puncture")["puncture"]
    assert rel(prediction.energy_to_puncture_mj, from_cli["energy_to_puncture_mj"]) < 1e-9
    assert prediction.force_n == plain.force_n
    # The curve's puncture carries the same number.
    curve = pu.loading_curve(pu.Problem(), points=20, options=options)
    assert rel(curve.puncture.energy_to_puncture_mj, prediction.energy_to_puncture_mj) < 1e-9


def test_paper_eq18_puncture_matches_cli(cli):
    problem = pu.Problem(part_two_equation="paper-eq18")
    from_cli = cli.json("puncture", "--part-two-equation", "paper-eq18")["puncture"]
    prediction = pu.predict_puncture(problem)
    assert rel(prediction.force_n, from_cli["force_n"]) < 1e-6
    assert round(prediction.force_n, 4) == 3.3409  # docs/model.md section 10


def test_loading_curve_matches_cli(cli):
    problem = pu.Problem(stick="force:0.3")
    curve = pu.loading_curve(problem, points=20)
    from_cli = cli.json("curve", "--points", "20", "--stick", "force:0.3")
    rows = from_cli["curve"]["points"]
    columns = curve.columns()
    assert list(columns) == CURVE_COLUMNS == list(rows[0])
    assert len(curve) == len(rows) > 20  # the depths, and both states at the switch
    for name in CURVE_COLUMNS:
        for ours, theirs in zip(columns[name], (r[name] for r in rows)):
            if isinstance(theirs, str):
                assert ours == theirs, name
            else:
                assert ours == pytest.approx(theirs, rel=1e-9, abs=1e-12), name
    s = from_cli["curve"]["stick_slip"]
    assert curve.stick_slip.occurs and s["occurs"]
    assert curve.stick_slip.depth_mm == pytest.approx(s["depth_mm"], rel=1e-9)
    assert curve.stick_slip.force_sliding_n == pytest.approx(s["force_sliding_n"], rel=1e-9)
    assert curve.part_two_onset_at_switch == from_cli["curve"]["part_two_onset"][
        "at_stick_slip_switch"]
    assert curve.puncture.force_n == pytest.approx(from_cli["puncture"]["force_n"], rel=1e-9)


def test_state_fields_match_cli(cli):
    state = pu.solve_at_force(pu.Problem(), 0.3)
    from_cli = cli.json("state", "--force", "0.3")
    rows = from_cli["state"]["fields"]
    columns = state.fields.columns()
    assert list(columns) == FIELD_COLUMNS == list(rows[0])
    assert len(state.fields) == len(rows)
    for name in FIELD_COLUMNS:
        np.testing.assert_allclose(columns[name], [r[name] for r in rows], rtol=1e-9,
                                   atol=1e-12, err_msg=name)
    assert state.depth_mm == pytest.approx(from_cli["state"]["depth_mm"], rel=1e-9)
    assert state.stage.token == from_cli["request"]["stage"] == "slip"


def test_state_at_depth_matches_cli(cli):
    state = pu.solve_at_depth(pu.Problem(friction=1.95), 20.0)
    from_cli = cli.json("state", "--depth", "20", "--friction", "1.95")["state"]
    assert state.force_n == pytest.approx(from_cli["force_n"], rel=1e-9)
    assert state.configuration.token == from_cli["configuration"]


def test_filleted_flat_punch_matches_cli(cli):
    punch = pu.FlatPunch(radius_mm=2.0, fillet_radius_mm=0.5)
    assert punch.fillet_radius_mm == 0.5 and pu.FlatPunch().fillet_radius_mm == 0.0
    assert repr(punch) == "FlatPunch(radius_mm=2, fillet_radius_mm=0.5)"
    state = pu.solve_at_depth(pu.Problem(indenter=punch, friction=0.0), 20.0)
    from_cli = cli.json("state", "--depth", "20", "--friction", "0", "--fillet-radius", "0.5")
    assert state.force_n == pytest.approx(from_cli["state"]["force_n"], rel=1e-9)
    assert from_cli["inputs"]["fillet_radius_mm"] == 0.5


@pytest.mark.parametrize("load,expected", [(0.2, pu.Stage.Stick), (0.5, pu.Stage.Slip)])
def test_automatic_stage_follows_the_stick_criterion(cli, load, expected):
    problem = pu.Problem(stick=pu.StickCriterion.force(0.3))
    state = pu.solve_at_force(problem, load)  # stage="auto"
    assert state.stage == expected
    assert cli.json("state", "--force", load, "--stick", "force:0.3")["request"]["stage"] == \
        expected.token


def test_fields_are_consistent_finite_arrays():
    state = pu.solve_at_force(pu.Problem(), 0.5)
    f = state.fields
    n = len(f)
    assert n > 200
    names = ["reference_radius_mm", "radius_mm", "deflection_mm", "slope_rad", "radial_stretch",
             "hoop_stretch", "thickness_stretch", "radial_stress_mpa", "hoop_stress_mpa",
             "first_invariant", "contact_pressure_mpa", "friction_traction_mpa"]
    for name in names:
        a = getattr(f, name)
        assert isinstance(a, np.ndarray) and a.dtype == np.float64 and a.shape == (n,), name
        assert np.all(np.isfinite(a)), name
        assert not a.flags.writeable, name
    assert f.part.shape == (n,) and set(f.part.tolist()) == {1, 2, 3}
    assert np.all(np.diff(f.reference_radius_mm) >= 0)
    assert f.reference_radius_mm[0] == 0 and f.reference_radius_mm[-1] == pytest.approx(25.0)
    assert np.all(np.diff(f.part) <= 0)  # III, then II, then I
    np.testing.assert_allclose(f.thickness_stretch, 1 / (f.radial_stretch * f.hoop_stretch),
                               rtol=1e-12)
    np.testing.assert_allclose(f.first_invariant,
                               pu.first_invariant(f.radial_stretch, f.hoop_stretch), rtol=1e-12)
    assert f.first_invariant.max() == pytest.approx(state.max_first_invariant, rel=1e-9)


def test_arrays_outlive_their_result():
    radius = pu.solve_at_force(pu.Problem(), 0.4).fields.radius_mm
    import gc

    gc.collect()
    assert np.all(np.isfinite(radius)) and radius[-1] == pytest.approx(25.0)


def test_curve_columns_are_consistent():
    curve = pu.loading_curve(pu.Problem(), points=30)
    assert curve.ok and len(curve) == 30 and len(curve.points) == 30
    for name in ["depth_mm", "force_n", "normalized_force", "part_three_stretch",
                 "part_two_length_mm", "corner_slope_rad", "max_first_invariant"]:
        a = getattr(curve, name)
        assert a.shape == (30,) and np.all(np.isfinite(a)), name
    assert len(curve.stage) == len(curve.configuration) == 30
    assert np.all(np.diff(curve.depth_mm) > 0)
    np.testing.assert_allclose(curve.normalized_force * curve.problem.force_scale_n,
                               curve.force_n, rtol=1e-12)
    assert curve.depth_mm[-1] == pytest.approx(curve.puncture.depth_mm, rel=1e-12)
    assert curve.max_first_invariant[-1] == pytest.approx(95.2, rel=1e-6)
    assert curve.part_two_onset_depth_mm == pytest.approx(15.469, abs=1e-3)


def test_progress_callback_and_threads():
    calls = []
    curve = pu.loading_curve(pu.Problem(), points=12, progress=lambda d, t: calls.append((d, t)))
    assert calls[-1] == (12, 12) and len(calls) >= 11
    # The solver runs without the GIL: threads give the same results.
    results = {}

    def run(mu):
        results[mu] = pu.predict_puncture(pu.Problem(friction=mu)).force_n

    threads = [threading.Thread(target=run, args=(mu,)) for mu in (0.18, 1.95)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results[0.18] == pytest.approx(curve.puncture.force_n, rel=1e-12)
    assert results[1.95] == pytest.approx(pu.predict_puncture(pu.Problem(friction=1.95)).force_n,
                                          rel=1e-12)


def test_results_carry_their_problem():
    problem = pu.Problem(indenter=pu.FlatPunch(radius_mm=1.0))
    curve = pu.loading_curve(problem, points=5)
    problem.friction = 0.5  # the result keeps its own copy
    assert curve.problem.friction == 0.18
    assert curve.problem.indenter.radius_mm == 1.0
    assert curve.puncture.problem.indenter.radius_mm == 1.0
    assert curve.puncture.state.problem.indenter.radius_mm == 1.0


def test_problem_defaults_match_cli(cli):
    inputs = cli.json("puncture")["inputs"]
    p = pu.Problem()
    assert p.geometry.clamp_radius_mm == inputs["clamp_radius_mm"]
    assert p.indenter.radius_mm == inputs["indenter_radius_mm"]
    assert p.geometry.thickness_mm == inputs["thickness_mm"]
    assert p.material.shear_modulus_mpa == inputs["material"]["shear_modulus_mpa"]
    assert p.material.law_name == inputs["material"]["law"]
    assert p.material.j_lim == inputs["material"]["j_lim"]
    assert p.friction == inputs["friction"] and p.critical_i1 == inputs["critical_i1"]
    assert p.stick.rule.token == inputs["stick"]["rule"]
    assert p.part_two_equation.token == inputs["part_two_equation"]
    assert p.force_scale_n == pytest.approx(inputs["force_scale_n"], rel=1e-15)


def test_problem_editing_and_copies():
    p = pu.Problem()
    p.indenter = pu.FlatPunch(radius_mm=1.0)
    p.geometry.thickness_mm = 0.3
    p.material = pu.Material.mooney_rivlin(shear_modulus_mpa=0.1, alpha=0.2)
    p.stick = "depth:3"
    p.stick.threshold = 4.0
    p.part_two_equation = pu.PartTwoEquation.PaperEq18
    assert p.indenter.radius_mm == 1.0 and p.geometry.thickness_mm == 0.3
    assert p.material.law_name == "mooney-rivlin" and p.material.alpha == 0.2
    assert p.material.j_lim is None and isinstance(p.material.law, pu.MooneyRivlin)
    assert p.stick.rule == pu.StickRule.Depth and p.stick.threshold == 4.0
    assert p.part_two_equation.token == "paper-eq18"
    q = copy.deepcopy(p)
    q.geometry.thickness_mm = 0.5
    q.indenter = pu.FlatPunch(3.0)
    assert p.geometry.thickness_mm == 0.3 and p.indenter.radius_mm == 1.0
    assert "mooney-rivlin" in p.material.description
    assert repr(pu.Problem()).startswith("Problem(geometry=Geometry(clamp_radius_mm=25")
    assert pu.StickCriterion("edge-tension:0.02").rule == pu.StickRule.EdgeTension
    assert pu.Problem(stick="always").stick.rule == pu.StickRule.Always
    assert pu.Problem(material=pu.Material(law=pu.NeoHookean())).material.locking_first_invariant \
        == math.inf


def test_material_stresses():
    stretch = np.linspace(1.0, 8.0, 15)
    neo = pu.Material.neo_hookean(shear_modulus_mpa=0.06)
    np.testing.assert_allclose(neo.uniaxial_stress_mpa(stretch), 0.06 * (stretch - stretch**-2),
                               rtol=1e-12)
    np.testing.assert_allclose(neo.equibiaxial_stress_mpa(stretch),
                               0.06 * (stretch - stretch**-5), rtol=1e-12)
    gent = pu.Material.gent()
    assert gent.locking_first_invariant == 128.0
    # Gent stiffens: above neo-Hookean, equal at small strain
    assert np.all(gent.uniaxial_stress_mpa(stretch[1:]) > neo.uniaxial_stress_mpa(stretch[1:]))
    assert gent.uniaxial_stress_mpa(1.001) == pytest.approx(neo.uniaxial_stress_mpa(1.001),
                                                            rel=1e-3)
    s1 = gent.radial_stress_mpa(3.0, 2.0)
    s2 = gent.hoop_stress_mpa(2.0, 3.0)
    assert s1 == pytest.approx(s2, rel=1e-14)  # symmetry of the law


def test_stick_slip_boundary():
    b = pu.stick_slip_boundary(pu.Problem(stick="force:0.3"))
    assert b.switches and b.first_stage == pu.Stage.Stick
    assert b.force_stuck_n == pytest.approx(0.3, rel=1e-9)
    assert b.depth_mm == pytest.approx(16.7776, abs=1e-3)
    none = pu.stick_slip_boundary(pu.Problem())
    assert not none.switches and none.first_stage == pu.Stage.Slip


def test_solver_options_are_used():
    options = pu.SolverOptions()
    options.record_fields = False
    state = pu.solve_at_force(pu.Problem(), 0.3, options=options)
    assert len(state.fields) == 0 and state.ok


def test_every_result_has_ok_as_a_property():
    # `if result.ok:` must test the outcome: a bound method would always be true.
    problem = pu.Problem()
    state = pu.solve_at_force(problem, 0.3)
    curve = pu.loading_curve(problem, points=5)
    for result in (state, curve, curve.puncture, pu.inflate_at_pole_stretch(problem, 2.0)):
        assert result.ok is True
    assert type(pu.Equilibrium.ok) is property and type(pu.PuncturePrediction.ok) is property


def test_reprs_are_the_library_reports():
    problem = pu.Problem()
    state = pu.solve_at_force(problem, 0.3)
    assert repr(state).startswith("<Equilibrium converged: slip stage, ")
    assert f"force 0.3 N" in repr(state)
    curve = pu.loading_curve(problem, points=5)
    assert repr(curve).startswith("<LoadingCurve converged: 5 points, depth 0 to ")
    assert curve.puncture.crack_location in repr(curve.puncture)


def test_every_result_is_an_outcome_with_reports():
    problem = pu.Problem()
    state = pu.solve_at_force(problem, 0.3, stage="slip")
    assert isinstance(state, pu.Outcome) and state.ok
    assert state.status == pu.Status.Converged
    assert "  clamp radius A          25 mm\n" in pu.full_report(problem)
    assert f"depth                   {state.depth_mm:.5g} mm" in pu.full_report(state, problem)
    prediction = pu.predict_puncture(problem)
    assert isinstance(prediction, pu.Outcome) and prediction.ok
    assert prediction.crack_location in pu.full_report(prediction)


def test_sphere_tipped_probe_matches_cli(cli):
    problem = pu.Problem(indenter=pu.SphereTipped(radius_mm=2.0), friction=0.0)
    assert repr(problem.indenter) == "SphereTipped(radius_mm=2)"
    prediction = pu.predict_puncture(problem)
    ours = cli.json("puncture", "--indenter", "sphere-tipped", "--friction", "0")
    assert ours["inputs"]["indenter"] == "sphere-tipped"
    assert prediction.force_n == pytest.approx(ours["puncture"]["force_n"], rel=1e-12)
    assert prediction.depth_mm == pytest.approx(ours["puncture"]["depth_mm"], rel=1e-12)
    assert prediction.crack_location == "the pole, under the tip of the sphere"
    state = pu.solve_at_depth(problem, 10.0)
    tip = state.fields.part == 3
    assert tip.any() and (state.fields.contact_pressure_mpa[tip] > 0).all()


def test_cone_and_ball_probes_match_cli(cli):
    cone = pu.Cone(radius_mm=2.0, half_angle_deg=30.0, tip_radius_mm=0.2)
    assert repr(cone) == "Cone(radius_mm=2, half_angle_deg=30, tip_radius_mm=0.2)"
    prediction = pu.predict_puncture(pu.Problem(indenter=cone, friction=0.0))
    ours = cli.json("puncture", "--indenter", "cone", "--cone-half-angle", "30",
                    "--tip-radius", "0.2", "--friction", "0")
    assert ours["inputs"]["indenter"] == "cone"
    assert prediction.force_n == pytest.approx(ours["puncture"]["force_n"], rel=1e-12)
    ball = pu.Ball(radius_mm=1.0, ball_radius_mm=3.0)
    assert repr(ball) == "Ball(radius_mm=1, ball_radius_mm=3)"
    state = pu.solve_at_depth(pu.Problem(indenter=ball, friction=0.0), 5.0)
    sphere = pu.solve_at_depth(pu.Problem(indenter=pu.SphereTipped(3.0), friction=0.0), 5.0)
    assert state.force_n == pytest.approx(sphere.force_n, rel=1e-9)


def test_yeoh_law_from_its_coefficients_matches_cli(cli):
    m = pu.Material.yeoh(c10_mpa=0.03, c20_mpa=0.0015, c30_mpa=0.00003)
    assert m.shear_modulus_mpa == 0.06 and isinstance(m.law, pu.Yeoh)
    assert m.law.c2 == pytest.approx(0.025) and m.law.c3 == pytest.approx(0.0005)
    assert m.law_name == "yeoh"
    prediction = pu.predict_puncture(pu.Problem(material=m))
    from_cli = cli.json("puncture", "--material", "yeoh", "--yeoh", "0.03,0.0015,0.00003")
    assert rel(prediction.force_n, from_cli["puncture"]["force_n"]) < 1e-12
    # Yeoh without its higher terms is neo-Hookean to the bit
    plain = pu.Problem(material=pu.Material(0.06, pu.Yeoh()))
    neo = pu.Problem(material=pu.Material.neo_hookean())
    assert pu.predict_puncture(plain).force_n == pu.predict_puncture(neo).force_n
    with pytest.raises(ValueError, match="c10_mpa"):
        pu.Material.yeoh(c10_mpa=0)


def test_prestretched_membrane_matches_cli_and_its_linear_limit(cli):
    problem = pu.Problem(preload=pu.Preload(prestretch=1.2))
    assert repr(problem.preload) == "Preload(prestretch=1.2)"
    assert problem.reference_clamp_radius_mm == pytest.approx(25.0 / 1.2, rel=1e-15)
    prediction = pu.predict_puncture(problem)
    ours = cli.json("puncture", "--prestretch", "1.2")
    assert ours["inputs"]["prestretch"] == 1.2
    assert prediction.force_n == pytest.approx(ours["puncture"]["force_n"], rel=1e-12)
    # Small deflection: F / delta -> 2 pi T0 / ln(A / a), T0 = G H s_eq(L0) / L0 (docs/model.md
    # section 16); at 0.05 mm the next order is ~1e-5 of the force.
    h = 0.2
    stress_mpa = float(problem.material.equibiaxial_stress_mpa(1.2))
    stiffness = 2 * np.pi * h * stress_mpa / 1.2 / np.log(25.0 / 2.0)
    frictionless = pu.Problem(preload=pu.Preload(prestretch=1.2), friction=0.0)
    state = pu.solve_at_depth(frictionless, 0.05)
    assert state.force_n / 0.05 == pytest.approx(stiffness, rel=1e-4)
    with pytest.raises(ValueError, match="pre-stretch must be a finite number >= 1"):
        pu.predict_puncture(pu.Problem(preload=pu.Preload(prestretch=0.9)))


def test_pressurised_membrane_matches_cli_and_starts_from_the_inflated_dome(cli):
    problem = pu.Problem(indenter=pu.SphereTipped(2.0), friction=0.0,
                         preload=pu.Preload(pressure_mpa=3e-4))
    assert repr(problem.preload) == "Preload(prestretch=1, pressure_mpa=0.0003)"
    dome = pu.inflate_at_pressure(pu.InflationProblem.of(problem), 3e-4).states[0]
    start = pu.solve_at_depth(problem, 0.0)
    assert start.ok and start.part_three_stretch == pytest.approx(dome.pole_stretch, rel=1e-12)
    ours = cli.json("state", "--indenter", "sphere-tipped", "--friction", "0", "--pressure",
                    "3e-4", "--depth", "5")
    assert ours["inputs"]["pressure_mpa"] == 3e-4
    assert pu.solve_at_depth(problem, 5.0).force_n == pytest.approx(ours["state"]["force_n"],
                                                                     rel=1e-12)
    with pytest.raises(ValueError, match="pressure"):
        pu.solve_at_depth(pu.Problem(preload=pu.Preload(pressure_mpa=-1.0)), 1.0)


def test_inflated_state_is_a_keyword_validated_like_the_cli(cli):
    last = pu.Preload(pressure_mpa=3e-4, inflated_state="last")
    assert last.inflated_state == "last"
    assert repr(last) == "Preload(prestretch=1, pressure_mpa=0.0003, inflated_state='last')"
    assert pu.Preload(pressure_mpa=9e-4, inflated_state=2).inflated_state == 2
    assert pu.Preload().inflated_state == "first"
    problem = pu.Problem(indenter=pu.SphereTipped(2.0), friction=0.0, preload=last)
    dome = pu.inflate_at_pressure(pu.InflationProblem.of(problem), 3e-4).states[-1]
    start = pu.solve_at_depth(problem, 0.0)
    assert start.ok and start.part_three_stretch == pytest.approx(dome.pole_stretch, rel=1e-12)
    ours = cli.json("state", "--indenter", "sphere-tipped", "--friction", "0", "--pressure",
                    "3e-4", "--inflated-state", "last", "--depth", "5")
    assert pu.solve_at_depth(problem, 5.0).force_n == pytest.approx(ours["state"]["force_n"],
                                                                     rel=1e-12)
    with pytest.raises(ValueError, match="inflated_state"):
        pu.Preload(inflated_state="stiff")
    beyond = pu.Problem(indenter=pu.SphereTipped(2.0), friction=0.0,
                        preload=pu.Preload(pressure_mpa=9e-4, inflated_state=4))
    with pytest.raises(ValueError, match="3 inflated states"):
        pu.solve_at_depth(beyond, 1.0)


def test_finite_elements_under_pressure_start_from_their_dome():
    problem = pu.Problem(indenter=pu.SphereTipped(2.0), friction=0.0,
                         preload=pu.Preload(pressure_mpa=3e-4))
    dome = pu.fe_inflated_state(problem, elements=64)
    inflated = pu.inflate_at_pressure(pu.InflationProblem.of(problem), 3e-4).states[0]
    assert dome.ok and dome.part_three_stretch == pytest.approx(inflated.pole_stretch, rel=5e-5)
    assert dome.volume_mm3 == pytest.approx(inflated.volume_mm3, rel=1e-8)
    [fe] = pu.fe_solve_at_depths(problem, [5.0], elements=64)
    assert fe.ok and fe.force_n == pytest.approx(pu.solve_at_depth(problem, 5.0).force_n, rel=1e-6)
    with pytest.raises(ValueError, match="pressure"):
        pu.fe_inflated_state(pu.Problem())


def test_sealed_chamber_matches_cli_and_reports_its_gas(cli):
    sealed = pu.Preload(pressure_mpa=3e-4, gas_volume_mm3=2e6)
    assert repr(sealed) == ("Preload(prestretch=1, pressure_mpa=0.0003, gas_volume_mm3=2e+06, "
                            "atmospheric_pressure_mpa=0.101325)")
    problem = pu.Problem(indenter=pu.SphereTipped(2.0), friction=0.0, preload=sealed)
    state = pu.solve_at_depth(problem, 5.0)
    assert state.ok and state.gas.pressure_mpa > 3e-4
    # the gas law with the state's own volume, against the contact-free state's
    dome = pu.solve_at_depth(problem, 0.0).gas
    assert dome.pressure_mpa == 3e-4
    content = (3e-4 + 0.101325) * (2e6 + dome.volume_mm3)
    assert (state.gas.pressure_mpa + 0.101325) * (2e6 + state.gas.volume_mm3) == pytest.approx(
        content, rel=1e-11)
    ours = cli.json("state", "--indenter", "sphere-tipped", "--friction", "0", "--pressure",
                    "3e-4", "--gas-volume", "2e6", "--depth", "5")
    assert ours["inputs"]["gas_volume_mm3"] == 2e6
    assert ours["state"]["gas"]["pressure_mpa"] == pytest.approx(state.gas.pressure_mpa, rel=1e-12)
    assert state.force_n == pytest.approx(ours["state"]["force_n"], rel=1e-12)
    curve = pu.loading_curve(problem, points=3, max_depth_mm=5.0)
    assert curve.ok and np.all(np.diff(curve.gas_pressure_mpa) > 0)
    assert set(curve.columns()) >= {"gas_pressure_mpa", "gas_volume_mm3"}
    assert pu.solve_at_depth(pu.Problem(), 1.0).gas is None
    with pytest.raises(ValueError, match="gas volume must be a finite number > 0"):
        pu.solve_at_depth(pu.Problem(preload=pu.Preload(gas_volume_mm3=0.0)), 1.0)


def test_ogden_arruda_boyce_and_gent_gent_match_cli(cli):
    # Ogden's (1972) three-term fit to Treloar: G = sum mu_p alpha_p / 2 = 0.4225 MPa
    m = pu.Material.ogden(mu_mpa=[0.63, 0.0012, -0.01], alpha=[1.3, 5, -2])
    assert m.shear_modulus_mpa == pytest.approx(0.4225, rel=1e-15)
    assert isinstance(m.law, pu.Ogden) and m.law_name == "ogden"
    assert sum(mu * a for mu, a in zip(m.law.mu, m.law.alpha)) == pytest.approx(2, rel=1e-15)
    prediction = pu.predict_puncture(pu.Problem(material=m))
    from_cli = cli.json("puncture", "--material", "ogden", "--ogden-mu", "0.63,0.0012,-0.01",
                        "--ogden-alpha", "1.3,5,-2")
    assert rel(prediction.force_n, from_cli["puncture"]["force_n"]) < 1e-12
    ab = pu.Problem(material=pu.Material(0.06, pu.ArrudaBoyce.from_chain_stretch(7)))
    assert ab.material.law.n == pytest.approx(49, rel=1e-15)
    from_cli = cli.json("puncture", "--material", "arruda-boyce", "--chain-stretch", "7")
    assert rel(pu.predict_puncture(ab).force_n, from_cli["puncture"]["force_n"]) < 1e-12
    gg = pu.Problem(material=pu.Material(0.06, pu.GentGent(j_lim=125, beta=0.2)))
    from_cli = cli.json("puncture", "--material", "gent-gent", "--i2-share", "0.2")
    assert rel(pu.predict_puncture(gg).force_n, from_cli["puncture"]["force_n"]) < 1e-12
    # one Ogden term with alpha = 2 is neo-Hookean (rounding), Gent-Gent with beta = 0 is Gent
    one = pu.Problem(material=pu.Material.ogden(mu_mpa=[0.06], alpha=[2]))  # G = 0.06 MPa
    neo = pu.Problem(material=pu.Material.neo_hookean())
    assert rel(pu.predict_puncture(one).force_n, pu.predict_puncture(neo).force_n) < 1e-10
    plain = pu.Problem(material=pu.Material(0.06, pu.GentGent(beta=0)))
    assert pu.predict_puncture(plain).force_n == pu.predict_puncture(pu.Problem()).force_n
    with pytest.raises(ValueError, match="alpha"):
        pu.Material.ogden(mu_mpa=[0.1, 0.2], alpha=[2])


def test_curve_events_and_failure_verdict_match_cli(cli):
    # An inflated membrane (docs/model.md §8.1): no event, and the probe punctures it locally,
    # as the CLI's JSON says.
    problem = pu.Problem(indenter=pu.SphereTipped(radius_mm=2.0), friction=0.0,
                         preload=pu.Preload(pressure_mpa=3e-4))
    curve = pu.loading_curve(problem, points=20)
    assert curve.ok
    assert curve.events == []
    verdict = curve.failure_verdict
    assert verdict.mode == pu.FailureMode.LocalPuncture
    assert verdict.mode.token == "local_puncture"
    from_cli = cli.json("curve", "--points", "20", "--indenter", "sphere-tipped",
                        "--indenter-radius", "2", "--friction", "0", "--pressure", "3e-4")
    assert "events" not in from_cli["curve"]
    cli_verdict = from_cli["curve"]["failure_verdict"]
    assert cli_verdict["mode"] == verdict.mode.token
    assert rel(verdict.force_n, cli_verdict["force_n"]) < 1e-9
    assert verdict.where == cli_verdict["where"]
    reach = [p.contact_edge_radius_mm + p.contact_edge_height_mm for p in curve.points]
    assert all(b > a for a, b in zip(reach[1:], reach[2:]))
    # A membrane mounted stress-free has no verdict.
    assert pu.loading_curve(pu.Problem(), points=5).failure_verdict is None
    assert pu.CurveEventKind.ForceMaximum.token == "force_maximum"


def test_middle_inflated_state_snaps_through_at_its_fold(cli):
    # The unstable middle state at 0.9 kPa (docs/model.md §8.1, "Following a fold"): its depth
    # turns back at 0.025 mm, the membrane lands on the first state (the probe leaves it), and the
    # branch past the fold is followed by arc length, as the CLI's JSON says.
    problem = pu.Problem(indenter=pu.SphereTipped(radius_mm=2.0),
                         preload=pu.Preload(pressure_mpa=9e-4, inflated_state=2))
    curve = pu.loading_curve(problem, points=20)
    assert curve.ok
    snap = curve.events[0]
    assert snap.kind == pu.CurveEventKind.SnapThrough
    assert snap.kind.token == "snap_through"
    assert abs(snap.depth_mm - 0.025355) < 1e-6
    assert snap.force_after_n == 0.0
    assert all(b.depth_mm < a.depth_mm for a, b in zip(curve.beyond_fold, curve.beyond_fold[1:]))
    from_cli = cli.json("curve", "--points", "20", "--indenter", "sphere-tipped",
                        "--pressure", "9e-4", "--inflated-state", "2")
    event = from_cli["curve"]["events"][0]
    assert event["kind"] == "snap_through"
    assert rel(event["depth_mm"], snap.depth_mm) < 1e-12
    assert len(from_cli["curve"]["beyond_fold"]) == len(curve.beyond_fold)
    assert rel(curve.puncture.force_n, from_cli["puncture"]["force_n"]) < 1e-12
    # predict_puncture goes through the fold too, under depth control: the curve's puncture.
    prediction = pu.predict_puncture(problem)
    assert prediction.ok
    assert rel(prediction.force_n, curve.puncture.force_n) < 1e-9
    assert rel(prediction.depth_mm, curve.puncture.depth_mm) < 1e-9
    assert prediction.snap_through.depth_mm == snap.depth_mm
    assert prediction.snap_through.force_after_n == 0.0
    assert curve.puncture.snap_through.depth_mm == snap.depth_mm


def test_puncture_failure_verdict_is_the_curves_and_the_clis(cli):
    # predict_puncture gives the loading curve's verdict when asked (SolverOptions.failure_verdict)
    # and the `puncture` command's JSON writes it; none for a membrane mounted stress-free.
    problem = pu.Problem(indenter=pu.SphereTipped(radius_mm=2.0), friction=0.0,
                         preload=pu.Preload(pressure_mpa=3e-4))
    assert pu.predict_puncture(problem).failure_verdict is None  # off unless asked
    options = pu.SolverOptions()
    options.failure_verdict = True
    prediction = pu.predict_puncture(problem, options)
    verdict = prediction.failure_verdict
    assert verdict.mode == pu.FailureMode.LocalPuncture
    assert verdict.depth_mm == prediction.depth_mm
    assert verdict.depth_mm == pu.loading_curve(problem).failure_verdict.depth_mm
    from_cli = cli.json("puncture", "--indenter", "sphere-tipped", "--indenter-radius", "2",
                        "--friction", "0", "--pressure", "3e-4")["puncture"]
    assert from_cli["failure_verdict"]["mode"] == "local_puncture"
    assert rel(verdict.depth_mm, from_cli["failure_verdict"]["depth_mm"]) < 1e-9
    assert verdict.reason == from_cli["failure_verdict"]["reason"]
    assert pu.predict_puncture(pu.Problem(), options).failure_verdict is None
    assert "failure_verdict" not in cli.json("puncture")["puncture"]
