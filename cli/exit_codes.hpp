// cli/exit_codes.hpp: the exit status of `drange`, one value per class of outcome. They are
// part of the command's interface (documented in `drange --help`); never renumber them.
#pragma once

#include <exception>
#include <string>

namespace drange::cli {

enum ExitCode : int {
  kExitSuccess = 0,
  kExitInvalid = 1,       // `drange check`: the triangulation is not a valid Delaunay triangulation
  kExitUsage = 2,         // bad command line: unknown option, missing or extra argument
  kExitInput = 3,         // input unreadable or malformed, or output cannot be written
  kExitDegenerate = 4,    // the points have no d-dimensional triangulation
  kExitOutOfMemory = 5,
  kExitInternal = 70,     // a bug: please report it (70 is EX_SOFTWARE in sysexits.h)
};

// The exit code of a failure (a library exception, bad_alloc, anything else: internal), and
// its message on standard error when `print`; `command_name` for a usage error's hint.
int report_failure(std::exception_ptr failure, const std::string& command_name, bool print);

}  // namespace drange::cli
