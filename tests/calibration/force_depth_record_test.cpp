// Testing-machine records (force_depth_record.hpp): the same record in other units, column
// orders, separators and decimal marks reads as the same points and gives the same fit; the
// contact point and the perforation are found by their documented rules; bad records are refused
// naming the file, line and column.
#include "puncture/force_depth_record.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "puncture/curve_fit.hpp"
#include "puncture/loading_curve.hpp"
#include "seeded_noise.hpp"

namespace puncture {
namespace {

struct Points {
  std::vector<double> depth_mm, force_n;
};

// The paper's curve at 60 depths to 90 % of the puncture depth, with noise, after 10 points of
// baseline (depth -1 to -0.1 mm, force noise only), the depth column offset by `offset_mm`.
Points model_points(double offset_mm) {
  const Problem truth;
  const auto p = predict_puncture(truth);
  CurveOptions c;
  for (int i = 1; i <= 60; ++i) c.depths_mm.push_back(0.9 * p.depth_mm * i / 60);
  const auto curve = loading_curve(truth, c);
  test::SeededNoise noise(5, 0.002);
  Points pts;
  for (int i = -10; i < 0; ++i) {
    pts.depth_mm.push_back(offset_mm + 0.1 * i);
    pts.force_n.push_back(noise());
  }
  pts.depth_mm.push_back(offset_mm);
  pts.force_n.push_back(noise());
  for (const auto& pt : curve.points) {
    pts.depth_mm.push_back(offset_mm + pt.depth_mm);
    pts.force_n.push_back(pt.force_n + noise());
  }
  return pts;
}

std::string decimal_comma(std::string s) {
  for (auto& ch : s)
    if (ch == '.') ch = ',';
  return s;
}

// The same points written in four ways.
std::vector<std::pair<std::string, RecordFormat>> four_ways(const Points& pts) {
  std::vector<std::pair<std::string, RecordFormat>> out;
  std::string a = "depth_mm,force_n\n";
  std::string b = "time_s;force_kN;depth_m\n";
  std::string c, d = "# exported\nForce [gf]\tTravel [mm]\n";
  for (std::size_t i = 0; i < pts.depth_mm.size(); ++i) {
    a += fmt::format("{:.17g},{:.17g}\n", pts.depth_mm[i], pts.force_n[i]);
    b += decimal_comma(fmt::format(
        "{:.3f};{:.17g};{:.17g}\n", 0.1 * i, pts.force_n[i] / 1000.0, pts.depth_mm[i] / 1000.0));
    c +=
        fmt::format("{:.17g}\t{:.17g}\n", pts.depth_mm[i] / 25.4, pts.force_n[i] / 4.4482216152605);
    d += fmt::format("{:.17g}\t{:.17g}\n", pts.force_n[i] / 9.80665e-3, pts.depth_mm[i]);
  }
  RecordFormat fa;
  RecordFormat fb;
  fb.depth = {"depth_m", 0};
  fb.force = {"force_kN", 0};
  fb.depth_unit = DepthUnit::Metre;
  fb.force_unit = ForceUnit::Kilonewton;
  RecordFormat fc;
  fc.depth = {"", 1};
  fc.force = {"", 2};
  fc.depth_unit = DepthUnit::Inch;
  fc.force_unit = ForceUnit::PoundForce;
  RecordFormat fd;
  fd.depth = {"Travel [mm]", 0};
  fd.force = {"", 1};
  fd.force_unit = ForceUnit::GramForce;
  out = {{a, fa}, {b, fb}, {c, fc}, {d, fd}};
  return out;
}

TEST(ForceDepthRecord, SameRecordInOtherUnitsAndLayoutsGivesTheSameFit) {
  const auto pts = model_points(3.0);
  std::vector<CurveFit> fits;
  std::vector<ForceDepthRecord> records;
  for (auto [text, format] : four_ways(pts)) {
    format.contact_depth = 3.0 / millimetres_per(format.depth_unit);
    const auto r = parse_force_depth_record(text, "record.csv", format);
    ASSERT_EQ(r.depth_mm.size(), 60u);
    records.push_back(r);
    CurveTest t{"record", Problem{}, r.depth_mm, r.force_n, std::nullopt};
    t.problem.material.shear_modulus_mpa = 0.07;
    std::get<Gent>(t.problem.material.law).j_lim = 140.0;
    CurveFitOptions o;
    o.free = {CurveParameter::ShearModulus, CurveParameter::JLim};
    fits.push_back(fit_curves({{t}}, o));
    ASSERT_TRUE(fits.back().ok()) << fits.back().message;
  }
  EXPECT_EQ(records[1].separator, ';');
  EXPECT_TRUE(records[1].decimal_comma);
  EXPECT_FALSE(records[2].header);
  EXPECT_EQ(records[3].separator, '\t');
  // The unit conversions and the text round trip change a depth or force by an ulp or two
  // (1e-16 relative): the points agree to 1e-14.  The fits agree to the optimiser's stop: it
  // ends when a step is below 1e-9 relative, which a different ulp can make one step earlier
  // or later; along the correlated (G, J_lim) direction that leaves up to ~1e-7 relative
  // (measured: 3.3e-8 in J_lim for the inch record), a 1e-5 of a standard error.
  for (std::size_t k = 1; k < records.size(); ++k) {
    for (std::size_t i = 0; i < records[0].depth_mm.size(); ++i) {
      EXPECT_NEAR(records[k].depth_mm[i], records[0].depth_mm[i], 1e-14 * 30.0) << k << " " << i;
      EXPECT_NEAR(records[k].force_n[i], records[0].force_n[i], 1e-14) << k << " " << i;
    }
    for (std::size_t j = 0; j < 2; ++j) {
      const double v = fits[0].parameters[j].value;
      EXPECT_NEAR(fits[k].parameters[j].value, v, 1e-7 * v) << k;
      EXPECT_NEAR(*fits[k].parameters[j].standard_error,
                  *fits[0].parameters[j].standard_error,
                  1e-6 * *fits[0].parameters[j].standard_error)
          << k;
    }
  }
}

TEST(ForceDepthRecord, FindsTheContactByTheSustainedRise) {
  const auto pts = model_points(3.0);
  const auto [text, format] = four_ways(pts).front();
  const auto r = parse_force_depth_record(text, "record.csv", format);
  ASSERT_TRUE(r.contact_found);
  // Baseline sd 0.002 N: threshold ~0.01 N above the mean.  The contact is the last point
  // before five in a row above it: found from the data, never before the true contact (3 mm),
  // and (the force ~ depth^3) before the depth where the force is 0.1 N.
  double threshold_depth = 0.0;
  for (std::size_t i = 0; i < pts.force_n.size(); ++i)
    if (pts.force_n[i] > 0.1) {
      threshold_depth = pts.depth_mm[i];
      break;
    }
  EXPECT_GE(r.contact_depth_mm, 3.0);
  EXPECT_LT(r.contact_depth_mm, threshold_depth);
  // Recomputed by the rule from the points.
  double mean = 0.0, var = 0.0;
  for (int i = 0; i < 10; ++i) mean += pts.force_n[static_cast<std::size_t>(i)] / 10.0;
  for (int i = 0; i < 10; ++i) var += std::pow(pts.force_n[static_cast<std::size_t>(i)] - mean, 2);
  const double threshold = mean + 5.0 * std::sqrt(var / 9.0);
  std::size_t rise = 10;
  while (true) {
    bool all = true;
    for (std::size_t j = rise; j < rise + 5; ++j) all = all && pts.force_n[j] > threshold;
    if (all) break;
    ++rise;
  }
  EXPECT_EQ(r.contact_depth_mm, pts.depth_mm[rise - 1]);
}

TEST(ForceDepthRecord, CutsAtThePerforation) {
  std::string text = "depth_mm,force_n\n";
  for (int i = 1; i <= 20; ++i) text += fmt::format("{},{}\n", 0.5 * i, 0.01 * i * i);
  text += "10.5,0.2\n11,0.05\n11.5,0.04\n";  // the drop, then the torn membrane
  RecordFormat f;
  f.contact_depth = 0.0;
  const auto r = parse_force_depth_record(text, "t.csv", f);
  ASSERT_EQ(r.depth_mm.size(), 20u);
  ASSERT_TRUE(r.perforation_depth_mm);
  EXPECT_EQ(*r.perforation_depth_mm, 10.0);
  EXPECT_DOUBLE_EQ(*r.perforation_force_n, 4.0);
  EXPECT_EQ(r.perforation_line, 21);
  f.cut_at_perforation = false;
  EXPECT_EQ(parse_force_depth_record(text, "t.csv", f).depth_mm.size(), 23u);
}

void expect_error(const std::string& text, const RecordFormat& f, const std::string& words,
                  int line, int column) {
  try {
    parse_force_depth_record(text, "bad.csv", f);
    ADD_FAILURE() << "accepted: " << words;
  } catch (const CsvError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), column) << e.what();
  }
}

TEST(ForceDepthRecord, RefusesBadRecordsNamingLineAndColumn) {
  RecordFormat f;
  f.contact_depth = 0.0;
  expect_error("depth,force_n\n1,2\n2,3\n", f, "bad.csv:1: missing depth column 'depth_mm'", 1, 0);
  expect_error(
      "depth_mm,force_n\n1,2\n2,abc\n3,4\n", f, "bad.csv:3: column 2 (force_n): 'abc'", 3, 2);
  expect_error("depth_mm,force_n\n1,2\n3,3\n2,4\n",
               f,
               "bad.csv:4: column 1 (depth_mm): the depth "
               "decreases",
               4,
               1);
  expect_error("depth_mm,force_n\n1,2\n3\n", f, "bad.csv:3: column 2 (force_n) is missing", 3, 2);
  RecordFormat no_header = f;
  no_header.header = Tristate::No;
  expect_error("1,2\n2,3\n", no_header, "no header", 1, 0);
  RecordFormat by_index = f;
  by_index.force = {"", 5};
  expect_error("depth_mm,force_n\n1,2\n2,3\n", by_index, "the force column 5 does not exist", 1, 5);
  expect_error("depth_mm,force_n\n", f, "0 points", 0, 0);
}

}  // namespace
}  // namespace puncture
