// cli/split_blocks.hpp: the decomposition of space into one block per process, kd-tree style:
// the blocks are halved recursively across their widest side, at the point-count quantile that
// a sample of the input gives, so that the blocks hold about equal numbers of points. A point's
// block depends on its coordinates alone, so exact copies of a point share a block.
#pragma once

#include <vector>

#include "split_regions.hpp"

namespace drange::cli {

class Blocks {
 public:
  // `sample`: rows of `dim` coordinates (the same on every process, so that every process
  // builds the same blocks).
  Blocks(const std::vector<double>& sample, int dim, int count);

  int block_of(const double* p) const;
  // The closure of the block (its outer sides infinite).
  const Box& box(int block) const { return boxes_[static_cast<std::size_t>(block)]; }
  // The blocks whose closures meet `box`, in increasing order.
  std::vector<int> meeting(const Box& box) const;

 private:
  struct Node {
    int axis = -1;  // -1: a leaf, block `left`
    double split = 0;  // x[axis] < split: left child, else right
    int left = 0, right = 0;
  };
  int build(std::vector<const double*> items, int first, int count, Box region);

  int dim_;
  std::vector<Node> nodes_;
  std::vector<Box> boxes_;
};

}  // namespace drange::cli
