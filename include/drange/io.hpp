// drange/io.hpp: reading points and triangulations, writing results, in the formats people
// already use (Qhull's input format, plain rows / CSV, `qdelaunay i` output).
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "drange/points.hpp"

namespace drange {

// Reads points from `path` ("-" means standard input). Three layouts are recognised:
//   Qhull: line 1 the dimension, line 2 the count, then one point per line;
//   rows:  one point per line, numbers separated by whitespace or commas, the dimension taken
//          from the first row (an optional header row of non-numbers is skipped);
//   NumPy: a .npy file (numpy.save), recognised by its magic bytes "\x93NUMPY" (or a name
//          ending in .npy), format version 1.0, 2.0 or 3.0, holding one array of shape
//          (points, dimension) of float64 or float32 ('<f8', '>f8', '<f4', '>f4'), in C or
//          Fortran order.
// In text, blank lines and lines starting with '#' are ignored. Throws InputError naming the
// file and the line for: unreadable path, malformed number, wrong number of coordinates, NaN
// or infinite value, a count that does not match the points present. For a .npy file the
// message names the file and the problem: bad magic or version, malformed header,
// unsupported dtype, a shape that is not 2-D, truncated data (bytes needed and present), or
// the zero-based row and column of a NaN or infinite value.
PointCloud read_points(const std::string& path);
PointCloud parse_points(std::istream& in, const std::string& name);

// Reads simplices in the `qdelaunay i` layout: line 1 the count m, then m lines of
// `vertices_per_simplex` zero-based indices. Throws InputError (file, line) when malformed.
std::vector<std::int32_t> read_simplices(const std::string& path, int vertices_per_simplex);

// Writes the `qdelaunay i` layout: the count, then one row of `per_row` integers per line.
// Used for simplices and for neighbours (-1 for none).
void write_index_rows(std::ostream& out, const std::vector<std::int32_t>& rows, int per_row);

// Writes points in Qhull's input format (dimension, count, one point per line, exact
// round-trip precision).
void write_points(std::ostream& out, const PointCloud& points);

// Writes a file all or nothing: `write` fills a stream bound to a temporary file next to
// `path`, which is renamed over `path` only when `write` returns and the stream is good.
// On any failure (exception from `write`, I/O error) the temporary file is removed and
// InputError (for paths) or the original exception propagates. path "-" writes to stdout.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace drange
