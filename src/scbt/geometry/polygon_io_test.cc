// The polygon text format: round trips over random polygons, and every error path.
#include "scbt/geometry/polygon_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace scbt {
namespace {

namespace fs = std::filesystem;

// Expects `fn` to throw `Exception` whose message contains `needle`.
template <typename Exception, typename Fn>
void expect_throw_containing(Fn fn, const std::string& needle) {
  try {
    fn();
    ADD_FAILURE() << "no exception; expected one mentioning '" << needle << "'";
  } catch (const Exception& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos)
        << "message '" << e.what() << "' does not mention '" << needle << "'";
  }
}

class PolygonIoRoundTrip : public ::testing::TestWithParam<unsigned> {};

TEST_P(PolygonIoRoundTrip, FormatThenParseKeepsTwoDecimals) {
  std::mt19937 rng(GetParam() + 1000u);
  std::uniform_int_distribution<int> count(0, 40);
  std::uniform_real_distribution<double> coordinate(-5000.0, 5000.0);
  Polygon polygon(count(rng));
  for (Point& p : polygon) p = Point(coordinate(rng), coordinate(rng));

  const std::string line = format_polygon_line(polygon);
  EXPECT_EQ(line.find('\n'), std::string::npos);
  const Polygon parsed = parse_polygon_line(line);
  ASSERT_EQ(parsed.size(), polygon.size());
  for (size_t i = 0; i < polygon.size(); ++i) {
    EXPECT_NEAR(parsed[i].x, polygon[i].x, 0.005 + 1e-9);
    EXPECT_NEAR(parsed[i].y, polygon[i].y, 0.005 + 1e-9);
  }
  // Formatting is a fixed point after one round.
  EXPECT_EQ(format_polygon_line(parsed), line);

  // The non-throwing variant agrees, and CRLF endings and extra blanks are accepted.
  Polygon again;
  std::string error;
  ASSERT_TRUE(try_parse_polygon_line("  " + line + " \t\r", &again, &error)) << error;
  EXPECT_EQ(again, parsed);
}

INSTANTIATE_TEST_SUITE_P(Seeds, PolygonIoRoundTrip, ::testing::Range(0u, 100u));

TEST(PolygonIo, ParsesAKnownLine) {
  const Polygon p = parse_polygon_line("3 1 2 3.5 -4 1e2 0\r");
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0], Point(1, 2));
  EXPECT_EQ(p[1], Point(3.5, -4));
  EXPECT_EQ(p[2], Point(100, 0));
  EXPECT_EQ(format_polygon_line(p), "3 1.00 2.00 3.50 -4.00 100.00 0.00");
}

TEST(PolygonIo, RejectsBadLines) {
  auto rejects = [](const std::string& line, const std::string& needle) {
    SCOPED_TRACE("line: '" + line + "'");
    expect_throw_containing<std::invalid_argument>([&] { parse_polygon_line(line); }, needle);
    Polygon p{{7, 7}};
    std::string error;
    EXPECT_FALSE(try_parse_polygon_line(line, &p, &error));
    EXPECT_NE(error.find(needle), std::string::npos) << error;
    EXPECT_EQ(p, Polygon({{7, 7}}));  // untouched on failure
  };
  rejects("", "empty");
  rejects("   \r", "empty");
  rejects("3 1 2 3 4", "found 4");      // too few coordinates
  rejects("2 1 2 3 4 5", "found 5");    // trailing garbage number
  rejects("2 1 2 3 4 x", "found 5");    // trailing garbage token
  rejects("2 1 2 3 abc", "'abc'");      // non-numeric token
  rejects("2 1 2 3 4.5.6", "'4.5.6'");  // half a number
  rejects("2 1 2 3 4abc", "'4abc'");    // trailing garbage inside a token
  rejects("2 1 nan 3 4", "finite");     // NaN
  rejects("2 1 2 inf 4", "finite");     // infinity
  rejects("2 1 2 -INF 4", "finite");
  rejects("2 1 2 3 1e999", "'1e999'");  // overflows
  rejects("x 1 2", "'x'");              // count not an integer
  rejects("2.5 1 2 3 4", "'2.5'");
  rejects("-1", "out of range");
}

TEST(PolygonIo, ParsePointsList) {
  const Polygon p = parse_points_list(" 1,2  3.5,-4\t10,20 ");
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0], Point(1, 2));
  EXPECT_EQ(p[1], Point(3.5, -4));
  EXPECT_EQ(p[2], Point(10, 20));
  EXPECT_TRUE(parse_points_list("").empty());
  for (const std::string bad : {"12", "1,", ",2", "1,2,3", "a,2", "1,nan", "inf,2", "1;2"}) {
    SCOPED_TRACE(bad);
    expect_throw_containing<std::invalid_argument>([&] { parse_points_list("0,0 " + bad); }, bad);
  }
}

class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("scbt_polygon_io_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& content) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << content;
    return path.string();
  }
  fs::path dir_;
};

TEST_F(TempDir, ReadFirstPolygon) {
  const std::string path = write("gt.txt", "3 1 1 10 1 5 8\r\n4 0 0 1 0 1 1 0 1\r\n");
  const Polygon p = read_first_polygon(path);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[2], Point(5, 8));
  const std::vector<std::string> lines = read_text_lines(path);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[1], "4 0 0 1 0 1 1 0 1");  // CR stripped
}

TEST_F(TempDir, ReadFirstPolygonErrorsNameTheFile) {
  const std::string missing = (dir_ / "missing.txt").string();
  expect_throw_containing<std::runtime_error>([&] { read_first_polygon(missing); }, missing);
  expect_throw_containing<std::runtime_error>([&] { read_text_lines(missing); }, missing);
  const std::string empty = write("empty.txt", "");
  expect_throw_containing<std::runtime_error>([&] { read_first_polygon(empty); }, empty);
  const std::string bad = write("bad.txt", "3 1 1 10 1 5\n");
  expect_throw_containing<std::runtime_error>([&] { read_first_polygon(bad); }, bad + ":1:");
}

TEST_F(TempDir, ReadFirstPolygonReadsOnlyTheFirstLine) {
  // An endless file fails at the line limit instead of filling memory.
  expect_throw_containing<std::runtime_error>([] { read_first_polygon("/dev/zero"); },
                                              "/dev/zero:1: line longer than 1 MiB");
  // A huge file whose first line is fine is not read to its end.
  const std::string big = write("big.txt", "3 1 1 10 1 5 8\n" + std::string(8 << 20, 'x'));
  EXPECT_EQ(read_first_polygon(big).size(), 3u);
  const std::string unterminated = write("last.txt", "3 1 1 10 1 5 8");
  EXPECT_EQ(read_first_polygon(unterminated).size(), 3u);
}

TEST_F(TempDir, AByteOrderMarkIsNamed) {
  const std::string path = write("bom.txt",
                                 "\xEF\xBB\xBF"
                                 "3 1 1 10 1 5 8\n");
  expect_throw_containing<std::runtime_error>(
      [&] { read_first_polygon(path); }, path + ":1: line starts with a UTF-8 byte-order mark");
}

TEST(PolygonIo, TinyNumbersAreNumbers) {
  const Polygon p = parse_polygon_line("3 1e-310 1 10 1 5 8");
  EXPECT_EQ(p[0].x, 1e-310);
  EXPECT_EQ(parse_points_list("1e-320,0 1,1")[0].x, 1e-320);
  expect_throw_containing<std::invalid_argument>([] { parse_polygon_line("3 1e400 1 10 1 5 8"); },
                                                 "('1e400') is not finite");
}

TEST(CheckBoundaryPolygon, RefusesMoreVerticesThanTheLimit) {
  Polygon circle;
  for (int i = 0; i <= kMaxBoundaryVertices; ++i) {
    const double angle = 2.0 * M_PI * i / (kMaxBoundaryVertices + 1);
    circle.emplace_back(1e4 * std::cos(angle), 1e4 * std::sin(angle));
  }
  expect_throw_containing<std::invalid_argument>([&] { check_boundary_polygon(circle); },
                                                 "at most " + std::to_string(kMaxBoundaryVertices));
  circle.pop_back();
  EXPECT_NO_THROW(check_boundary_polygon(circle));
}

TEST(CheckBoundaryPolygon, AcceptsASimplePolygon) {
  EXPECT_NO_THROW(check_boundary_polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  EXPECT_NO_THROW(check_boundary_polygon({{0, 0}, {0, 10}, {10, 10}, {10, 0}}));  // either turn
}

TEST(CheckBoundaryPolygon, RejectsUnusablePolygons) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto rejects = [](const Polygon& polygon, const std::string& needle) {
    expect_throw_containing<std::invalid_argument>([&] { check_boundary_polygon(polygon); },
                                                   needle);
  };
  rejects({}, "3 distinct");
  rejects({{0, 0}, {10, 0}}, "3 distinct");
  rejects({{0, 0}, {10, 0}, {0, 0}, {10, 0}}, "3 distinct");
  rejects({{0, 0}, {10, 0}, {10, 10}, {10, 0}}, "repeats");
  rejects({{0, 0}, {10, 0}, {20, 0}}, "polygon encloses no area (its vertices lie on one line)");
  rejects({{10, 10}, {20, 20}, {30, 30}, {40, 40}}, "no area (its vertices lie on one line)");
  // A bow-tie crosses itself, whether or not its lobes' areas cancel.
  rejects({{0, 0}, {10, 10}, {10, 0}, {0, 10}}, "polygon crosses itself");
  rejects({{0, 0}, {30, 20}, {30, 0}, {0, 10}}, "polygon crosses itself");
  rejects({{10, 10}, {11, 10}, {10, 11}}, "polygon encloses 0.5 px², smaller than 1 px²");
  rejects({{0, 0}, {nan, 0}, {10, 10}}, "vertex 2");
  rejects({{0, 0}, {10, 0}, {10, inf}}, "vertex 3");
}

// Ground-truth files repeat a vertex right after itself, or the first one last: those go; a
// vertex repeated elsewhere stays (and is refused as a boundary).
TEST(DropRepeatedVertices, DropsOnlyConsecutiveRepeats) {
  Polygon p = {{0, 0}, {10, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}};
  EXPECT_EQ(drop_repeated_vertices(&p), 2);
  EXPECT_EQ(p, (Polygon{{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  EXPECT_NO_THROW(check_boundary_polygon(p));
  Polygon back = {{0, 0}, {10, 0}, {10, 10}, {10, 0}};
  EXPECT_EQ(drop_repeated_vertices(&back), 0);
  EXPECT_EQ(back.size(), 4u);
  Polygon same = {{1, 1}, {1, 1}, {1, 1}};
  EXPECT_EQ(drop_repeated_vertices(&same), 2);
  EXPECT_EQ(same.size(), 1u);
}

// Text quoted from a file is escaped: a NUL byte does not cut the message.
TEST(PolygonIo, AQuotedNulByteIsEscaped) {
  expect_throw_containing<std::invalid_argument>(
      [] { parse_polygon_line(std::string("3 1 1 6\0x 1 5 8", 15)); },
      "coordinate '6\\x00x' is not a number");
}

TEST_F(TempDir, AFolderIsNamedAsOne) {
  expect_throw_containing<std::runtime_error>([&] { read_first_polygon(dir_.string()); },
                                              dir_.string() + ": is a folder, not a file");
}

TEST_F(TempDir, PolygonLinesAreAllRead) {
  const std::string path = write("gt.txt", "3 1 1 10 1 5 8\r\n3 2 2 10 1 5 8\n\n");
  EXPECT_EQ(read_polygon_lines(path),
            (std::vector<std::string>{"3 1 1 10 1 5 8", "3 2 2 10 1 5 8", ""}));
  expect_throw_containing<std::runtime_error>([] { read_polygon_lines("/dev/zero"); },
                                              "/dev/zero:1: line longer than 1 MiB");
  expect_throw_containing<std::runtime_error>([&] { read_polygon_lines(write("e.txt", "")); },
                                              "e.txt: file is empty");
}

}  // namespace
}  // namespace scbt
