"""Puncture of a clamped thin rubber membrane by a rigid flat-ended cylindrical indenter.

The C++ solver of the `puncture` project (axisymmetric nonlinear membrane theory, Gent rubber,
Coulomb friction on the indenter; the model is docs/model.md).  Units: lengths in mm, forces in N,
moduli and stresses in MPa.

    import puncture
    problem = puncture.Problem()                      # the paper's membrane, 2 mm indenter
    curve = puncture.loading_curve(problem)           # depth to puncture, numpy columns
    state = puncture.solve_at_force(problem, 0.5)     # one equilibrium with its fields
    puncture.plots.loading_curve(curve, "curve.png")  # matplotlib figures (puncture.plots)

Invalid input raises ValueError naming the attribute and its allowed range; a solve that does
not converge raises SolverError (a RuntimeError) with .status and .message.
"""

from ._puncture import (
    Configuration,
    CurvePoint,
    Equilibrium,
    Gent,
    Geometry,
    LoadingCurve,
    Material,
    MembraneFields,
    MooneyRivlin,
    NeoHookean,
    PartTwoEquation,
    Problem,
    PuncturePrediction,
    SolverError,
    SolverOptions,
    Stage,
    StageBoundary,
    Status,
    StickCriterion,
    StickRule,
    StickSlipSwitch,
    __version__,
    first_invariant,
    force_scale_n,
    loading_curve,
    predict_puncture,
    solve_at_depth,
    solve_at_force,
    stick_slip_boundary,
)

__all__ = [
    "Configuration",
    "CurvePoint",
    "Equilibrium",
    "Gent",
    "Geometry",
    "LoadingCurve",
    "Material",
    "MembraneFields",
    "MooneyRivlin",
    "NeoHookean",
    "PartTwoEquation",
    "Problem",
    "PuncturePrediction",
    "SolverError",
    "SolverOptions",
    "Stage",
    "StageBoundary",
    "Status",
    "StickCriterion",
    "StickRule",
    "StickSlipSwitch",
    "first_invariant",
    "force_scale_n",
    "loading_curve",
    "plots",
    "predict_puncture",
    "solve_at_depth",
    "solve_at_force",
    "stick_slip_boundary",
]

# Shown as puncture.Problem, puncture.SolverError, ... rather than puncture._puncture.*.
for _name in __all__:
    _obj = globals().get(_name)
    if isinstance(_obj, type):
        _obj.__module__ = __name__
del _name, _obj


def __getattr__(name):
    # `puncture.plots` without importing matplotlib for users who never plot.
    if name == "plots":
        import importlib

        return importlib.import_module(".plots", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
