// cli/split_read.hpp: each process of a split run reads its share of the input file: a byte
// range of a text file, from the first line that starts in it to the last one that does (the
// header, Qhull's two lines or a CSV header row, is read by every process from the file's
// start), or its share of the rows of a .npy file.
#pragma once

#include <cstdint>
#include <string>

#include "agreement.hpp"
#include "drange/points.hpp"
#include "processes.hpp"

namespace drange::cli {

struct PointShare {
  PointCloud points;         // this process's points, in input order
  std::int64_t first = 0;    // the input index of points[0]
  std::int64_t total = 0;    // the points of the whole input
};

// Malformed input stops every process (Agreement) with the single-process reader's message,
// its line number included.
PointShare read_point_share(const std::string& path, const Processes& group, const Agreement& agree);

}  // namespace drange::cli
