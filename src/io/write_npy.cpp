// io/write_npy.cpp: one array as a NumPy .npy file, format version 1.0 as specified in
// NumPy's numpy/lib/format.py: the magic "\x93NUMPY", the version bytes 1 and 0, the header
// length as 2 bytes little-endian, the header (a Python dict literal, padded with spaces
// and ended by a newline so that the data starts at a multiple of 64 bytes), then the
// elements, little-endian, in C order.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "io/npy.hpp"

namespace drange {
namespace {

// The data of a .npy starts at a multiple of this (NumPy's ARRAY_ALIGN).
constexpr std::size_t kAlignment = 64;
// magic (6), version (2), header length (2).
constexpr std::size_t kPreambleBytes = 10;

const char* descr(NpyType type) {
  switch (type) {
    case NpyType::Int32:
      return "<i4";
    case NpyType::Int64:
      return "<i8";
    case NpyType::Float64:
      return "<f8";
  }
  return "";
}

std::size_t item_bytes(NpyType type) { return type == NpyType::Int32 ? 4 : 8; }

// Copies `count` elements of `Bits` width into little-endian bytes, whatever the host's order.
template <typename Bits>
void put_little_endian(const void* values, std::size_t count, unsigned char* out) {
  const auto* bytes = static_cast<const unsigned char*>(values);
  for (std::size_t i = 0; i < count; ++i, bytes += sizeof(Bits)) {
    Bits bits;
    std::memcpy(&bits, bytes, sizeof bits);
    for (std::size_t b = 0; b < sizeof(Bits); ++b) *out++ = static_cast<unsigned char>(bits >> (8 * b));
  }
}

}  // namespace

std::size_t NpyArray::size() const {
  std::size_t count = 1;
  for (std::size_t extent : shape) count *= extent;
  return count;
}

namespace io {

std::string python_tuple(const std::vector<std::size_t>& shape) {
  std::string text = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    if (i > 0) text += ", ";
    text += std::to_string(shape[i]);
  }
  return text + (shape.size() == 1 ? ",)" : ")");
}

std::string npy_header(const NpyArray& array) {
  std::string dict = std::string("{'descr': '") + descr(array.type) +
                     "', 'fortran_order': False, 'shape': " + python_tuple(array.shape) + ", }";
  const std::size_t unpadded = kPreambleBytes + dict.size() + 1;  // + 1: the final newline
  dict.append((kAlignment - unpadded % kAlignment) % kAlignment, ' ');
  dict += '\n';
  if (dict.size() > UINT16_MAX)
    throw UsageError("write_npy: a header of " + std::to_string(dict.size()) + " bytes does not fit format 1.0");

  std::string header("\x93NUMPY\x01\x00", 8);
  header += static_cast<char>(dict.size() & 0xff);
  header += static_cast<char>(dict.size() >> 8);
  return header + dict;
}

std::size_t npy_data_bytes(const NpyArray& array) { return array.size() * item_bytes(array.type); }

void for_each_npy_block(const NpyArray& array, const std::function<void(const char*, std::size_t)>& sink) {
  constexpr std::size_t kBlockElements = 8192;
  const std::size_t width = item_bytes(array.type);
  const std::size_t count = array.size();
  std::vector<unsigned char> block(kBlockElements * width);
  const auto* data = static_cast<const unsigned char*>(array.data);
  for (std::size_t start = 0; start < count; start += kBlockElements) {
    const std::size_t n = std::min(kBlockElements, count - start);
    if (width == 4) {
      put_little_endian<std::uint32_t>(data + start * width, n, block.data());
    } else {
      put_little_endian<std::uint64_t>(data + start * width, n, block.data());
    }
    sink(reinterpret_cast<const char*>(block.data()), n * width);
  }
}

}  // namespace io

void write_npy(std::ostream& out, const NpyArray& array) {
  if (array.data == nullptr && array.size() != 0) throw UsageError("write_npy: no data for a non-empty array");
  const std::string header = io::npy_header(array);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  io::for_each_npy_block(array,
                         [&](const char* bytes, std::size_t n) { out.write(bytes, static_cast<std::streamsize>(n)); });
}

}  // namespace drange
