// io/write_points.cpp: points in Qhull's input format (dimension, count, one point per line).
// Coordinates are written in the shortest form that reads back as the same double, so a
// write/read round trip is bit-identical (std::to_chars guarantees it).
#include <ostream>
#include <string>

#include "drange/errors.hpp"
#include "drange/io.hpp"
#include "io/output_buffer.hpp"

namespace drange {

void write_points(std::ostream& out, const PointCloud& points) {
  if (points.dim < 1) throw UsageError("write_points: dimension must be at least 1, got " + std::to_string(points.dim));
  const std::size_t dim = static_cast<std::size_t>(points.dim);
  if (points.coords.size() % dim != 0) {
    throw UsageError("write_points: " + std::to_string(points.coords.size()) +
                     " coordinates do not make points of dimension " + std::to_string(points.dim));
  }
  io::OutputBuffer buffer(out);
  buffer.put_number(points.dim);
  buffer.put('\n');
  buffer.put_number(points.size());
  buffer.put('\n');
  for (std::size_t i = 0; i < points.coords.size(); i += dim) {
    for (std::size_t k = 0; k < dim; ++k) {
      if (k > 0) buffer.put(' ');
      buffer.put_number(points.coords[i + k]);
    }
    buffer.put('\n');
  }
  buffer.flush();
}

}  // namespace drange
