// tests/npy_test.cpp: NumPy .npy files: points read by read_points (every dtype, byte order,
// memory order and header version drange accepts, bit for bit), every error message, the
// speed of a large read, and write_npy's layout, also as numpy.load reads it.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "drange/io.hpp"
#include "python_check.hpp"
#include "temp_dir.hpp"

namespace drange {
namespace {

using testing::read_text;
using testing::run_python;
using testing::TempDir;
using testing::write_text;

// The raw bytes of `values` as float64 or float32, in either byte order, independent of the host's.
std::string raw_bytes(const std::vector<double>& values, bool as_float32, bool big_endian) {
  std::string out;
  for (double value : values) {
    std::uint64_t bits = 0;
    std::size_t width = 8;
    if (as_float32) {
      const auto narrow = static_cast<float>(value);
      std::uint32_t bits32;
      std::memcpy(&bits32, &narrow, sizeof bits32);
      bits = bits32;
      width = 4;
    } else {
      std::memcpy(&bits, &value, sizeof bits);
    }
    for (std::size_t b = 0; b < width; ++b) {
      const std::size_t shift = 8 * (big_endian ? width - 1 - b : b);
      out += static_cast<char>((bits >> shift) & 0xff);
    }
  }
  return out;
}

// A .npy file made by hand: the header dict `dict` (padded here as NumPy pads it), then `data`.
std::string npy_file(const std::string& dict, const std::string& data, int major = 1) {
  const std::size_t prefix = major == 1 ? 10 : 12;
  std::string header = dict;
  while ((prefix + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::string out = "\x93NUMPY";
  out += static_cast<char>(major);
  out += '\0';
  for (std::size_t b = 0; b < (major == 1 ? 2u : 4u); ++b) out += static_cast<char>((header.size() >> (8 * b)) & 0xff);
  return out + header + data;
}

std::string dict(const std::string& descr, const std::string& shape, bool fortran = false) {
  return "{'descr': '" + descr + "', 'fortran_order': " + (fortran ? "True" : "False") + ", 'shape': " + shape + ", }";
}

PointCloud parse(const std::string& bytes, const std::string& name = "p.npy") {
  std::istringstream in(bytes);
  return parse_points(in, name);
}

std::string parse_error(const std::string& bytes, const std::string& name = "p.npy") {
  try {
    parse(bytes, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::vector<std::uint64_t> bits_of(const std::vector<double>& values) {
  std::vector<std::uint64_t> bits(values.size());
  std::memcpy(bits.data(), values.data(), values.size() * sizeof(double));
  return bits;
}

// Values whose bits a decimal detour could change: signed zero, subnormals, extremes.
const std::vector<double> kTricky = {
    0.1,       -0.0,         4.9406564584124654e-324, 2.2250738585072014e-308, 1.7976931348623157e308, -1e-300,
    1.0 / 3.0, 123456789.125};

std::string write_npy_bytes(const NpyArray& array) {
  std::ostringstream out;
  write_npy(out, array);
  return out.str();
}

// ---------------------------------------------------------------- reading: accepted files

TEST(NpyRead, Float64RoundTripIsBitExact) {
  const PointCloud cloud = parse(write_npy_bytes(NpyArray(kTricky.data(), {4, 2})));
  EXPECT_EQ(cloud.dim, 2);
  EXPECT_EQ(bits_of(cloud.coords), bits_of(kTricky));
}

TEST(NpyRead, Float32IsWidenedExactly) {
  const std::vector<double> values = {0.1, -2.5, 3.0e38, 1e-40, 7, 8};
  const PointCloud cloud = parse(npy_file(dict("<f4", "(3, 2)"), raw_bytes(values, true, false)));
  ASSERT_EQ(cloud.coords.size(), values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(cloud.coords[i], static_cast<double>(static_cast<float>(values[i]))) << i;
  }
  EXPECT_NE(cloud.coords[0], 0.1);  // the float's value, not the decimal's
}

TEST(NpyRead, BigEndian) {
  EXPECT_EQ(bits_of(parse(npy_file(dict(">f8", "(4, 2)"), raw_bytes(kTricky, false, true))).coords), bits_of(kTricky));
  const std::vector<double> halves = {0.5, -1.25, 3, 4};
  EXPECT_EQ(parse(npy_file(dict(">f4", "(2, 2)"), raw_bytes(halves, true, true))).coords, halves);
}

TEST(NpyRead, FortranOrderIsTransposed) {
  // Points (1, 2, 3), (4, 5, 6): in Fortran order the file holds column after column.
  const std::vector<double> columns = {1, 4, 2, 5, 3, 6};
  const PointCloud cloud = parse(npy_file(dict("<f8", "(2, 3)", true), raw_bytes(columns, false, false)));
  EXPECT_EQ(cloud.dim, 3);
  EXPECT_EQ(cloud.coords, (std::vector<double>{1, 2, 3, 4, 5, 6}));
  const PointCloud narrow = parse(npy_file(dict(">f4", "(2, 3)", true), raw_bytes(columns, true, true)));
  EXPECT_EQ(narrow.coords, (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

TEST(NpyRead, HeaderVersions2And3) {
  const std::vector<double> values = {1, 2, 3, 4};
  for (int major : {2, 3}) {
    const PointCloud cloud = parse(npy_file(dict("<f8", "(2, 2)"), raw_bytes(values, false, false), major));
    EXPECT_EQ(cloud.coords, values) << "version " << major;
  }
}

TEST(NpyRead, HeaderSpellingsNumpyMayWrite) {
  const std::string data = raw_bytes({1, 2, 3, 4}, false, false);
  // Keys in another order, double quotes, no trailing comma, Python 2 long integers.
  for (const std::string& header :
       {std::string("{'shape': (2, 2), 'fortran_order': False, 'descr': '<f8'}"),
        std::string("{\"descr\": \"<f8\", \"fortran_order\": False, \"shape\": (2L, 2L)}")}) {
    EXPECT_EQ(parse(npy_file(header, data)).coords, (std::vector<double>{1, 2, 3, 4})) << header;
  }
}

TEST(NpyRead, BytesAfterTheArrayAreIgnoredAsNumpyDoes) {
  const std::string file = npy_file(dict("<f8", "(1, 2)"), raw_bytes({1, 2}, false, false)) + "more";
  EXPECT_EQ(parse(file).coords, (std::vector<double>{1, 2}));
}

TEST(NpyRead, FromAFileAndFromStandardInput) {
  TempDir dir;
  const std::string bytes = write_npy_bytes(NpyArray(kTricky.data(), {2, 4}));
  const std::string path = dir.file("points.npy");
  write_text(path, bytes);
  EXPECT_EQ(bits_of(read_points(path).coords), bits_of(kTricky));

  // Recognised by the magic bytes, without a name to go by.
  std::istringstream in(bytes);
  std::streambuf* saved = std::cin.rdbuf(in.rdbuf());
  PointCloud from_stdin;
  try {
    from_stdin = read_points("-");
  } catch (...) {
    std::cin.rdbuf(saved);
    throw;
  }
  std::cin.rdbuf(saved);
  EXPECT_EQ(from_stdin.dim, 4);
  EXPECT_EQ(bits_of(from_stdin.coords), bits_of(kTricky));
}

TEST(NpyRead, MillionPointsIn3DAreFast) {
  constexpr std::size_t n = 1000000;
  std::vector<double> values(3 * n);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<double>(i) * 0.5;
  const std::string bytes = write_npy_bytes(NpyArray(values.data(), {n, 3}));
  const auto start = std::chrono::steady_clock::now();
  const PointCloud cloud = parse(bytes);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(cloud.coords, values);
  // A small fraction of the bound on an idle machine; the loose bound (a busy machine is
  // slower) only catches a slow path, such as reading the data element by element from a stream.
  EXPECT_LT(seconds, 1.5);
}

// ---------------------------------------------------------------- reading: every error

TEST(NpyRead, ErrorMessages) {
  const std::string two = raw_bytes({1, 2}, false, false);
  struct Case {
    std::string bytes;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"\x93NUMPX\x01\x00",
       "p.npy: not a NumPy .npy file: it starts with \"\\x93NUMPX\", not the magic \"\\x93NUMPY\""},
      {"1 2\n3 4\n", "p.npy: not a NumPy .npy file: it starts with \"1 2\\x0a3 \", not the magic \"\\x93NUMPY\""},
      {std::string("\x93NUMPY\x04\x00", 8),
       "p.npy: unsupported .npy format version 4.0 (drange reads 1.0, 2.0 and 3.0)"},
      {std::string("\x93NUMPY\x01\x01", 8),
       "p.npy: unsupported .npy format version 1.1 (drange reads 1.0, 2.0 and 3.0)"},
      {"\x93NUMPY", "p.npy: the .npy file ends before its version"},
      {std::string("\x93NUMPY\x01\x00\x76", 9), "p.npy: the .npy file ends before its header length"},
      {std::string("\x93NUMPY\x01\x00\x76\x00{'descr'", 18),
       "p.npy: the .npy file ends inside its header: the header is 118 bytes, 8 are present"},
      {std::string("PK\x03\x04", 4) + "rest",
       "p.npy: a zip archive (an .npz?): drange reads the points from a .npy file (numpy.save) holding one array of "
       "shape (points, dimension)"},
      {npy_file(dict("<i8", "(1, 2)"), two),
       "p.npy: unsupported .npy dtype '<i8': drange reads float64 ('<f8', '>f8') or float32 ('<f4', '>f4'); convert "
       "with array.astype(numpy.float64)"},
      {npy_file("{'descr': [('x', '<f8'), ('y', '<f8')], 'fortran_order': False, 'shape': (1,), }", two),
       "p.npy: unsupported .npy dtype: a structured (record) dtype; drange reads float64 or float32 arrays of shape "
       "(points, dimension)"},
      {npy_file(dict("<f8", "(2,)"), two),
       "p.npy: the .npy array has shape (2,): points must be a 2-D array of shape (points, dimension)"},
      {npy_file(dict("<f8", "(1, 1, 2)"), two),
       "p.npy: the .npy array has shape (1, 1, 2): points must be a 2-D array of shape (points, dimension)"},
      {npy_file(dict("<f8", "(0, 3)"), ""), "p.npy: no points"},
      {npy_file(dict("<f8", "(2, 0)"), ""), "p.npy: the .npy array has shape (2, 0): no coordinates"},
      {npy_file(dict("<f8", "(2, 2)"), two + "abc"),
       "p.npy: the .npy data is truncated: shape (2, 2) of '<f8' needs 32 bytes, found 19"},
      {npy_file(dict("<f8", "(4294967296, 4294967296)"), two),
       "p.npy: the .npy array's shape (4294967296, 4294967296) is too large"},
      {npy_file(dict("<f8", "(2, 2)"), raw_bytes({1, 2, std::nan(""), 4}, false, false)),
       "p.npy: row 1, column 0 (zero-based) is NaN"},
      {npy_file(dict("<f4", "(1, 3)", true), raw_bytes({1, -HUGE_VAL, 2}, true, false)),
       "p.npy: row 0, column 1 (zero-based) is infinite"},
      {npy_file("{'descr': '<f8', 'shape': (1, 2), }", two),
       "p.npy: malformed .npy header: the header has no 'fortran_order'"},
      {npy_file("{'descr': '<f8', 'fortran_order': False, }", two),
       "p.npy: malformed .npy header: the header has no 'shape'"},
      {npy_file("{'fortran_order': False, 'shape': (1, 2), }", two),
       "p.npy: malformed .npy header: the header has no 'descr' (the dtype)"},
      {npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 2), 'extra': 1}", two),
       "p.npy: malformed .npy header: unexpected key 'extra' in the header (a .npy header has 'descr', "
       "'fortran_order', "
       "'shape')"},
      {npy_file("{'descr': '<f8', 'fortran_order': Maybe, 'shape': (1, 2)}", two),
       "p.npy: malformed .npy header: expected True or False for 'fortran_order' at byte 34 of the header, found "
       "\"Maybe, 'shape': (1, 2)}\""},
      {npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (1, -2)}", two),
       "p.npy: malformed .npy header: expected a non-negative integer in 'shape' at byte 54 of the header, found "
       "\"-2)}\""},
      {npy_file("{'descr': '<f8' 'fortran_order': False}", two),
       "p.npy: malformed .npy header: expected ',' or '}' after the value of 'descr' at byte 16 of the header, found "
       "\"'fortran_order': False}\""},
      {npy_file("['descr']", two),
       "p.npy: malformed .npy header: expected the header dict to open with '{' at byte 0 of the header, found "
       "\"['descr']\""},
  };
  for (const Case& c : cases) EXPECT_EQ(parse_error(c.bytes), c.message);
}

// Whatever a cut-off or damaged file holds, the reader answers with an InputError.
TEST(NpyRead, TruncatedOrDamagedFilesAreInputErrors) {
  const std::string file = write_npy_bytes(NpyArray(kTricky.data(), {4, 2}));
  for (std::size_t size = 0; size < file.size(); ++size) {
    EXPECT_THROW(parse(file.substr(0, size)), InputError) << "first " << size << " bytes";
  }
  for (std::size_t at = 0; at < 80; ++at) {
    std::string damaged = file;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x5a);
    try {
      parse(damaged);  // a flip in the padding may leave the file valid
    } catch (const InputError&) {
    }
  }
}

TEST(NpyRead, ErrorsNameTheFile) {
  TempDir dir;
  const std::string path = dir.file("bad.npy");
  write_text(path, npy_file(dict("<i4", "(1, 2)"), "12345678"));
  try {
    read_points(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": unsupported .npy dtype '<i4'", 0), 0u) << e.what();
  }
}

// ---------------------------------------------------------------- writing

TEST(NpyWrite, HeaderLayout) {
  const std::vector<std::int32_t> values = {1, -2, 3, 70000, 5, 6};
  const std::string bytes = write_npy_bytes(NpyArray(values.data(), {3, 2}));
  ASSERT_GE(bytes.size(), 10u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t header_length = static_cast<unsigned char>(bytes[8]) | static_cast<unsigned char>(bytes[9]) << 8;
  EXPECT_EQ((10 + header_length) % 64, 0u);
  const std::string header = bytes.substr(10, header_length);
  EXPECT_EQ(header.rfind("{'descr': '<i4', 'fortran_order': False, 'shape': (3, 2), }", 0), 0u) << header;
  EXPECT_EQ(header.back(), '\n');
  ASSERT_EQ(bytes.size(), 10 + header_length + 6 * 4);
  // Little-endian: 70000 = 0x00011170.
  EXPECT_EQ(bytes.substr(10 + header_length + 12, 4), std::string("\x70\x11\x01\x00", 4));
}

TEST(NpyWrite, ShapesAndTypes) {
  const std::int64_t scalar = 7;
  const std::vector<double> vector = {1.5, 2.5, 3.5};
  EXPECT_NE(write_npy_bytes(NpyArray(&scalar, {})).find("'descr': '<i8', 'fortran_order': False, 'shape': (), }"),
            std::string::npos);
  EXPECT_NE(
      write_npy_bytes(NpyArray(vector.data(), {3})).find("'descr': '<f8', 'fortran_order': False, 'shape': (3,), }"),
      std::string::npos);
  EXPECT_NE(write_npy_bytes(NpyArray(static_cast<const std::int32_t*>(nullptr), {0, 4})).find("'shape': (0, 4), }"),
            std::string::npos);
  EXPECT_THROW(write_npy_bytes(NpyArray(static_cast<const double*>(nullptr), {2})), UsageError);
}

TEST(NpyWrite, NumpyLoadsWhatWeWrite) {
  DRANGE_REQUIRE_PYTHON("numpy");
  TempDir dir;
  const std::vector<std::int32_t> ints = {0, -1, 2147483647, -2147483647 - 1, 5, 6};
  const std::vector<std::int64_t> longs = {-9007199254740993LL, 1};
  write_text(dir.file("i4.npy"), write_npy_bytes(NpyArray(ints.data(), {2, 3})));
  write_text(dir.file("i8.npy"), write_npy_bytes(NpyArray(longs.data(), {2})));
  write_text(dir.file("f8.npy"), write_npy_bytes(NpyArray(kTricky.data(), {4, 2})));
  const std::string script = R"(
import sys, numpy as np
d = sys.argv[1]
a = np.load(d + '/i4.npy'); assert a.dtype == np.int32 and a.shape == (2, 3), a
assert a.tolist() == [[0, -1, 2147483647], [-2147483648, 5, 6]], a
b = np.load(d + '/i8.npy'); assert b.dtype == np.int64 and b.tolist() == [-9007199254740993, 1], b
c = np.load(d + '/f8.npy'); assert c.dtype == np.float64 and c.shape == (4, 2), c
assert c.ravel().view(np.uint64).tolist() == np.array([float.fromhex(x) for x in sys.argv[2:]]).view(np.uint64).tolist()
print('ok')
)";
  std::vector<std::string> args = {dir.path()};
  for (double value : kTricky) {
    char hex[64];
    std::snprintf(hex, sizeof hex, "%a", value);
    args.push_back(hex);
  }
  EXPECT_EQ(run_python(dir, script, args), "ok\n");
}

TEST(NpyRead, FilesWrittenByNumpy) {
  DRANGE_REQUIRE_PYTHON("numpy");
  TempDir dir;
  const std::string script = R"(
import sys, numpy as np
d = sys.argv[1]
a = np.array([[0.1, 2.0, -3.5], [4.0, 1e-300, 6.25]])
np.save(d + '/c.npy', a)
np.save(d + '/f.npy', np.asfortranarray(a))
np.save(d + '/be.npy', a.astype('>f8'))
np.save(d + '/f4.npy', a.astype(np.float32))
print('ok')
)";
  ASSERT_EQ(run_python(dir, script, {dir.path()}), "ok\n");
  const std::vector<double> expected = {0.1, 2.0, -3.5, 4.0, 1e-300, 6.25};
  for (const char* name : {"c.npy", "f.npy", "be.npy"}) EXPECT_EQ(read_points(dir.file(name)).coords, expected) << name;
  const PointCloud narrow = read_points(dir.file("f4.npy"));
  ASSERT_EQ(narrow.coords.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(narrow.coords[i], static_cast<double>(static_cast<float>(expected[i])));
}

}  // namespace
}  // namespace drange
