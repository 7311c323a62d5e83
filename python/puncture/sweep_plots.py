"""Design maps of a sweep's CSV (`puncture sweep ... --plot FILE`).

    design_map(data, path)   an output over two swept flags: filled contours through the points
                             that have it (triangulated, so any design works), every point
                             marked, failed points as red crosses; over one flag, the output
                             against it

`data` is what the CLI passes: {"csv": results.csv, "parameters": [swept flags],
"output": column}.  Needs numpy and matplotlib only.
"""

import csv

import numpy as np
from matplotlib.figure import Figure
from matplotlib.tri import Triangulation

if __package__:  # the same formats and style as the other figures
    from .plots import save
else:  # run by plot_cli.py as a script: its directory is on sys.path
    from plots import save

FAILED_COLOUR = "#c62828"
LABELS = {"puncture_force_n": "puncture force [N]", "puncture_depth_mm": "puncture depth [mm]"}


def _number(text):
    try:
        return float(text)
    except ValueError:
        return np.nan


def _label(column):
    if column.startswith("force_n_at_"):
        return f"force at {column[len('force_n_at_'):-len('_mm')]} mm [N]"
    return LABELS.get(column, column.replace("_", " "))


def design_map(data, path=None):
    with open(data["csv"], newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    output = data["output"]
    numeric = [p for p in data["parameters"]
               if rows and all(np.isfinite(_number(r[p])) for r in rows)]
    if not numeric:
        raise ValueError("--plot: no swept flag is a number: nothing to draw a map over")
    axes = numeric[:2]
    x = np.array([_number(r[axes[0]]) for r in rows])
    z = np.array([_number(r[output]) for r in rows])
    found = np.isfinite(z)
    fig = Figure(figsize=(6.4, 4.8), constrained_layout=True)
    ax = fig.add_subplot()
    title = f"{_label(output)}: {found.sum()} of {len(rows)} points"
    if len(axes) == 1:
        order = np.argsort(x)
        ax.plot(x[order][found[order]], z[order][found[order]], "o-", color="black", ms=3)
        ax.plot(x[~found], np.full((~found).sum(), np.nanmin(z) if found.any() else 0.0), "x",
                color=FAILED_COLOUR, label="failed")
        ax.set_ylabel(_label(output))
    else:
        y = np.array([_number(r[axes[1]]) for r in rows])
        if found.sum() >= 3:
            tri = Triangulation(x[found], y[found])
            filled = ax.tricontourf(tri, z[found], levels=14, cmap="viridis")
            ax.tricontour(tri, z[found], levels=14, colors="white", linewidths=0.4)
            fig.colorbar(filled, ax=ax, label=_label(output))
        ax.plot(x[found], y[found], ".", color="black", ms=2, label="point")
        ax.plot(x[~found], y[~found], "x", color=FAILED_COLOUR, ms=6, label="failed")
        ax.set_ylabel(axes[1])
        if len(data["parameters"]) > 2:
            title += f" (projected on {axes[0]}, {axes[1]})"
    ax.set_xlabel(axes[0])
    ax.set_title(title)
    if (~found).any():
        ax.legend(loc="best")
    if path is not None:
        save(fig, path)
    return fig
