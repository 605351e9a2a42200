// check/problem_log.cpp: the capped problem list and the message helpers.
#include "check/problem_log.hpp"

#include <cstdio>
#include <utility>

namespace drange::check {

void ProblemLog::add(std::string line) {
  ++count_;
  if (lines_.size() < cap_) lines_.push_back(std::move(line));
}

std::string format_ids(const std::int32_t* ids, int count) {
  std::string text = "(";
  for (int i = 0; i < count; ++i) {
    if (i > 0) text += ' ';
    text += std::to_string(ids[i]);
  }
  text += ')';
  return text;
}

std::string format_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string format_point(const double* p, int dim) {
  std::string text = "(";
  for (int k = 0; k < dim; ++k) {
    if (k > 0) text += ' ';
    text += format_number(p[k]);
  }
  text += ')';
  return text;
}

}  // namespace drange::check
