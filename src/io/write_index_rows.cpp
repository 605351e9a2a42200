// io/write_index_rows.cpp: the `qdelaunay i` layout (the row count, then one row of
// space-separated integers per line), used for simplices and for neighbours (-1 for none).
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "drange/errors.hpp"
#include "drange/io.hpp"
#include "io/output_buffer.hpp"

namespace drange {

void write_index_rows(std::ostream& out, const std::vector<std::int32_t>& rows, int per_row) {
  if (per_row < 1) throw UsageError("write_index_rows: entries per row must be at least 1, got " + std::to_string(per_row));
  const std::size_t width = static_cast<std::size_t>(per_row);
  if (rows.size() % width != 0) {
    throw UsageError("write_index_rows: " + std::to_string(rows.size()) + " entries do not make rows of " +
                     std::to_string(per_row));
  }
  io::OutputBuffer buffer(out);
  buffer.put_number(rows.size() / width);
  buffer.put('\n');
  for (std::size_t i = 0; i < rows.size(); i += width) {
    for (std::size_t k = 0; k < width; ++k) {
      if (k > 0) buffer.put(' ');
      buffer.put_number(rows[i + k]);
    }
    buffer.put('\n');
  }
  buffer.flush();
}

}  // namespace drange
