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
