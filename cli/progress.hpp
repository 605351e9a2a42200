// cli/progress.hpp: the progress line that `drange` draws on standard error during long runs:
//   1 234 567 simplices  812k/s  61%  about 3 s left
// The fraction done and the time left compare the simplices found with the number expected
// for uniform random points (expected_simplices), so they are estimates: on other inputs
// the fraction stops at 99% until the run ends, and the time left is left out then.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace drange::cli {

// The number of Delaunay simplices of `points` uniform random points in the unit cube of
// dimension `dim` (2..11): measured per point for d <= 7, extrapolated beyond (progress.cpp).
double expected_simplices(std::size_t points, int dim);

// The text of the progress line (no "\r", no newline):
//   "1 234 567 simplices  812k/s  61%  about 3 s left"
// The rate is left out when no time has passed; the percentage is capped at 99%, and the
// time left is left out once the count reaches that cap (the estimate was too low).
std::string progress_line(std::size_t found, double expected, double elapsed_seconds);

// A callback for drange::Options::progress that redraws one line on standard error, at most
// five times a second and only once the run has taken more than a second. The line is erased
// when the engine reports its final count (see drange::Options::progress), and, should the
// run be abandoned by an exception, when the last copy of the callback is destroyed.
// Empty (nothing drawn) when `quiet`, or when standard error is not a terminal.
std::function<void(std::size_t)> make_progress_reporter(std::size_t points, int dim, bool quiet);

}  // namespace drange::cli
