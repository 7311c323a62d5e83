# Sphinx configuration of the documentation site, built by scripts/build-docs.sh (which sets
# PUNCTURE_DOCS_BUILD to the directory holding Doxygen's XML and the generated CLI reference).
import os
import pathlib
import re

from docutils import nodes
from sphinx.util.docutils import SphinxDirective

root = pathlib.Path(__file__).resolve().parent.parent
docs_build = os.environ.get("PUNCTURE_DOCS_BUILD")
if not docs_build:
    raise RuntimeError("PUNCTURE_DOCS_BUILD is not set: build the docs with scripts/build-docs.sh")
docs_build = pathlib.Path(docs_build)

project = "puncture"
author = "the puncture authors"
copyright = "the puncture authors"
# One version, the project's (CMakeLists.txt).
release = re.search(r"project\(puncture VERSION ([0-9.]+)",
                    (root / "CMakeLists.txt").read_text()).group(1)
version = release

extensions = ["myst_parser", "breathe", "sphinx.ext.mathjax"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
# Not pages: the help2man include and the Doxygen filter's neighbours.
exclude_patterns = ["puncture.h2m", "CMakeLists.txt"]

# The Markdown pages (model, verification, architecture) write maths as $..$ and $$..$$, and
# link to each other's sections by their headings.
myst_enable_extensions = ["dollarmath"]
myst_heading_anchors = 3

# The C++ API from Doxygen's XML (include/puncture/).
breathe_projects = {"puncture": str(docs_build / "doxygen" / "xml")}
breathe_default_project = "puncture"
breathe_default_members = ("members", "undoc-members")
primary_domain = "cpp"
highlight_language = "none"  # a plain ``` block (text, tables) as it is

try:
    import sphinx_rtd_theme  # noqa: F401  (python3-sphinx-rtd-theme)
    html_theme = "sphinx_rtd_theme"
except ImportError:
    html_theme = "alabaster"
html_title = f"puncture {release}"
html_show_sourcelink = False


def _group_id(header):
    """The Doxygen group of a header (docs/doxygen_filter.py): puncture_problem_hpp."""
    return re.sub(r"[^A-Za-z0-9]", "_", header)


def _generated_pages(app, docname, source):
    """The page `cli` is written at build time by docs/cli_reference.py from the program's
    --help (the committed cli.rst only says so); the page `api` gets every public header it
    does not list yet, so that a new header is documented without editing it."""
    if docname == "cli":
        source[0] = (docs_build / "generated" / "cli.rst").read_text(encoding="utf-8")
    elif docname == "api":
        headers = sorted(p.relative_to(root / "include").as_posix()
                         for p in (root / "include" / "puncture").rglob("*.hpp"))
        listed = set(re.findall(r"^\.\. doxygengroup:: (\S+)", source[0], re.M))
        missing = [h for h in headers if _group_id(h) not in listed]
        if missing:
            source[0] += "\nOther headers\n-------------\n\n" + "".join(
                f"``{h}``\n{'~' * (len(h) + 4)}\n\n.. doxygengroup:: {_group_id(h)}\n\n"
                for h in missing)


class RunOutput(SphinxDirective):
    """`.. run-output:: NAME`: what a program printed when the docs were built, as a literal
    block: scripts/build-docs.sh runs every example (NAME: the example's, e.g. 01_puncture_point)
    and the CLI's first run (puncture_puncture)."""
    required_arguments = 1

    def run(self):
        path = docs_build / "generated" / "output" / (self.arguments[0] + ".txt")
        if not path.exists():
            raise self.error(f"no output of {self.arguments[0]}: {path} is missing "
                             "(scripts/build-docs.sh runs the built programs)")
        self.env.note_dependency(str(path))
        text = path.read_text(encoding="utf-8")
        block = nodes.literal_block(text, text)
        block["language"] = "text"
        return [block]


def setup(app):
    app.connect("source-read", _generated_pages)
    app.add_directive("run-output", RunOutput)
