#pragma once
// Why to trust a result: cross-checks of the shooting solver for the user's own membrane,
// against methods that share nothing with it but the material laws.
//
//   - the second method (finite_element.hpp) in the two limits it covers: the membrane sliding
//     without friction, and held at the indenter's edge; force, Part III stretch and largest I1
//     at depths up to each limit's puncture;
//   - work and energy: the work of the indenter, the integral of the shooting's force over the
//     depth, against the finite elements' stored energy, at the same two limits;
//   - the small-deflection (Foppl) limit: F = C(a/A) E H delta^3 / A^2 from an independent
//     small-strain solver, for held and sliding edges.
// Friction between the two limits (the user's mu') has no second method: it is covered by the
// Coulomb and capstan identities of the test suite (tests/solver).  On every other probe
// (sphere-tipped, rounded corner, cone, ball) the frictionless limit is checked (force, pole
// stretch, contact edge, largest I1, work), up to the puncture or, for the cone and the ball, the
// end of their model (the Foppl check is the flat punch's); with the stick rule `always` (also
// at a held gas pressure) also the held force, pole stretch, contact edge and largest I1 against
// the elements held where the membrane touched, up to the held puncture or the held model's end
// (group "held where it touched"); with a rule that switches, those held rows up to the switch
// ("held until the switch") and the frictionless rows after it ("sliding after the switch").
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "puncture/finite_element.hpp"
#include "puncture/outcome.hpp"
#include "puncture/problem.hpp"

namespace puncture {

enum class Verdict { Pass, Fail, Skipped };

struct VerificationCheck {
  std::string group;        // "frictionless", "held", "work = energy", "small deflection"
  std::string quantity;     // what is compared, with its unit
  std::string condition;    // where: e.g. "depth 16.9 mm (1/4 of the puncture depth)"
  double shooting = 0.0;    // the shooting solver's value
  double reference = 0.0;   // the independent method's value
  double difference = 0.0;  // reference / shooting - 1
  double tolerance = 0.0;   // |difference| allowed
  Verdict verdict = Verdict::Skipped;
  std::string note;  // why skipped, or what the tolerance rests on
};

// False for a skipped check and for one that failed for want of a value (a method found no
// equilibrium): then `note` says why.
bool has_numbers(const VerificationCheck& check);

struct VerifyOptions {
  int elements = 128;  // finite elements along the free part (also run at half, for the error)
  int depths = 4;      // depths per limit, equally spaced up to its puncture depth
  // Called as the checks progress: done, total, what is being computed.
  std::function<void(int, int, std::string_view)> progress;
};

// ok() when every check passed; ChecksFailed when one failed, else Incomplete when one could not
// be made (skipped); the message says how many and the first skipped one's reason.
struct VerificationReport : Outcome {
  std::vector<VerificationCheck> checks;
  int elements = 0;
  int count(Verdict verdict) const;
};

// Throws std::invalid_argument (InvalidInput naming the parameter) for an invalid problem or
// options.
VerificationReport verify(const Problem& problem, const VerifyOptions& options = {});

std::string to_string(Verdict verdict);

}  // namespace puncture
