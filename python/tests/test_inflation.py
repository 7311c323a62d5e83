"""The inflation (bulge) test from Python: numpy results, the CLI's numbers, the same errors as
the rest of the package, a figure, and an independent check of the neo-Hookean limit point with
scipy's boundary-value solver (skipped without scipy)."""

import json
import math

import numpy as np
import pytest

import puncture as pu


@pytest.fixture(scope="module")
def gent_curve():
    return pu.inflation_curve(pu.InflationProblem(), points=40)


def test_state_has_numpy_fields_from_pole_to_clamp():
    s = pu.inflate_at_pole_stretch(pu.InflationProblem(), 2.0)
    assert s.ok and s.status == pu.Status.Converged
    f = s.fields
    assert isinstance(f.radius_mm, np.ndarray) and not f.radius_mm.flags.writeable
    assert len(f) == f.first_invariant.size > 200
    assert f.reference_radius_mm[0] == 0.0 and f.reference_radius_mm[-1] == pytest.approx(25.0)
    assert f.hoop_stretch[-1] == pytest.approx(1.0, abs=1e-8)  # the clamp
    assert isinstance(f, pu.MembraneFields)  # the same type as an indented state's
    assert f.deflection_mm[0] == pytest.approx(s.pole_height_mm)  # along the pressure: height
    assert set(f.part) == {1}  # free throughout
    assert not f.contact_pressure_mpa.any()
    assert {"R_mm", "r_mm", "z_mm", "slope_rad", "lambda1", "lambda2", "lambda3", "s1_mpa",
            "s2_mpa", "I1"} <= set(f.columns())
    assert s.problem.clamp_radius_mm == 25.0


def test_curve_columns_extrema_and_burst(gent_curve):
    c = gent_curve
    assert c.ok and len(c) == 40
    assert isinstance(c.pressure_mpa, np.ndarray) and c.pressure_mpa.size == 40
    assert np.all(np.diff(c.volume_mm3) > 0)
    assert [e.kind for e in c.extrema] == [pu.ExtremumKind.Maximum, pu.ExtremumKind.Minimum]
    assert c.burst.ok
    assert c.burst.state.max_first_invariant == pytest.approx(95.2, rel=1e-9)
    assert c.columns()["max_i1"][-1] == pytest.approx(95.2, rel=1e-9)


def test_python_and_cli_give_the_same_numbers(cli, gent_curve):
    d = cli.json("inflate", "--points", "40")
    assert d["curve"]["end_pole_stretch"] == pytest.approx(gent_curve.end_pole_stretch, rel=1e-12)
    assert [p["pressure_mpa"] for p in d["curve"]["points"]] == pytest.approx(
        gent_curve.pressure_mpa.tolist(), rel=1e-12)
    assert d["curve"]["extrema"][0]["pole_stretch"] == pytest.approx(
        gent_curve.extrema[0].state.pole_stretch, rel=1e-12)


def test_an_indentation_problem_gives_its_membrane():
    problem = pu.Problem(geometry=pu.Geometry(clamp_radius_mm=30, thickness_mm=0.3))
    a = pu.inflate_at_pole_stretch(problem, 1.5)
    b = pu.inflate_at_pole_stretch(pu.InflationProblem.of(problem), 1.5)
    assert a.problem.clamp_radius_mm == 30 and a.problem.thickness_mm == 0.3
    assert a.pressure_mpa == b.pressure_mpa


def test_every_state_at_a_pressure():
    nh = pu.InflationProblem(material=pu.Material.neo_hookean())
    limit = pu.pressure_extrema(nh, 4.0)[0]
    two = pu.inflate_at_pressure(nh, 0.95 * limit.state.pressure_mpa)
    assert len(two.states) == 2
    assert two.states[0].pole_stretch < limit.state.pole_stretch < two.states[1].pole_stretch
    with pytest.raises(pu.SolverError, match="highest pressure") as none:
        pu.inflate_at_pressure(nh, 1.05 * limit.state.pressure_mpa)
    assert none.value.status == pu.Status.NotReached
    assert none.value.failure_kind == pu.FailureKind.Physical


@pytest.mark.parametrize("call,match", [
    (lambda: pu.inflate_at_pole_stretch(pu.InflationProblem(thickness_mm=-1), 2.0),
     r"^invalid input:\n  thickness_mm: thickness must be a finite number > 0 mm"),
    (lambda: pu.inflation_curve(pu.InflationProblem(critical_i1=200)),
     r"critical_i1: critical I1 must be below the Gent locking limit"),
    (lambda: pu.inflate_at_pole_stretch(pu.InflationProblem(), 0.5),
     r"^pole_stretch: pole stretch must be a finite number >= 1"),
    (lambda: pu.inflate_at_pressure(pu.InflationProblem(), math.nan),
     r"^pressure_mpa: pressure must be a finite number >= 0 MPa"),
    (lambda: pu.inflation_curve(pu.InflationProblem(), max_pole_stretch=9.0),
     r"^max_pole_stretch: max pole stretch must be below"),
    (lambda: pu.inflation_curve(pu.InflationProblem(), points=1),
     r"^points: points must be in the range 2 to 100000"),
])
def test_invalid_input_raises_value_error_naming_it(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_beyond_locking_raises_solver_error():
    stiff = pu.InflationProblem(material=pu.Material.gent(j_lim=20), critical_i1=20)
    with pytest.raises(pu.SolverError) as info:
        pu.inflate_at_pole_stretch(stiff, 3.5)
    assert info.value.status == pu.Status.BeyondLocking
    assert "locking" in info.value.message


def test_progress_is_reported():
    seen = []
    pu.inflation_curve(pu.InflationProblem(), points=5, max_pole_stretch=2.0,
                       progress=lambda done, total: seen.append((done, total)))
    assert seen == [(k, 5) for k in range(1, 6)]


def test_figure_from_bindings_and_from_cli_json(tmp_path, cli, gent_curve):
    pytest.importorskip("matplotlib")
    from puncture import plots

    from test_plots import check_png

    path = tmp_path / "inflation.png"
    fig = plots.inflation_curve(gent_curve, path)
    check_png(path)
    assert "limit point" in " ".join(t.get_text() for t in fig.axes[0].get_legend().get_texts())
    d = cli.json("inflate", "--points", "20", "--material", "neo-hookean")
    plots.inflation_curve(d, tmp_path / "from_json.svg")
    assert "<svg" in (tmp_path / "from_json.svg").read_text()
    with pytest.raises(ValueError, match="path"):
        plots.inflation_curve(gent_curve, tmp_path / "x.txt")


def test_neo_hookean_limit_point_agrees_with_an_independent_solver():
    """scipy's collocation solver on a different form of the equations (the normal balance
    p = kappa1 T1 + kappa2 T2 for the slope, instead of the vertical balance of the cap), with
    the pressure as an unknown parameter: the pressures agree, and the library's limit point is
    the maximum of scipy's pressure too."""
    integrate = pytest.importorskip("scipy.integrate")
    nh = pu.InflationProblem(material=pu.Material.neo_hookean())
    d = 1e-4  # start off the pole; the equibiaxial start is exact to O(d^2) = 1e-8

    def stresses(l1, l2):
        l3 = 1.0 / (l1 * l2)
        return (l1 * l1 - l3 * l3) / l1, (l2 * l2 - l3 * l3) / l2

    def rhs(r, y, p):
        pressure = p[0]
        l1, l2, phi = y
        s1, s2 = stresses(l1, l2)
        l3 = 1.0 / (l1 * l2)
        a1 = 1.0 + 3.0 * l3 * l3 / (l1 * l1)  # d s1 / d lambda1
        a2 = 2.0 * l3 * l3 / (l1 * l2)  # d s1 / d lambda2
        dl2 = (l1 * np.cos(phi) - l2) / r
        dl1 = (s2 * np.cos(phi) - s1 - r * a2 * dl2) / (r * a1)
        dphi = (pressure * l1 * l2 - s2 * np.sin(phi) / r) / s1
        return np.vstack([dl1, dl2, dphi])

    guess = {}

    def normalised_pressure(l0):
        def bc(ya, yb, p):
            s1, _ = stresses(ya[0], ya[1])
            return np.array([ya[1] - l0, ya[0] - ya[1], ya[2] - p[0] * ya[1] ** 2 * d / (2 * s1),
                             yb[1] - 1.0])

        r = np.linspace(d, 1.0, 400)
        if guess:
            y0, p0 = guess["sol"].sol(r), guess["sol"].p
        else:
            y0, p0 = np.vstack([np.full_like(r, l0), l0 + (1 - l0) * r * r, r]), [1.0]
        sol = integrate.solve_bvp(rhs, bc, r, y0, p=p0, tol=1e-7, max_nodes=500000)
        assert sol.success, sol.message
        guess["sol"] = sol
        return sol.p[0]

    limit = pu.pressure_extrema(nh, 4.0)[0].state
    for l0 in (1.2, 1.6, 2.0):
        ours = pu.inflate_at_pole_stretch(nh, l0).normalized_pressure
        # collocation tolerance 1e-7 and the start's O(d^2): agreement to 1e-6 relative
        assert normalised_pressure(l0) == pytest.approx(ours, rel=1e-6)
    h = 0.02
    at = [normalised_pressure(limit.pole_stretch + k * h) for k in (-1, 0, 1)]
    assert at[1] == pytest.approx(limit.normalized_pressure, rel=1e-6)
    # The parabola's vertex through the three: the maximum of scipy's curve, within
    # h^2 P'''/(6 P'') ~ 1e-4 of the library's limit point.
    vertex = limit.pole_stretch + h * (at[0] - at[2]) / (2 * (at[0] - 2 * at[1] + at[2]))
    assert vertex == pytest.approx(limit.pole_stretch, abs=2e-4)


def test_mooney_rivlin_burst_lies_near_the_clamp_by_an_independent_solver():
    """Mooney-Rivlin (alpha = 0.1) bursts near the clamp, not at the pole: scipy's collocation
    solver, on the normal-balance form of the equations and started from the library's fields,
    agrees on the pressure of the library's burst state and on where its largest I1 lies; and
    the law-aware calibration reads that burst's pole stretch back as the critical I1."""
    integrate = pytest.importorskip("scipy.integrate")
    alpha = 0.1
    mr = pu.InflationProblem(material=pu.Material.mooney_rivlin(alpha=alpha))
    state = pu.inflation_burst(mr).state
    l0, A = state.pole_stretch, mr.clamp_radius_mm

    def stresses(l1, l2):
        return ((l1 - l1 ** -3 * l2 ** -2) * (1 - alpha + alpha * l2 * l2),
                (l2 - l2 ** -3 * l1 ** -2) * (1 - alpha + alpha * l1 * l1))

    def rhs(R, y, p):
        l1, l2, phi = y
        s1, s2 = stresses(l1, l2)
        g = 1 - alpha + alpha * l2 * l2
        a1 = (1 + 3 * l1 ** -4 * l2 ** -2) * g  # d s1 / d lambda1
        a2 = 2 * l1 ** -3 * l2 ** -3 * g + (l1 - l1 ** -3 * l2 ** -2) * 2 * alpha * l2
        dl2 = (l1 * np.cos(phi) - l2) / R
        dl1 = (s2 * np.cos(phi) - s1 - R * a2 * dl2) / (R * a1)
        dphi = (p[0] * l1 * l2 - s2 * np.sin(phi) / R) / s1
        return np.vstack([dl1, dl2, dphi])

    d = 1e-4  # the equibiaxial start off the pole, exact to O(d^2)

    def bc(ya, yb, p):
        s1, _ = stresses(ya[0], ya[1])
        return np.array([ya[1] - l0, ya[0] - ya[1], ya[2] - p[0] * ya[1] ** 2 * d / (2 * s1),
                         yb[1] - 1.0])

    f = state.fields
    Rf = np.asarray(f.reference_radius_mm) / A
    R = np.concatenate([[d], np.linspace(0.002, 1.0, 2000)])
    guess = np.vstack([np.interp(R, Rf, f.radial_stretch), np.interp(R, Rf, f.hoop_stretch),
                       np.interp(R, Rf, f.slope_rad)])
    sol = integrate.solve_bvp(rhs, bc, R, guess, p=[state.normalized_pressure], tol=1e-8,
                              max_nodes=1000000)
    assert sol.success, sol.message
    # Measured: 1.2e-9 in pressure, 9.5e-9 in the largest I1, 2e-6 of A in where it lies.
    assert sol.p[0] == pytest.approx(state.normalized_pressure, rel=1e-7)
    fine = np.linspace(d, 1.0, 200001)
    l1, l2, _ = sol.sol(fine)
    i1 = l1 ** 2 + l2 ** 2 + (l1 * l2) ** -2
    k = int(np.argmax(i1))
    assert i1[k] == pytest.approx(state.max_first_invariant, rel=1e-7)
    assert fine[k] == pytest.approx(state.max_first_invariant_reference_radius_mm / A, abs=1e-4)
    assert i1[0] == pytest.approx(pu.equibiaxial_first_invariant(l0), rel=1e-7)
    assert i1[0] < 84.0 < 95.0 < i1[k]  # the pole is far below the burst's I1

    e = pu.critical_i1_from_inflation([0.5 * l0], 0.5, law=pu.MooneyRivlin(alpha))
    assert e.from_membrane and e.mean == pytest.approx(mr.critical_i1, rel=1e-8)
    assert e.largest_i1_radius_fractions[0] == pytest.approx(fine[k], abs=1e-4)
    paper = pu.critical_i1_from_inflation([0.5 * l0], 0.5)
    assert not paper.from_membrane and paper.mean == pytest.approx(i1[0], rel=1e-7)


def test_a_prestretched_membrane_inflates_from_its_pre_stretch():
    problem = pu.InflationProblem(prestretch=1.2)
    assert problem.prestretch == 1.2
    flat = pu.inflate_at_pole_stretch(problem, 1.2)
    assert flat.pressure_mpa == 0.0 and flat.fields.hoop_stretch[-1] == 1.2
    assert flat.fields.reference_radius_mm[-1] == pytest.approx(25.0 / 1.2)
    # Small pressure: the pre-tensioned membrane's linear law, volume = pi p A^4 / (8 T0) with
    # T0 = G H s_eq(L0) / L0 (docs/model.md §16), to the relative error ~ the pole stretch's excess.
    s = pu.inflate_at_pole_stretch(problem, 1.2 * (1 + 1e-6))
    s_eq_mpa = pu.Material().equibiaxial_stress_mpa(1.2)  # G s_eq(L0), the paper's Gent
    tension = 0.2 * s_eq_mpa / 1.2
    assert s.volume_mm3 == pytest.approx(math.pi * s.pressure_mpa * 25.0**4 / (8 * tension), rel=1e-5)
    with pytest.raises(ValueError, match="pre-stretch 1.2"):
        pu.inflate_at_pole_stretch(problem, 1.1)
    assert pu.InflationProblem.of(pu.Problem(preload=pu.Preload(prestretch=1.3))).prestretch == 1.3
