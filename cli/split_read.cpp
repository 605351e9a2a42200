// cli/split_read.cpp: see split_read.hpp.
#include "split_read.hpp"

#include <algorithm>
#include <cstring>
#include <string_view>

#include "drange/io.hpp"
#include "io/npy.hpp"
#include "io/read_text.hpp"
#include "io/text_points.hpp"

namespace drange::cli {
namespace {

constexpr std::size_t kPrefix = std::size_t{1} << 16;
constexpr std::size_t kExtension = std::size_t{1} << 16;

// A .npy file: every process reads it whole and keeps its share of the rows (see
// docs/scaling.md, "Limits").
PointShare npy_share(const std::string& path, const Processes& group) {
  PointShare share;
  PointCloud all = read_points(path);
  const auto n = static_cast<std::int64_t>(all.size());
  share.first = n * group.rank() / group.count();
  const std::int64_t end = n * (group.rank() + 1) / group.count();
  share.points.dim = all.dim;
  share.points.coords.assign(all.coords.begin() + share.first * all.dim, all.coords.begin() + end * all.dim);
  share.total = n;
  return share;
}

// This process's whole lines: those that start in [begin, end) of the file.
std::string whole_lines(const std::string& path, std::size_t begin, std::size_t end, std::size_t rows_begin,
                        std::size_t size, std::size_t& start) {
  const std::size_t from = begin > rows_begin ? begin - 1 : begin;
  std::string text = io::read_file_range(path, from, end);
  // Lines starting before `end` run to their newline.
  for (std::size_t at = end; at < size && (text.empty() || text.back() != '\n');) {
    const std::string more = io::read_file_range(path, at, std::min(size, at + kExtension));
    if (more.empty()) break;
    const std::size_t newline = more.find('\n');
    text.append(more, 0, newline == std::string::npos ? more.size() : newline + 1);
    at += more.size();
    if (newline != std::string::npos) break;
  }
  std::size_t skip = 0;
  if (from < begin) {  // begin is a line start only after a newline
    const std::size_t newline = text.find('\n');
    skip = newline == std::string::npos ? text.size() : newline + 1;
  }
  start = from + skip;
  return text.substr(skip);
}

}  // namespace

PointShare read_point_share(const std::string& path, const Processes& group, const Agreement& agree) {
  const std::string name = io::display_name(path);
  PointShare share;
  bool numpy = false;
  io::TextLayout layout;
  std::size_t size = 0;
  agree.run([&] {
    size = io::file_size(path);
    std::string prefix;
    for (std::size_t want = kPrefix;; want *= 4) {
      prefix = io::read_file_range(path, 0, std::min(size, want));
      numpy = io::is_numpy_input(prefix, name);
      if (numpy) return;
      layout = io::detect_text_layout(prefix, prefix.size() == size, name);
      if (layout.complete) return;
    }
  });
  if (numpy) {
    agree.run([&] { share = npy_share(path, group); });
    return share;
  }
  const std::size_t bytes = size - layout.rows_begin;
  const auto cut = [&](int r) {
    // bytes * r / count without overflow: a file's size times the processes fits in a long double.
    return layout.rows_begin + static_cast<std::size_t>(static_cast<long double>(bytes) * r / group.count());
  };
  std::string text;
  std::size_t start = 0;
  long long newlines = 0;
  agree.run([&] {
    text = whole_lines(path, cut(group.rank()), cut(group.rank() + 1), layout.rows_begin, size, start);
    for (const char* at = text.data(); (at = static_cast<const char*>(std::memchr(at, '\n', text.data() + text.size() - at)));
         ++at)
      ++newlines;
  });
  const long long lines_before = group.sum_before(newlines);
  agree.run([&] {
    share.points = io::parse_text_rows(text, start, layout.lines_before + 1 + static_cast<std::size_t>(lines_before),
                                       layout, name);
    share.points.dim = layout.dim;
  });
  std::string().swap(text);
  const auto mine = static_cast<long long>(share.points.size());
  share.first = group.sum_before(mine);
  share.total = group.sum(mine);
  agree.run([&] { io::check_text_point_count(layout, static_cast<std::size_t>(share.total), name); });
  return share;
}

}  // namespace drange::cli
