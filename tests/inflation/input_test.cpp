// Bad input throws std::invalid_argument naming the parameter; the solver's own limits are
// statuses; nothing is ever NaN.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "inflation_test_support.hpp"

namespace puncture {
namespace {

using test::all_finite;
using test::membrane;

template <class F>
void expect_invalid(F&& f, const std::string& mentions) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one mentioning '" << mentions << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(mentions), std::string::npos) << e.what();
  }
}

TEST(InflationInput, InvalidProblemsAndRequestsThrowNamingTheParameter) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto p = membrane();
  p.thickness_mm = -0.2;
  expect_invalid([&] { inflate_at_pole_stretch(p, 2.0); }, "thickness");
  p = membrane();
  p.clamp_radius_mm = nan;
  expect_invalid([&] { inflation_curve(p); }, "clamp radius");
  p = membrane();
  p.material.shear_modulus_mpa = 0.0;
  expect_invalid([&] { inflate_at_pressure(p, 1e-3); }, "shear modulus");
  p = membrane(Gent{-1.0});
  expect_invalid([&] { inflation_burst(p); }, "J_lim");
  p = membrane(MooneyRivlin{1.0});
  expect_invalid([&] { inflate_at_pole_stretch(p, 2.0); }, "Mooney-Rivlin alpha");
  p = membrane(Gent{50.0});
  p.critical_i1 = 60.0;
  expect_invalid([&] { inflation_curve(p); }, "critical I1");

  const auto ok = membrane();
  expect_invalid([&] { inflate_at_pole_stretch(ok, 0.9); }, "pole stretch");
  expect_invalid([&] { inflate_at_pole_stretch(ok, nan); }, "pole stretch");
  expect_invalid([&] { inflate_at_pressure(ok, -1e-3); }, "pressure");
  expect_invalid([&] { inflate_at_pressure(ok, INFINITY); }, "pressure");
  expect_invalid([&] { inflation_curve(ok, {.points = 1}); }, "points");
  expect_invalid([&] { inflation_curve(ok, {.max_pole_stretch = 0.5}); }, "max pole stretch");
  expect_invalid([&] { inflation_curve(ok, {.max_pole_stretch = 9.0}); }, "locks");
  expect_invalid([&] { inflation_curve(ok, {.scan_points = 2}); }, "scan points");
  expect_invalid([&] { pressure_extrema(ok, 0.0); }, "max pole stretch");
}

TEST(InflationInput, PoleStretchBeyondLockingIsAStatusNotANumber) {
  const auto p = membrane(Gent{20.0});  // locks at pole stretch ~3.39
  const auto s = inflate_at_pole_stretch(p, 3.5);
  EXPECT_EQ(s.status, Status::BeyondLocking);
  EXPECT_NE(s.message.find("locking"), std::string::npos) << s.message;
  EXPECT_TRUE(std::isfinite(s.pressure_mpa));
  EXPECT_TRUE(s.fields.size() == 0u);
}

TEST(InflationInput, TheFlatStateIsExact) {
  const auto s = inflate_at_pole_stretch(membrane(), 1.0);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.pressure_mpa, 0.0);
  EXPECT_EQ(s.volume_mm3, 0.0);
  EXPECT_EQ(s.stored_energy_mj, 0.0);
  EXPECT_TRUE(std::isinf(s.pole_curvature_radius_mm));  // documented: flat
  ASSERT_GT(s.fields.size(), 2u);
  for (std::size_t i = 0; i < s.fields.size(); ++i) {
    EXPECT_EQ(s.fields.radial_stretch[i], 1.0);
    EXPECT_EQ(s.fields.deflection_mm[i], 0.0);
  }
}

TEST(InflationInput, NoNaNAnywhereAlongTheCurves) {
  for (const auto& [name, law] : test::laws()) {
    SCOPED_TRACE(name);
    const auto p = membrane(law);
    const auto c = inflation_curve(p, {.points = 30});
    ASSERT_TRUE(c.ok()) << c.message;
    for (const auto& s : c.states) {
      for (const double x : {s.pressure_mpa,
                             s.normalized_pressure,
                             s.pole_height_mm,
                             s.volume_mm3,
                             s.stored_energy_mj,
                             s.pole_stress_mpa,
                             s.pole_tension_n_per_mm,
                             s.clamp_radial_stretch,
                             s.clamp_slope_rad,
                             s.max_first_invariant,
                             s.max_first_invariant_reference_radius_mm,
                             s.max_first_invariant_radius_mm,
                             s.clamp_residual})
        EXPECT_TRUE(std::isfinite(x));
    }
    const auto& f = c.burst.state.fields;
    ASSERT_GT(f.size(), 100u);
    for (const auto* v : {&f.reference_radius_mm,
                          &f.radius_mm,
                          &f.deflection_mm,
                          &f.slope_rad,
                          &f.radial_stretch,
                          &f.hoop_stretch,
                          &f.thickness_stretch,
                          &f.radial_stress_mpa,
                          &f.hoop_stress_mpa,
                          &f.first_invariant})
      EXPECT_TRUE(all_finite(*v));
  }
}

}  // namespace
}  // namespace puncture
