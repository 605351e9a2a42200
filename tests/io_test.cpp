// tests/io_test.cpp: the readers and writers of drange/io.hpp: every format they accept,
// every error message (exact text, file and line), round trips, and all-or-nothing writes.
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "drange/errors.hpp"
#include "drange/io.hpp"
#include "io/output_buffer.hpp"
#include "temp_dir.hpp"

namespace drange {
namespace {

using testing::count_entries;
using testing::read_text;
using testing::TempDir;
using testing::write_text;

PointCloud parse(const std::string& text, const std::string& name = "points.txt") {
  std::istringstream in(text);
  return parse_points(in, name);
}

// The InputError message parsing `text` produces, or a marker when it does not throw.
std::string parse_error(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string simplices_error(const TempDir& dir, const std::string& text, int per_row) {
  const std::string path = dir.file("s.txt");
  write_text(path, text);
  try {
    read_simplices(path, per_row);
  } catch (const InputError& e) {
    const std::string message = e.what();
    // Report relative to the directory so that expectations stay readable.
    return message.compare(0, dir.path().size() + 1, dir.path() + "/") == 0 ? message.substr(dir.path().size() + 1)
                                                                             : message;
  }
  return "(no error)";
}

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

double from_bits(std::uint64_t b) {
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

// ---------------------------------------------------------------- reading points: formats

TEST(IoReadPoints, QhullFormat) {
  const PointCloud cloud = parse("3\n2\n1 2 3\n4 5 6.5\n");
  EXPECT_EQ(cloud.dim, 3);
  EXPECT_EQ(cloud.coords, (std::vector<double>{1, 2, 3, 4, 5, 6.5}));
}

TEST(IoReadPoints, QhullFormatAsRboxWritesIt) {
  // rbox puts its command line after the dimension and ends rows with a space.
  const PointCloud cloud = parse("2 rbox 3 D2\n3\n0.5 -0.25 \n1 1 \n-1e-3 2 \n");
  EXPECT_EQ(cloud.dim, 2);
  EXPECT_EQ(cloud.coords, (std::vector<double>{0.5, -0.25, 1, 1, -1e-3, 2}));
}

TEST(IoReadPoints, RowsSeparatedByWhitespace) {
  const PointCloud cloud = parse("1 2\n3\t4\n  5   6  \n");
  EXPECT_EQ(cloud.dim, 2);
  EXPECT_EQ(cloud.coords, (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

TEST(IoReadPoints, CsvWithHeaderAndCommas) {
  const PointCloud cloud = parse("x,y,z\n1,2,3\n4, 5 ,6\n7 ,8,  9\n");
  EXPECT_EQ(cloud.dim, 3);
  EXPECT_EQ(cloud.coords, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
}

TEST(IoReadPoints, QuotedCsvHeaderIsSkipped) {
  const PointCloud cloud = parse("\"x\",\"y\"\n1,2\n");
  EXPECT_EQ(cloud.dim, 2);
  EXPECT_EQ(cloud.coords, (std::vector<double>{1, 2}));
}

TEST(IoReadPoints, CommentsBlankLinesWindowsLineEndsAndByteOrderMark) {
  const PointCloud cloud = parse("\xEF\xBB\xBF# made by hand\r\n\r\n2\r\n2\r\n   # indented comment\r\n1 2\r\n\r\n3 4\r\n");
  EXPECT_EQ(cloud.dim, 2);
  EXPECT_EQ(cloud.coords, (std::vector<double>{1, 2, 3, 4}));
}

TEST(IoReadPoints, NoFinalNewline) {
  const PointCloud cloud = parse("1 2\n3 4");
  EXPECT_EQ(cloud.coords, (std::vector<double>{1, 2, 3, 4}));
}

TEST(IoReadPoints, NumberSpellings) {
  const PointCloud cloud = parse("+1.5 -2e-3 .5 5. 1E+2 1e-400 -1e-400 -0 4.9e-324\n");
  ASSERT_EQ(cloud.dim, 9);
  EXPECT_EQ(cloud.coords[0], 1.5);
  EXPECT_EQ(cloud.coords[1], -2e-3);
  EXPECT_EQ(cloud.coords[2], 0.5);
  EXPECT_EQ(cloud.coords[3], 5.0);
  EXPECT_EQ(cloud.coords[4], 100.0);
  // Too small for a double: rounds to a signed zero, as strtod does.
  EXPECT_EQ(bits(cloud.coords[5]), bits(0.0));
  EXPECT_EQ(bits(cloud.coords[6]), bits(-0.0));
  EXPECT_EQ(bits(cloud.coords[7]), bits(-0.0));
  EXPECT_EQ(cloud.coords[8], std::numeric_limits<double>::denorm_min());
}

TEST(IoReadPoints, DecimalsAreCorrectlyRounded) {
  const PointCloud cloud = parse("0.1 0.2 0.30000000000000004 1.7976931348623157e308\n");
  EXPECT_EQ(cloud.coords[0], 0.1);
  EXPECT_EQ(cloud.coords[1], 0.2);
  EXPECT_EQ(cloud.coords[2], 0.1 + 0.2);
  EXPECT_EQ(cloud.coords[3], std::numeric_limits<double>::max());
}

TEST(IoReadPoints, OneDimensionalRows) {
  const PointCloud cloud = parse("0.5\n1.5\n2.5\n");
  EXPECT_EQ(cloud.dim, 1);
  EXPECT_EQ(cloud.size(), 3u);
}

TEST(IoReadPoints, ReadsAFileByPath) {
  TempDir dir;
  write_text(dir.file("p.txt"), "2\n1\n7 8\n");
  const PointCloud cloud = read_points(dir.file("p.txt"));
  EXPECT_EQ(cloud.dim, 2);
  EXPECT_EQ(cloud.coords, (std::vector<double>{7, 8}));
}

// ---------------------------------------------------------------- reading points: errors

TEST(IoReadPoints, WrongNumberOfCoordinatesNamesThePhysicalLine) {
  EXPECT_EQ(parse_error("1 2 3\n4 5 6\n7 8\n"), "points.txt:3: expected 3 coordinates, found 2");
  // Comments and blank lines count as lines: the number is the one an editor shows.
  EXPECT_EQ(parse_error("# c\n\n1 2 3\n# c\n4 5 6 7\n"), "points.txt:5: expected 3 coordinates, found 4");
  EXPECT_EQ(parse_error("0.5\n2 3\n"), "points.txt:2: expected 1 coordinate, found 2");
}

TEST(IoReadPoints, LoneIntegerOnTheFirstLineExplainsItself) {
  // A count or a dimension alone, as other formats write it, is not Qhull's two-line header.
  EXPECT_EQ(parse_error("3\n1 2 3\n4 5 6\n"),
            "points.txt:2: expected 1 coordinate, found 3 (line 1 holds a single integer and was read as a "
            "1-dimensional point; Qhull's format has the dimension on the first line and the number of points on "
            "the second)");
}

TEST(IoReadPoints, WrongNumberOfCoordinatesInQhullFormat) {
  EXPECT_EQ(parse_error("3\n3\n1 2 3\n4 5 6\n7 8\n"), "points.txt:5: expected 3 coordinates, found 2");
}

TEST(IoReadPoints, FirstRowAfterQhullHeaderExplainsTheHeader) {
  // A wrong header is the likelier mistake here, so the message shows how it was read.
  EXPECT_EQ(parse_error("3\n2\n1 2\n3 4\n"),
            "points.txt:3: expected 3 coordinates, found 2 (lines 1-2 were read as a Qhull header: dimension 3, "
            "2 points)");
}

TEST(IoReadPoints, NotANumber) {
  EXPECT_EQ(parse_error("1 2 3\n1.2.3 4 5\n"), "points.txt:2: not a number: \"1.2.3\"");
  EXPECT_EQ(parse_error("1 2\n3 abc\n"), "points.txt:2: not a number: \"abc\"");
  EXPECT_EQ(parse_error("1 2\n3 0x10\n"), "points.txt:2: not a number: \"0x10\"");
  EXPECT_EQ(parse_error("1 2\n3 1e\n"), "points.txt:2: not a number: \"1e\"");
  EXPECT_EQ(parse_error("1 2\n3 ++1\n"), "points.txt:2: not a number: \"++1\"");
}

TEST(IoReadPoints, MixedHeaderIsAnError) {
  // Only a row with no number at all is a header.
  EXPECT_EQ(parse_error("x,y,1\n1,2,3\n"), "points.txt:1: not a number: \"x\"");
}

TEST(IoReadPoints, NaNAndInfinity) {
  EXPECT_EQ(parse_error("1 2 3\n4 5 6\n7 8 9\n1 2 3\n5 5 5\n6 6 6\n7 7 7\n8 8 8\n1 nan 3\n"),
            "points.txt:9: coordinate 2 is NaN");
  EXPECT_EQ(parse_error("1 2\nNaN 2\n"), "points.txt:2: coordinate 1 is NaN");
  EXPECT_EQ(parse_error("1 2\ninf 2\n"), "points.txt:2: coordinate 1 is infinite");
  EXPECT_EQ(parse_error("1 2\n1 -Infinity\n"), "points.txt:2: coordinate 2 is infinite");
  EXPECT_EQ(parse_error("1 2\n1 1e999\n"), "points.txt:2: coordinate 2 is too large for a double: \"1e999\"");
}

TEST(IoReadPoints, EmptyFields) {
  EXPECT_EQ(parse_error("1,2,3\n1,,3\n"), "points.txt:2: coordinate 2 is empty");
  EXPECT_EQ(parse_error("1,2\n1,2,\n"), "points.txt:2: expected 2 coordinates, found 3");
  EXPECT_EQ(parse_error("1,2,3\n1,2,\n"), "points.txt:2: coordinate 3 is empty");
  EXPECT_EQ(parse_error("1,2\n,2\n"), "points.txt:2: coordinate 1 is empty");
}

TEST(IoReadPoints, HeaderCountMismatch) {
  EXPECT_EQ(parse_error("2\n100\n1 2\n3 4\n"), "points.txt: header says 100 points, found 2");
  EXPECT_EQ(parse_error("2\n1\n1 2\n3 4\n"), "points.txt: header says 1 point, found 2");
}

TEST(IoReadPoints, HugeHeaderCountDoesNotAllocate) {
  EXPECT_EQ(parse_error("2\n1000000000000000\n1 2\n"), "points.txt: header says 1000000000000000 points, found 1");
  EXPECT_EQ(parse_error("2\n99999999999999999999999\n1 2\n"),
            "points.txt:2: point count \"99999999999999999999999\" is too large");
}

TEST(IoReadPoints, BadDimensionInHeader) {
  EXPECT_EQ(parse_error("0\n5\n"), "points.txt:1: dimension must be at least 1, found 0");
  EXPECT_EQ(parse_error("99999999999\n5\n"), "points.txt:1: dimension \"99999999999\" is too large");
}

TEST(IoReadPoints, NoPoints) {
  EXPECT_EQ(parse_error(""), "points.txt: no points");
  EXPECT_EQ(parse_error("# only a comment\n\n   \n"), "points.txt: no points");
  EXPECT_EQ(parse_error("x,y,z\n"), "points.txt: no points");
  EXPECT_EQ(parse_error("3\n0\n"), "points.txt: no points");
}

TEST(IoReadPoints, ControlCharactersAndLongTokensAreShownSafely) {
  EXPECT_EQ(parse_error("1 2\n\x01x 3\n"), "points.txt:2: not a number: \"\\x01x\"");
  const std::string long_token(100, 'z');
  EXPECT_EQ(parse_error("1 2\n" + long_token + " 3\n"),
            "points.txt:2: not a number: \"" + std::string(40, 'z') + "...\"");
}

TEST(IoReadPoints, CannotOpen) {
  try {
    read_points("/nonexistent-drange-dir/x.txt");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "cannot open '/nonexistent-drange-dir/x.txt': No such file or directory");
  }
}

TEST(IoReadPoints, DirectoryIsNotAFile) {
  TempDir dir;
  try {
    read_points(dir.path());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read '" + dir.path() + "': Is a directory");
  }
}

TEST(IoReadPoints, ErrorsNameTheFileByItsPath) {
  TempDir dir;
  write_text(dir.file("bad.txt"), "1 2\n3 x\n");
  try {
    read_points(dir.file("bad.txt"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), dir.file("bad.txt") + ":2: not a number: \"x\"");
  }
}

TEST(IoReadPoints, AMillionRowsKeepEveryValue) {
  // 1 000 000 points in 3D, about 60 MB of text, every value checked: the rows after the first
  // go through the reader's one-pass path (read_points.cpp, append_plain_row).
  std::string text = "3\n1000000\n";
  text.reserve(64u << 20);
  for (int i = 0; i < 1000000; ++i) {
    text += std::to_string(i * 0.001234567) + " " + std::to_string(-i * 0.7654321) + " 0.123456789012345\n";
  }
  const PointCloud cloud = parse(text);
  ASSERT_EQ(cloud.size(), 1000000u);
  for (int i = 0; i < 1000000; i += 9973) {
    EXPECT_EQ(cloud.point(static_cast<std::size_t>(i))[0], std::stod(std::to_string(i * 0.001234567))) << i;
    EXPECT_EQ(cloud.point(static_cast<std::size_t>(i))[1], std::stod(std::to_string(-i * 0.7654321))) << i;
    EXPECT_EQ(cloud.point(static_cast<std::size_t>(i))[2], 0.123456789012345) << i;
  }
}

TEST(IoReadPoints, LaterRowsAreReadAsTheFirst) {
  // The first row is split into fields and each parsed on its own; the rows after it go
  // through a one-pass reader that hands anything unusual back to that path. Every spelling
  // and separator must give the same bits either way, in both layouts.
  const std::vector<std::string> rows = {
      "+1.5 -2e-3", ".5 5.", "1E+2\t1e-400", "-1e-400 -0", "4.9e-324 1.7976931348623157e308",
      "0.30000000000000004,7", " 1 , 2 ", "1,\t2\r", "\t-3\t\t4  ", "1e5,+2", "0x1p3 1",
  };
  for (const std::string& row : rows) {
    SCOPED_TRACE(row);
    const std::string twice = row + "\n" + row + "\n";
    for (const std::string& text : {twice, "2\n2\n" + twice}) {
      std::string error;
      try {
        const PointCloud cloud = parse(text);
        ASSERT_EQ(cloud.dim, 2);
        ASSERT_EQ(cloud.size(), 2u);
        EXPECT_EQ(bits(cloud.coords[2]), bits(cloud.coords[0]));
        EXPECT_EQ(bits(cloud.coords[3]), bits(cloud.coords[1]));
      } catch (const InputError& e) {
        error = e.what();
      }
      if (row == "0x1p3 1") EXPECT_EQ(error.substr(error.find(':')), text == twice ? ":1: not a number: \"0x1p3\"" : ":3: not a number: \"0x1p3\"");
      else EXPECT_EQ(error, "");
    }
  }
  // And the rows the one-pass reader refuses are still reported by line.
  EXPECT_EQ(parse_error("1 2\n3 4\n5 6 7\n"), "points.txt:3: expected 2 coordinates, found 3");
  EXPECT_EQ(parse_error("1 2\n3 4\n5\n"), "points.txt:3: expected 2 coordinates, found 1");
  EXPECT_EQ(parse_error("1 2\n3 4\n5 6 #\n"), "points.txt:3: expected 2 coordinates, found 3");
  EXPECT_EQ(parse_error("1 2\n3 4\n5 6x\n"), "points.txt:3: not a number: \"6x\"");
  EXPECT_EQ(parse_error("1 2\n3 4\n5 1e-\n"), "points.txt:3: not a number: \"1e-\"");
  EXPECT_EQ(parse_error("2\n3\n1 2\n3 4\n5,,6\n"), "points.txt:5: expected 2 coordinates, found 3");
}

// ---------------------------------------------------------------- reading simplices

TEST(IoReadSimplices, QdelaunayLayout) {
  TempDir dir;
  // As `qdelaunay i` writes it: trailing spaces.
  write_text(dir.file("s.txt"), "4\n3 2 4 \n0 3 4 \n3 1 2 \n3 0 1 \n");
  EXPECT_EQ(read_simplices(dir.file("s.txt"), 3), (std::vector<std::int32_t>{3, 2, 4, 0, 3, 4, 3, 1, 2, 3, 0, 1}));
}

TEST(IoReadSimplices, ZeroSimplices) {
  TempDir dir;
  write_text(dir.file("s.txt"), "0\n");
  EXPECT_TRUE(read_simplices(dir.file("s.txt"), 3).empty());
}

TEST(IoReadSimplices, LargestIndex) {
  TempDir dir;
  write_text(dir.file("s.txt"), "1\n0 2147483647\n");
  EXPECT_EQ(read_simplices(dir.file("s.txt"), 2), (std::vector<std::int32_t>{0, 2147483647}));
}

TEST(IoReadSimplices, Errors) {
  TempDir dir;
  EXPECT_EQ(simplices_error(dir, "2\n0 1 2\n0 1\n", 3), "s.txt:3: expected 3 indices, found 2");
  EXPECT_EQ(simplices_error(dir, "1\n0 1 2 3\n", 3), "s.txt:2: expected 3 indices, found 4");
  EXPECT_EQ(simplices_error(dir, "1\n0 1.5 2\n", 3), "s.txt:2: not an integer: \"1.5\"");
  EXPECT_EQ(simplices_error(dir, "1\n0 x 2\n", 3), "s.txt:2: not an integer: \"x\"");
  EXPECT_EQ(simplices_error(dir, "1\n# c\n0 -1 2\n", 3), "s.txt:3: negative index: \"-1\"");
  EXPECT_EQ(simplices_error(dir, "1\n0 2147483648 2\n", 3),
            "s.txt:2: index \"2147483648\" is too large (at most 2147483647)");
  EXPECT_EQ(simplices_error(dir, "1\n0 99999999999999999999999 2\n", 3),
            "s.txt:2: index \"99999999999999999999999\" is too large (at most 2147483647)");
  EXPECT_EQ(simplices_error(dir, "1\n0,,2\n", 3), "s.txt:2: index 2 is empty");
  EXPECT_EQ(simplices_error(dir, "3\n0 1 2\n1 2 3\n", 3), "s.txt: header says 3 simplices, found 2");
  EXPECT_EQ(simplices_error(dir, "1\n0 1 2\n1 2 3\n", 3), "s.txt: header says 1 simplex, found 2");
  EXPECT_EQ(simplices_error(dir, "", 3), "s.txt: empty, expected the number of simplices on the first line");
  EXPECT_EQ(simplices_error(dir, "0 1 2\n", 3), "s.txt:1: expected the number of simplices, found \"0 1 2\"");
  EXPECT_EQ(simplices_error(dir, "-2\n", 3), "s.txt:1: expected the number of simplices, found \"-2\"");
}

TEST(IoReadSimplices, CannotOpen) {
  try {
    read_simplices("/nonexistent-drange-dir/s.txt", 3);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "cannot open '/nonexistent-drange-dir/s.txt': No such file or directory");
  }
}

TEST(IoReadSimplices, RejectsNonsensicalRowWidth) {
  EXPECT_THROW(read_simplices("/dev/null", 0), UsageError);
}

// ---------------------------------------------------------------- writing

TEST(IoWrite, IndexRowsLayout) {
  std::ostringstream out;
  write_index_rows(out, {0, 1, 2, 3, -1, 5}, 3);
  EXPECT_EQ(out.str(), "2\n0 1 2\n3 -1 5\n");
}

TEST(IoWrite, IndexRowsEmpty) {
  std::ostringstream out;
  write_index_rows(out, {}, 4);
  EXPECT_EQ(out.str(), "0\n");
}

TEST(IoWrite, IndexRowsRejectsRaggedInput) {
  std::ostringstream out;
  EXPECT_THROW(write_index_rows(out, {0, 1, 2, 3}, 3), UsageError);
  EXPECT_THROW(write_index_rows(out, {0, 1}, 0), UsageError);
}

TEST(IoWrite, IndexRowsRoundTripThroughReadSimplices) {
  TempDir dir;
  std::vector<std::int32_t> rows;
  for (std::int32_t i = 0; i < 400000; ++i) rows.push_back(i * 5367 % 2147483647);
  {
    std::ostringstream out;
    write_index_rows(out, rows, 4);
    write_text(dir.file("s.txt"), out.str());
  }
  EXPECT_EQ(read_simplices(dir.file("s.txt"), 4), rows);
}

TEST(IoWrite, OutputBufferAcrossItsFlushes) {
  // Texts longer than the buffer, and numbers and characters on either side of each flush
  // (every 1 MiB), come out in order.
  std::ostringstream out;
  std::string expected;
  {
    io::OutputBuffer buffer(out);
    const std::string long_text(3 * (1u << 20) + 17, 'x');
    for (int round = 0; round < 3; ++round) {
      for (std::int64_t i = 0; i < 200000; ++i) {
        buffer.put_number(i * 7919 - 1000000);
        buffer.put(i % 2 ? ' ' : '\n');
        expected += std::to_string(i * 7919 - 1000000) + (i % 2 ? ' ' : '\n');
      }
      buffer.put_number(-2.2250738585072014e-308);  // the longest shortest form: 24 characters
      buffer.put_text(long_text);
      expected += "-2.2250738585072014e-308" + long_text;
    }
    buffer.flush();
  }
  EXPECT_EQ(out.str().size(), expected.size());
  EXPECT_TRUE(out.str() == expected);
}

TEST(IoWrite, PointsLayout) {
  PointCloud cloud;
  cloud.dim = 2;
  cloud.coords = {0.1, -0.0, 1e300, 5, 123456789012.0, 1e-7};
  std::ostringstream out;
  write_points(out, cloud);
  EXPECT_EQ(out.str(), "2\n3\n0.1 -0\n1e+300 5\n123456789012 1e-07\n");
}

TEST(IoWrite, PointsRoundTripBitIdentical) {
  // Doubles from all over the range: random bit patterns (finite only), denormals, extremes.
  PointCloud cloud;
  cloud.dim = 3;
  std::uint64_t state = 12345;
  while (cloud.coords.size() < 30000) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double x = from_bits(state ^ (state >> 29));
    if (std::isfinite(x)) cloud.coords.push_back(x);
  }
  for (double x : {0.0, -0.0, std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
                   std::numeric_limits<double>::min(), std::numeric_limits<double>::max(),
                   -std::numeric_limits<double>::max(), 0.1, 1.0 / 3.0, 2.0 / 3.0, 1e-310, 9007199254740993.0}) {
    cloud.coords.push_back(x);
  }
  while (cloud.coords.size() % 3 != 0) cloud.coords.push_back(0.5);

  std::ostringstream out;
  write_points(out, cloud);
  const PointCloud back = parse(out.str());
  ASSERT_EQ(back.dim, cloud.dim);
  ASSERT_EQ(back.coords.size(), cloud.coords.size());
  for (std::size_t i = 0; i < cloud.coords.size(); ++i) {
    ASSERT_EQ(bits(back.coords[i]), bits(cloud.coords[i])) << "coordinate " << i << " = " << cloud.coords[i];
  }
}

TEST(IoWrite, PointsRejectsBadCloud) {
  std::ostringstream out;
  PointCloud no_dimension;
  EXPECT_THROW(write_points(out, no_dimension), UsageError);
  PointCloud ragged;
  ragged.dim = 2;
  ragged.coords = {1, 2, 3};
  EXPECT_THROW(write_points(out, ragged), UsageError);
}

// ---------------------------------------------------------------- all-or-nothing files

TEST(IoAtomicWrite, WritesTheFileAndNothingElse) {
  TempDir dir;
  write_file_atomically(dir.file("out.txt"), [](std::ostream& out) { out << "hello\n"; });
  EXPECT_EQ(read_text(dir.file("out.txt")), "hello\n");
  EXPECT_EQ(count_entries(dir.path()), 1u);
}

TEST(IoAtomicWrite, ReplacesAnExistingFile) {
  TempDir dir;
  write_text(dir.file("out.txt"), "old content that is longer\n");
  write_file_atomically(dir.file("out.txt"), [](std::ostream& out) { out << "new\n"; });
  EXPECT_EQ(read_text(dir.file("out.txt")), "new\n");
  EXPECT_EQ(count_entries(dir.path()), 1u);
}

TEST(IoAtomicWrite, WriterThatThrowsLeavesNoFile) {
  TempDir dir;
  EXPECT_THROW(write_file_atomically(dir.file("out.txt"),
                                     [](std::ostream& out) {
                                       out << std::string(1 << 20, 'x');  // some of it reaches the disk
                                       throw std::runtime_error("writer failed");
                                     }),
               std::runtime_error);
  EXPECT_EQ(count_entries(dir.path()), 0u);
}

TEST(IoAtomicWrite, WriterThatThrowsDoesNotClobberAnExistingFile) {
  TempDir dir;
  write_text(dir.file("out.txt"), "precious\n");
  try {
    write_file_atomically(dir.file("out.txt"), [](std::ostream& out) {
      out << "partial";
      throw std::runtime_error("writer failed");
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "writer failed");  // the original exception, not a new one
  }
  EXPECT_EQ(read_text(dir.file("out.txt")), "precious\n");
  EXPECT_EQ(count_entries(dir.path()), 1u);
}

TEST(IoAtomicWrite, FailedStreamIsAnInputErrorAndKeepsTheOldFile) {
  TempDir dir;
  write_text(dir.file("out.txt"), "precious\n");
  try {
    write_file_atomically(dir.file("out.txt"), [](std::ostream& out) {
      out << "partial";
      out.setstate(std::ios::badbit);
    });
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write '" + dir.file("out.txt") + "': Input/output error");
  }
  EXPECT_EQ(read_text(dir.file("out.txt")), "precious\n");
  EXPECT_EQ(count_entries(dir.path()), 1u);
}

TEST(IoAtomicWrite, MissingDirectory) {
  TempDir dir;
  try {
    write_file_atomically(dir.file("no/such/out.txt"), [](std::ostream& out) { out << "x"; });
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write '" + dir.file("no/such/out.txt") + "': No such file or directory");
  }
}

TEST(IoAtomicWrite, PathIsADirectory) {
  TempDir dir;
  try {
    write_file_atomically(dir.path(), [](std::ostream& out) { out << "x"; });
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write '" + dir.path() + "': Is a directory");
  }
}

TEST(IoAtomicWrite, DeviceIsWrittenInPlace) {
  // Renaming over /dev/null would replace the device; it must be written to instead.
  write_file_atomically("/dev/null", [](std::ostream& out) { out << "discarded\n"; });
  struct stat info {};
  ASSERT_EQ(stat("/dev/null", &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
}

TEST(IoAtomicWrite, FullDeviceReportsTheReason) {
  if (access("/dev/full", W_OK) != 0) GTEST_SKIP() << "/dev/full is not available";
  try {
    write_file_atomically("/dev/full", [](std::ostream& out) { out << std::string(100000, 'x'); });
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "cannot write '/dev/full': No space left on device");
  }
}

TEST(IoAtomicWrite, KeepsThePermissionsOfTheReplacedFile) {
  TempDir dir;
  write_text(dir.file("out.txt"), "old\n");
  ASSERT_EQ(chmod(dir.file("out.txt").c_str(), 0640), 0);
  write_file_atomically(dir.file("out.txt"), [](std::ostream& out) { out << "new\n"; });
  struct stat info {};
  ASSERT_EQ(stat(dir.file("out.txt").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640u);
}

TEST(IoAtomicWrite, FollowsASymbolicLink) {
  TempDir dir;
  write_text(dir.file("target.txt"), "old\n");
  std::filesystem::create_symlink(dir.file("target.txt"), dir.file("link.txt"));
  write_file_atomically(dir.file("link.txt"), [](std::ostream& out) { out << "new\n"; });
  EXPECT_TRUE(std::filesystem::is_symlink(dir.file("link.txt")));
  EXPECT_EQ(read_text(dir.file("target.txt")), "new\n");
  EXPECT_EQ(count_entries(dir.path()), 2u);
}

TEST(IoAtomicWrite, ReadOnlyFileIsNotReplaced) {
  if (geteuid() == 0) GTEST_SKIP() << "root may write any file";
  TempDir dir;
  write_text(dir.file("out.txt"), "precious\n");
  ASSERT_EQ(chmod(dir.file("out.txt").c_str(), 0444), 0);
  EXPECT_THROW(write_file_atomically(dir.file("out.txt"), [](std::ostream& out) { out << "new\n"; }), InputError);
  EXPECT_EQ(read_text(dir.file("out.txt")), "precious\n");
}

}  // namespace
}  // namespace drange
