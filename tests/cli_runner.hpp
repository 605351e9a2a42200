// tests/cli_runner.hpp: running the built `drange` executable (DRANGE_CLI_PATH) as a user runs
// it, through the shell with files and redirections, and collecting its exit code, standard
// output and standard error. Shared by the CLI tests.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "python_check.hpp"
#include "temp_dir.hpp"

#ifndef DRANGE_CLI_PATH
#error "DRANGE_CLI_PATH must name the built drange executable"
#endif

namespace drange::testing {

struct CliRun {
  int code = -1;
  std::string out;
  std::string err;
};

// Runs `drange ARGS` in the shell; standard input comes from `stdin_path` (or /dev/null).
// Standard output and error go to files in `dir`, removed again before returning.
inline CliRun run_cli(const TempDir& dir, const std::vector<std::string>& args,
                      const std::string& stdin_path = "/dev/null") {
  std::string command = shell_word(DRANGE_CLI_PATH);
  for (const std::string& arg : args) command += " " + shell_word(arg);
  const std::string out_path = dir.file(".stdout");
  const std::string err_path = dir.file(".stderr");
  command += " < " + shell_word(stdin_path) + " > " + shell_word(out_path) + " 2> " + shell_word(err_path);
  const int status = std::system(command.c_str());
  CliRun run;
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = read_text(out_path);
  run.err = read_text(err_path);
  std::remove(out_path.c_str());
  std::remove(err_path.c_str());
  return run;
}

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The four corners of the unit square and its centre: four triangles, all around the centre.
inline constexpr const char* kSquareWithCentre = "2\n5\n0 0\n1 0\n1 1\n0 1\n0.5 0.5\n";

}  // namespace drange::testing
