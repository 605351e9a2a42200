// cli/only_ids.cpp: --only IDS, a comma-separated list or @FILE.
#include "only_ids.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "drange/errors.hpp"

namespace drange::cli {
namespace {

std::int64_t parse_id(const std::string& word, const std::string& where) {
  if (word.empty()) throw UsageError("--only: an empty point id in " + where);
  std::int64_t value = 0;
  for (const char c : word) {
    if (c < '0' || c > '9')
      throw UsageError("--only: '" + word + "' in " + where + " is not a point id (a zero-based input index)");
    if (value > (std::numeric_limits<std::int64_t>::max() - (c - '0')) / 10)
      throw UsageError("--only: point id " + word + " in " + where + " is out of range");
    value = value * 10 + (c - '0');
  }
  return value;
}

}  // namespace

std::vector<std::int64_t> parse_only_ids(const std::string& text) {
  std::vector<std::int64_t> ids;
  if (!text.empty() && text[0] == '@') {
    const std::string path = text.substr(1);
    std::ifstream in(path);
    if (!in) throw InputError("--only: cannot read '" + path + "': " + std::strerror(errno));
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
      for (char& c : line)
        if (c == ',' || c == '\t' || c == '\r') c = ' ';
      std::istringstream words(line);
      const std::string where = path + ", line " + std::to_string(number);
      for (std::string word; words >> word;) ids.push_back(parse_id(word, where));
    }
    if (in.bad()) throw InputError("--only: error reading '" + path + "'");
    if (ids.empty()) throw UsageError("--only: '" + path + "' holds no point id");
    return ids;
  }
  if (text.empty()) throw UsageError("--only needs at least one point id");
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = text.find(',', begin);
    ids.push_back(parse_id(text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin), "'" + text + "'"));
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return ids;
}

}  // namespace drange::cli
