// cli/progress.cpp: the progress line of long runs (see progress.hpp).
#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "drange/delaunay.hpp"

namespace drange::cli {
namespace {

// Delaunay simplices per point of N uniform random points in the unit cube, counted with
//   drange generate uniform N D --seed 1 | drange delaunay --stats -o /dev/null
//   d = 2..6 at N = 20 000:  39 967, 133 748, 600 030, 3 222 486, 19 408 083 simplices
//                            (2.00, 6.69, 30.0, 161.1, 970.4 per point)
//   d = 7 at N = 1 000:      3 156 538 (a run of 20 000 would take hours)
// 3D uses 6.75, measured at N = 10^6 (docs/performance.md; the Poisson limit is 6.77). Points near the
// cube's boundary have fewer simplices, so the ratio still grows with N, the more so the
// higher d: these are estimates, and the fraction shown is capped at 99% until the end.
// Beyond d = 7 nothing was measured: the ratio is extrapolated by a factor of d - 1 per
// dimension (the measured factors from d - 1 to d are 3.3, 4.5, 5.4, 6.0, then 3.3 to the
// small-N 7D figure).
constexpr double kSimplicesPerPoint[] = {0, 0, 2.0, 6.75, 30.0, 161.1, 970.4, 3157.0};
constexpr int kMeasuredDims = 7;

// No line for runs shorter than this, and no more redraws than one per kRedrawSeconds:
// a line that flickers by is noise, and a terminal is slow.
constexpr double kQuietSeconds = 1.0;
constexpr double kRedrawSeconds = 0.2;

// The cap of the fraction shown before the end, when the estimate turns out too low.
constexpr double kMaxFraction = 0.99;

// "1234567" -> "1 234 567".
std::string grouped(std::size_t n) {
  const std::string digits = std::to_string(n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
    out += digits[i];
  }
  return out;
}

// "6554/s", "812k/s", "1.2M/s": three or four significant digits.
std::string rate_text(double per_second) {
  char text[32];
  if (per_second < 1e4) std::snprintf(text, sizeof text, "%.0f/s", per_second);
  else if (per_second < 1e6) std::snprintf(text, sizeof text, "%.0fk/s", per_second / 1e3);
  else std::snprintf(text, sizeof text, "%.1fM/s", per_second / 1e6);
  return text;
}

// "about 3 s left", "about 12 min left", "about 2 h 05 min left".
std::string time_left_text(double seconds) {
  char text[48];
  if (seconds < 59.5) std::snprintf(text, sizeof text, "about %.0f s left", std::max(1.0, std::ceil(seconds)));
  else if (seconds < 3570) std::snprintf(text, sizeof text, "about %.0f min left", std::round(seconds / 60));
  else {
    const long minutes = std::lround(seconds / 60);
    std::snprintf(text, sizeof text, "about %ld h %02ld min left", minutes / 60, minutes % 60);
  }
  return text;
}

using Clock = std::chrono::steady_clock;

// The line on standard error, shared by the copies of the callback.
class ProgressLine {
 public:
  explicit ProgressLine(double expected) : expected_(expected), start_(Clock::now()) {}
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  ~ProgressLine() { erase(); }

  void report(std::size_t found) {
    // The engine's counts before the last are multiples of kProgressInterval; the final one is
    // not, or repeats the one before (drange/delaunay.hpp).
    const bool final_count = found % kProgressInterval != 0 || found == last_found_;
    last_found_ = found;
    if (final_count) {
      erase();
      return;
    }
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    if (first_found_ == 0) first_found_ = found, first_elapsed_ = elapsed;
    if (elapsed < kQuietSeconds || (drawn_ && elapsed - last_drawn_ < kRedrawSeconds)) return;
    // The rate is measured from the first report on, leaving out the setup before the search
    // (the kd-tree, the first facet): the line gets the time the search takes at that rate,
    // and no time at the first report (no rate shown yet).
    const double search_seconds = found > first_found_ ? (elapsed - first_elapsed_) * static_cast<double>(found) /
                                                             static_cast<double>(found - first_found_)
                                                       : 0.0;
    // "\r" returns to the line's start, "\033[K" clears it: the new text may be shorter.
    std::fprintf(stderr, "\r\033[K%s", progress_line(found, expected_, search_seconds).c_str());
    std::fflush(stderr);
    drawn_ = true;
    last_drawn_ = elapsed;
  }

 private:
  void erase() {
    if (!drawn_) return;
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    drawn_ = false;
  }

  double expected_;
  Clock::time_point start_;
  std::size_t last_found_ = 0;
  std::size_t first_found_ = 0;  // the count and time of the first report
  double first_elapsed_ = 0;
  bool drawn_ = false;
  double last_drawn_ = 0;
};

}  // namespace

double expected_simplices(std::size_t points, int dim) {
  if (dim < 2) return 0;
  double per_point = kSimplicesPerPoint[std::min(dim, kMeasuredDims)];
  for (int d = kMeasuredDims + 1; d <= dim; ++d) per_point *= d - 1;
  return per_point * static_cast<double>(points);
}

std::string progress_line(std::size_t found, double expected, double elapsed_seconds) {
  std::string line = grouped(found) + (found == 1 ? " simplex" : " simplices");
  if (elapsed_seconds > 0) line += "  " + rate_text(static_cast<double>(found) / elapsed_seconds);
  if (!(expected > 0)) return line;
  const double fraction = std::min(static_cast<double>(found) / expected, kMaxFraction);
  line += "  " + std::to_string(static_cast<int>(fraction * 100)) + "%";
  if (fraction < kMaxFraction && found > 0 && elapsed_seconds > 0) {
    line += "  " + time_left_text(elapsed_seconds * (expected - static_cast<double>(found)) / static_cast<double>(found));
  }
  return line;
}

std::function<void(std::size_t)> make_progress_reporter(std::size_t points, int dim, bool quiet) {
  if (quiet || !isatty(STDERR_FILENO)) return {};
  auto line = std::make_shared<ProgressLine>(expected_simplices(points, dim));
  return [line](std::size_t found) { line->report(found); };
}

}  // namespace drange::cli
