#include "command_verify.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "cli_error.hpp"
#include "output.hpp"
#include "parameter_flags.hpp"
#include "progress.hpp"
#include "puncture/verification.hpp"

namespace puncture::cli {

void add_verify_command(CLI::App& app, VerifyFlags& f) {
  f.command = app.add_subcommand(
      "verify",
      "Check the solver for this membrane against independent methods: finite elements\n"
      "(a second solver minimising the stored energy) at mu' = 0 and held at the edge,\n"
      "the work of the force against the stored energy, and the small-deflection (Foppl)\n"
      "limit; a table of quantity, shooting, second method, difference and verdict.\n"
      "For the other probes (sphere-tipped, rounded corner, cone, ball): mu' = 0 and the\n"
      "work (no Foppl disc), up to the puncture or the model's end; with --stick always\n"
      "also the held force, pole stretch, contact edge and largest I1 against elements\n"
      "held where the membrane touched (also under --pressure), and with a --stick rule\n"
      "that switches those held rows up to the switch and mu' = 0 rows after it.\n"
      "Under --pressure: mu' = 0 from the elements' own inflated dome (U - p V\n"
      "minimised, the work against its change) and the dome against the shooting's;\n"
      "with --gas-volume over the sealed chamber (the gas law's pressure per depth)");
  f.command->footer(
      "The physical flags (see puncture --help) choose the membrane; the friction and stick\n"
      "flags are replaced by the two limits the finite elements cover (on a smooth probe\n"
      "--stick adds the held one, up to the rule's switch).  Takes seconds (a minute or\n"
      "more held to the puncture).\n"
      "Exit code 4 when a check is outside its tolerance (the table is written first).");
  f.command
      ->add_option("--elements",
                   f.elements,
                   "Quadratic finite elements along the free part [count] (4 to 4096);\n"
                   "half as many are run too, to estimate their own error")
      ->capture_default_str();
  f.command
      ->add_option("--depths",
                   f.depths,
                   "Depths compared per limit, equally spaced up to its puncture\n"
                   "[count] (1 to 50)")
      ->capture_default_str();
}

VerifyOutcome run_verify(const Problem& problem, const VerifyFlags& f, Format format) {
  if (f.elements < 4 || f.elements > 4096)
    throw InputError(fmt::format("--elements: must be in the range 4 to 4096, got {}", f.elements));
  if (f.depths < 1 || f.depths > 50)
    throw InputError(fmt::format("--depths: must be in the range 1 to 50, got {}", f.depths));
  VerifyOptions options;
  options.elements = f.elements;
  options.depths = f.depths;
  Progress progress("verify");
  options.progress = [&](int done, int total, std::string_view what) {
    progress.note(fmt::format("{}/{} {}", done, total, what));
  };
  VerifyReport report{problem, {}};
  try {
    report.verification = verify(problem, options);
  } catch (const InvalidInput& e) {
    rethrow_with_flags(e);  // naming the flag (--indenter, --pressure)
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  VerifyOutcome outcome;
  outcome.text = render(report, format);
  outcome.passed = report.verification.ok();
  outcome.failed = report.verification.count(Verdict::Fail);
  outcome.message = report.verification.message;
  return outcome;
}

}  // namespace puncture::cli
