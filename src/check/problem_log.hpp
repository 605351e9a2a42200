// check/problem_log.hpp: the validator's list of problems: every problem is counted, the
// first `cap` of them are kept as text (formatting the rest would only cost time).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace drange::check {

class ProblemLog {
 public:
  explicit ProblemLog(std::size_t cap) : cap_(cap) {}

  // True while a new problem's text would still be kept: callers build the message only then.
  bool wants_text() const { return lines_.size() < cap_; }
  // Counts one problem; keeps `line` if the cap allows.
  void add(std::string line);
  // Counts one problem whose text the caller did not build (wants_text() was false).
  void count_only() { ++count_; }
  // Counts one problem, calling make_text() for its line only if the line will be kept.
  template <class MakeText>
  void report(MakeText make_text) {
    if (wants_text()) add(make_text());
    else count_only();
  }

  std::size_t count() const { return count_; }
  const std::vector<std::string>& lines() const { return lines_; }
  std::vector<std::string> take_lines() { return std::move(lines_); }

 private:
  std::size_t cap_;
  std::size_t count_ = 0;
  std::vector<std::string> lines_;
};

// "(3 7 12)": vertex ids in parentheses, for messages.
std::string format_ids(const std::int32_t* ids, int count);
// A double with enough digits to read it back exactly ("%.17g").
std::string format_number(double x);
// "(0.5 0.25)": a point's coordinates.
std::string format_point(const double* p, int dim);

}  // namespace drange::check
