"""The docs site's two generators: the Doxygen filter that reads the headers' plain comments as
documentation, and the CLI reference's discovery of commands from --help.  Standard library
only: /usr/bin/python3 -m unittest discover -s tests/docs."""
import pathlib
import sys
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "docs"))
import cli_reference  # noqa: E402
import doxygen_filter  # noqa: E402

HEADER = """#pragma once
// What the header holds.
// A second line, x <= 1 and #13.
#include <string>

namespace puncture {

// ---------------------------------------------------------------------------------------------
// A section heading, followed by a blank line.

// The membrane's dimensions.
struct Geometry {
  double clamp_radius_mm = 25.0;  // radius A [mm]
  int count = 0;                  // a trailing comment
                                  // continued on the next line
  // A leading comment of the next member.
  double thickness_mm = 0.2;
  bool ok() const {
    // inside a body: left alone
    return true;
  }
  // A closing remark of the struct.
};

}  // namespace puncture
"""


class DoxygenFilterTest(unittest.TestCase):
    def setUp(self):
        self.out = doxygen_filter.filter_header("/src/include/puncture/problem.hpp",
                                                HEADER.split("\n"))

    def line_with(self, text):
        return next(line for line in self.out if text in line)

    def test_the_header_is_a_group_documented_by_its_opening_comment(self):
        self.assertEqual(self.out[1], "/// \\defgroup puncture_problem_hpp puncture/problem.hpp")
        self.assertEqual(self.out[2], "/// What the header holds.")
        # Doxygen's special characters stay text.
        self.assertEqual(self.out[3], "/// A second line, x \\<= 1 and \\#13.")

    def test_the_namespace_content_is_in_the_group(self):
        opening = self.out.index("namespace puncture {")
        self.assertEqual(self.out[opening + 1:opening + 3],
                         ["/// \\addtogroup puncture_problem_hpp", "/// @{"])
        self.assertEqual(self.out[-3:-1], ["/// @}", "}  // namespace puncture"])

    def test_leading_trailing_and_continued_comments_document_declarations(self):
        self.assertEqual(self.line_with("The membrane's"), "/// The membrane's dimensions.")
        self.assertIn("25.0;  ///< radius A [mm]", self.line_with("clamp_radius_mm"))
        self.assertEqual(self.line_with("continued").strip(), "///< continued on the next line")
        self.assertEqual(self.line_with("A leading comment").strip(),
                         "/// A leading comment of the next member.")

    def test_section_headings_rulers_and_bodies_stay_plain(self):
        self.assertEqual(self.line_with("section heading"),
                         "// A section heading, followed by a blank line.")
        self.assertFalse(any("-----" in line for line in self.out))
        self.assertEqual(self.line_with("inside a body").strip(), "// inside a body: left alone")
        self.assertEqual(self.line_with("closing remark").strip(),
                         "// A closing remark of the struct.")

    def test_a_comment_in_a_string_is_code(self):
        self.assertEqual(doxygen_filter.split_code_comment('s = "a // b";  // note'),
                         ('s = "a // b";  ', " note"))


HELP = """Model parameters from experiments
Usage: puncture calibrate [OPTIONS] SUBCOMMAND

Options:
  -h,--help                       Print this help message and exit

Subcommands:
  critical-i1                     Critical I1 from inflation (bulge) tests: the mark at the
                                  membrane's centre
  jlim                            Gent J_lim from one puncture test
  band                            The predicted puncture force and its band

Examples:
  puncture calibrate jlim --puncture-force 0.7
"""


class CliReferenceTest(unittest.TestCase):
    def test_subcommands_are_read_from_their_section_only(self):
        self.assertEqual(cli_reference.subcommands(HELP), ["critical-i1", "jlim", "band"])

    def test_a_help_without_subcommands_has_none(self):
        self.assertEqual(cli_reference.subcommands("Usage: puncture state [OPTIONS]\n"), [])

    def test_a_section_is_the_help_verbatim_under_the_command(self):
        text = cli_reference.section(("calibrate", "jlim"), "Usage: x\n\n  --flag  [mm]\n")
        self.assertTrue(text.startswith("``puncture calibrate jlim``\n~~~~"))
        self.assertIn(".. code-block:: text\n\n   Usage: x\n\n     --flag  [mm]\n", text)


if __name__ == "__main__":
    unittest.main()
