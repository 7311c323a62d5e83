#!/usr/bin/env bash
# Builds the documentation site into BUILD_DIR/docs/html (default BUILD_DIR: build):
#   1. Doxygen reads the public headers (include/puncture/) into XML for Breathe, through
#      docs/doxygen_filter.py (the headers' plain comments are their documentation);
#   2. docs/cli_reference.py writes the CLI reference from BUILD_DIR/apps/puncture/puncture's own
#      --help, every command and subcommand found from the top-level help;
#   3. the examples (BUILD_DIR/examples/) and `puncture puncture` run, for the output the pages
#      show;
#   4. Sphinx (with MyST for the Markdown pages and Breathe for the API) writes the HTML.
# Any warning of Doxygen or Sphinx fails the build (exit 1).  Needs the built `puncture` program
# and examples, and the Debian packages doxygen, python3-sphinx, python3-breathe, python3-myst-parser
# (scripts/install-deps.sh); python3-sphinx-rtd-theme is used when installed.  No network.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
if [[ ! -d "${1:-$root/build}" ]]; then
  echo "build-docs.sh: build directory ${1:-$root/build} not found (usage: scripts/build-docs.sh [BUILD_DIR])" >&2
  exit 1
fi
build="$(cd "${1:-$root/build}" && pwd)"
python="${PUNCTURE_PYTHON:-/usr/bin/python3}"
cli="$build/apps/puncture/puncture"
out="$build/docs"

if [[ ! -x "$cli" ]]; then
  echo "build-docs.sh: $cli not found: build the program first (cmake --build $build --target puncture)" >&2
  exit 1
fi
for tool in doxygen "$python"; do
  command -v "$tool" >/dev/null || { echo "build-docs.sh: $tool not found (scripts/install-deps.sh)" >&2; exit 1; }
done
if ! "$python" -c "import sphinx, breathe, myst_parser" 2>/dev/null; then
  echo "build-docs.sh: $python cannot import sphinx, breathe and myst_parser (scripts/install-deps.sh)" >&2
  exit 1
fi

rm -rf "$out/doxygen" "$out/generated" "$out/html" "$out/doctrees"
mkdir -p "$out/doxygen" "$out/generated"

# Doxygen: XML only, for Breathe; every header of the public API, warnings are errors.
cat >"$out/Doxyfile" <<EOF
PROJECT_NAME           = puncture
INPUT                  = $root/include/puncture
FILE_PATTERNS          = *.hpp
RECURSIVE              = YES
STRIP_FROM_PATH        = $root/include
STRIP_FROM_INC_PATH    = $root/include
FULL_PATH_NAMES        = YES
INPUT_FILTER           = "$python $root/docs/doxygen_filter.py"
FILTER_SOURCE_FILES    = NO
OUTPUT_DIRECTORY       = $out/doxygen
GENERATE_HTML          = NO
GENERATE_LATEX         = NO
GENERATE_XML           = YES
XML_PROGRAMLISTING     = NO
EXTRACT_ALL            = YES
EXTRACT_PRIVATE        = NO
EXTRACT_STATIC         = YES
JAVADOC_AUTOBRIEF      = NO
MARKDOWN_SUPPORT       = YES
AUTOLINK_SUPPORT       = NO
ENABLE_PREPROCESSING   = YES
QUIET                  = YES
WARNINGS               = YES
WARN_IF_UNDOCUMENTED   = NO
WARN_AS_ERROR          = FAIL_ON_WARNINGS
EOF
(cd "$out" && doxygen Doxyfile)

# The CLI reference, from the program's own help.
"$python" "$root/docs/cli_reference.py" "$cli" "$out/generated/cli.rst"

# The output the pages show: the tutorials' examples and the program's puncture point, run in
# parallel (each is one thread).
mkdir -p "$out/generated/output"
"$cli" puncture >"$out/generated/output/puncture_puncture.txt" &
pids=("$!:puncture puncture")
for source in "$root"/examples/[0-9][0-9]_*.cpp; do
  name="$(basename "$source" .cpp)"
  if [[ ! -x "$build/examples/$name" ]]; then
    echo "build-docs.sh: $build/examples/$name not found: build the examples first" >&2
    exit 1
  fi
  (cd "$out/generated/output" && timeout 300 "$build/examples/$name" >"$name.txt") &
  pids+=("$!:$name")
done
for job in "${pids[@]}"; do
  wait "${job%%:*}" || { echo "build-docs.sh: ${job#*:} failed" >&2; exit 1; }
done

# Sphinx: warnings are errors, all of them reported before failing.
PUNCTURE_DOCS_BUILD="$out" "$python" -m sphinx -W --keep-going -q -b html \
  -d "$out/doctrees" "$root/docs" "$out/html"
echo "build-docs.sh: $out/html/index.html"
