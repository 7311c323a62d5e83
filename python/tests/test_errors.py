"""Invalid input raises ValueError with the CLI's messages; solver failures raise SolverError."""

import math

import pytest

import puncture as pu

# (Problem keyword arguments, the CLI flags giving the same problem, the attributes named)
INVALID = [
    ({"geometry": pu.Geometry(clamp_radius_mm=-2)}, ["--clamp-radius", "-2"],
     ["geometry.clamp_radius_mm"]),
    ({"geometry": pu.Geometry(thickness_mm=0)}, ["--thickness", "0"], ["geometry.thickness_mm"]),
    ({"indenter": pu.FlatPunch(radius_mm=25)}, ["--indenter-radius", "25"],
     ["indenter.radius_mm"]),
    ({"material": pu.Material.gent(shear_modulus_mpa=math.nan)}, ["--shear-modulus", "nan"],
     ["material.shear_modulus_mpa"]),
    ({"material": pu.Material.gent(j_lim=0)}, ["--jlim", "0"],
     ["material.law.j_lim", "critical_i1"]),
    ({"material": pu.Material.mooney_rivlin(alpha=1)},
     ["--material", "mooney-rivlin", "--mr-alpha", "1"], ["material.law.alpha"]),
    ({"material": pu.Material.yeoh(c10_mpa=0.03, c20_mpa=-0.001, c30_mpa=0.0001)},
     ["--material", "yeoh", "--yeoh", "0.03,-0.001,0.0001"], ["material.law.c2"]),
    ({"material": pu.Material.ogden(mu_mpa=[0.06, 0.001], alpha=[2, -2])},
     ["--material", "ogden", "--ogden-mu", "0.06,0.001", "--ogden-alpha", "2,-2"],
     ["material.law.mu"]),
    ({"material": pu.Material(0.06, pu.ArrudaBoyce(n=1))},
     ["--material", "arruda-boyce", "--chain-segments", "1"],
     ["material.law.n", "critical_i1"]),
    ({"material": pu.Material(0.06, pu.GentGent(j_lim=125, beta=0.6))},
     ["--material", "gent-gent", "--i2-share", "0.6"], ["material.law.beta"]),
    ({"indenter": pu.FlatPunch(radius_mm=2, fillet_radius_mm=2)}, ["--fillet-radius", "2"],
     ["indenter.fillet_radius_mm"]),
    ({"friction": -0.1}, ["--friction", "-0.1"], ["friction"]),
    ({"friction": 11}, ["--friction", "11"], ["friction"]),
    ({"critical_i1": 128}, ["--critical-i1", "128"], ["critical_i1"]),
    ({"stick": "force:-1"}, ["--stick", "force:-1"], ["stick.threshold"]),
    # the sphere-tipped probe is held without gas or at a held pressure, not over a sealed chamber
    ({"indenter": pu.SphereTipped(), "friction": 0, "stick": "always",
      "preload": pu.Preload(pressure_mpa=0.005, gas_volume_mm3=2e6)},
     ["--indenter", "sphere-tipped", "--friction", "0", "--stick", "always", "--pressure",
      "0.005", "--gas-volume", "2e6"], ["stick.rule"]),
    # Coulomb friction cannot hold the membrane on the flat punch
    ({"stick": "coulomb"}, ["--stick", "coulomb"], ["stick.rule"]),
    ({"indenter": pu.Ball(2.0, 2.0), "friction": 0},
     ["--indenter", "ball", "--ball-radius", "2", "--friction", "0"], ["indenter.ball_radius_mm"]),
    ({"indenter": pu.Cone(2.0, 90.0, 0.5), "friction": 0},
     ["--indenter", "cone", "--cone-half-angle", "90", "--tip-radius", "0.5", "--friction", "0"],
     ["indenter.half_angle_deg"]),
    ({"geometry": pu.Geometry(clamp_radius_mm=-1), "friction": -1},
     ["--clamp-radius", "-1", "--friction", "-1"], ["geometry.clamp_radius_mm", "friction"]),
]


@pytest.mark.parametrize("kwargs,flags,attributes", INVALID)
def test_invalid_problem_raises_value_error_like_the_cli(cli, kwargs, flags, attributes):
    problem = pu.Problem(**kwargs)
    assert problem.validation_errors()
    rc, out, err = cli.run("puncture", *flags)
    assert rc == 1 and out == ""
    cli_text = err.removeprefix("puncture: error: ")
    for call in (lambda: pu.predict_puncture(problem),
                 lambda: pu.solve_at_force(problem, 0.1),
                 lambda: pu.solve_at_depth(problem, 1.0),
                 lambda: pu.loading_curve(problem),
                 lambda: pu.stick_slip_boundary(problem),
                 problem.validate):
        with pytest.raises(ValueError) as info:
            call()
        text = str(info.value)
        assert text.startswith("invalid input:\n  ")
        ours = [line.strip().split(": ", 1) for line in text.splitlines()[1:]]
        theirs = [line.strip().split(": ", 1) for line in cli_text.strip().splitlines()[1:]]
        # the same library messages, prefixed with the attribute instead of the flag
        assert [m for _, m in ours] == [m for _, m in theirs]
        assert [e.message for e in problem.validation_errors()] == [m for _, m in ours]
        assert [e.parameter for e in problem.validation_errors()] == attributes
        assert [a for a, _ in ours] == attributes


@pytest.mark.parametrize("value", [-1.0, math.nan, math.inf])
def test_invalid_load_raises_value_error(cli, value):
    with pytest.raises(ValueError, match=r"^force_n: must be a finite number >= 0 N, got"):
        pu.solve_at_force(pu.Problem(), value)
    with pytest.raises(ValueError, match=r"^depth_mm: must be a finite number >= 0 mm, got"):
        pu.solve_at_depth(pu.Problem(), value)
    rc, _, err = cli.run("state", "--force", str(value))
    assert rc == 1 and "--force: must be a finite number >= 0 N, got" in err


def test_invalid_options_raise_value_error():
    with pytest.raises(ValueError, match="points: must be in the range 2 to 100000, got 1"):
        pu.loading_curve(pu.Problem(), points=1)
    with pytest.raises(ValueError, match=r"max_depth_mm: must be a finite number >= 0 mm"):
        pu.loading_curve(pu.Problem(), max_depth_mm=-3)
    with pytest.raises(ValueError, match="stage: expected Stage, 'stick', 'slip' or 'auto'"):
        pu.solve_at_force(pu.Problem(), 0.1, stage="glued")
    with pytest.raises(ValueError, match="stick: expected none, always, force:<N>"):
        pu.Problem(stick="glue:1")
    with pytest.raises(ValueError, match="stick: expected"):
        pu.Problem().stick = "force"
    with pytest.raises(ValueError, match="part_two_equation: expected"):
        pu.Problem(part_two_equation="eq19")


def test_beyond_locking_raises_solver_error_like_the_cli(cli):
    with pytest.raises(pu.SolverError) as info:
        pu.solve_at_force(pu.Problem(), 1e8)
    e = info.value
    assert isinstance(e, RuntimeError)
    assert e.status == pu.Status.BeyondLocking and e.status.token == "beyond locking"
    assert e.failure_kind == pu.FailureKind.Physical and e.failure_kind.token == "physical"
    assert e.message and e.message in str(e)
    rc, out, err = cli.run("state", "--force", "1e8")
    assert rc == 2 and out == ""
    first, kind = err.strip().split("\n")
    assert first == f"puncture: solver failure: {e}"
    assert kind.strip().startswith("failure kind: physical:")


def test_held_membrane_wrapping_the_side_raises_solver_error(cli):
    with pytest.raises(pu.SolverError) as info:
        pu.solve_at_force(pu.Problem(), 100, stage=pu.Stage.Stick)
    assert info.value.status == pu.Status.StickWrapsSide
    rc, _, err = cli.run("state", "--force", "100", "--stage", "stick")
    assert rc == 2 and err.splitlines()[0] == f"puncture: solver failure: {info.value}"
    assert info.value.failure_kind == pu.FailureKind.Physical


def test_solver_error_is_catchable_as_runtime_error():
    with pytest.raises(RuntimeError):
        pu.solve_at_force(pu.Problem(), 1e8)
    assert issubclass(pu.SolverError, RuntimeError)
