// Energy identities of the inflation curve: the pressure does the work that the membrane
// stores, dU/dV = p (U = integral of W 2 pi R H dR, V the volume under the dome), checked by
// differences between neighbouring states and by integrating p dV along the whole curve.
#include <cmath>

#include "inflation_test_support.hpp"

namespace puncture {
namespace {

using test::membrane;
using test::solved;

TEST(InflationEnergy, StoredEnergyGrowsAsPressureTimesVolume) {
  for (const auto& [name, law] : test::laws()) {
    const auto p = membrane(law);
    for (const double l0 : {1.02, 1.5, 2.2, 3.0}) {
      SCOPED_TRACE(name + " at pole stretch " + std::to_string(l0));
      // Central differences with step h = 1e-3 min(1, l0 - 1): truncation ~ (h / (l0 - 1))^2
      // <= 1e-6, and the states' own error (1e-10 relative) divided by h / (l0 - 1) is 1e-7;
      // 1e-5 covers both with a margin while a wrong energy density or volume (a missing
      // factor) fails by far.
      const double h = 1e-3 * std::min(1.0, l0 - 1.0);
      const auto lo = solved(p, l0 - h), mid = solved(p, l0), hi = solved(p, l0 + h);
      const double du_dv =
          (hi.stored_energy_mj - lo.stored_energy_mj) / (hi.volume_mm3 - lo.volume_mm3);
      EXPECT_NEAR(du_dv / mid.pressure_mpa, 1.0, 1e-5);
      test::record(fmt::format("{}_du_dv_{:g}", name, l0), std::abs(du_dv / mid.pressure_mpa - 1));
    }
  }
}

// Work of the pressure from flat to pole stretch `end`, the integral of p dV by the trapezoidal
// rule on `intervals` states equally spaced in s = (l0 - 1)^(1/2).  Near flat V ~ s and
// p ~ s^3 (the Hencky scaling): in s both are smooth, so the rule's error is O(ds^2), whereas
// equal steps in l0 would meet the square-root singularity of V(l0) at the flat state.
double pressure_work_mj(const InflationProblem& p, double end, int intervals) {
  SolverOptions o;
  o.record_fields = false;
  const double s_end = std::sqrt(end - 1.0);
  double work = 0.0, p_prev = 0.0, v_prev = 0.0;
  for (int k = 1; k <= intervals; ++k) {
    const double s = s_end * k / intervals;
    const auto state = solved(p, 1.0 + s * s, o);
    work += 0.5 * (p_prev + state.pressure_mpa) * (state.volume_mm3 - v_prev);
    p_prev = state.pressure_mpa;
    v_prev = state.volume_mm3;
  }
  return work;
}

TEST(InflationEnergy, WorkOfThePressureAlongTheCurveIsTheStoredEnergy) {
  for (const auto& [name, law] : test::laws()) {
    SCOPED_TRACE(name);
    const auto p = membrane(law);
    const double stored = solved(p, 3.0).stored_energy_mj;
    // 50, 100 and 200 intervals: the quadrature's error, O(ds^2), must fall about fourfold
    // per halving (at least threefold); Richardson's extrapolation (4 W_200 - W_100) / 3 then
    // removes that order, leaving O(ds^4) ~ 1e-7.  An energy that is not the pressure's work
    // would leave a constant gap instead.
    double previous = INFINITY, last = 0.0, before_last = 0.0;
    for (const int intervals : {50, 100, 200}) {
      const double work = pressure_work_mj(p, 3.0, intervals);
      const double error = std::abs(work / stored - 1.0);
      EXPECT_LT(error, previous / 3.0) << intervals << " intervals";
      previous = error;
      before_last = last;
      last = work;
      test::record(fmt::format("{}_work_error_{}_intervals", name, intervals), error);
    }
    const double extrapolated = (4.0 * last - before_last) / 3.0;
    EXPECT_NEAR(extrapolated / stored, 1.0, 1e-6);
    test::record(name + "_work_error_extrapolated", std::abs(extrapolated / stored - 1.0));
  }
}

TEST(InflationEnergy, StoredEnergyIsTheIntegralOfTheFieldsEnergyDensity) {
  // The solver integrates W along with the meridian; here the same integral from the
  // recorded fields (Simpson's rule on 2000 intervals of R: error ~ 1e-12).
  for (const auto& [name, law] : test::laws()) {
    SCOPED_TRACE(name);
    const auto p = membrane(law);
    SolverOptions o;
    o.field_points = 2000;
    const auto s = solved(p, 2.5, o);
    const auto& f = s.fields;
    double u = 0.0;
    for (std::size_t i = 1; i < f.size(); ++i) {
      auto w = [&](std::size_t j) {
        return test::energy_density_mpa(p, f.radial_stretch[j], f.hoop_stretch[j]) *
               f.reference_radius_mm[j];
      };
      // Trapezoid on the (unequal) samples; the step is <= A / 2000, error ~ 1e-7.
      u += 0.5 * (w(i - 1) + w(i)) * (f.reference_radius_mm[i] - f.reference_radius_mm[i - 1]);
    }
    u *= 2.0 * M_PI * p.thickness_mm;
    EXPECT_NEAR(u / s.stored_energy_mj, 1.0, 1e-6);
  }
}

}  // namespace
}  // namespace puncture
