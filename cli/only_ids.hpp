// cli/only_ids.hpp: the --only argument of `drange delaunay`: the points whose stars to compute.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace drange::cli {

// Parses IDS: zero-based input indices separated by commas ("3,17,42"), or "@FILE", a file of
// them separated by commas, spaces or newlines. Throws UsageError naming a word that is not a
// non-negative decimal integer, or an empty list; InputError when FILE cannot be read. Ids out
// of range or given twice are the library's to reject (drange::delaunay_stars), by name too.
std::vector<std::int64_t> parse_only_ids(const std::string& text);

}  // namespace drange::cli
