"""Puncture of a clamped thin rubber membrane by a rigid probe (flat, rounded, sphere-tipped, ball, cone).

The C++ solver of the `puncture` project (axisymmetric nonlinear membrane theory, Gent rubber,
Coulomb friction on the indenter; the model is docs/model.md).  Units: lengths in mm, forces in N,
moduli and stresses in MPa.

    import puncture
    problem = puncture.Problem()                      # the paper's membrane, 2 mm indenter
    curve = puncture.loading_curve(problem)           # depth to puncture, numpy columns
    state = puncture.solve_at_force(problem, 0.5)     # one equilibrium with its fields
    puncture.plots.loading_curve(curve, "curve.png")  # matplotlib figures (puncture.plots)

The calibrations of the CLI's `calibrate` and `fit` commands: critical_i1_from_inflation,
friction_from_hole, j_lim_from_puncture_force, fit_uniaxial (every law, uniaxial or
equibiaxial data; with uniaxial_points and uniaxial_points_from_csv), compare_uniaxial_fits
(laws ranked by AIC), material_presets (published materials with their sources), fit_curves (force-depth records, CurveTest, read_force_depth_record),
and puncture_band, the puncture force over the parameters' intervals:

    band = puncture.puncture_band(problem, critical_i1=puncture.plus_minus(95.2, 4.8))

The inflation (bulge) test of the same membrane under a uniform pressure: inflation_curve (from
flat to the burst, with the pressure's limit point), inflate_at_pole_stretch and
inflate_at_pressure (every state at a pressure: the pressure is not monotone):

    curve = puncture.inflation_curve(puncture.InflationProblem(clamp_radius_mm=30))

Why to trust the numbers: verify(problem) runs the checks of `puncture verify` (a second
solver, finite elements minimising the stored energy, fe_solve_at_depths; work = energy; the
small-deflection limit) and returns them with verdicts:

    report = puncture.verify(problem)
    assert report.ok

Invalid input raises ValueError naming the attribute and its allowed range; a solve that does
not converge raises SolverError (a RuntimeError) with .status and .message.
"""

from ._puncture import (
    BandEvaluation,
    BandParameter,
    BandParameters,
    BurstTest,
    Configuration,
    CriticalI1Estimate,
    CurveEvent,
    CurveEventKind,
    CurvePoint,
    Equilibrium,
    FailureKind,
    FailureMode,
    FailureVerdict,
    FitLaw,
    FittedParameter,
    FrictionEstimate,
    Outcome,
    full_report,
    Gent,
    FlatPunch,
    SphereTipped,
    Ball,
    Cone,
    Preload,
    Geometry,
    HoleMethod,
    Inversion,
    JLimEstimate,
    LoadingCurve,
    Material,
    MembraneFields,
    MooneyRivlin,
    NeoHookean,
    Yeoh,
    Ogden,
    ArrudaBoyce,
    GentGent,
    ParameterRange,
    ParameterSensitivity,
    PartTwoEquation,
    Problem,
    PunctureBand,
    PuncturePrediction,
    ScanSample,
    SolverError,
    SolverOptions,
    SpecimenGeometry,
    Stage,
    StageBoundary,
    Status,
    StickCriterion,
    StickRule,
    StickSlipSwitch,
    UniaxialFit,
    InformationCriteria,
    MaterialPreset,
    StressTest,
    __version__,
    burst_tests_from_csv,
    compare_uniaxial_fits,
    critical_i1_from_inflation,
    documented_depth_direction,
    documented_force_direction,
    equibiaxial_first_invariant,
    equibiaxial_stretch_for_first_invariant,
    first_invariant,
    fit_uniaxial,
    force_scale_n,
    information_criteria,
    material_preset,
    material_presets,
    friction_from_hole,
    j_lim_from_puncture_force,
    loading_curve,
    plus_minus,
    predict_puncture,
    puncture_band,
    solve_at_depth,
    solve_at_force,
    stick_slip_boundary,
    uniaxial_points,
    uniaxial_points_from_csv,
)

__all__ = [
    "Outcome",
    "full_report",
    "BandEvaluation",
    "BandParameter",
    "BandParameters",
    "BurstTest",
    "Configuration",
    "CriticalI1Estimate",
    "CurveEvent",
    "CurveEventKind",
    "CurvePoint",
    "Equilibrium",
    "FailureKind",
    "FailureMode",
    "FailureVerdict",
    "FitLaw",
    "FittedParameter",
    "FrictionEstimate",
    "Gent",
    "FlatPunch",
    "SphereTipped",
    "Ball",
    "Cone",
    "Preload",
    "Geometry",
    "HoleMethod",
    "Inversion",
    "JLimEstimate",
    "LoadingCurve",
    "Material",
    "MembraneFields",
    "MooneyRivlin",
    "NeoHookean",
    "Yeoh",
    "Ogden",
    "ArrudaBoyce",
    "GentGent",
    "ParameterRange",
    "ParameterSensitivity",
    "PartTwoEquation",
    "Problem",
    "PunctureBand",
    "PuncturePrediction",
    "ScanSample",
    "SolverError",
    "SolverOptions",
    "SpecimenGeometry",
    "Stage",
    "StageBoundary",
    "Status",
    "StickCriterion",
    "StickRule",
    "StickSlipSwitch",
    "UniaxialFit",
    "InformationCriteria",
    "MaterialPreset",
    "StressTest",
    "burst_tests_from_csv",
    "compare_uniaxial_fits",
    "critical_i1_from_inflation",
    "documented_depth_direction",
    "documented_force_direction",
    "equibiaxial_first_invariant",
    "equibiaxial_stretch_for_first_invariant",
    "first_invariant",
    "fit_uniaxial",
    "force_scale_n",
    "information_criteria",
    "material_preset",
    "material_presets",
    "friction_from_hole",
    "j_lim_from_puncture_force",
    "loading_curve",
    "plots",
    "plus_minus",
    "predict_puncture",
    "puncture_band",
    "solve_at_depth",
    "solve_at_force",
    "stick_slip_boundary",
    "uniaxial_points",
    "uniaxial_points_from_csv",
]

# The inflation (bulge) test.
from ._puncture import (  # noqa: E402
    ExtremumKind,
    InflationAtPressure,
    InflationBurst,
    InflationCurve,
    InflationProblem,
    InflationState,
    PressureExtremum,
    inflate_at_pole_stretch,
    inflate_at_pressure,
    inflation_burst,
    inflation_curve,
    pressure_extrema,
)

__all__ += [
    "ExtremumKind",
    "InflationAtPressure",
    "InflationBurst",
    "InflationCurve",
    "InflationProblem",
    "InflationState",
    "PressureExtremum",
    "inflate_at_pole_stretch",
    "inflate_at_pressure",
    "inflation_burst",
    "inflation_curve",
    "pressure_extrema",
]

# The fit of force-depth records (`puncture fit curve`).
from ._puncture import (  # noqa: E402
    CurveFit,
    CurveTest,
    CurveTestFit,
    FittedCurveParameter,
    fit_curves,
    read_force_depth_record,
)

__all__ += [
    "CurveFit",
    "CurveTest",
    "CurveTestFit",
    "FittedCurveParameter",
    "fit_curves",
    "read_force_depth_record",
]

# The second method (finite elements) and the cross-checks of `puncture verify`.
from ._puncture import (  # noqa: E402
    FeContact,
    FePart,
    FeState,
    VerificationCheck,
    VerificationReport,
    Verdict,
    fe_inflated_state,
    fe_solve_at_depths,
    verify,
)

__all__ += [
    "FeContact",
    "FePart",
    "FeState",
    "VerificationCheck",
    "VerificationReport",
    "Verdict",
    "fe_inflated_state",
    "fe_solve_at_depths",
    "verify",
]

# Failure criteria (the CLI's --criterion NAME:VALUE) and their critical values from bursts.
from ._puncture import (  # noqa: E402
    CriticalEnergyDensity,
    CriticalEnergyRelease,
    CriticalFirstInvariant,
    CriticalTrueStress,
    CriticalValueEstimate,
    EnergyRelease,
    FailureAssessment,
    MaxPrincipalStretch,
    assess,
    criterion_from_name,
    criterion_name,
    criterion_names,
    critical_value_from_inflation,
    describe_criterion,
    energy_release,
    failure_criteria,
    measure_at,
)

__all__ += [
    "CriticalEnergyDensity",
    "CriticalEnergyRelease",
    "CriticalFirstInvariant",
    "CriticalTrueStress",
    "CriticalValueEstimate",
    "EnergyRelease",
    "FailureAssessment",
    "MaxPrincipalStretch",
    "assess",
    "criterion_from_name",
    "criterion_name",
    "criterion_names",
    "critical_value_from_inflation",
    "describe_criterion",
    "energy_release",
    "failure_criteria",
    "measure_at",
]

# Sweeps: many problems on every core (sweeps.py, the engine of `puncture sweep`).
from .sweeps import sweep  # noqa: E402

__all__ += ["sweep"]

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
