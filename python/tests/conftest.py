"""Shared fixtures: the built `puncture` package (PYTHONPATH=<build>/python) and the built CLI
($PUNCTURE_CLI), both set by ctest (python/CMakeLists.txt)."""

import json
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli_path():
    path = os.environ.get("PUNCTURE_CLI")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("PUNCTURE_CLI is not set to the built puncture executable")
    return path


class Cli:
    def __init__(self, path):
        self.path = path

    def run(self, *args, env=None):
        """(exit code, stdout, stderr) of `puncture args...`."""
        full_env = dict(os.environ)
        full_env.update(env or {})
        p = subprocess.run([self.path, *map(str, args)], capture_output=True, text=True,
                           env=full_env, timeout=600)
        return p.returncode, p.stdout, p.stderr

    def json(self, *args):
        """The parsed --format json output of a successful run."""
        rc, out, err = self.run(*args, "--format", "json")
        assert rc == 0, err
        return json.loads(out)


@pytest.fixture(scope="session")
def cli(cli_path):
    return Cli(cli_path)
