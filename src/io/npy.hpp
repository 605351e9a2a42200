// io/npy.hpp: the NumPy formats inside the library: reading points from a .npy file, and the
// pieces of a .npy file that both write_npy and the .npz writer need.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "drange/formats.hpp"
#include "drange/points.hpp"

namespace drange::io {

// True when the input should be read as NumPy binary data rather than text: it starts with
// the .npy magic byte 0x93 or a zip signature (an .npz, which is refused with a message
// that says so), or its name ends in ".npy" or ".npz".
bool is_numpy_input(std::string_view bytes, const std::string& name);

// Parses a .npy file (format versions 1.0, 2.0 and 3.0) holding a 2-D array of shape
// (points, dimension) with dtype '<f8', '>f8', '<f4' or '>f4' (float32 is widened, which is
// exact), in C or Fortran order. Bytes after the array are ignored, as numpy.load does.
// Throws InputError "<name>: <what>" for every malformed case.
PointCloud parse_npy_points(std::string_view bytes, const std::string& name);

// Python's repr of a shape tuple: "()", "(5,)", "(5, 3)".
std::string python_tuple(const std::vector<std::size_t>& shape);

// The bytes before the data of a .npy file for `array`: magic, version 1.0, header length
// and the padded header dict. Its length is a multiple of 64.
std::string npy_header(const NpyArray& array);

// The size in bytes of the array's elements.
std::size_t npy_data_bytes(const NpyArray& array);

// Hands the array's elements to `sink` as little-endian bytes, in C order, in blocks of at
// most a few tens of kilobytes (so that no copy of the whole array is made).
void for_each_npy_block(const NpyArray& array, const std::function<void(const char*, std::size_t)>& sink);

}  // namespace drange::io
