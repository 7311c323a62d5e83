// The engine: rows in point order, identical whatever the threads and the window, each equal
// to the public solve at its point; failed points are rows; resume and stop deliver exactly the
// missing rows; an invalid point or a failing sink stops the sweep with its error.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <stdexcept>

#include "puncture/loading_curve.hpp"
#include "puncture/sweep.hpp"

namespace puncture {
namespace {

// friction and critical I1 of the paper's membrane with a 1 mm neo-Hookean or Gent probe.
Problem problem_at(const SweepPoint& p) {
  Problem problem;
  problem.indenter = FlatPunch{1.0};
  problem.friction = p.values[0];
  problem.critical_i1 = p.values[1];
  return problem;
}

SweepSpec small_spec() {
  SweepSpec spec;
  spec.design = SweepDesign::LatinHypercube;
  spec.samples = 6;
  spec.seed = 11;
  spec.parameters = {{"friction", {}, {DistributionKind::Uniform, 0.0, 1.0}},
                     {"critical-i1", {}, {DistributionKind::Uniform, 20.0, 90.0}}};
  spec.outputs.force_at_depth_mm = {5.0};
  return spec;
}

std::vector<SweepRow> run(const SweepSpec& spec, const ProblemOfPoint& problem_of,
                          SweepOptions options, SweepSummary* summary = nullptr) {
  std::vector<SweepRow> rows;
  options.on_row = [&rows](const SweepRow& row) { rows.push_back(row); };
  const SweepSummary s = sweep(spec, problem_of, options);
  if (summary) *summary = s;
  return rows;
}

// Every number and word of two rows, exactly.
void expect_same(const SweepRow& a, const SweepRow& b) {
  EXPECT_EQ(a.point.index, b.point.index);
  EXPECT_EQ(a.point.texts, b.point.texts);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.message, b.message);
  ASSERT_EQ(a.puncture.has_value(), b.puncture.has_value());
  if (a.puncture) {
    EXPECT_EQ(a.puncture->status, b.puncture->status);
    EXPECT_EQ(a.puncture->force_n, b.puncture->force_n);
    EXPECT_EQ(a.puncture->depth_mm, b.puncture->depth_mm);
    EXPECT_EQ(a.puncture->max_first_invariant, b.puncture->max_first_invariant);
    EXPECT_EQ(a.puncture->crack_location, b.puncture->crack_location);
  }
  ASSERT_EQ(a.at_depth.size(), b.at_depth.size());
  for (std::size_t k = 0; k < a.at_depth.size(); ++k) {
    EXPECT_EQ(a.at_depth[k].status, b.at_depth[k].status);
    EXPECT_EQ(a.at_depth[k].force_n, b.at_depth[k].force_n);
  }
}

TEST(SweepEngine, RowsAreThePublicSolvesInPointOrder) {
  const SweepSpec spec = small_spec();
  SweepSummary summary;
  const auto rows = run(spec, problem_at, {.threads = 1}, &summary);
  ASSERT_EQ(rows.size(), spec.samples);
  EXPECT_TRUE(summary.ok()) << summary.message;
  EXPECT_EQ(summary.delivered, spec.samples);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const SweepRow& row = rows[i];
    EXPECT_EQ(row.point.index, i);
    const Problem problem = problem_at(sweep_point(spec, i));
    // The same numbers as `puncture puncture` (fields recorded there, not here).
    const PuncturePrediction p = predict_puncture(problem);
    ASSERT_TRUE(row.puncture.has_value());
    EXPECT_EQ(row.puncture->status, p.status);
    if (p.ok()) {
      EXPECT_EQ(row.puncture->force_n, p.force_n);
      EXPECT_EQ(row.puncture->depth_mm, p.depth_mm);
      EXPECT_EQ(row.puncture->crack_location, p.crack_location);
      // The criterion is met at the puncture point.
      EXPECT_NEAR(row.puncture->max_first_invariant, problem.critical_i1, 1e-6);
    }
    const Equilibrium e = solve_at_depth(problem, 5.0, Stage::Slip);
    ASSERT_EQ(row.at_depth.size(), 1u);
    EXPECT_EQ(row.at_depth[0].status, e.status);
    if (e.ok()) {
      EXPECT_EQ(row.at_depth[0].force_n, e.force_n);
    }
  }
}

// Across a grid's points: the membrane's force scales with G H and its depth does not depend on
// them (the normalised problem is the same); each point checked against the first.
TEST(SweepEngine, ForceScalesWithShearModulusTimesThicknessAcrossTheGrid) {
  SweepSpec spec;
  spec.parameters = {{"shear-modulus", {"0.06", "0.045"}, {}},
                     {"thickness", evenly_spaced_levels(0.15, 0.25, 3), {}}};
  spec.outputs.force_at_depth_mm = {10.0};
  const auto problem_of = [](const SweepPoint& p) {
    Problem problem;
    problem.material.shear_modulus_mpa = p.values[0];
    problem.geometry.thickness_mm = p.values[1];
    return problem;
  };
  const auto rows = run(spec, problem_of, {.threads = 2});
  ASSERT_EQ(rows.size(), 6u);
  const SweepRow& first = rows[0];
  ASSERT_TRUE(first.ok()) << first.message;
  const double gh0 = first.point.values[0] * first.point.values[1];
  for (const SweepRow& row : rows) {
    ASSERT_TRUE(row.ok()) << row.message;
    const double scale = row.point.values[0] * row.point.values[1] / gh0;
    EXPECT_NEAR(row.puncture->force_n / (first.puncture->force_n * scale), 1.0, 1e-12);
    EXPECT_NEAR(row.at_depth[0].force_n / (first.at_depth[0].force_n * scale), 1.0, 1e-12);
    EXPECT_NEAR(row.puncture->depth_mm, first.puncture->depth_mm, 1e-12 * first.puncture->depth_mm);
  }
}

TEST(SweepEngine, IdenticalRowsWhateverTheThreadsAndTheWindow) {
  const SweepSpec spec = small_spec();
  const auto serial = run(spec, problem_at, {.threads = 1});
  for (const int threads : {2, 3}) {
    for (const std::size_t window : {1u, 64u}) {
      const auto parallel =
          run(spec, problem_at, {.threads = threads, .window_per_thread = window});
      ASSERT_EQ(parallel.size(), serial.size());
      for (std::size_t i = 0; i < serial.size(); ++i) expect_same(parallel[i], serial[i]);
    }
  }
}

// A critical I1 just below the Gent lock (3 + J_lim = 128) with the membrane held at the edge
// (--stick always): no puncture, a physical failure, kept as a row with its status and kind.
TEST(SweepEngine, FailedPointsAreRowsWithTheirStatus) {
  SweepSpec spec;
  spec.parameters = {{"stick", {"none", "always"}, {}}, {"critical-i1", {"50", "127.9"}, {}}};
  const auto problem_of = [](const SweepPoint& p) {
    Problem problem;
    problem.stick.rule = p.texts[0] == "always" ? StickRule::Always : StickRule::None;
    problem.critical_i1 = p.values[1];
    return problem;
  };
  SweepSummary summary;
  const auto rows = run(spec, problem_of, {.threads = 2}, &summary);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_TRUE(summary.ok());
  std::size_t failed = 0;
  for (const SweepRow& row : rows) {
    const PuncturePrediction p = predict_puncture(problem_of(row.point));
    EXPECT_EQ(row.status, p.status) << row.point.index;
    if (!row.ok()) {
      ++failed;
      EXPECT_FALSE(row.message.empty());
      EXPECT_EQ(row.message.rfind("puncture: ", 0), 0u) << row.message;
    }
  }
  // Held at the edge, the membrane would wrap the side before I1 reaches 127.9 (physical).
  EXPECT_EQ(failed, 1u);
  EXPECT_FALSE(rows[3].ok());
  EXPECT_EQ(rows[3].failure_kind(), FailureKind::Physical);
  EXPECT_FALSE(rows[3].puncture->ok());
  EXPECT_EQ(summary.failed_physical, 1u);
  EXPECT_EQ(summary.converged, 3u);
}

TEST(SweepEngine, ResumeDeliversExactlyTheMissingRows) {
  const SweepSpec spec = small_spec();
  const auto whole = run(spec, problem_at, {.threads = 2});
  SweepSummary summary;
  const auto tail = run(spec, problem_at, {.threads = 2, .first_point = 4}, &summary);
  ASSERT_EQ(tail.size(), 2u);
  EXPECT_TRUE(summary.ok());
  EXPECT_EQ(summary.first_point, 4u);
  for (std::size_t k = 0; k < tail.size(); ++k) expect_same(tail[k], whole[4 + k]);
  EXPECT_TRUE(run(spec, problem_at, {.first_point = 6}).empty());
  EXPECT_THROW(run(spec, problem_at, {.first_point = 7}), std::invalid_argument);
}

// Shares of a sweep (processes): offset r of stride 3 delivers points first + r, first + r + 3,
// ... in order, each row identical to the whole sweep's.
TEST(SweepEngine, SharesOfAStrideTogetherAreTheWholeSweep) {
  SweepSpec spec = small_spec();
  spec.samples = 8;
  const auto whole = run(spec, problem_at, {.threads = 1});
  std::size_t rows = 0;
  for (std::size_t offset = 0; offset < 3; ++offset) {
    SweepSummary summary;
    const auto share = run(spec,
                           problem_at,
                           {.threads = 2, .first_point = 1, .stride = 3, .offset = offset},
                           &summary);
    EXPECT_TRUE(summary.ok());
    EXPECT_EQ(summary.own_points, share.size());
    for (std::size_t k = 0; k < share.size(); ++k) {
      ASSERT_EQ(share[k].point.index, 1 + offset + 3 * k);
      expect_same(share[k], whole[share[k].point.index]);
    }
    rows += share.size();
  }
  EXPECT_EQ(rows, 7u);  // points 1 .. 7
  EXPECT_THROW(run(spec, problem_at, {.stride = 2, .offset = 2}), std::invalid_argument);
}

TEST(SweepEngine, StopDeliversAPrefixAndReportsIncomplete) {
  const SweepSpec spec = small_spec();
  std::atomic<bool> stop{false};
  std::vector<std::size_t> seen;
  SweepOptions options{.threads = 2, .window_per_thread = 1};
  options.stop = &stop;
  options.on_row = [&](const SweepRow& row) {
    seen.push_back(row.point.index);
    if (seen.size() == 2) stop = true;
  };
  const SweepSummary summary = sweep(spec, problem_at, options);
  EXPECT_EQ(summary.status, Status::Incomplete);
  ASSERT_GE(seen.size(), 2u);
  EXPECT_LT(seen.size(), spec.samples);
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], i);
  EXPECT_EQ(summary.delivered, seen.size());
}

// Point 3's thickness is negative: refused before any solve, naming the point, with 1 or 2
// threads (the lowest invalid point).
TEST(SweepEngine, AnInvalidPointIsRefusedBeforeAnySolve) {
  SweepSpec spec;
  spec.parameters = {{"thickness", {"0.2", "0.1", "0.3", "-0.1", "0", "0.2"}, {}}};
  const auto problem_of = [](const SweepPoint& p) {
    Problem problem;
    problem.geometry.thickness_mm = p.values[0];
    return problem;
  };
  for (const int threads : {1, 2}) {
    std::size_t rows = 0;
    SweepOptions options{.threads = threads};
    options.on_row = [&rows](const SweepRow&) { ++rows; };
    try {
      sweep(spec, problem_of, options);
      ADD_FAILURE() << "accepted";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("sweep point 3"), std::string::npos) << e.what();
      ASSERT_FALSE(e.errors().empty());
      EXPECT_EQ(e.errors()[0].parameter, "geometry.thickness_mm");
    }
    EXPECT_EQ(rows, 0u);
  }
}

// A share checks its own points only (points 3 and 4 are invalid): the stride-2 share from
// offset 1 meets point 3, the one from offset 0 point 4, the lowest over the shares is the
// whole sweep's.  Each problem is built once per check and once per solve; none is built
// twice when the caller checked already.  Point by point (without warm chains: with them the
// line is one chain, warm_chains_test.cpp).
TEST(SweepEngine, EachShareChecksItsOwnPoints) {
  SweepSpec spec;
  spec.parameters = {{"thickness", {"0.2", "0.1", "0.3", "-0.1", "0", "0.2"}, {}}};
  spec.warm_start = false;
  std::atomic<int> built{0};
  const auto problem_of = [&built](const SweepPoint& p) {
    ++built;
    Problem problem;
    problem.indenter = FlatPunch{1.0};
    problem.geometry.thickness_mm = p.values[0];
    return problem;
  };
  for (const int threads : {1, 2}) {
    const auto whole = first_invalid_point(spec, problem_of, {.threads = threads});
    ASSERT_TRUE(whole);
    EXPECT_EQ(whole->index, 3u);
    EXPECT_THROW(std::rethrow_exception(whole->error), InvalidInput);
    const auto odd =
        first_invalid_point(spec, problem_of, {.threads = threads, .stride = 2, .offset = 1});
    const auto even = first_invalid_point(spec, problem_of, {.threads = threads, .stride = 2});
    ASSERT_TRUE(odd && even);
    EXPECT_EQ(odd->index, 3u);
    EXPECT_EQ(even->index, 4u);
    // From point 5 on (a resume), the share of offset 0 holds no invalid point.
    EXPECT_FALSE(first_invalid_point(spec, problem_of, {.first_point = 5, .stride = 2}));
  }
  const SweepOptions tail{.threads = 1, .first_point = 5, .stride = 2};
  built = 0;
  EXPECT_EQ(run(spec, problem_of, tail).size(), 1u);
  EXPECT_EQ(built.load(), 2);  // point 5: checked, then solved
  built = 0;
  SweepOptions checked = tail;
  checked.points_checked = true;
  EXPECT_EQ(run(spec, problem_of, checked).size(), 1u);
  EXPECT_EQ(built.load(), 1);
}

TEST(SweepEngine, ASinkThatFailsStopsTheSweepWithItsError) {
  const SweepSpec spec = small_spec();
  SweepOptions options{.threads = 2};
  options.on_row = [](const SweepRow& row) {
    if (row.point.index == 1) throw std::runtime_error("disk full");
  };
  EXPECT_THROW(sweep(spec, problem_at, options), std::runtime_error);
}

TEST(SweepEngine, ProgressCountsEveryRow) {
  const SweepSpec spec = small_spec();
  SweepProgress last;
  int calls = 0;
  SweepOptions options{.threads = 2, .progress_every_s = 0.0};
  options.progress = [&](const SweepProgress& p) {
    EXPECT_GE(p.done, last.done);
    last = p;
    ++calls;
  };
  sweep(spec, problem_at, options);
  EXPECT_GE(calls, 2);
  EXPECT_EQ(last.done, spec.samples);
  EXPECT_EQ(last.to_do, spec.samples);
}

}  // namespace
}  // namespace puncture
