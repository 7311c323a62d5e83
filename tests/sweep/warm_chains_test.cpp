// Warm chains (SweepSpec::warm_start): a grid's lines are solved in chains of kWarmChainPoints,
// each point's puncture search starting from the one before.  Checks: the chains and the shares
// that take them; warm rows equal to cold rows to the shooting's tolerance (the forces at a
// depth, not warm, bit for bit); the rows identical bit for bit whatever the threads, the window,
// the shares and a resume inside a chain (which solves the chain's earlier points again).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "puncture/loading_curve.hpp"
#include "puncture/sweep.hpp"

namespace puncture {
namespace {

// The paper's membrane: critical I1 by friction, friction fastest (lines of `levels` points).
SweepSpec warm_grid(int levels = 20) {
  SweepSpec spec;
  spec.parameters = {{"critical-i1", {"80", "95.2"}, {}},
                     {"friction", evenly_spaced_levels(0.05, 0.4, levels), {}}};
  spec.outputs.force_at_depth_mm = {10.0};
  return spec;
}

Problem chain_problem_at(const SweepPoint& p) {
  Problem problem;
  problem.critical_i1 = p.values[0];
  problem.friction = p.values[1];
  return problem;
}

std::vector<SweepRow> run(const SweepSpec& spec, SweepOptions options,
                          SweepSummary* summary = nullptr) {
  std::vector<SweepRow> rows;
  options.on_row = [&rows](const SweepRow& row) { rows.push_back(row); };
  const SweepSummary s = sweep(spec, chain_problem_at, options);
  if (summary) *summary = s;
  return rows;
}

void expect_same_row(const SweepRow& a, const SweepRow& b) {
  ASSERT_EQ(a.point.index, b.point.index);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.message, b.message);
  ASSERT_EQ(a.puncture.has_value(), b.puncture.has_value());
  EXPECT_EQ(a.puncture->force_n, b.puncture->force_n) << a.point.index;
  EXPECT_EQ(a.puncture->depth_mm, b.puncture->depth_mm) << a.point.index;
  EXPECT_EQ(a.puncture->max_first_invariant, b.puncture->max_first_invariant);
  EXPECT_EQ(a.puncture->part_two_top_stretch, b.puncture->part_two_top_stretch);
  ASSERT_EQ(a.at_depth.size(), b.at_depth.size());
  for (std::size_t k = 0; k < a.at_depth.size(); ++k)
    EXPECT_EQ(a.at_depth[k].force_n, b.at_depth[k].force_n);
}

TEST(WarmChains, FollowTheGridLines) {
  const SweepSpec spec = warm_grid(20);  // lines of 20: chains of 16 and 4
  const auto chain = [&](std::size_t i) {
    const PointRange r = warm_chain_of(spec, i);
    return std::pair{r.begin, r.end};
  };
  EXPECT_EQ(chain(0), (std::pair<std::size_t, std::size_t>{0, 16}));
  EXPECT_EQ(chain(15), (std::pair<std::size_t, std::size_t>{0, 16}));
  EXPECT_EQ(chain(16), (std::pair<std::size_t, std::size_t>{16, 20}));
  EXPECT_EQ(chain(20), (std::pair<std::size_t, std::size_t>{20, 36}));
  EXPECT_EQ(chain(39), (std::pair<std::size_t, std::size_t>{36, 40}));
  EXPECT_EQ(chain(3), (std::pair<std::size_t, std::size_t>{0, 16}));
  EXPECT_EQ(warm_chain_of(warm_grid(3), 4).begin, 3u);  // a short line is one chain
  EXPECT_EQ(warm_chain_of(warm_grid(3), 4).end, 6u);
  EXPECT_THROW(warm_chain_of(spec, 40), std::invalid_argument);
  // No chains: warm starts off, nothing to carry (no puncture), or a sampled design.
  SweepSpec cold = spec;
  cold.warm_start = false;
  SweepSpec no_puncture = spec;
  no_puncture.outputs.puncture = false;
  SweepSpec sampled = spec;
  sampled.design = SweepDesign::MonteCarlo;
  sampled.samples = 40;
  sampled.parameters = {{"critical-i1", {}, {DistributionKind::Uniform, 80.0, 95.2}},
                        {"friction", {}, {DistributionKind::Uniform, 0.05, 0.4}}};
  for (const SweepSpec& s : {cold, no_puncture, sampled}) {
    EXPECT_EQ(warm_chain_of(s, 7).begin, 7u);
    EXPECT_EQ(warm_chain_of(s, 7).end, 8u);
    EXPECT_EQ(share_of_point(s, 5, 3, 7), 2u);  // point by point, as before chains
  }
  // The chains from first_point's are dealt in turn: from 0, chains 0, 2 to share 0 and 1, 3 to
  // share 1; from 18 (chain 1), chains 1, 3 to share 0 and chain 2 to share 1.
  for (const std::size_t i : {0u, 15u, 20u, 35u}) EXPECT_EQ(share_of_point(spec, 0, 2, i), 0u);
  for (const std::size_t i : {16u, 19u, 36u, 39u}) EXPECT_EQ(share_of_point(spec, 0, 2, i), 1u);
  for (const std::size_t i : {18u, 19u, 36u}) EXPECT_EQ(share_of_point(spec, 18, 2, i), 0u);
  EXPECT_EQ(share_of_point(spec, 18, 2, 20), 1u);
}

// Warm rows against cold rows: the same statuses and words; the puncture's force and depth
// within 1e-12 relative (both roots meet the clamp to 1e-12: the shooting's resolution,
// warm_start_test.cpp), its I1 and corner stretch (the state's, marched down Part II from the
// root, which amplifies the difference) within 1e-10; the forces at a depth are not warm: bit
// for bit.  The cold
// rows are the public solves to the last digit.
TEST(WarmChains, WarmRowsEqualColdRowsToTheShootingTolerance) {
  const SweepSpec warm = warm_grid();
  SweepSpec cold = warm;
  cold.warm_start = false;
  const auto warm_rows = run(warm, {.threads = 2});
  const auto cold_rows = run(cold, {.threads = 2});
  ASSERT_EQ(warm_rows.size(), 40u);
  ASSERT_EQ(cold_rows.size(), 40u);
  double worst = 0.0;
  int differing = 0;
  for (std::size_t i = 0; i < warm_rows.size(); ++i) {
    const SweepRow &w = warm_rows[i], &c = cold_rows[i];
    ASSERT_TRUE(c.ok()) << c.message;
    ASSERT_EQ(w.status, c.status) << w.message;
    const PuncturePrediction single = predict_puncture(chain_problem_at(c.point));
    EXPECT_EQ(c.puncture->force_n, single.force_n);
    EXPECT_EQ(c.puncture->depth_mm, single.depth_mm);
    const double df = std::abs(w.puncture->force_n / c.puncture->force_n - 1.0);
    const double dd = std::abs(w.puncture->depth_mm / c.puncture->depth_mm - 1.0);
    const double di =
        std::abs(w.puncture->max_first_invariant / c.puncture->max_first_invariant - 1.0);
    EXPECT_LE(df, 1e-12) << i;
    EXPECT_LE(dd, 1e-12) << i;
    EXPECT_LE(di, 1e-10) << i;
    EXPECT_NEAR(w.puncture->part_three_stretch,
                c.puncture->part_three_stretch,
                1e-10 * c.puncture->part_three_stretch);
    EXPECT_EQ(w.puncture->crack_location, c.puncture->crack_location);
    EXPECT_EQ(w.at_depth[0].force_n, c.at_depth[0].force_n);
    worst = std::max({worst, df, dd});
    differing += w.puncture->force_n != c.puncture->force_n;
  }
  // The chains' starts were used: some roots land on other doubles.
  EXPECT_GT(differing, 0);
  ::testing::Test::RecordProperty("largest_relative_difference", fmt::format("{:.3e}", worst));
  ::testing::Test::RecordProperty("rows_differing", differing);
}

TEST(WarmChains, IdenticalRowsWhateverTheThreadsTheWindowAndTheShares) {
  const SweepSpec spec = warm_grid();
  const auto serial = run(spec, {.threads = 1});
  ASSERT_EQ(serial.size(), 40u);
  for (const int threads : {2, 3})
    for (const std::size_t window : {1u, 64u}) {
      const auto parallel = run(spec, {.threads = threads, .window_per_thread = window});
      ASSERT_EQ(parallel.size(), serial.size());
      for (std::size_t i = 0; i < serial.size(); ++i) expect_same_row(parallel[i], serial[i]);
    }
  // Shares of 2 and 3 processes, from the start and from inside the first chain: each row the
  // serial run's, the shares together every point once.
  for (const std::size_t first : {0u, 7u})
    for (const std::size_t stride : {2u, 3u}) {
      std::size_t rows = 0;
      for (std::size_t offset = 0; offset < stride; ++offset) {
        SweepSummary summary;
        const auto share =
            run(spec,
                {.threads = 2, .first_point = first, .stride = stride, .offset = offset},
                &summary);
        EXPECT_TRUE(summary.ok());
        EXPECT_EQ(summary.own_points, share.size());
        for (const SweepRow& row : share) {
          EXPECT_EQ(share_of_point(spec, first, stride, row.point.index), offset);
          expect_same_row(row, serial[row.point.index]);
        }
        rows += share.size();
      }
      EXPECT_EQ(rows, 40u - first);
    }
}

// A resume inside a chain (point 7 of the chain 0 .. 15, point 18 of 16 .. 19, point 25 of
// 20 .. 35) solves the chain's earlier points again, not delivered, and gives the rows of one
// uninterrupted run.
TEST(WarmChains, AResumeInsideAChainGivesTheUninterruptedRows) {
  const SweepSpec spec = warm_grid();
  const auto whole = run(spec, {.threads = 1});
  for (const std::size_t first : {7u, 18u, 25u}) {
    std::atomic<int> built{0};
    std::vector<SweepRow> tail;
    SweepOptions options{.threads = 2, .first_point = first};
    options.on_row = [&tail](const SweepRow& row) { tail.push_back(row); };
    const SweepSummary summary = sweep(
        spec,
        [&built](const SweepPoint& p) {
          ++built;
          return chain_problem_at(p);
        },
        options);
    EXPECT_TRUE(summary.ok());
    ASSERT_EQ(tail.size(), 40u - first);
    for (std::size_t k = 0; k < tail.size(); ++k) expect_same_row(tail[k], whole[first + k]);
    // Each delivered point built twice (checked, solved); the chain's earlier points once.
    const std::size_t chain_begin = warm_chain_of(spec, first).begin;
    EXPECT_EQ(static_cast<std::size_t>(built.load()), 2 * (40 - first) + (first - chain_begin));
  }
}

TEST(WarmChains, StopDeliversAPrefix) {
  const SweepSpec spec = warm_grid();
  std::atomic<bool> stop{false};
  std::vector<std::size_t> seen;
  SweepOptions options{.threads = 2, .window_per_thread = 1};
  options.stop = &stop;
  options.on_row = [&](const SweepRow& row) {
    seen.push_back(row.point.index);
    if (seen.size() == 3) stop = true;
  };
  const SweepSummary summary = sweep(spec, chain_problem_at, options);
  EXPECT_EQ(summary.status, Status::Incomplete);
  ASSERT_GE(seen.size(), 3u);
  EXPECT_LT(seen.size(), 40u);
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], i);
}

}  // namespace
}  // namespace puncture
