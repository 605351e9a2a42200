// cli/agreement.cpp: see agreement.hpp.
#include "agreement.hpp"

#include <exception>

#include "exit_codes.hpp"

namespace drange::cli {

void Agreement::run(const std::function<void()>& work) const {
  std::exception_ptr failure;
  int code = kExitSuccess;
  try {
    work();
  } catch (...) {
    failure = std::current_exception();
    code = report_failure(failure, "delaunay", false);
  }
  const int worst = group_.max(code);
  if (worst == kExitSuccess) return;
  const int speaker = -group_.max(code == worst ? -group_.rank() : -group_.count());
  if (group_.rank() == speaker) report_failure(failure, "delaunay", true);
  throw Stopped{worst};
}

}  // namespace drange::cli
