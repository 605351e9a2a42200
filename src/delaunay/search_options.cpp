// delaunay/search_options.cpp: the named search variants.
#include "delaunay/search_options.hpp"

#include <string>

#include "drange/delaunay.hpp"
#include "drange/errors.hpp"

namespace drange {
namespace {

struct NamedVariant {
  const char* name;
  engine::SearchOptions options;
};

// Every variant, once: search_variant reads its options, variant_names its names.
constexpr engine::FacetOrder automatic = engine::FacetOrder::automatic, fifo = engine::FacetOrder::fifo,
                             spatial = engine::FacetOrder::spatial;
const NamedVariant kVariants[] = {
    //                kdtree prune  order  bottom_up seed  ball   shell  ties   facet order  hull
    {"full",          {true,  true,  true,  true,  true,  true,  true,  true,  automatic, true}},
    {"scan",          {false, false, false, false, false, false, false, false, fifo,      false}},
    {"kdtree",        {true,  false, false, false, false, false, false, false, fifo,      false}},
    {"no-prune",      {true,  false, true,  true,  true,  true,  true,  true,  automatic, true}},
    {"no-order",      {true,  true,  false, true,  true,  true,  true,  true,  automatic, true}},
    {"paper",         {true,  true,  true,  false, false, false, false, false, fifo,      false}},
    {"no-bottom-up",  {true,  true,  true,  false, true,  true,  true,  true,  automatic, true}},
    {"no-seed",       {true,  true,  true,  true,  false, true,  true,  true,  automatic, true}},
    {"no-ball",       {true,  true,  true,  true,  true,  false, true,  true,  automatic, true}},
    {"no-shell",      {true,  true,  true,  true,  true,  true,  false, true,  automatic, true}},
    {"no-tie-memory", {true,  true,  true,  true,  true,  true,  true,  false, automatic, true}},
    {"no-hull",       {true,  true,  true,  true,  true,  true,  true,  true,  automatic, false}},
    {"fifo",          {true,  true,  true,  true,  true,  true,  true,  true,  fifo,      true}},
    {"spatial",       {true,  true,  true,  true,  true,  true,  true,  true,  spatial,   true}},
};

}  // namespace

const char* variant_names() {
  static const std::string names = [] {
    std::string joined;
    for (const NamedVariant& variant : kVariants) joined += (joined.empty() ? "" : ", ") + std::string(variant.name);
    return joined;
  }();
  return names.c_str();
}

namespace engine {

SearchOptions search_variant(const std::string& name) {
  for (const NamedVariant& variant : kVariants)
    if (name == variant.name) return variant.options;
  throw UsageError("unknown search variant '" + name + "' (expected one of: " + variant_names() + ")");
}

}  // namespace engine
}  // namespace drange
