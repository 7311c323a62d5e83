#!/usr/bin/env python3
"""The benchmarks as ratios to one Part I integration (BM_PartOneIntegration) measured in the same
run: the machine-independent unit.  With a second program (e.g. a build of an earlier commit), the
two are run alternately and each benchmark's time ratio after / before is printed as well.

    bench/ratios.py build/bench/puncture_bench [BEFORE_BENCH] [--runs N] [--filter REGEX]

Medians over the runs of the CPU time; standard library only.
"""
import argparse
import json
import statistics
import subprocess
import sys

BASELINE = "BM_PartOneIntegration"


def run(program, pattern):
    out = subprocess.run(
        [program, f"--benchmark_filter={pattern}", "--benchmark_min_time=0.5",
         "--benchmark_format=json"],
        capture_output=True, text=True, check=True).stdout
    return {b["name"]: b["cpu_time"] * {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
            for b in json.loads(out)["benchmarks"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("program")
    parser.add_argument("before", nargs="?")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--filter", default="PartOne|AtForce|AtDepth|Puncture|LoadingCurve")
    args = parser.parse_args()
    pattern = f"{BASELINE}|{args.filter}"
    programs = [args.program] + ([args.before] if args.before else [])
    times = {p: {} for p in programs}
    for k in range(args.runs):
        for p in programs:  # alternately, so that both see the same load on the machine
            for name, t in run(p, pattern).items():
                times[p].setdefault(name, []).append(t)
            print(f"run {k + 1}/{args.runs}: {p}", file=sys.stderr)
    median = {p: {n: statistics.median(v) for n, v in times[p].items()} for p in programs}
    now = median[args.program]
    head = f"{'benchmark':34s} {'time':>10s} {'/ one integration':>18s}"
    if args.before:
        head += f" {'before':>10s} {'/ one integration':>18s} {'after / before':>15s}"
    print(head)
    for name, t in now.items():
        line = f"{name:34s} {t * 1e3:8.3f} ms {t / now[BASELINE]:18.1f}"
        if args.before:
            b = median[args.before]
            if name in b:
                line += f" {b[name] * 1e3:8.3f} ms {b[name] / b[BASELINE]:18.1f} {t / b[name]:15.3f}"
        print(line)


if __name__ == "__main__":
    main()
