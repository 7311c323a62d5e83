"""puncture.sweep: the sweep engine from Python (python/puncture/sweeps.py, bind_sweep.cpp)."""

import numpy as np
import pytest

import puncture as pu

SPEC = {
    "design": "latin-hypercube",
    "samples": 8,
    "seed": 3,
    "force-at-depth": [5.0],
    "parameters": {
        "friction": {"range": [0.0, 1.0]},
        "critical_i1": {"distribution": "truncated-normal", "mean": 60, "sd": 15,
                        "range": [20, 100]},
    },
}


def small_probe(v):
    return pu.Problem(indenter=pu.FlatPunch(1.0), friction=v["friction"],
                      critical_i1=v["critical_i1"])


def test_rows_are_the_public_solves_in_point_order():
    table = pu.sweep(SPEC, small_probe, dataframe=False)
    assert list(table["point"]) == list(range(8))
    for i in range(8):
        problem = small_probe({"friction": table["friction"][i],
                               "critical_i1": table["critical_i1"][i]})
        p = pu.predict_puncture(problem)
        assert table["status"][i] == "converged"
        assert table["puncture_force_n"][i] == p.force_n  # to the bit
        assert table["puncture_depth_mm"][i] == p.depth_mm
        assert table["force_n_at_5_mm"][i] == pu.solve_at_depth(problem, 5.0).force_n


def test_identical_whatever_the_threads():
    one = pu.sweep(SPEC, small_probe, threads=1, dataframe=False)
    two = pu.sweep(SPEC, small_probe, threads=2, dataframe=False)
    assert one.keys() == two.keys()
    for key in one:
        assert np.array_equal(np.asarray(one[key]), np.asarray(two[key])), key


def test_a_failed_point_is_a_row():
    # Held at the edge (--stick always), the membrane wraps the side before I1 reaches 127.9.
    spec = {"design": "grid",
            "parameters": {"stick": {"values": ["none", "always"]},
                           "critical_i1": {"values": [50, 127.9]}}}
    table = pu.sweep(spec, lambda v: pu.Problem(stick=v["stick"], critical_i1=v["critical_i1"]),
                     dataframe=False)
    assert table["stick"] == ["none", "none", "always", "always"]
    assert table["status"][3] != "converged" and table["failure_kind"][3] == "physical"
    assert np.isnan(table["puncture_force_n"][3])
    assert table["message"][3].startswith("puncture: ")
    assert all(s == "converged" for s in table["status"][:3])


def test_invalid_input_raises():
    with pytest.raises(ValueError, match="design"):
        pu.sweep({"design": "random", "parameters": {}}, small_probe)
    with pytest.raises(ValueError, match="samples"):
        pu.sweep({"design": "sobol", "parameters": {"friction": {"range": [0, 1]}}}, small_probe)
    spec = {"design": "grid", "parameters": {"thickness_mm": {"values": [0.2, -0.1]}}}
    with pytest.raises(ValueError, match="sweep point 1"):
        pu.sweep(spec, lambda v: pu.Problem(geometry=pu.Geometry(thickness_mm=v["thickness_mm"])))


def test_an_error_in_problem_of_is_raised():
    def broken(v):
        raise KeyError("no such parameter")

    with pytest.raises(KeyError):
        pu.sweep(SPEC, broken)


def test_shares_together_are_the_whole_sweep():
    """What examples/dask_sweep.py does across workers: every n-th point, then point order."""
    whole = pu.sweep(SPEC, small_probe, dataframe=False)
    parts = [pu.sweep(SPEC, small_probe, share=(k, 3), dataframe=False) for k in range(3)]
    points = np.concatenate([p["point"] for p in parts])
    order = np.argsort(points)
    assert list(points[order]) == list(range(8))
    force = np.concatenate([p["puncture_force_n"] for p in parts])[order]
    assert np.array_equal(force, whole["puncture_force_n"])


WARM_GRID = {"design": "grid",
             "parameters": {"critical_i1": {"values": [80, 95.2]},
                            "friction": {"range": [0.05, 0.4], "levels": 20}}}


def paper_membrane(v):
    return pu.Problem(friction=v["friction"], critical_i1=v["critical_i1"])


def test_warm_rows_equal_cold_rows_to_the_shooting_tolerance():
    """A grid's friction lines in warm chains (16 + 4 points): force and depth within 1e-12 of
    the cold rows (which are predict_puncture's to the bit), I1 and stretch within 1e-10."""
    warm = pu.sweep(WARM_GRID, paper_membrane, dataframe=False)
    cold = pu.sweep(dict(WARM_GRID, **{"warm-start": False}), paper_membrane, dataframe=False)
    assert list(warm["status"]) == list(cold["status"]) == ["converged"] * 40
    for key in ("puncture_force_n", "puncture_depth_mm"):
        np.testing.assert_allclose(warm[key], cold[key], rtol=1e-12, atol=0)
    # I1 and the corner stretch come from the state marched down Part II from the root.
    for key in ("max_i1", "part_three_stretch"):
        np.testing.assert_allclose(warm[key], cold[key], rtol=1e-10, atol=0)
    assert list(warm["crack_location"]) == list(cold["crack_location"])
    for i in (0, 17, 39):
        p = pu.predict_puncture(paper_membrane({"friction": cold["friction"][i],
                                                "critical_i1": cold["critical_i1"][i]}))
        assert cold["puncture_force_n"][i] == p.force_n


def test_a_warm_start_from_python():
    """SolverOptions.puncture_top_stretch_start from a neighbour's part_two_top_stretch."""
    cold = pu.predict_puncture(paper_membrane({"friction": 0.2, "critical_i1": 95.2}))
    near = pu.predict_puncture(paper_membrane({"friction": 0.19, "critical_i1": 95.2}))
    options = pu.SolverOptions()
    options.puncture_top_stretch_start = near.part_two_top_stretch
    warm = pu.predict_puncture(paper_membrane({"friction": 0.2, "critical_i1": 95.2}), options)
    assert warm.force_n == pytest.approx(cold.force_n, rel=1e-12, abs=0)
    assert warm.depth_mm == pytest.approx(cold.depth_mm, rel=1e-12, abs=0)


def test_warm_shares_together_are_the_whole_sweep_bit_for_bit():
    """Shares take whole chains: every row the same as the single run's, whatever n."""
    whole = pu.sweep(WARM_GRID, paper_membrane, threads=1, dataframe=False)
    for n in (2, 3):
        parts = [pu.sweep(WARM_GRID, paper_membrane, share=(k, n), dataframe=False)
                 for k in range(n)]
        points = np.concatenate([p["point"] for p in parts])
        order = np.argsort(points)
        assert list(points[order]) == list(range(40))
        force = np.concatenate([p["puncture_force_n"] for p in parts])[order]
        assert np.array_equal(force, whole["puncture_force_n"])


def test_warm_start_on_a_sampled_design_is_refused():
    with pytest.raises(ValueError, match="warm-start: a latin-hypercube has no neighbouring"):
        pu.sweep(dict(SPEC, **{"warm-start": True}), small_probe)
    with pytest.raises(ValueError, match="warm-start: must be True or False"):
        pu.sweep(dict(WARM_GRID, **{"warm-start": "yes"}), paper_membrane)


def test_dask_example_gives_the_single_machine_table():
    """python/examples/dask_sweep.py on a local Dask cluster (skipped without python3-dask and
    python3-distributed): the same table as one puncture.sweep."""
    distributed = pytest.importorskip("distributed")
    import importlib.util
    import os

    path = os.path.join(os.path.dirname(__file__), "..", "examples", "dask_sweep.py")
    spec = importlib.util.spec_from_file_location("dask_sweep", path)
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    with distributed.Client(n_workers=2, threads_per_worker=1, processes=False) as client:
        table = example.sweep_on(client)
    whole = pu.sweep(example.SPEC, example.problem_of, dataframe=False)
    assert np.array_equal(table["point"], whole["point"])
    assert np.array_equal(table["puncture_force_n"], whole["puncture_force_n"])
    assert list(table["status"]) == list(whole["status"])
