"""Sweeps from Python: many problems on every core, one row each (the engine of `puncture sweep`).

    import puncture
    spec = {"design": "latin-hypercube", "samples": 200, "seed": 1,
            "parameters": {"friction": {"range": [0.1, 0.3]},
                           "critical_i1": {"distribution": "normal", "mean": 95.2, "sd": 4.8}}}
    table = puncture.sweep(spec, lambda v: puncture.Problem(friction=v["friction"],
                                                            critical_i1=v["critical_i1"]))
    # a grid over words: {"indenter": {"values": ["flat", "sphere"]}} gives v["indenter"] a str
    table["puncture_force_n"]        # numpy arrays (a pandas DataFrame when pandas is there)

The spec has the keys of the CLI's SPEC.toml (docs/sweeps.md): design, samples, seed, puncture,
force-at-depth (depths in mm), warm-start (a grid: each puncture search starts from its
neighbour's along the last parameter, in chains of 16 points; default True) and parameters, each
{range}, {range, levels}, {values} or {distribution, mean, sd[, range]}.  The names are yours: `problem_of(values)` receives a dict
name -> number (or word) per point and returns its Problem; it runs with the GIL held, the
solves without it.  Rows come in point order, identical whatever `threads`; a failed point is a
row with its status, failure_kind and message, its outputs NaN.  Invalid input raises ValueError.
"""

from ._puncture import _sweep

DISTRIBUTIONS = ("uniform", "normal", "lognormal", "truncated-normal")


def _levels(name, p):
    if "values" in p:
        return [v if isinstance(v, str) else repr(float(v)) for v in p["values"]]
    if "range" in p and "levels" in p:
        lo, hi = (float(x) for x in p["range"])
        n = int(p["levels"])
        if n < 2:
            raise ValueError(f"{name}.levels: a grid needs >= 2 levels, got {n}")
        return [repr(hi if k == n - 1 else lo + (k / (n - 1)) * (hi - lo)) for k in range(n)]
    raise ValueError(f"{name}: a grid needs values = [...] or range = [lower, upper] with levels")


def _distribution(name, p):
    kind = p.get("distribution", "uniform")
    if kind not in DISTRIBUTIONS:
        raise ValueError(f"{name}.distribution: '{kind}' is not one of {', '.join(DISTRIBUTIONS)}")
    lo, hi = (float(x) for x in p.get("range", (0.0, 1.0)))
    if kind in ("uniform", "truncated-normal") and "range" not in p:
        raise ValueError(f"{name}: a {kind} distribution needs range = [lower, upper]")
    if kind != "uniform" and not ("mean" in p and "sd" in p):
        raise ValueError(f"{name}: a {kind} distribution needs mean and sd")
    return (kind, lo, hi, float(p.get("mean", 0.0)), float(p.get("sd", 0.0)))


def sweep(spec, problem_of, threads=0, share=(0, 1), dataframe=None):
    """Solves every point of `spec` (see the module's doc); returns its columns as numpy arrays
    (a dict), or a pandas DataFrame when pandas is installed and `dataframe` is not False.

    share=(k, n): only the warm chains k, k + n, k + 2n, ... (one point each without warm
    starts: the points k, k + n, ...; one of n workers, e.g. on a Dask cluster:
    examples/dask_sweep.py); the n shares' rows together are the whole sweep's, each row the
    same whatever n.  A share checks its own points' problems only: an invalid point raises in
    the share holding it."""
    known = {"design", "samples", "seed", "puncture", "force-at-depth", "warm-start",
             "parameters"}
    unknown = set(spec) - known
    if unknown:
        raise ValueError(f"spec: unknown key(s) {sorted(unknown)} (keys: {sorted(known)})")
    design = spec.get("design")
    if design is None:
        raise ValueError("spec: 'design' is missing (grid, latin-hypercube, sobol or monte-carlo)")
    parameters = spec.get("parameters") or {}
    grid = design == "grid"
    warm = spec.get("warm-start", grid)
    if not isinstance(warm, bool):
        raise ValueError(f"warm-start: must be True or False, got {warm!r}")
    if warm and not grid:
        raise ValueError(f"warm-start: a {design} has no neighbouring points to start from (only "
                         "a grid does); its points are always solved cold")
    names, levels, distributions = [], [], []
    for name, p in parameters.items():
        names.append(name)
        levels.append(_levels(name, p) if grid else [])
        distributions.append(("uniform", 0.0, 1.0, 0.0, 0.0) if grid else _distribution(name, p))
    columns = _sweep(design, names, levels, distributions, int(spec.get("samples", 0)),
                     int(spec.get("seed", 0)), bool(spec.get("puncture", True)),
                     [float(d) for d in spec.get("force-at-depth", [])], warm, int(threads),
                     int(share[0]), int(share[1]), problem_of)
    if dataframe is not False:
        try:
            import pandas
        except ImportError:
            return columns
        return pandas.DataFrame(columns)
    return columns
