#!/usr/bin/env python3
"""Writes the CLI reference page (reStructuredText) from the program's own help.

    cli_reference.py PUNCTURE_EXE OUTPUT.rst

The commands are not listed here: they are read from the "Subcommands:" section of
`puncture --help`, then of each command's --help in turn (e.g. `calibrate` -> `critical-i1`),
so a new command appears in the reference without editing anything.  Each command's section is
its --help verbatim.  Exits 1 naming the command when a --help fails.  Standard library only.
"""
import re
import subprocess
import sys

# A subcommand's line: two spaces, its name, then its description after two or more spaces
# (continuation lines of a description are indented further).
SUBCOMMAND = re.compile(r"^  ([a-z][a-z0-9-]*)(\s{2,}|$)")


def help_text(exe, path):
    run = subprocess.run([exe, *path, "--help"], capture_output=True, text=True, timeout=60)
    if run.returncode != 0:
        command = " ".join(["puncture", *path, "--help"])
        sys.exit(f"cli_reference.py: '{command}' failed (exit {run.returncode}): {run.stderr}")
    return run.stdout


def subcommands(text):
    """The names listed in the "Subcommands:" section of a help text, in order."""
    names, inside = [], False
    for line in text.splitlines():
        if line.startswith("Subcommands:"):
            inside = True
        elif inside and not line.strip():
            break
        elif inside and (m := SUBCOMMAND.match(line)):
            names.append(m.group(1))
    return names


def commands(exe, path=()):
    """(path, help) for the program and every command below it, depth first."""
    text = help_text(exe, list(path))
    yield path, text
    for name in subcommands(text):
        yield from commands(exe, (*path, name))


def section(path, text):
    """A command's section: a sub-subcommand (e.g. `calibrate band`) one level below its
    command."""
    title = "``" + " ".join(["puncture", *path]) + "``"
    underline = "~" if len(path) > 1 else "-"
    lines = [title, underline * len(title), "", ".. code-block:: text", ""]
    lines += ["   " + line if line.strip() else "" for line in text.rstrip().splitlines()]
    return "\n".join(lines) + "\n\n"


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: cli_reference.py PUNCTURE_EXE OUTPUT.rst")
    exe, output = sys.argv[1], sys.argv[2]
    found = list(commands(exe))
    page = [
        "Command-line reference",
        "======================",
        "",
        "Every command of the ``puncture`` program with its options, as its own ``--help``",
        "prints them (this page is generated from the program when the documentation is built).",
        "Units: lengths in mm, forces in N, moduli and stresses in MPa.",
        "",
        "Commands: " + ", ".join("``" + " ".join(p) + "``" for p, _ in found if p) + ".",
        "",
    ]
    with open(output, "w", encoding="utf-8") as f:
        f.write("\n".join(page) + "\n")
        for path, text in found:
            f.write(section(path, text))


if __name__ == "__main__":
    main()
