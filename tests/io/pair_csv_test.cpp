#include "io/pair_csv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io_test_util.hpp"

namespace cardemo {
namespace {

using testing::failsAt;

constexpr std::string_view kRow2 = "0,0,0,4,2,3,1,90,4,2";
constexpr std::string_view kRow3 = "0,0,0,1,0,0,0,2,4,6,1,2,3,1,0,0,0,1,1,1";

Parsed<std::vector<PairRow2>> parse2(std::string_view text) {
  return parsePairs2(text, "p.csv");
}
Parsed<std::vector<PairRow3>> parse3(std::string_view text) {
  return parsePairs3(text, "p.csv");
}

TEST(PairCsv, Parses2DRowsWithHeaderCommentsAndBlanks) {
  const Parsed<std::vector<PairRow2>> p = parse2(
      "# pairs\n"
      "\n"
      "ax,ay,a_heading_deg,a_length,a_width,bx,by,b_heading_deg,b_length,b_width\n"
      "0,0,0,4,2,3,1,90,4,2\n"
      "  # indented comment\n"
      " 1.5 , -2e3 ,\t45, 1e-2 ,100, 0,0,0,1,1 \n");
  ASSERT_TRUE(p.ok()) << p.error().toString();
  const auto& rows = p.value();
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].line, 4);
  EXPECT_EQ(rows[0].a.center, Eigen::Vector2d(0, 0));
  EXPECT_EQ(rows[0].a.half, Eigen::Vector2d(2, 1));
  EXPECT_EQ(rows[0].a.axis, Eigen::Vector2d(1, 0));
  EXPECT_EQ(rows[0].b.center, Eigen::Vector2d(3, 1));
  EXPECT_EQ(rows[0].b.axis, Eigen::Vector2d(0, 1));  // exact at 90 degrees
  EXPECT_EQ(rows[1].line, 6);
  EXPECT_EQ(rows[1].a.center, Eigen::Vector2d(1.5, -2000));
  EXPECT_EQ(rows[1].a.half, Eigen::Vector2d(0.005, 50));
}

TEST(PairCsv, Parses3DRows) {
  const double h = std::sqrt(0.5);
  const std::string rotated = "5,6,7," + std::to_string(2 * h) + ",0,0," + std::to_string(2 * h) +
                              ",2,4,6,0,0,0,1,0,0,0,1,1,1";
  const Parsed<std::vector<PairRow3>> p = parse3(std::string(kRow3) + "\n" + rotated + "\n");
  ASSERT_TRUE(p.ok()) << p.error().toString();
  const auto& rows = p.value();
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].a.center, Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(rows[0].a.half, Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(rows[0].a.rotation().isApprox(Eigen::Matrix3d::Identity(), 1e-15));
  EXPECT_EQ(rows[0].b.center, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(rows[0].b.half, Eigen::Vector3d(0.5, 0.5, 0.5));
  // 90 degrees about z, from a non-unit quaternion: box x axis becomes world y.
  EXPECT_EQ(rows[1].a.center, Eigen::Vector3d(5, 6, 7));
  EXPECT_NEAR(rows[1].a.rotation()(0, 0), 0.0, 1e-6);
  EXPECT_NEAR(rows[1].a.rotation()(1, 0), 1.0, 1e-6);
  EXPECT_EQ(rows[1].line, 2);
}

TEST(PairCsv, EmptyInputGivesNoRows) {
  ASSERT_TRUE(parse2("").ok());
  EXPECT_TRUE(parse2("").value().empty());
  EXPECT_TRUE(parse2("# only\n\n").value().empty());
}

TEST(PairCsv, CrLfLineEndings) {
  const Parsed<std::vector<PairRow2>> p = parse2("ax,ay\r\n0,0,0,4,2,3,1,90,4,2\r\n\r\n");
  ASSERT_TRUE(p.ok()) << p.error().toString();
  ASSERT_EQ(p.value().size(), 1u);
  EXPECT_EQ(p.value()[0].line, 2);
  EXPECT_EQ(p.value()[0].b.half, Eigen::Vector2d(2, 1));
}

TEST(PairCsv, LeadingPlusIsAccepted) {
  const Parsed<std::vector<PairRow2>> p = parse2("+1,0,0,4,2,3,1,90,4,+2\n");
  ASSERT_TRUE(p.ok()) << p.error().toString();
  EXPECT_EQ(p.value()[0].a.center.x(), 1.0);
}

// --- malformed input ---

TEST(PairCsvErrors, HeaderIsOnlySkippedOnTheFirstDataLine) {
  EXPECT_TRUE(failsAt(parse2("0,0,0,4,2,3,1,90,4,2\nax,ay,a,b,c,d,e,f,g,h\n"), 2,
                      "field 1 (ax): not a number: \"ax\""));
  EXPECT_TRUE(failsAt(parse2("ax\nbx\n"), 2, "expected 10 fields, found 1"));
}

TEST(PairCsvErrors, WrongFieldCount) {
  EXPECT_TRUE(failsAt(parse2("0,0,0,4,2,3,1,90,4\n"), 1, "expected 10 fields, found 9"));
  EXPECT_TRUE(failsAt(parse2("# c\n0,0,0,4,2,3,1,90,4,2,\n"), 2, "expected 10 fields, found 11"));
  EXPECT_TRUE(failsAt(parse3(std::string(kRow3) + ",1\n"), 1, "expected 20 fields, found 21"));
  EXPECT_TRUE(failsAt(parse3(std::string(kRow2) + "\n"), 1, "expected 20 fields, found 10"));
  EXPECT_TRUE(failsAt(parse2("0 0 0 4 2 3 1 90 4 2\n"), 1, "expected 10 fields, found 1"));
}

TEST(PairCsvErrors, NonNumericField) {
  EXPECT_TRUE(failsAt(parse2("0,0,0,abc,2,3,1,90,4,2\n"), 1, "field 4 (a_length): not a number"));
  EXPECT_TRUE(failsAt(parse2("0,0,0,4,2,3,1,90,4,2x\n"), 1, "field 10 (b_width): not a number"));
  EXPECT_TRUE(
      failsAt(parse2("0,0,0,4,2,3,1,9 0,4,2\n"), 1, "field 8 (b_heading_deg): not a number"));
  EXPECT_TRUE(failsAt(parse2("0,0,0,4,2,3,1,0x10,4,2\n"), 1, "field 8 (b_heading_deg)"));
  EXPECT_TRUE(failsAt(parse2("0,0,0,4,2,3,1,--1,4,2\n"), 1, "field 8 (b_heading_deg)"));
}

TEST(PairCsvErrors, EmptyField) {
  EXPECT_TRUE(failsAt(parse2("0, ,0,4,2,3,1,90,4,2\n"), 1, "field 2 (ay): empty"));
}

TEST(PairCsvErrors, SizeNotPositive) {
  EXPECT_TRUE(
      failsAt(parse2("0,0,0,0,2,3,1,90,4,2\n"), 1, "field 4 (a_length): must be finite and > 0"));
  EXPECT_TRUE(failsAt(parse2("0,0,0,4,-2,3,1,90,4,2\n"), 1, "field 5 (a_width): must be finite"));
  EXPECT_TRUE(failsAt(parse3("0,0,0,1,0,0,0,2,4,0,1,2,3,1,0,0,0,1,1,1\n"), 1,
                      "field 10 (a_sz): must be finite and > 0"));
}

TEST(PairCsvErrors, NotFinite) {
  EXPECT_TRUE(failsAt(parse2("0,nan,0,4,2,3,1,90,4,2\n"), 1, "field 2 (ay): must be finite"));
  EXPECT_TRUE(failsAt(parse2("0,0,0,inf,2,3,1,90,4,2\n"), 1, "field 4 (a_length): must be finite"));
  EXPECT_TRUE(failsAt(parse2("0,0,-infinity,4,2,3,1,90,4,2\n"), 1, "field 3 (a_heading_deg)"));
  EXPECT_TRUE(
      failsAt(parse2("0,1e999,0,4,2,3,1,90,4,2\n"), 1, "field 2 (ay): number out of range"));
}

TEST(PairCsvErrors, FirstLineStartingWithALetterIsAHeaderEvenIfNumeric) {
  // Contract: a first line that starts with a letter is a header, so "nan,..." there is skipped.
  const Parsed<std::vector<PairRow2>> p = parse2("nan,0,0,4,2,3,1,90,4,2\n0,0,0,4,2,3,1,90,4,2\n");
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.value().size(), 1u);
  EXPECT_EQ(p.value()[0].line, 2);
}

TEST(PairCsvErrors, CoordinateTooLarge) {
  EXPECT_TRUE(failsAt(parse2("0,0,0,4,2,2e9,1,90,4,2\n"), 1,
                      "field 6 (bx): must be finite with |value| <= 1e9"));
}

TEST(PairCsvErrors, ZeroQuaternion) {
  EXPECT_TRUE(
      failsAt(parse3("# 3d\n0,0,0,0,0,0,0,2,4,6,1,2,3,1,0,0,0,1,1,1\n"), 2, "zero quaternion"));
  EXPECT_TRUE(failsAt(parse3("0,0,0,1,0,0,0,2,4,6,1,2,3,0,0,0,-0,1,1,1\n"), 1,
                      "(bqw..bqz): zero quaternion"));
  EXPECT_TRUE(
      failsAt(parse3("0,0,0,1e-200,0,0,0,2,4,6,1,2,3,1,0,0,0,1,1,1\n"), 1, "too close to zero"));
}

TEST(PairCsvErrors, OneMegabyteLine) {
  const std::string big(1 << 20, '1');
  EXPECT_TRUE(
      failsAt(parse2(std::string(kRow2) + "\n" + big + "\n"), 2, "line longer than 4096 bytes"));
  EXPECT_TRUE(failsAt(parse3(std::string(1 << 20, ',')), 1, "line longer than 4096 bytes"));
}

TEST(PairCsvErrors, ControlAndGarbageBytes) {
  EXPECT_TRUE(failsAt(parse2(std::string_view("0,0\0,0,4,2,3,1,90,4,2\n", 22)), 1,
                      "field 2 (ay): not a number"));
  EXPECT_TRUE(failsAt(parse2("\xff\xfe,,,\n"), 1, "expected 10 fields, found 4"));
}

}  // namespace
}  // namespace cardemo
