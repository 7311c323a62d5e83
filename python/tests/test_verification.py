"""The second method and `verify` from Python: the CLI's table, the finite elements against the
shooting solver, and the errors."""

import pytest

import puncture as pu


def test_verify_matches_the_cli(cli):
    report = pu.verify(pu.Problem(), elements=32, depths=1)
    c = cli.json("verify", "--elements", "32", "--depths", "1")
    assert report.ok and c["passed"]
    assert len(report.checks) == len(c["checks"])
    for mine, theirs in zip(report.checks, c["checks"]):
        assert (mine.group, mine.quantity, mine.condition) == (
            theirs["group"], theirs["quantity"], theirs["condition"])
        assert mine.verdict.name.lower() == theirs["verdict"].lower()
        # The same deterministic computation: equal to the last bit.
        assert mine.second_method == pytest.approx(theirs["second_method"], rel=1e-15, abs=0.0)
        assert mine.shooting == pytest.approx(theirs["shooting"], rel=1e-15, abs=0.0)
    assert report.count(pu.Verdict.Fail) == 0


def test_finite_elements_agree_with_the_shooting():
    problem = pu.Problem()
    problem.friction = 0.0
    states = pu.fe_solve_at_depths(problem, [10.0, 20.0], pu.FeContact.Frictionless, elements=64)
    for s in states:
        assert s.ok, s.message
        e = pu.solve_at_depth(problem, s.depth_mm, "slip")
        # 64 quadratic elements: the force within ~3e-6 of the shooting's (docs/verification.md).
        assert s.force_n == pytest.approx(e.force_n, rel=1e-5)
        assert s.part_three_stretch == pytest.approx(e.part_three_stretch, rel=2e-4)
    assert states[1].part_two and not states[0].part_two
    # Fields: nodes from the centre to the clamp, I1 inside a part, None outside.
    last = states[1]
    assert [p.part for p in last.parts] == [3, 2, 1]
    assert last.parts[-1].radius_mm[-1] == pytest.approx(problem.geometry.clamp_radius_mm)
    assert last.first_invariant(1, 10.0) > 3.0
    assert last.first_invariant(3, 10.0) is None


def test_finite_elements_on_the_sphere_tipped_probe():
    problem = pu.Problem()
    problem.indenter = pu.SphereTipped(2.0)
    problem.friction = 0.0
    states = pu.fe_solve_at_depths(problem, [10.0, 20.0], pu.FeContact.Frictionless, elements=64)
    for s in states:
        assert s.ok, s.message
        e = pu.solve_at_depth(problem, s.depth_mm, "slip")
        # 64 quadratic elements: the force within ~2e-7 of the shooting's (docs/model.md §15.3),
        # the pole stretch (a derivative, O(h^2)) within ~2e-4.
        assert s.force_n == pytest.approx(e.force_n, rel=2e-6)
        assert s.part_three_stretch == pytest.approx(e.part_three_stretch, rel=1e-3)
        assert s.largest_penetration_mm <= 1e-9
    # The cap on the hemisphere, then past the equator the side too; both on the profile.
    assert not states[0].part_two and states[1].part_two
    assert [p.part for p in states[1].parts] == [3, 2, 1]
    assert len(states[1].parts[0].arclength_mm) == len(states[1].parts[0].radius_mm)
    assert len(states[1].parts[2].arclength_mm) == 0
    assert states[1].contact_edge_radius_mm == pytest.approx(2.0)
    report = pu.verify(problem, elements=32, depths=1)
    assert report.ok, report.message
    assert "pole stretch" in [c.quantity for c in report.checks]
    # Held where it touched (the stick rule `always`): stiffer than sliding (docs/model.md §15.4).
    held = pu.fe_solve_at_depths(problem, [10.0], pu.FeContact.Held, elements=32)[0]
    assert held.ok, held.message
    assert held.force_n > 1.05 * states[0].force_n


def test_errors_are_value_errors():
    with pytest.raises(ValueError, match="order"):
        pu.fe_solve_at_depths(pu.Problem(), [5.0], order=3)
    with pytest.raises(ValueError, match="increasing"):
        pu.fe_solve_at_depths(pu.Problem(), [5.0, 4.0])
    with pytest.raises(ValueError, match="elements"):
        pu.verify(pu.Problem(), elements=2)
    bad = pu.Problem()
    bad.geometry.thickness_mm = -1.0
    with pytest.raises(ValueError, match="thickness"):
        pu.verify(bad)
