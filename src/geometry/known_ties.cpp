// geometry/known_ties.cpp: sets of points known to lie on one surface, found from their points.
#include "geometry/known_ties.hpp"

#include <algorithm>

#include "drange/errors.hpp"

namespace drange::geometry {

KnownTies::KnownTies(int defining, std::int32_t points)
    : defining_(defining), points_(points), max_links_(kMinLinks + kLinksPerPoint * static_cast<std::size_t>(points)) {
  if (defining < 1) throw InternalError("KnownTies: no defining points");
}

bool KnownTies::member(std::int32_t set, std::int32_t id) const {
  const std::vector<std::int32_t>& members = sets_[static_cast<std::size_t>(set)];
  return std::binary_search(members.begin(), members.end(), id);
}

std::int32_t KnownTies::find(const std::int32_t* simplex) const {
  std::uint64_t wanted = 0;
  for (int i = 1; i < defining_; ++i) wanted |= signature_bit(simplex[i]);
  for (std::int32_t l = first_link_[static_cast<std::size_t>(simplex[0])]; l >= 0; l = links_[static_cast<std::size_t>(l)].next) {
    const std::int32_t set = links_[static_cast<std::size_t>(l)].set;
    if ((signatures_[static_cast<std::size_t>(set)] & wanted) != wanted) continue;  // a point certainly not in it
    bool all = true;
    for (int i = 1; i < defining_ && all; ++i) all = member(set, simplex[i]);
    if (all) return set;
  }
  return -1;
}

bool KnownTies::holds(const std::int32_t* simplex, std::int32_t id) const {
  if (first_link_.empty()) return false;
  if (!std::equal(last_simplex_.begin(), last_simplex_.end(), simplex) || last_simplex_.empty()) {
    last_simplex_.assign(simplex, simplex + defining_);
    last_set_ = find(simplex);
  }
  return last_set_ >= 0 && (signatures_[static_cast<std::size_t>(last_set_)] & signature_bit(id)) != 0 && member(last_set_, id);
}

void KnownTies::link(std::int32_t set, std::int32_t id) {
  std::vector<std::int32_t>& members = sets_[static_cast<std::size_t>(set)];
  const auto at = std::lower_bound(members.begin(), members.end(), id);
  if (at != members.end() && *at == id) return;
  members.insert(at, id);
  signatures_[static_cast<std::size_t>(set)] |= signature_bit(id);
  std::int32_t& first = first_link_[static_cast<std::size_t>(id)];
  links_.push_back({set, first});
  first = static_cast<std::int32_t>(links_.size() - 1);
}

void KnownTies::forget() {
  sets_.clear();
  signatures_.clear();
  links_.clear();
  std::fill(first_link_.begin(), first_link_.end(), -1);
}

void KnownTies::record(const std::int32_t* simplex, std::int32_t id) {
  last_simplex_.clear();
  if (first_link_.empty()) first_link_.assign(static_cast<std::size_t>(points_), -1);
  if (links_.size() + static_cast<std::size_t>(defining_) + 1 > max_links_) forget();
  std::int32_t set = find(simplex);
  if (set < 0) {
    set = static_cast<std::int32_t>(sets_.size());
    sets_.emplace_back();
    signatures_.push_back(0);
    for (int i = 0; i < defining_; ++i) link(set, simplex[i]);
  }
  if (static_cast<int>(sets_[static_cast<std::size_t>(set)].size()) < kMaxMembers) link(set, id);
}

}  // namespace drange::geometry
