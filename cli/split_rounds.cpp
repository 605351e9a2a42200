// cli/split_rounds.cpp: see split_rounds.hpp.
#include "split_rounds.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "drange/errors.hpp"
#include "split_blocks.hpp"

namespace drange::cli {
namespace {

using Clock = std::chrono::steady_clock;

// The sample that places the splits: about this many points in all.
constexpr std::int64_t kSample = 1 << 14;
// The ghost layer's width in mean spacings: wide enough that most stars near a block's side are
// decided in the first round, thin next to the block.
constexpr double kGhostSpacings = 3.0;
// More rounds than this means the regions do not converge: a bug.
constexpr int kMostRounds = 64;

// The points a process holds, ordered by input index (so that the engine keeps the same
// representative of exact copies as one process, and orders ties alike).
struct Held {
  int dim = 0;
  std::vector<double> coords;
  std::vector<std::int64_t> ids;
  std::vector<char> own;

  std::size_t size() const { return ids.size(); }
  const double* point(std::size_t i) const { return coords.data() + i * static_cast<std::size_t>(dim); }

  // Adds rows of (coordinates, index) not held yet, and keeps the order.
  void add(const std::vector<double>& rows, int self, const Blocks& blocks) {
    const auto width = static_cast<std::size_t>(dim) + 1;
    std::vector<std::int64_t> new_ids;
    std::vector<double> new_coords;
    for (std::size_t at = 0; at + width <= rows.size(); at += width) {
      new_ids.push_back(static_cast<std::int64_t>(rows[at + width - 1]));
      new_coords.insert(new_coords.end(), rows.begin() + static_cast<std::ptrdiff_t>(at),
                        rows.begin() + static_cast<std::ptrdiff_t>(at + width - 1));
    }
    std::vector<std::size_t> order(ids.size() + new_ids.size());
    std::iota(order.begin(), order.end(), 0);
    const auto id_of = [&](std::size_t i) { return i < ids.size() ? ids[i] : new_ids[i - ids.size()]; };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id_of(a) < id_of(b); });
    Held merged;
    merged.dim = dim;
    for (std::size_t i : order) {
      const std::int64_t id = id_of(i);
      if (!merged.ids.empty() && merged.ids.back() == id) continue;
      const double* p = i < ids.size() ? point(i) : new_coords.data() + (i - ids.size()) * static_cast<std::size_t>(dim);
      merged.ids.push_back(id);
      merged.coords.insert(merged.coords.end(), p, p + dim);
      merged.own.push_back(i < ids.size() ? own[i] : static_cast<char>(blocks.block_of(p) == self));
    }
    *this = std::move(merged);
  }
};

void append_row(std::vector<double>& out, const double* p, int dim, std::int64_t id) {
  out.insert(out.end(), p, p + dim);
  out.push_back(static_cast<double>(id));
}

Box bounds_of(const PointShare& share, const Processes& group) {
  const auto d = static_cast<std::size_t>(share.points.dim);
  std::vector<double> lo(d, std::numeric_limits<double>::infinity()), hi(d, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < share.points.size(); ++i)
    for (std::size_t k = 0; k < d; ++k) {
      lo[k] = std::min(lo[k], share.points.point(i)[k]);
      hi[k] = std::max(hi[k], share.points.point(i)[k]);
    }
  return Box{group.reduce(lo, Processes::Reduction::Min), group.reduce(hi, Processes::Reduction::Max)};
}

// The mean spacing of the points: the side of a cube holding one point on average.
double mean_spacing(const Box& bounds, std::int64_t points) {
  const std::size_t d = bounds.lo.size();
  double volume = 1, widest = 0;
  std::size_t sides = 0;
  for (std::size_t k = 0; k < d; ++k) {
    const double side = bounds.hi[k] - bounds.lo[k];
    widest = std::max(widest, side);
    if (side > 0) {
      volume *= side;
      ++sides;
    }
  }
  if (sides == 0) return 0;
  return std::pow(volume / static_cast<double>(std::max<std::int64_t>(points, 1)), 1.0 / static_cast<double>(sides));
}

Box widened(Box box, double by) {
  for (std::size_t k = 0; k < box.lo.size(); ++k) {
    box.lo[k] -= by;
    box.hi[k] += by;
  }
  return box;
}

// The process's own points ordered by their first coordinate, to answer requests for boxes.
class OwnIndex {
 public:
  explicit OwnIndex(const Held& held) : held_(held) {
    for (std::size_t i = 0; i < held.size(); ++i)
      if (held.own[i]) order_.push_back(i);
    std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) { return held.point(a)[0] < held.point(b)[0]; });
  }
  // Appends the own points in `box` not yet sent to this requester (`sent` marks them).
  void answer(const Box& box, std::vector<char>& sent, std::vector<double>& out) const {
    auto it = std::lower_bound(order_.begin(), order_.end(), box.lo[0],
                               [&](std::size_t i, double x) { return held_.point(i)[0] < x; });
    for (; it != order_.end() && held_.point(*it)[0] <= box.hi[0]; ++it) {
      if (sent[*it] || !box.contains_point(held_.point(*it))) continue;
      sent[*it] = 1;
      append_row(out, held_.point(*it), held_.dim, held_.ids[*it]);
    }
  }

 private:
  const Held& held_;
  std::vector<std::size_t> order_;
};

}  // namespace

SplitPart triangulate_share(PointShare share, const Processes& group, const Agreement& agree, const Options& options) {
  SplitPart part;
  const int dim = share.points.dim;
  const auto d = static_cast<std::size_t>(dim);
  const auto n = static_cast<std::size_t>(group.count());
  const Box bounds = bounds_of(share, group);

  // The blocks, from a sample that takes every stride-th point of the input.
  const std::int64_t stride = std::max<std::int64_t>(1, share.total / kSample);
  std::vector<double> sample;
  for (std::size_t i = 0; i < share.points.size(); ++i)
    if ((share.first + static_cast<std::int64_t>(i)) % stride == 0)
      sample.insert(sample.end(), share.points.point(i), share.points.point(i) + dim);
  const Blocks blocks(group.all_gather(sample), dim, group.count());
  const double margin = kGhostSpacings * mean_spacing(bounds, share.total);
  std::vector<Box> layers;
  for (int b = 0; b < group.count(); ++b) layers.push_back(widened(blocks.box(b), margin));

  // Each point to its block and to the blocks whose ghost layer holds it.
  Held held;
  held.dim = dim;
  {
    std::vector<std::vector<double>> to(n);
    for (std::size_t i = 0; i < share.points.size(); ++i) {
      const double* p = share.points.point(i);
      const int home = blocks.block_of(p);
      for (int b = 0; b < group.count(); ++b)
        if (b == home || layers[static_cast<std::size_t>(b)].contains_point(p))
          append_row(to[static_cast<std::size_t>(b)], p, dim, share.first + static_cast<std::int64_t>(i));
    }
    share.points = PointCloud();
    for (std::size_t b = 0; b < n; ++b)
      if (b != static_cast<std::size_t>(group.rank())) part.bytes_sent += 8.0 * static_cast<double>(to[b].size());
    std::vector<std::size_t> from;
    held.add(group.exchange(to, from), group.rank(), blocks);
  }

  // The regions whose points this process holds in full: its ghost layer, then each box it asked
  // for.
  std::vector<Box> known{layers[static_cast<std::size_t>(group.rank())]};
  const auto is_known = [&](const Box& region) {
    for (const Box& box : known)
      if (box.contains(region)) return true;
    return false;
  };
  std::vector<std::int64_t> pending;
  for (std::size_t i = 0; i < held.size(); ++i)
    if (held.own[i]) pending.push_back(held.ids[i]);
  part.points_owned = pending.size();

  Options star_options = options;
  star_options.compute_neighbors = true;
  star_options.progress = nullptr;
  const auto width = d + 1;
  for (;;) {
    if (++part.rounds > kMostRounds) throw InternalError("split run: the ghost rounds do not converge");
    std::vector<Box> requests;
    std::vector<std::int64_t> still;
    agree.run([&] {
      if (pending.empty()) return;
      // The pending points' places in the held order.
      std::vector<std::int64_t> local;
      std::vector<char> is_pending(held.size(), 0);
      for (std::int64_t id : pending) {
        const auto at = static_cast<std::size_t>(std::lower_bound(held.ids.begin(), held.ids.end(), id) - held.ids.begin());
        local.push_back(static_cast<std::int64_t>(at));
        is_pending[at] = 1;
      }
      Triangulation stars;
      const auto start = Clock::now();
      try {
        stars = delaunay_stars(PointsView(held.coords.data(), held.size(), dim), local, star_options);
      } catch (const DegenerateInputError&) {
        // Too few points here, or all in one hyperplane: ask for every point. Holding them all,
        // the input itself is degenerate, and the error is the single process's.
        if (is_known(bounds)) throw;
        requests.push_back(bounds);
        still = pending;
        return;
      }
      part.seconds_search += std::chrono::duration<double>(Clock::now() - start).count();
      if (part.rounds == 1)
        for (const Duplicate& dup : stars.duplicates) {
          const auto i = static_cast<std::size_t>(dup.index);
          if (!held.own[i]) continue;
          part.duplicates.push_back(static_cast<double>(held.ids[i]));
          part.duplicates.push_back(static_cast<double>(held.ids[static_cast<std::size_t>(dup.original)]));
          part.duplicates.insert(part.duplicates.end(), held.point(i), held.point(i) + dim);
        }
      std::vector<char> open(held.size(), 0);  // pending points whose star is not final
      std::vector<const double*> corners(width), facet(d);
      for (std::size_t s = 0; s < stars.size(); ++s) {
        const std::int32_t* v = stars.simplex(s);
        for (std::size_t k = 0; k < width; ++k) corners[k] = held.point(static_cast<std::size_t>(v[k]));
        const Box ball = ball_region(corners, bounds);
        if (!is_known(ball)) {
          for (std::size_t k = 0; k < width; ++k) open[static_cast<std::size_t>(v[k])] = 1;
          requests.push_back(ball);
        }
        for (std::size_t k = 0; k < width; ++k) {
          if (stars.neighbors[s * width + k] >= 0) continue;
          // A hull facet here: is it the whole input's?
          bool through_pending = false;
          for (std::size_t j = 0, f = 0; j < width; ++j) {
            if (j == k) continue;
            facet[f++] = corners[j];
            through_pending = through_pending || is_pending[static_cast<std::size_t>(v[j])];
          }
          if (!through_pending) continue;
          const Box beyond = beyond_region(facet, corners[k], bounds);
          if (is_known(beyond)) continue;
          for (std::size_t j = 0; j < width; ++j)
            if (j != k) open[static_cast<std::size_t>(v[j])] = 1;
          requests.push_back(beyond);
        }
      }
      // Keep the simplices whose smallest vertex is a pending point with a final star.
      for (std::size_t s = 0; s < stars.size(); ++s) {
        const std::int32_t* v = stars.simplex(s);
        const auto low = static_cast<std::size_t>(*std::min_element(v, v + width));
        if (!is_pending[low] || open[low]) continue;
        for (std::size_t k = 0; k < width; ++k)
          part.simplices.push_back(static_cast<std::int32_t>(held.ids[static_cast<std::size_t>(v[k])]));
      }
      for (std::size_t i = 0; i < held.size(); ++i)
        if (is_pending[i] && open[i]) still.push_back(held.ids[i]);
    });
    pending = std::move(still);
    if (group.sum(static_cast<long long>(requests.size())) == 0) break;

    // Ask the blocks that meet each region for their points in it; answer the others' asks.
    std::vector<std::vector<double>> asks(n);
    for (const Box& region : requests) {
      for (int b : blocks.meeting(region)) {
        if (b == group.rank()) continue;
        auto& to = asks[static_cast<std::size_t>(b)];
        to.insert(to.end(), region.lo.begin(), region.lo.end());
        to.insert(to.end(), region.hi.begin(), region.hi.end());
      }
      known.push_back(region);
    }
    for (std::size_t b = 0; b < n; ++b) part.bytes_sent += 8.0 * static_cast<double>(asks[b].size());
    std::vector<std::size_t> from;
    const std::vector<double> asked = group.exchange(asks, from);
    std::vector<std::vector<double>> answers(n);
    {
      const OwnIndex index(held);
      std::size_t at = 0;
      for (std::size_t b = 0; b < n; ++b) {
        std::vector<char> sent(held.size(), 0);
        for (const std::size_t end = at + from[b]; at + 2 * d <= end; at += 2 * d) {
          const Box region{std::vector<double>(asked.begin() + static_cast<std::ptrdiff_t>(at),
                                               asked.begin() + static_cast<std::ptrdiff_t>(at + d)),
                           std::vector<double>(asked.begin() + static_cast<std::ptrdiff_t>(at + d),
                                               asked.begin() + static_cast<std::ptrdiff_t>(at + 2 * d))};
          index.answer(region, sent, answers[b]);
        }
      }
    }
    for (std::size_t b = 0; b < n; ++b) part.bytes_sent += 8.0 * static_cast<double>(answers[b].size());
    held.add(group.exchange(answers, from), group.rank(), blocks);
  }
  for (char own : held.own) part.ghost_points += own ? 0 : 1;
  return part;
}

}  // namespace drange::cli
