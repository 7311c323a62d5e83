#pragma once
// What a held (stuck) membrane point keeps (docs/model.md §15.4, §17.3): the state it joined the
// contact with and the tractions the probe must supply to hold it.
#include <cmath>

#include "numerics/shooting.hpp"

namespace puncture::detail {

// One grid point of a held profile's history: the material point R that joined the contact at
// the edge.
struct StuckPoint {
  double r = 0.0;      // reference radius / (A / L0)
  double theta = 0.0;  // where it holds: psi (the polar angle theta on a sphere)
  double l1 = 1.0;     // its meridional stretch (the free membrane's at the edge when it joined)
  double f = 0.0;      // the force then, / (2 pi G H A / L0)
  double depth = 0.0;  // the depth then, / (A / L0)
};

// The tractions the probe must supply to hold a stuck point (normalised by G H / A): the
// contact pressure p (normal balance, as sliding) and the tangential traction tau towards the
// tip, tau r lambda1 = d(R s1)/dR - s2 cos(phi) (tangential balance).
struct StuckTraction {
  double pressure = 0.0;
  double tangential = 0.0;
};

// |tau| / p of a held point (beyond the domain where p <= 0 with a traction).
inline double held_traction_ratio_of(const StuckTraction& t) {
  return t.pressure > 0.0 ? std::abs(t.tangential) / t.pressure
                          : (t.tangential == 0.0 ? 0.0 : kBeyondDomain);
}

}  // namespace puncture::detail
