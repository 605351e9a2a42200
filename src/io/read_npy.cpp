// io/read_npy.cpp: points from a NumPy .npy file (numpy.save), as specified in NumPy's
// numpy/lib/format.py ("Format Version 1.0" to "3.0"):
//   "\x93NUMPY", major and minor version bytes, the header length (2 bytes little-endian in
//   1.0, 4 bytes in 2.0 and 3.0), the header: a Python dict literal with exactly the keys
//   'descr', 'fortran_order' and 'shape', then the raw array data.
// The whole file is already in memory (read_points loads it before looking at it); the data is
// converted in one pass, with the byte order and the element size resolved once, not per element.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "io/input_error.hpp"
#include "io/npy.hpp"

namespace drange::io {
namespace {

constexpr std::string_view kMagic = "\x93NUMPY";
constexpr std::string_view kZipSignature = "PK\x03\x04";

bool ends_with(const std::string& text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A few bytes in double quotes, every byte that is not printable ASCII as \xNN.
std::string escaped(std::string_view bytes) {
  std::string out = "\"";
  for (char c : bytes) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f && c != '"' && c != '\\') {
      out += c;
    } else {
      static const char kHex[] = "0123456789abcdef";
      out += {'\\', 'x', kHex[byte >> 4], kHex[byte & 0xf]};
    }
  }
  return out + "\"";
}

// What the header dict says.
struct NpyHeader {
  std::string descr;
  bool fortran_order = false;
  std::vector<std::size_t> shape;
};

// A strict reader of the small subset of Python literals that a .npy header uses: a dict
// with string keys whose values are a string, True/False, or a tuple of integers.
class HeaderParser {
 public:
  // The padding (spaces and the final newline) is dropped, so that messages quote the text.
  HeaderParser(std::string_view text, const std::string& name) : text_(text), name_(name) {
    while (!text_.empty() && is_space(text_.back())) text_.remove_suffix(1);
  }

  NpyHeader parse() {
    NpyHeader header;
    bool seen_descr = false, seen_order = false, seen_shape = false;
    expect('{', "the header dict to open with '{'");
    while (!consume('}')) {
      const std::string key = parse_string("a quoted key");
      expect(':', "':' after the key '" + key + "'");
      if (key == "descr") {
        if (peek() != '\'' && peek() != '"') {
          fail_in_file(name_,
                       "unsupported .npy dtype: a structured (record) dtype; drange reads float64 or float32 "
                       "arrays of shape (points, dimension)");
        }
        header.descr = parse_string("a dtype string");
        seen_descr = true;
      } else if (key == "fortran_order") {
        header.fortran_order = parse_bool();
        seen_order = true;
      } else if (key == "shape") {
        header.shape = parse_shape();
        seen_shape = true;
      } else {
        fail("unexpected key '" + key + "' in the header (a .npy header has 'descr', 'fortran_order', 'shape')");
      }
      if (!consume(',')) {
        expect('}', "',' or '}' after the value of '" + key + "'");
        break;
      }
    }
    skip_space();
    if (pos_ != text_.size()) fail_here("nothing after the header dict");
    if (!seen_descr) fail("the header has no 'descr' (the dtype)");
    if (!seen_order) fail("the header has no 'fortran_order'");
    if (!seen_shape) fail("the header has no 'shape'");
    return header;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { fail_in_file(name_, "malformed .npy header: " + what); }

  [[noreturn]] void fail_here(const std::string& expected) const {
    fail("expected " + expected + " at byte " + std::to_string(pos_) + " of the header, found " +
         (pos_ < text_.size() ? quoted(text_.substr(pos_)) : std::string("its end")));
  }

  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
  }

  char peek() {
    skip_space();
    return pos_ < text_.size() ? text_[pos_] : '\0';
  }

  bool consume(char c) {
    if (peek() != c) return false;
    ++pos_;
    return true;
  }

  void expect(char c, const std::string& expected) {
    if (!consume(c)) fail_here(expected);
  }

  // A Python string literal in single or double quotes, without escapes (dtype strings and
  // the three key names have none).
  std::string parse_string(const std::string& expected) {
    const char quote = peek();
    if (quote != '\'' && quote != '"') fail_here(expected);
    const std::size_t end = text_.find(quote, pos_ + 1);
    if (end == std::string_view::npos) fail_here("a closing quote");
    std::string value(text_.substr(pos_ + 1, end - pos_ - 1));
    pos_ = end + 1;
    return value;
  }

  bool parse_word(std::string_view word) {
    skip_space();
    if (text_.substr(pos_, word.size()) != word) return false;
    pos_ += word.size();
    return true;
  }

  bool parse_bool() {
    if (parse_word("True")) return true;
    if (parse_word("False")) return false;
    fail_here("True or False for 'fortran_order'");
  }

  // "(3, 2)", "(3,)", "()"; Python 2 wrote long integers with a suffix: "(3L, 2L)".
  std::vector<std::size_t> parse_shape() {
    std::vector<std::size_t> shape;
    expect('(', "a tuple for 'shape'");
    while (!consume(')')) {
      shape.push_back(parse_extent());
      if (!consume(',')) {
        expect(')', "',' or ')' in 'shape'");
        break;
      }
    }
    return shape;
  }

  std::size_t parse_extent() {
    skip_space();
    const std::size_t start = pos_;
    std::size_t value = 0;
    while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') {
      const auto digit = static_cast<std::size_t>(text_[pos_] - '0');
      if (value > (SIZE_MAX - digit) / 10) fail("a 'shape' extent is too large");
      value = value * 10 + digit;
      ++pos_;
    }
    if (pos_ == start) fail_here("a non-negative integer in 'shape'");
    if (pos_ < text_.size() && (text_[pos_] == 'L' || text_[pos_] == 'l')) ++pos_;
    return value;
  }

  std::string_view text_;
  const std::string& name_;
  std::size_t pos_ = 0;
};

// Reads an unsigned little-endian integer of `bytes` bytes.
std::uint64_t little_endian(const unsigned char* p, std::size_t bytes) {
  std::uint64_t value = 0;
  for (std::size_t b = 0; b < bytes; ++b) value |= std::uint64_t{p[b]} << (8 * b);
  return value;
}

// One element's bits, assembled byte by byte so that the host's byte order never matters
// (compilers turn the loop into a load, and a byte swap for the other order).
template <typename Bits, bool kBigEndian>
Bits load_bits(const unsigned char* p) {
  Bits value = 0;
  for (std::size_t b = 0; b < sizeof(Bits); ++b) {
    const std::size_t from = kBigEndian ? sizeof(Bits) - 1 - b : b;
    value |= static_cast<Bits>(static_cast<Bits>(p[from]) << (8 * b));
  }
  return value;
}

double to_double(std::uint64_t bits) {
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// float32 to float64 is exact: every float is a double.
double to_double(std::uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return static_cast<double>(value);
}

// Converts the n x d elements to row-major doubles. In Fortran order the file holds the
// columns one after another, so element (i, k) is at position k * n + i.
template <typename Bits, bool kBigEndian>
void decode(const unsigned char* data, std::size_t n, std::size_t d, bool fortran_order, double* out) {
  if (!fortran_order) {
    for (std::size_t e = 0; e < n * d; ++e) out[e] = to_double(load_bits<Bits, kBigEndian>(data + e * sizeof(Bits)));
    return;
  }
  for (std::size_t k = 0; k < d; ++k) {
    for (std::size_t i = 0; i < n; ++i, data += sizeof(Bits))
      out[i * d + k] = to_double(load_bits<Bits, kBigEndian>(data));
  }
}

struct Dtype {
  std::size_t bytes = 0;  // 0: not supported
  bool big_endian = false;
};

Dtype parse_dtype(const std::string& descr) {
  if (descr == "<f8") return {8, false};
  if (descr == ">f8") return {8, true};
  if (descr == "<f4") return {4, false};
  if (descr == ">f4") return {4, true};
  return {};
}

void decode(const Dtype& dtype, const unsigned char* data, std::size_t n, std::size_t d, bool fortran_order,
            double* out) {
  if (dtype.bytes == 8) {
    dtype.big_endian ? decode<std::uint64_t, true>(data, n, d, fortran_order, out)
                     : decode<std::uint64_t, false>(data, n, d, fortran_order, out);
  } else {
    dtype.big_endian ? decode<std::uint32_t, true>(data, n, d, fortran_order, out)
                     : decode<std::uint32_t, false>(data, n, d, fortran_order, out);
  }
}

// The header text and the offset of the data, after checking magic and version.
std::string_view read_preamble(std::string_view bytes, const std::string& name, std::size_t& data_offset) {
  if (bytes.substr(0, kZipSignature.size()) == kZipSignature) {
    fail_in_file(name,
                 "a zip archive (an .npz?): drange reads the points from a .npy file (numpy.save) holding "
                 "one array of shape (points, dimension)");
  }
  if (bytes.substr(0, kMagic.size()) != kMagic) {
    fail_in_file(name, "not a NumPy .npy file: it starts with " + escaped(bytes.substr(0, kMagic.size())) +
                           ", not the magic \"\\x93NUMPY\"");
  }
  if (bytes.size() < kMagic.size() + 2) fail_in_file(name, "the .npy file ends before its version");
  const auto major = static_cast<unsigned char>(bytes[6]);
  const auto minor = static_cast<unsigned char>(bytes[7]);
  if (minor != 0 || major < 1 || major > 3) {
    fail_in_file(name, "unsupported .npy format version " + std::to_string(major) + "." + std::to_string(minor) +
                           " (drange reads 1.0, 2.0 and 3.0)");
  }
  const std::size_t length_bytes = major == 1 ? 2 : 4;
  const std::size_t header_start = kMagic.size() + 2 + length_bytes;
  if (bytes.size() < header_start) fail_in_file(name, "the .npy file ends before its header length");
  const std::size_t header_length =
      little_endian(reinterpret_cast<const unsigned char*>(bytes.data()) + kMagic.size() + 2, length_bytes);
  if (bytes.size() - header_start < header_length) {
    fail_in_file(name, "the .npy file ends inside its header: the header is " + std::to_string(header_length) +
                           " bytes, " + std::to_string(bytes.size() - header_start) + " are present");
  }
  data_offset = header_start + header_length;
  return bytes.substr(header_start, header_length);
}

// n * d * itemsize, or 0 with overflow = true when that does not fit in size_t.
std::size_t checked_bytes(std::size_t n, std::size_t d, std::size_t itemsize, bool& overflow) {
  overflow = d != 0 && n > SIZE_MAX / itemsize / d;
  return overflow ? 0 : n * d * itemsize;
}

}  // namespace

bool is_numpy_input(std::string_view bytes, const std::string& name) {
  return (!bytes.empty() && bytes.front() == kMagic.front()) ||
         bytes.substr(0, kZipSignature.size()) == kZipSignature || ends_with(name, ".npy") || ends_with(name, ".npz");
}

PointCloud parse_npy_points(std::string_view bytes, const std::string& name) {
  std::size_t data_offset = 0;
  const std::string_view header_text = read_preamble(bytes, name, data_offset);
  const NpyHeader header = HeaderParser(header_text, name).parse();

  const Dtype dtype = parse_dtype(header.descr);
  if (dtype.bytes == 0) {
    fail_in_file(name, "unsupported .npy dtype '" + header.descr +
                           "': drange reads float64 ('<f8', '>f8') or float32 ('<f4', '>f4'); convert with "
                           "array.astype(numpy.float64)");
  }
  if (header.shape.size() != 2) {
    fail_in_file(name, "the .npy array has shape " + python_tuple(header.shape) +
                           ": points must be a 2-D array of shape (points, dimension)");
  }
  const std::size_t n = header.shape[0], d = header.shape[1];
  if (n == 0) fail_in_file(name, "no points");
  if (d == 0) fail_in_file(name, "the .npy array has shape " + python_tuple(header.shape) + ": no coordinates");
  bool overflow = false;
  const std::size_t needed = checked_bytes(n, d, dtype.bytes, overflow);
  if (overflow || d > static_cast<std::size_t>(INT32_MAX)) {
    fail_in_file(name, "the .npy array's shape " + python_tuple(header.shape) + " is too large");
  }
  const std::size_t present = bytes.size() - data_offset;
  if (present < needed) {
    fail_in_file(name, "the .npy data is truncated: shape " + python_tuple(header.shape) + " of '" + header.descr +
                           "' needs " + std::to_string(needed) + " bytes, found " + std::to_string(present));
  }

  PointCloud cloud;
  cloud.dim = static_cast<int>(d);
  cloud.coords.resize(n * d);
  decode(dtype, reinterpret_cast<const unsigned char*>(bytes.data()) + data_offset, n, d, header.fortran_order,
         cloud.coords.data());

  // Checked after the conversion, so that the first bad value in row order is the one named.
  for (std::size_t e = 0; e < cloud.coords.size(); ++e) {
    if (std::isfinite(cloud.coords[e])) continue;
    fail_in_file(name, "row " + std::to_string(e / d) + ", column " + std::to_string(e % d) + " (zero-based) is " +
                           (std::isnan(cloud.coords[e]) ? "NaN" : "infinite"));
  }
  return cloud;
}

}  // namespace drange::io
