// The strict CSV reader: what it accepts, and that every rejection names the line and column.
#include "puncture/csv.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace puncture {
namespace {

// The CsvError of parsing `text`, or a test failure when it parses.
CsvError error_of(const std::string& text, std::size_t min_rows = 1) {
  try {
    parse_numeric_csv(text, "data.csv", min_rows);
  } catch (const CsvError& e) {
    return e;
  }
  ADD_FAILURE() << "parsed without error:\n" << text;
  return CsvError("");
}

TEST(Csv, ReadsHeaderAndRows) {
  const auto t = parse_numeric_csv("stretch,nominal_stress_mpa\n1,0\n1.5, 2.5e-2\n+2 ,-3\n", "x");
  ASSERT_EQ(t.columns.size(), 2u);
  EXPECT_EQ(t.columns[0], "stretch");
  EXPECT_EQ(t.columns[1], "nominal_stress_mpa");
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[1][1], 0.025);
  EXPECT_EQ(t.rows[2][0], 2.0);
  EXPECT_EQ(t.rows[2][1], -3.0);
  EXPECT_EQ(t.line_numbers, (std::vector<int>{2, 3, 4}));
  EXPECT_EQ(t.column("stretch"), (std::vector<double>{1.0, 1.5, 2.0}));
}

TEST(Csv, SkipsBlankAndCommentLinesAndAcceptsCrlfAndBom) {
  const auto t = parse_numeric_csv(
      "\xEF\xBB\xBF# tensile test 3\r\n\r\nstretch,nominal_stress_mpa\r\n  # start\r\n1,0\r\n"
      "\r\n2,0.1",
      "x");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.line_numbers, (std::vector<int>{5, 7}));
  EXPECT_EQ(t.rows[1][1], 0.1);
}

TEST(Csv, RejectsEmptyInput) {
  EXPECT_NE(std::string(error_of("").what()).find("empty"), std::string::npos);
  EXPECT_NE(std::string(error_of("# only a comment\n\n").what()).find("no header"),
            std::string::npos);
}

TEST(Csv, RequiresAHeader) {
  const auto e = error_of("1.0,2.0\n3,4\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_NE(std::string(e.what()).find("header"), std::string::npos);
}

TEST(Csv, RejectsEmptyAndRepeatedColumnNames) {
  const auto empty = error_of("stretch,,x\n1,2,3\n");
  EXPECT_EQ(empty.line(), 1);
  EXPECT_EQ(empty.column(), 2);
  const auto repeated = error_of("a,b,a\n1,2,3\n");
  EXPECT_EQ(repeated.column(), 3);
  EXPECT_NE(std::string(repeated.what()).find("repeats"), std::string::npos);
}

TEST(Csv, RejectsAWrongNumberOfFields) {
  const auto e = error_of("a,b\n1,2\n3\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(std::string(e.what()), "data.csv:3: 1 field, but the header has 2 columns");
  EXPECT_EQ(error_of("a,b\n1,2,3\n").line(), 2);
}

TEST(Csv, NamesLineAndColumnOfABadValue) {
  const auto e = error_of("stretch,nominal_stress_mpa\n1,0\n1.2,abc\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.column(), 2);
  EXPECT_EQ(std::string(e.what()),
            "data.csv:3: column 2 (nominal_stress_mpa): 'abc' is not a number");
}

TEST(Csv, RejectsEveryKindOfNonNumber) {
  for (const char* bad : {"1.5x", "x1", "--1", "+-1", "+", "0x10", "1e", "\"1\"", ".", "1 2"}) {
    const auto e = error_of(std::string("a,b\n1,") + bad + "\n");
    EXPECT_EQ(e.line(), 2) << bad;
    EXPECT_EQ(e.column(), 2) << bad;
    EXPECT_NE(std::string(e.what()).find("is not a number"), std::string::npos) << e.what();
  }
  EXPECT_EQ(error_of("a,b\n1,\n").column(), 2);
  EXPECT_NE(std::string(error_of("a,b\n1, \n").what()).find("empty value"), std::string::npos);
}

TEST(Csv, RejectsNonFiniteAndOutOfRangeValues) {
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity"}) {
    const auto e = error_of(std::string("a\n") + bad + "\n");
    EXPECT_NE(std::string(e.what()).find("not a finite number"), std::string::npos) << bad;
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 1);
  }
  const auto huge = error_of("a\n1e400\n");
  EXPECT_NE(std::string(huge.what()).find("out of the range"), std::string::npos);
}

TEST(Csv, RequiresEnoughRows) {
  const auto e = error_of("a,b\n1,2\n3,4\n", 3);
  EXPECT_EQ(std::string(e.what()), "data.csv: too few data rows: 2 found, at least 3 needed");
  EXPECT_EQ(error_of("a,b\n").line(), 0);
}

TEST(Csv, MissingColumnNamesTheHeader) {
  const auto t = parse_numeric_csv("force_n,depth_mm\n1,2\n", "data.csv");
  try {
    t.column("stretch");
    FAIL() << "no error";
  } catch (const CsvError& e) {
    EXPECT_EQ(std::string(e.what()),
              "data.csv: missing column 'stretch' (the header has: force_n,depth_mm)");
  }
}

TEST(Csv, ReadsFilesAndReportsUnreadableOnes) {
  const std::string path = testing::TempDir() + "csv_test_data.csv";
  {
    std::ofstream f(path);
    f << "a,b\n1,2\n";
  }
  const auto t = read_numeric_csv(path);
  EXPECT_EQ(t.source, path);
  EXPECT_EQ(t.rows.size(), 1u);
  std::remove(path.c_str());
  EXPECT_THROW(read_numeric_csv(path), CsvError);
}

}  // namespace
}  // namespace puncture
