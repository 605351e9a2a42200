// cli/split_rounds.cpp: see split_rounds.hpp.
#include "split_rounds.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include "drange/errors.hpp"
#include "drange/hull.hpp"
#include "split_blocks.hpp"
#include "util/check_points.hpp"

namespace drange::cli {
namespace {

using Clock = std::chrono::steady_clock;

// The sample that places the splits: about this many points in all, and at least this many per
// block (a quantile from k sample points is off by about 1/sqrt(k) of the block's count).
constexpr std::int64_t kSample = 1 << 14;
constexpr std::int64_t kSamplePerBlock = 1 << 10;
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
  lo = group.reduce(lo, Processes::Reduction::Min);
  hi = group.reduce(hi, Processes::Reduction::Max);
  Box box = Box::filled(d, 0, 0);
  std::copy(lo.begin(), lo.end(), box.lo.begin());
  std::copy(hi.begin(), hi.end(), box.hi.begin());
  return box;
}

// The mean spacing of the points: the side of a cube holding one point on average.
double mean_spacing(const Box& bounds, std::int64_t points) {
  const std::size_t d = bounds.dim;
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
  for (std::size_t k = 0; k < box.dim; ++k) {
    box.lo[k] -= by;
    box.hi[k] += by;
  }
  return box;
}

Box clipped(Box box, const Box& bounds) {
  for (std::size_t k = 0; k < box.dim; ++k) {
    box.lo[k] = std::max(box.lo[k], bounds.lo[k]);
    box.hi[k] = std::min(box.hi[k], bounds.hi[k]);
  }
  return box;
}

// The process's own points in a grid of cells (a few points per cell, over their bounding box),
// to answer requests for boxes, thin slabs along the input's sides included, by visiting only
// the cells that meet them.
class OwnIndex {
 public:
  explicit OwnIndex(const Held& held) : held_(held), d_(static_cast<std::size_t>(held.dim)) {
    std::vector<std::size_t> own;
    for (std::size_t i = 0; i < held.size(); ++i)
      if (held.own[i]) own.push_back(i);
    lo_.assign(d_, std::numeric_limits<double>::infinity());
    hi_.assign(d_, -std::numeric_limits<double>::infinity());
    for (std::size_t i : own)
      for (std::size_t k = 0; k < d_; ++k) {
        lo_[k] = std::min(lo_[k], held.point(i)[k]);
        hi_[k] = std::max(hi_[k], held.point(i)[k]);
      }
    const double per_axis = std::max(1.0, std::floor(std::pow(static_cast<double>(own.size()) / 4.0, 1.0 / static_cast<double>(d_))));
    cells_.assign(d_, static_cast<std::size_t>(per_axis));
    std::size_t total = 1;
    for (std::size_t k = 0; k < d_; ++k) total *= cells_[k];
    start_.assign(total + 1, 0);
    for (std::size_t i : own) ++start_[cell_of(held.point(i)) + 1];
    for (std::size_t c = 0; c < total; ++c) start_[c + 1] += start_[c];
    members_.resize(own.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i : own) members_[fill[cell_of(held.point(i))]++] = i;
  }

  // Appends the own points in `box` not yet sent to this requester (`sent` marks them).
  void answer(const Box& box, std::vector<char>& sent, std::vector<double>& out) const {
    if (members_.empty()) return;
    std::vector<std::size_t> first(d_), last(d_), at(d_);
    for (std::size_t k = 0; k < d_; ++k) {
      if (box.hi[k] < lo_[k] || box.lo[k] > hi_[k]) return;
      first[k] = axis_cell(k, box.lo[k]);
      last[k] = axis_cell(k, box.hi[k]);
    }
    at = first;
    for (;;) {
      std::size_t c = 0;
      for (std::size_t k = 0; k < d_; ++k) c = c * cells_[k] + at[k];
      for (std::size_t m = start_[c]; m < start_[c + 1]; ++m) {
        const std::size_t i = members_[m];
        if (sent[i] || !box.contains_point(held_.point(i))) continue;
        sent[i] = 1;
        append_row(out, held_.point(i), held_.dim, held_.ids[i]);
      }
      std::size_t k = d_;  // the next cell, last axis fastest
      while (k > 0 && at[k - 1] == last[k - 1]) {
        at[k - 1] = first[k - 1];
        --k;
      }
      if (k == 0) return;
      ++at[k - 1];
    }
  }

 private:
  std::size_t axis_cell(std::size_t k, double x) const {
    if (!(x > lo_[k])) return 0;
    const double f = (x - lo_[k]) / (hi_[k] - lo_[k]) * static_cast<double>(cells_[k]);
    return std::min(cells_[k] - 1, static_cast<std::size_t>(std::max(0.0, f)));
  }
  std::size_t cell_of(const double* p) const {
    std::size_t c = 0;
    for (std::size_t k = 0; k < d_; ++k) c = c * cells_[k] + axis_cell(k, p[k]);
    return c;
  }

  const Held& held_;
  std::size_t d_;
  std::vector<double> lo_, hi_;
  std::vector<std::size_t> cells_, start_, members_;
};

// The pending points on the boundary of the hull of the points held (its vertices, and the points
// in its faces): no hull facet of their triangulation goes through any other point.
std::vector<char> hull_candidates(const Held& held, const std::vector<char>& is_pending) {
  const ConvexHull hull = convex_hull(PointsView(held.coords.data(), held.size(), held.dim));
  std::vector<char> candidate(held.size(), 0);
  for (std::int32_t v : hull.vertices) candidate[static_cast<std::size_t>(v)] = is_pending[static_cast<std::size_t>(v)];
  for (std::size_t c = 0; c < hull.coplanar.size(); c += 3)
    candidate[static_cast<std::size_t>(hull.coplanar[c])] = is_pending[static_cast<std::size_t>(hull.coplanar[c])];
  return candidate;
}

// For facet k of each simplex (row s * (d + 1) + k): whether no other simplex returned has it,
// among the facets through a `candidate` point (a star holds both simplices of each facet through
// its point, so there one alone is a hull facet of the points held); 0 for the other facets. Facets are matched by a
// hash of their sorted vertices, then compared.
std::vector<char> unmatched_facets(const Triangulation& stars, const std::vector<char>& candidate) {
  const auto width = static_cast<std::size_t>(stars.dim) + 1;
  std::vector<char> unmatched(stars.simplices.size(), 0);
  std::vector<std::pair<std::uint64_t, std::size_t>> keys;  // (hash, row)
  // The sorted vertices of the facet in row r.
  const auto facet_of = [&](std::size_t r) {
    std::array<std::int32_t, kMaxDimension + 1> facet{};
    const std::int32_t* v = stars.simplex(r / width);
    std::size_t f = 0;
    for (std::size_t j = 0; j < width; ++j)
      if (j != r % width) facet[f++] = v[j];
    std::sort(facet.begin(), facet.begin() + static_cast<std::ptrdiff_t>(f));
    return facet;
  };
  for (std::size_t s = 0; s < stars.size(); ++s) {
    const std::int32_t* v = stars.simplex(s);
    if (std::none_of(v, v + width, [&](std::int32_t i) { return candidate[static_cast<std::size_t>(i)] != 0; })) continue;
    std::array<std::int32_t, kMaxDimension + 1> sorted{};
    std::copy(v, v + width, sorted.begin());
    std::sort(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(width));
    for (std::size_t k = 0; k < width; ++k) {
      const std::int32_t opposite = stars.simplex(s)[k];
      bool through_pending = false;
      std::uint64_t hash = 1469598103934665603ull;
      for (std::size_t j = 0; j < width; ++j) {
        if (sorted[j] == opposite) continue;
        through_pending = through_pending || candidate[static_cast<std::size_t>(sorted[j])];
        hash = (hash ^ static_cast<std::uint64_t>(sorted[j])) * 1099511628211ull;
      }
      if (through_pending) keys.emplace_back(hash, s * width + k);
    }
  }
  std::sort(keys.begin(), keys.end());
  const auto same = [&](std::size_t a, std::size_t b) { return facet_of(a) == facet_of(b); };
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i;
    while (j < keys.size() && keys[j].first == keys[i].first) ++j;
    for (std::size_t a = i; a < j; ++a) {  // a hash's facets: usually two, the same one
      bool matched = false;
      for (std::size_t b = i; b < j && !matched; ++b) matched = b != a && same(keys[a].second, keys[b].second);
      unmatched[keys[a].second] = matched ? 0 : 1;
    }
    i = j;
  }
  return unmatched;
}

}  // namespace

SplitPart triangulate_share(PointShare share, const Processes& group, const Agreement& agree, const Options& options) {
  SplitPart part;
  const int dim = share.points.dim;
  const auto d = static_cast<std::size_t>(dim);
  const auto n = static_cast<std::size_t>(group.count());
  // The engine's own limits, on the whole input (every process knows its dimension and count, so
  // all throw alike): the dimension, and 32-bit ids. With no coordinates to read, check_points
  // stops at these.
  util::check_points(PointsView(nullptr, 0, dim), "triangulates");
  if (share.total >= std::numeric_limits<std::int32_t>::max())
    util::check_points(PointsView(nullptr, static_cast<std::size_t>(share.total), dim), "triangulates");
  const Box bounds = bounds_of(share, group);

  // The blocks, from a sample that takes every stride-th point of the input.
  const std::int64_t stride =
      std::max<std::int64_t>(1, share.total / std::max<std::int64_t>(kSample, kSamplePerBlock * group.count()));
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
  star_options.compute_neighbors = false;  // unmatched_facets() finds the few that matter
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
        }
      const std::vector<char> unmatched = unmatched_facets(stars, hull_candidates(held, is_pending));
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
          if (!unmatched[s * width + k]) continue;
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
    for (Box region : requests) {
      // Widened by the ghost layer's width, so that the simplices the new points make are
      // mostly decided in the next round.
      region = clipped(widened(region, margin), bounds);
      for (int b : blocks.meeting(region)) {
        if (b == group.rank()) continue;
        auto& to = asks[static_cast<std::size_t>(b)];
        to.insert(to.end(), region.lo.begin(), region.lo.begin() + static_cast<std::ptrdiff_t>(d));
        to.insert(to.end(), region.hi.begin(), region.hi.begin() + static_cast<std::ptrdiff_t>(d));
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
          Box region = Box::filled(d, 0, 0);
          std::copy_n(asked.begin() + static_cast<std::ptrdiff_t>(at), d, region.lo.begin());
          std::copy_n(asked.begin() + static_cast<std::ptrdiff_t>(at + d), d, region.hi.begin());
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
