"""Every command line the docs' pages show (a `build/apps/puncture/puncture ...` line of a
``.. code-block:: sh``) runs and succeeds with the built program, PUNCTURE_CLI: a flag renamed
or a value the program refuses fails here, not in a reader's shell."""
import os
import pathlib
import re
import shlex
import subprocess
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
PROGRAM = "build/apps/puncture/puncture"


def shown_commands():
    """(page, command) for each program line of the pages' sh blocks (with `\\` continuations)."""
    for page in sorted((ROOT / "docs").rglob("*.rst")):
        for block in re.findall(r"^\.\. code-block:: sh\n\n((?:   .*\n|\n)+)", page.read_text(),
                                re.M):
            text = re.sub(r"\\\n\s*", " ", block)
            for line in text.splitlines():
                if line.strip().startswith(PROGRAM):
                    yield page.relative_to(ROOT).as_posix(), line.strip()


class TutorialCommandsTest(unittest.TestCase):
    def test_the_pages_show_commands(self):
        self.assertGreaterEqual(len(list(shown_commands())), 5)

    def test_every_command_shown_runs(self):
        cli = os.environ.get("PUNCTURE_CLI")
        if not cli:
            self.skipTest("PUNCTURE_CLI (the built program) is not set")
        with tempfile.TemporaryDirectory() as work:
            # The commands' files (examples/data/...) relative to the repository, their
            # outputs (-o, --plot) in a scratch folder.
            os.symlink(ROOT / "examples", pathlib.Path(work) / "examples")
            for page, command in shown_commands():
                with self.subTest(page=page, command=command):
                    args = shlex.split(command)
                    run = subprocess.run([cli, *args[1:]], cwd=work, capture_output=True,
                                         text=True, timeout=300)
                    self.assertEqual(run.returncode, 0, run.stderr)


if __name__ == "__main__":
    unittest.main()
