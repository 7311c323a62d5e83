#!/usr/bin/python3
"""A sweep spread over a Dask cluster: each of N tasks solves every N-th point
(puncture.sweep(..., share=(k, N))) on its worker's cores, and the shares are put back in point
order: the same table as one puncture.sweep on one machine.

    python3 dask_sweep.py                        # a local cluster (Debian: python3-dask
                                                 # python3-distributed)
    python3 dask_sweep.py tcp://scheduler:8786   # an existing cluster; its workers need the
                                                 # puncture package on their PYTHONPATH
"""
import sys

import numpy as np
from dask.distributed import Client

import puncture

SPEC = {
    "design": "latin-hypercube",
    "samples": 1000,
    "seed": 1,
    "parameters": {
        "friction": {"distribution": "truncated-normal", "mean": 0.18, "sd": 0.05,
                     "range": [0.03, 0.33]},
        "critical_i1": {"distribution": "normal", "mean": 95.2, "sd": 4.8},
    },
}


def problem_of(v):  # a point's values -> its Problem
    return puncture.Problem(friction=v["friction"], critical_i1=v["critical_i1"])


def share(k, n):  # runs on a worker
    return puncture.sweep(SPEC, problem_of, share=(k, n), dataframe=False)


def sweep_on(client):
    """The whole sweep's table, its shares solved on the cluster's workers."""
    n = 4 * max(1, len(client.scheduler_info()["workers"]))
    parts = client.gather(client.map(share, range(n), [n] * n))
    table = {key: np.concatenate([np.asarray(p[key]) for p in parts]) for key in parts[0]}
    order = np.argsort(table["point"])  # back in point order
    return {key: column[order] for key, column in table.items()}


def main():
    client = Client(sys.argv[1]) if len(sys.argv) > 1 else Client()
    table = sweep_on(client)
    order = table["point"]
    force = table["puncture_force_n"][table["status"] == "converged"]
    print(f"{len(force)} of {len(order)} points punctured; force percentiles 5/50/95 %: "
          f"{np.percentile(force, [5, 50, 95])} N")


if __name__ == "__main__":
    main()
