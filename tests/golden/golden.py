#!/usr/bin/env python3
"""Golden outputs of the `puncture` CLI: every number it prints, kept so that a change of the
code's structure can be shown to change no number.

    golden.py check  PUNCTURE_EXE DATA_DIR [CASE ...]   compare (exit 1 on any difference)
    golden.py record PUNCTURE_EXE DATA_DIR [CASE ...]   (re)write the stored outputs
    golden.py added  PUNCTURE_EXE DATA_DIR [CASE ...]   as check, but keys the stored output
                                                       lacks are allowed (an output that gained
                                                       fields keeps every old number: run this
                                                       before recording it again)

Each case runs the CLI with --format json and stores its output.  `check` compares the parsed
JSON: the same keys, arrays of the same lengths, the same strings and booleans, integers exactly,
and floating-point numbers to 1e-12 relative (with an absolute floor of 1e-300: a stored zero must
stay zero).  Record again only for an intended change of the numbers, and say why in the commit.
Standard library only, so any Python 3 runs it.
"""
import json
import pathlib
import subprocess
import sys

RELATIVE_TOLERANCE = 1e-12
ABSOLUTE_FLOOR = 1e-300

TESTS = pathlib.Path(__file__).resolve().parent.parent
CLI_DATA = TESTS / "cli"

# name -> CLI arguments (without --format json).  Each law, each stick rule, both Part II
# equations, the states, the puncture points, the inflation test, the calibrations, verify, the
# curved probes and a gas pressure.
CASES = {
    "curve_default": ["curve"],
    "curve_dry_1mm": ["curve", "--points", "60", "--indenter-radius", "1", "--friction", "1.95"],
    "curve_frictionless": ["curve", "--points", "60", "--friction", "0"],
    "curve_neo_hookean": ["curve", "--points", "60", "--material", "neo-hookean",
                          "--critical-i1", "30"],
    "curve_mooney_rivlin": ["curve", "--points", "60", "--material", "mooney-rivlin",
                            "--critical-i1", "40"],
    "curve_stick_force": ["curve", "--points", "60", "--stick", "force:0.3"],
    "curve_stick_depth": ["curve", "--points", "60", "--stick", "depth:10"],
    "curve_stick_edge_tension": ["curve", "--points", "60", "--stick", "edge-tension:0.02"],
    "curve_stick_always": ["curve", "--points", "60", "--stick", "always"],
    "curve_paper_eq18": ["curve", "--points", "60", "--part-two-equation", "paper-eq18"],
    "curve_max_depth": ["curve", "--points", "30", "--max-depth", "10", "--indenter-radius", "4"],
    "state_force_slip": ["state", "--force", "0.3"],
    "state_force_part_two": ["state", "--force", "0.6"],
    "state_depth": ["state", "--depth", "20"],
    "state_stick": ["state", "--stick", "always", "--force", "0.5"],
    "state_stick_depth": ["state", "--stick", "always", "--depth", "12"],
    "state_auto_held": ["state", "--stick", "force:0.3", "--force", "0.2"],
    "state_neo_hookean": ["state", "--material", "neo-hookean", "--force", "0.4"],
    "state_mooney_rivlin": ["state", "--material", "mooney-rivlin", "--depth", "15"],
    "state_unloaded": ["state", "--force", "0"],
    "puncture_default": ["puncture"],
    "puncture_dry_small": ["puncture", "--indenter-radius", "1", "--friction", "1.95"],
    "puncture_frictionless": ["puncture", "--friction", "0"],
    "puncture_neo_hookean": ["puncture", "--material", "neo-hookean", "--critical-i1", "30"],
    "puncture_mooney_rivlin": ["puncture", "--material", "mooney-rivlin", "--critical-i1", "40"],
    "puncture_stick_force": ["puncture", "--stick", "force:0.3"],
    "puncture_stick_always": ["puncture", "--stick", "always", "--indenter-radius", "4"],
    "puncture_paper_eq18": ["puncture", "--part-two-equation", "paper-eq18"],
    "puncture_large_indenter": ["puncture", "--indenter-radius", "4", "--thickness", "0.3"],
    "inflate_curve": ["inflate"],
    "inflate_pole_stretch": ["inflate", "--pole-stretch", "2"],
    "inflate_pressure": ["inflate", "--pressure", "0.0006"],
    "inflate_neo_hookean": ["inflate", "--material", "neo-hookean"],
    "calibrate_critical_i1": ["calibrate", "critical-i1", "--mark-radius", "0.5",
                              "--burst-radii", "3.346,3.407,3.515,3.527"],
    "fit_uniaxial_gent": ["fit", "uniaxial", str(CLI_DATA / "uniaxial_gent.csv"),
                          "--material", "gent"],
    "fit_uniaxial_neo_hookean": ["fit", "uniaxial", str(CLI_DATA / "uniaxial_gent.csv"),
                                 "--material", "neo-hookean"],
    "calibrate_jlim": ["calibrate", "jlim", "--shear-modulus", "0.05988", "--critical-i1",
                       "95.2", "--indenter-radius", "2", "--puncture-force", "0.7"],
    "calibrate_friction": ["calibrate", "friction", "--shear-modulus", "0.05988", "--jlim",
                           "124.86", "--indenter-radius", "1", "--puncture-force", "1.72",
                           "--hole-ratio", "1.58", "--hole-ratio-sd", "0.14"],
    "calibrate_band": ["calibrate", "band", "--critical-i1-sd", "4.8", "--friction-sd", "0.05"],
    "verify_default": ["verify", "--elements", "32", "--depths", "3"],
    # The curved probes and a gas pressure: states at a force and punctures (their curves' points
    # follow the depth Newton's stopping, within the curve tolerance, so no curve here).
    "state_sphere_tipped": ["state", "--indenter", "sphere-tipped", "--force", "0.3"],
    "state_fillet": ["state", "--fillet-radius", "0.5", "--force", "0.3"],
    "state_ball": ["state", "--indenter", "ball", "--ball-radius", "2", "--indenter-radius", "1",
                   "--force", "0.1"],
    "state_cone": ["state", "--indenter", "cone", "--cone-half-angle", "30", "--tip-radius", "0.5",
                   "--force", "0.1"],
    "state_pressure": ["state", "--pressure", "3e-4", "--force", "0.5"],
    "state_sphere_stick": ["state", "--indenter", "sphere-tipped", "--stick", "always", "--force",
                           "0.3"],
    "puncture_sphere_tipped": ["puncture", "--indenter", "sphere-tipped"],
    "puncture_astm": ["puncture", "--test", "astm-f1306", "--friction", "0"],
}


def without_checkout(value):
    """The output with the checkout's own path (input files echoed back) replaced by $TESTS."""
    if isinstance(value, str):
        return value.replace(str(TESTS), "$TESTS")
    if isinstance(value, list):
        return [without_checkout(v) for v in value]
    if isinstance(value, dict):
        return {k: without_checkout(v) for k, v in value.items()}
    return value


def run(exe, args):
    proc = subprocess.run([exe, *args, "--format", "json"], capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError(f"exit code {proc.returncode}: {' '.join(args)}\n{proc.stderr}")
    return without_checkout(json.loads(proc.stdout))


def differences(stored, now, path="$", allow_added=False):
    """Every place where `now` differs from `stored` beyond the tolerance, as text (keys new in
    `now` are differences unless allow_added)."""
    if isinstance(stored, bool) or isinstance(now, bool) or stored is None or now is None:
        return [] if stored == now else [f"{path}: {stored!r} -> {now!r}"]
    if isinstance(stored, (int, float)) and isinstance(now, (int, float)):
        if isinstance(stored, int) and isinstance(now, int):
            return [] if stored == now else [f"{path}: {stored} -> {now}"]
        scale = max(abs(stored), abs(now))
        if abs(stored - now) <= max(RELATIVE_TOLERANCE * scale, ABSOLUTE_FLOOR):
            return []
        return [f"{path}: {stored!r} -> {now!r} (relative {abs(stored - now) / scale:.3g})"]
    if type(stored) is not type(now):
        return [f"{path}: {type(stored).__name__} -> {type(now).__name__}"]
    if isinstance(stored, dict):
        out = [f"{path}.{k}: missing now" for k in stored if k not in now]
        if not allow_added:
            out += [f"{path}.{k}: new" for k in now if k not in stored]
        for k in stored:
            if k in now:
                out += differences(stored[k], now[k], f"{path}.{k}", allow_added)
        return out
    if isinstance(stored, list):
        if len(stored) != len(now):
            return [f"{path}: {len(stored)} items -> {len(now)}"]
        out = []
        for i, (a, b) in enumerate(zip(stored, now)):
            out += differences(a, b, f"{path}[{i}]", allow_added)
        return out
    return [] if stored == now else [f"{path}: {stored!r} -> {now!r}"]


def main(argv):
    if len(argv) < 4 or argv[1] not in ("check", "record", "added"):
        print(__doc__, file=sys.stderr)
        return 2
    mode, exe, data = argv[1], argv[2], pathlib.Path(argv[3])
    names = argv[4:] or list(CASES)
    unknown = [n for n in names if n not in CASES]
    if unknown:
        print(f"unknown case(s): {', '.join(unknown)}", file=sys.stderr)
        return 2
    failed = 0
    for name in names:
        now = run(exe, CASES[name])
        file = data / f"{name}.json"
        if mode == "record":
            data.mkdir(parents=True, exist_ok=True)
            file.write_text(json.dumps(now, indent=1) + "\n")
            print(f"recorded {name}")
            continue
        if not file.exists():
            print(f"{name}: no stored output {file} (run golden.py record)")
            failed += 1
            continue
        diff = differences(json.loads(file.read_text()), now, allow_added=mode == "added")
        if diff:
            failed += 1
            print(f"{name}: {len(diff)} difference(s)")
            for line in diff[:20]:
                print(f"  {line}")
        else:
            print(f"{name}: same")
    if mode != "record":
        print(f"{len(names) - failed} of {len(names)} cases unchanged")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
