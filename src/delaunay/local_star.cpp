// delaunay/local_star.cpp: the stars of given points by walks and a wrapping restricted to them
// (local_star.hpp says why each step is exact).
#include "delaunay/local_star.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "delaunay/facet_queue.hpp"
#include "delaunay/facet_table.hpp"
#include "delaunay/simplex_estimate.hpp"
#include "delaunay/simplex_facets.hpp"
#include "drange/errors.hpp"
#include "geometry/predicates.hpp"

namespace drange::engine {
namespace {

// The spatial queue's keys: the smallest vertex id in blocks of 8, as the whole construction's.
constexpr int kStarBlockShift = 3;

}  // namespace

StarWrapper::StarWrapper(const PointStore& points, FacetSearch& search, const FirstFacet& first)
    : points_(points),
      search_(search),
      d_(points.dim),
      facets_(static_cast<std::size_t>((points.dim + 1) * points.dim)),
      sides_(static_cast<std::size_t>(points.dim + 1)) {
  SearchCounters ignored;
  current_ = found_simplex(first.ids.data(), first.sigma, search_.find_apex(first.ids.data(), first.sigma, ignored));
  if (current_.apex < 0) throw InternalError("delaunay stars: the first facet has no simplex on its inner side");
}

FoundSimplex StarWrapper::found_simplex(const std::int32_t* facet, int sigma, std::int32_t apex) const {
  FoundSimplex s;
  std::copy_n(facet, d_, s.facet.begin());
  s.sigma = sigma;
  s.apex = apex;
  return s;
}

void StarWrapper::vertices_of(const FoundSimplex& s, std::int32_t* out) const {
  std::copy_n(s.facet.begin(), d_, out);
  if (s.sigma < 0) std::swap(out[0], out[1]);
  out[d_] = s.apex;
}

void StarWrapper::facets_of(const FoundSimplex& s) {
  const auto d = static_cast<std::size_t>(d_);
  simplex_other_facets(s.facet.data(), d_, s.apex, s.sigma < 0, facets_.data(), sides_.data());
  // Facet d omits the apex: the facet the simplex was found from, whose open side held the apex.
  std::copy_n(s.facet.begin(), d_, facets_.begin() + static_cast<std::ptrdiff_t>(d * d));
  sides_[d] = -s.sigma;
}

void StarWrapper::walk_to(std::int32_t p, SearchCounters& counters) {
  const auto d = static_cast<std::size_t>(d_);
  std::vector<std::int32_t> vertices(d + 1);
  std::vector<const double*> rows(d);
  // More steps than there are simplices: the walk cycled, which the acyclicity theorem rules out.
  const std::size_t limit = simplex_upper_bound(d_, static_cast<std::size_t>(points_.size));
  for (std::size_t step = 0; step <= limit; ++step) {
    vertices_of(current_, vertices.data());
    if (std::find(vertices.begin(), vertices.end(), p) != vertices.end()) return;
    facets_of(current_);
    bool crossed = false;
    for (std::size_t f = 0; f <= d && !crossed; ++f) {
      const std::int32_t* facet = &facets_[f * d];
      const geometry::Frame frame{d_, d_, nullptr, points_.point(facet[0])};
      for (std::size_t i = 1; i < d; ++i) rows[i - 1] = points_.point(facet[i]);
      rows[d - 1] = points_.point(p);
      if (sides_[f] * geometry::orientation(frame, rows.data()) <= 0) continue;  // p not strictly beyond
      const std::int32_t apex = search_.find_apex(facet, sides_[f], counters);
      // p lies in the hull, never strictly beyond a hull facet.
      if (apex < 0) throw InternalError("delaunay stars: the walk to point " + std::to_string(p) + " left the hull");
      current_ = found_simplex(facet, sides_[f], apex);
      crossed = true;
    }
    if (!crossed)
      throw InternalError("delaunay stars: point " + std::to_string(p) + " lies in a simplex without being its vertex");
  }
  throw InternalError("delaunay stars: the walk to point " + std::to_string(p) + " does not end");
}

void StarWrapper::stars(const std::vector<std::int32_t>& wanted, std::vector<std::int32_t>& rows,
                        SearchCounters& counters, std::vector<std::int32_t>& hull_facets, std::vector<std::int32_t>* links) {
  const auto d = static_cast<std::size_t>(d_);
  std::vector<std::int32_t> order(wanted);
  std::sort(order.begin(), order.end());
  order.erase(std::unique(order.begin(), order.end()), order.end());
  // Each wanted point's mark: wanted, or wanted and a vertex of a simplex found (its star is
  // under way). A range of ids (a block) keeps marks for its own points alone and is told by
  // two comparisons; other sets keep a mark per point (0: not wanted).
  const bool range = !order.empty() && order.back() - order.front() + 1 == static_cast<std::int32_t>(order.size());
  const std::int32_t low = range ? order.front() : 0;
  enum : char { kOther, kWanted, kCovered };
  std::vector<char> mark(range ? order.size() : static_cast<std::size_t>(points_.size), kOther);
  for (const std::int32_t p : order) mark[static_cast<std::size_t>(p - low)] = kWanted;
  const auto wanted_point = [&](std::int32_t v) {
    return range ? static_cast<std::size_t>(static_cast<std::uint32_t>(v - low)) < mark.size()
                 : mark[static_cast<std::size_t>(v)] != kOther;
  };
  // The stars' open facets through a wanted point (found on one side, not yet on the other),
  // and the queue of those to search, least smallest vertex id first: the whole construction's
  // spatial order (ids follow the kd-tree, so consecutive searches read nearby nodes). One
  // table for every start: a facet through a wanted point is reached from both sides within
  // one wrapping. Both know the facet's first side (row, facet) for the links.
  FacetTable open(d_);
  SpatialFacetQueue queue(d_, points_.size, kStarBlockShift);
  std::vector<std::int32_t> vertices(d + 1), facet(d);
  const auto link = [&](FacetOwner a, FacetOwner b) {
    (*links)[static_cast<std::size_t>(a.simplex) * (d + 1) + static_cast<std::size_t>(a.face)] = b.simplex;
    (*links)[static_cast<std::size_t>(b.simplex) * (d + 1) + static_cast<std::size_t>(b.face)] = a.simplex;
  };
  // A simplex is recorded in two steps: `found` writes its row and asks the cache for its
  // facets' table slots; `settle`, a search later when the slots have arrived, opens the facets
  // or closes those open already. Between the two, only a facet of that simplex can be
  // affected by the pending settle, and the loop settles first when its next facet is one.
  struct Pending {
    bool waiting = false;
    std::int32_t row = 0;
    FacetOwner from{-1, -1};  // the facet it was found from (its first side), or none
    std::uint32_t hashes[kMaxDimension + 1];
    bool opened[kMaxDimension + 1];
  } pending;
  const auto found = [&](const FoundSimplex& s, const FacetOwner* from) {
    pending.waiting = true;
    pending.row = static_cast<std::int32_t>(rows.size() / (d + 1));
    pending.from = from ? *from : FacetOwner{-1, -1};
    vertices_of(s, vertices.data());
    rows.insert(rows.end(), vertices.begin(), vertices.end());
    if (links) links->resize(rows.size(), kNotOpened);
    for (const std::int32_t v : vertices)
      if (wanted_point(v)) mark[static_cast<std::size_t>(v - low)] = kCovered;
    facets_of(s);
    for (std::size_t f = 0; f <= d; ++f) {
      const std::int32_t* ids = &facets_[f * d];
      // Facet d of a simplex found from a facet is that facet, closed already; a facet through
      // no wanted point leads out of the stars and is left alone.
      pending.opened[f] = !(from && f == d) && std::any_of(ids, ids + d, [&](std::int32_t v) {
        return wanted_point(v);
      });
      if (!pending.opened[f]) continue;
      pending.hashes[f] = facet_hash(ids, d_);
      open.prefetch(pending.hashes[f]);
    }
  };
  const auto settle = [&] {
    if (!pending.waiting) return;
    pending.waiting = false;
    for (std::size_t f = 0; f <= d; ++f) {
      const FacetOwner here{pending.row, static_cast<std::int32_t>(f)};
      if (f == d && pending.from.simplex >= 0 && links) link(pending.from, here);
      if (!pending.opened[f]) continue;
      const std::int32_t* ids = &facets_[f * d];
      FacetOwner other{};
      if (open.close_or_open(ids, pending.hashes[f], here, &other)) {  // both sides found
        if (links) link(other, here);
        continue;
      }
      queue.push(ids, pending.hashes[f], here, sides_[f], -1);
    }
  };
  // Whether the pending simplex's settle would open or close `ids` (of hash `hash`).
  const auto pending_facet = [&](const std::int32_t* ids, std::uint32_t hash) {
    if (!pending.waiting) return false;
    for (std::size_t f = 0; f <= d; ++f)
      if (pending.opened[f] && pending.hashes[f] == hash && std::equal(ids, ids + d, &facets_[f * d])) return true;
    return false;
  };
  // More simplices than n points can have: a wrong apex made them overlap (simplex_estimate.hpp).
  const std::size_t limit = simplex_upper_bound(d_, static_cast<std::size_t>(points_.size)) * (d + 1);
  // Facets leave the queue a few turns ahead, into a ring, so that each one's table slot is
  // asked for before its turn reads it. A facet closed while in the ring is skipped at its
  // turn, as one closed in the queue; the simplices do not depend on the order of the turns.
  constexpr std::size_t kAhead = 8;
  std::vector<std::int32_t> ring(kAhead * d);
  FacetInfo ring_info[kAhead];
  std::size_t first = 0, filled = 0;  // the ring holds turns first..filled-1
  std::size_t reported = rows.size();  // the rows reported so far end here
  const auto report = [&](bool rest) {
    if (!report_ || rows.size() == reported || (!rest && rows.size() - reported < report_every_ * (d + 1))) return;
    report_(&rows[reported], (rows.size() - reported) / (d + 1));
    reported = rows.size();
  };
  for (const std::int32_t p : order) {
    if (mark[static_cast<std::size_t>(p - low)] == kCovered) continue;
    walk_to(p, counters);
    found(current_, nullptr);
    settle();
    for (;;) {
      for (; filled < first + kAhead && !queue.empty(); ++filled) {
        const std::size_t slot = filled % kAhead;
        queue.pop(&ring[slot * d], ring_info[slot]);
        open.prefetch(ring_info[slot].hash);
      }
      if (first == filled) {
        if (!pending.waiting) break;
        settle();  // its facets may refill the queue
        continue;
      }
      const std::size_t slot = first++ % kAhead;
      std::copy_n(&ring[slot * d], d, facet.begin());
      const FacetInfo info = ring_info[slot];
      max_open_facets_ = std::max(max_open_facets_, open.size());
      if (rows.size() > limit) throw InternalError("delaunay stars: more simplices than the points can have");
      if (pending_facet(facet.data(), info.hash)) settle();
      // Closed meanwhile (its other simplex found from another facet): nothing to search.
      if (!open.remove(facet.data(), info.hash)) continue;
      const std::int32_t apex = search_.find_apex(facet.data(), info.sigma, counters);
      settle();
      if (apex < 0) {
        hull_facets.insert(hull_facets.end(), facet.begin(), facet.end());
        if (links)
          (*links)[static_cast<std::size_t>(info.owner.simplex) * (d + 1) + static_cast<std::size_t>(info.owner.face)] = kHullSide;
        continue;
      }
      found(found_simplex(facet.data(), info.sigma, apex), &info.owner);
      report(false);
    }
  }
  report(true);
}

}  // namespace drange::engine
