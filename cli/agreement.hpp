// cli/agreement.hpp: the processes of a split run agree on failures. Work that may fail on one
// process and not another (reading its part, its own triangulation) runs inside run(); every
// process then learns the worst exit code, and when there is one, the lowest process with it
// prints its message and all throw Stopped together, so that the next collective call is never
// left waiting. A bad input fails the process that reads it; the lowest such process read the
// earliest bytes of the file, so its message is the single-process reader's.
#pragma once

#include <functional>

#include "processes.hpp"

namespace drange::cli {

struct Stopped {
  int code;
};

class Agreement {
 public:
  explicit Agreement(const Processes& group) : group_(group) {}
  // Runs `work` here; throws Stopped on every process when it failed on any.
  void run(const std::function<void()>& work) const;

 private:
  const Processes& group_;
};

}  // namespace drange::cli
