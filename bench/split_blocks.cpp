// bench/split_blocks.cpp: the work and balance of a run split in P blocks (docs/scaling.md):
// every block of drange::delaunay_block computed one after the other in this process, on one
// thread, against drange::delaunay on one thread, so that processes sharing few cores do not
// distort the times.
//
//   drange_split_blocks POINTS [P ...]      (default P: 2 4)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "drange/drange.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: drange_split_blocks POINTS [P ...]\n");
    return 2;
  }
  const drange::PointCloud points = drange::read_points(argv[1]);
  std::vector<int> counts;
  for (int i = 2; i < argc; ++i) counts.push_back(std::atoi(argv[i]));
  if (counts.empty()) counts = {2, 4};
  drange::Options options;
  options.threads = 1;
  const drange::Triangulation whole = drange::delaunay(points, options);
  std::printf("whole: search %.3f s, %zu simplices\n", whole.stats.seconds_search, whole.size());
  for (const int blocks : counts) {
    double sum = 0.0, largest = 0.0;
    std::size_t simplices = 0;
    for (int b = 0; b < blocks; ++b) {
      const drange::Triangulation part = drange::delaunay_block(points, b, blocks, options);
      sum += part.stats.seconds_search;
      largest = std::max(largest, part.stats.seconds_search);
      simplices += part.size();
    }
    std::printf("P=%d: blocks' search %.3f s = %.2f x the whole search; balance (max/mean) %.3f; %zu simplices\n", blocks,
                sum, sum / whole.stats.seconds_search, largest / (sum / blocks), simplices);
  }
  return 0;
}
