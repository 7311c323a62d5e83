"""Draws the `puncture` command-line tool's results; the CLI runs it for --plot and figures.

    python3 plot_cli.py curve   CURVE.json   OUT.png|svg|pdf   (puncture curve --format json)
    python3 plot_cli.py state   STATE.json   OUT.png|svg|pdf   (puncture state --format json)
    python3 plot_cli.py figures FIGURES.json OUT_DIR           (puncture figures)
    python3 plot_cli.py uniaxial-fit FIT.json OUT.png|svg|pdf  (puncture fit uniaxial --format json)
    python3 plot_cli.py uniaxial-compare FITS.json OUT.png|svg|pdf
                                                  (puncture fit uniaxial --compare ... --format json)
    python3 plot_cli.py band  BAND.json  OUT.png|svg|pdf       (puncture calibrate band ...)
    python3 plot_cli.py jlim  JLIM.json  OUT.png|svg|pdf       (puncture calibrate jlim ...)
    python3 plot_cli.py sweep   MAP.json     OUT.png|svg|pdf   (puncture sweep --plot)
    python3 plot_cli.py fit-curve FIT.json   OUT.png|svg|pdf   (puncture fit curve --format json)

Needs numpy and matplotlib, not the compiled extension.  Exit status: 0 drawn, 2 bad usage,
3 numpy or matplotlib missing, 1 any other failure; the reason goes to stderr.
"""

import json
import sys

KINDS = ("curve", "state", "figures", "uniaxial-fit", "uniaxial-compare", "fit-curve", "band",
         "jlim", "sweep")
EXIT_USAGE = 2
EXIT_MISSING_MODULE = 3


def _modules():
    if __package__:
        from . import calibration_plots, paper_figures, plots, sweep_plots
    else:  # run as a script: its directory is on sys.path
        import calibration_plots
        import paper_figures
        import plots
        import sweep_plots
    return plots, paper_figures, calibration_plots, sweep_plots


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 3 or argv[0] not in KINDS:
        print(f"usage: plot_cli.py {'|'.join(KINDS)} DATA.json OUTPUT", file=sys.stderr)
        return EXIT_USAGE
    kind, data_path, target = argv
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as e:
        print(
            f"puncture: plot: {sys.executable} cannot import {e.name or e}: install it (Debian: "
            "apt-get install python3-matplotlib python3-numpy) or set PUNCTURE_PYTHON to a "
            "Python 3 that has numpy and matplotlib",
            file=sys.stderr,
        )
        return EXIT_MISSING_MODULE
    try:
        plots, paper_figures, calibration_plots, sweep_plots = _modules()
        with open(data_path, encoding="utf-8") as f:
            data = json.load(f)
        if kind == "curve":
            plots.loading_curve(data, target)
        elif kind == "state":
            plots.state_overview(data, target)
        elif kind == "uniaxial-fit":
            calibration_plots.uniaxial_fit(data, target)
        elif kind == "uniaxial-compare":
            calibration_plots.uniaxial_comparison(data, target)
        elif kind == "band":
            calibration_plots.puncture_band(data, target)
        elif kind == "jlim":
            calibration_plots.j_lim_scan(data, target)
        elif kind == "sweep":
            sweep_plots.design_map(data, target)
        elif kind == "fit-curve":
            plots.fit_curves(data, target)
        else:
            for path in paper_figures.draw_all(data, target):
                print(path)
    except Exception as e:  # noqa: BLE001 - reported, not hidden
        print(f"puncture: plot: {type(e).__name__}: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
