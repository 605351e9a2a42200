// tests/python_check.hpp: checking an output file with the reader its users have, Python
// (json, xml.etree, zipfile, numpy). A test writes a short script that prints "ok" or what is
// wrong; when /usr/bin/python3 or a module is missing the test is skipped, loudly.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "temp_dir.hpp"

namespace drange::testing {

inline constexpr const char* kPython = "/usr/bin/python3";

inline std::string shell_word(const std::string& word) {
  std::string quoted = "'";
  for (char c : word) {
    if (c == '\'')
      quoted += "'\\''";
    else
      quoted += c;
  }
  return quoted + "'";
}

// Runs `python3 SCRIPT ARGS...` and returns what it printed (stdout and stderr).
inline std::string run_python(const TempDir& dir, const std::string& script, const std::vector<std::string>& args) {
  const std::string script_path = dir.file("check.py");
  write_text(script_path, script);
  std::string command = std::string(kPython) + " " + shell_word(script_path);
  for (const std::string& arg : args) command += " " + shell_word(arg);
  command += " 2>&1";
  std::string output;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[4096];
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, n);
    pclose(pipe);
  }
  return output;
}

// True when python3 can import every module in `modules` (space separated, e.g. "numpy").
// Remembered per process: starting Python with numpy costs a tenth of a second.
inline bool python_has(const std::string& modules) {
  static std::map<std::string, bool> known;
  const auto found = known.find(modules);
  if (found != known.end()) return found->second;
  std::string imports;
  for (std::size_t start = 0; start < modules.size();) {
    std::size_t end = modules.find(' ', start);
    if (end == std::string::npos) end = modules.size();
    imports += "import " + modules.substr(start, end - start) + "; ";
    start = end + 1;
  }
  const std::string command = std::string(kPython) + " -c " + shell_word(imports) + " > /dev/null 2>&1";
  return known[modules] = std::system(command.c_str()) == 0;
}

}  // namespace drange::testing

// Skips the test, with a message that shows in the test log, when Python lacks `modules`.
#define DRANGE_REQUIRE_PYTHON(modules)                                                        \
  do {                                                                                        \
    if (!::drange::testing::python_has(modules)) {                                            \
      GTEST_SKIP() << "SKIPPED: " << ::drange::testing::kPython << " with " << (modules)      \
                   << " is not available, so this output was NOT checked by its real reader"; \
    }                                                                                         \
  } while (false)
