// The fields' samples (numerics/even_samples.hpp): interpolated between the integration's steps,
// they must be as accurate as the integration itself.  Each sample is compared with an
// independent integration from the part's start to the sample's radius at tolerance 1e-14.
#include "numerics/even_samples.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "indentation/dispatch.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

// y' = y on [0, 2] (closed form e^r) and y' = -y r (e^(-r^2 / 2)): between the knots (within
// 2e-12 of the closed forms) the interpolation stays within the integration's local tolerance,
// 3e-11 relative (measured 1.5e-11).
TEST(EvenSamples, ClosedFormsBetweenTheSteps) {
  using State = std::array<double, 2>;
  const auto system = [](const State& y, State& dy, double r) {
    dy[0] = y[0];
    dy[1] = -r * y[1];
  };
  const detail::IntegrationSettings settings{3e-11, 3e-13, 100000};
  detail::Knots<State> knots;
  State y{1.0, 1.0};
  ASSERT_TRUE(detail::integrate_part(system, y, 0.0, 2.0, settings, [&](double r, const State& x) {
    knots.add(r, x);
    return true;
  }));
  ASSERT_GE(knots.r.size(), 5u);  // several steps, so the samples fall between them
  const auto samples = detail::even_samples(system, knots, 200, settings);
  ASSERT_EQ(samples.size(), 201u);
  double worst = 0.0;
  for (const auto& [r, s] : samples) {
    worst = std::max(worst, std::abs(s[0] / std::exp(r) - 1.0));
    worst = std::max(worst, std::abs(s[1] / std::exp(-0.5 * r * r) - 1.0));
  }
  EXPECT_LE(worst, settings.rel_tol);
  EXPECT_DOUBLE_EQ(samples.front().first, 0.0);
  EXPECT_DOUBLE_EQ(samples.back().first, 2.0);
}

// Part I of states with and without Part II, sliding and held: every sample within 1e-10 of the
// independent integration (the knots themselves are within ~3e-11: the interpolation adds no
// more than the integration's own error), and the sampled state is the unsampled one.
TEST(EvenSamples, PartOneSamplesMeetAnIndependentIntegration) {
  const Problem p = paper_problem();
  SolverOptions options;
  options.record_fields = false;
  const Gent& law = std::get<Gent>(p.material.law);
  const detail::IndentationShooting<detail::FlatPunchContact<Gent>> shooting(
      law,
      detail::shooting_settings(options),
      detail::contact_settings(p, std::get<FlatPunch>(p.indenter)));
  const detail::IntegrationSettings reference{1e-14, 1e-16, 1000000};
  for (const auto& [stage, f] : {std::pair{Stage::Slip, 0.05},
                                 std::pair{Stage::Slip, 0.4},
                                 std::pair{Stage::Stick, 0.05},
                                 std::pair{Stage::Stick, 0.3}}) {
    const auto sol = shooting.solve(stage, f);
    ASSERT_TRUE(sol.ok()) << sol.message;
    const auto bare = shooting.assemble(sol.configuration, f, sol.parameter, false);
    EXPECT_EQ(bare.depth, sol.depth);  // the same steps: the same state to the last bit
    EXPECT_EQ(bare.residual, sol.residual);
    const auto start = shooting.contact().free_start(sol.configuration, f, sol.parameter);
    ASSERT_TRUE(start.has_value());
    const detail::FreeMembraneSystem<Gent, detail::Stretches> system{
        law, detail::TransverseLoad{f, 0.0}, law.locking_i1()};
    ASSERT_EQ(sol.part_one.size(), static_cast<std::size_t>(options.field_points) + 1);
    double worst = 0.0;
    for (const auto& s : sol.part_one) {
      const auto y = detail::advance(system, start->state, start->r0, s[0], reference);
      ASSERT_TRUE(y.has_value());
      for (int j = 0; j < 4; ++j)
        worst = std::max(worst, std::abs((*y)[j] - s[j + 1]) / std::max(1.0, std::abs((*y)[j])));
    }
    EXPECT_LE(worst, 1e-10) << to_string(stage) << " f " << f;
  }
}

}  // namespace
}  // namespace puncture::test
