// cli/main.cpp: `drange`, the command-line front end. Dispatches to a command and turns the
// library's typed exceptions into one message on standard error and a documented exit code
// (exit_codes.hpp).
#include <exception>
#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "args.hpp"
#include "commands.hpp"
#include "drange/errors.hpp"
#include "exit_codes.hpp"
#include "processes.hpp"

namespace drange::cli {
namespace {

struct Command {
  const char* name;
  int (*run)(const std::vector<std::string>& args);
  std::string (*help)();
};

constexpr Command kCommands[] = {
    {"delaunay", run_delaunay, delaunay_help},
    {"voronoi", run_voronoi, voronoi_help},
    {"check", run_check, check_help},
    {"hull", run_hull, hull_help},
    {"generate", run_generate, generate_help},
};

const Command* find_command(const std::string& name) {
  for (const Command& command : kCommands) {
    if (name == command.name) return &command;
  }
  return nullptr;
}

[[noreturn]] void unknown_command(const std::string& name) {
  throw UsageError("unknown command '" + name + "' (expected delaunay, voronoi, check, hull, generate or help)");
}

// `drange help [COMMAND]`.
int run_help(const std::vector<std::string>& args) {
  if (args.empty()) {
    std::cout << general_help();
    return kExitSuccess;
  }
  if (args.size() > 1) throw UsageError("unexpected argument '" + args[1] + "'");
  const Command* command = find_command(args[0]);
  if (command == nullptr) unknown_command(args[0]);
  std::cout << command->help();
  return kExitSuccess;
}

// Runs the command line; `command_name` is set as soon as the command is known, for the hint
// that follows a usage error.
int dispatch(const std::vector<std::string>& args, std::string& command_name) {
  if (args.empty()) {
    std::cerr << general_help();
    return kExitUsage;
  }
  const std::string& first = args[0];
  if (first == "--help" || first == "-h") {
    std::cout << general_help();
    return kExitSuccess;
  }
  if (first == "--version") {
    if (args.size() > 1) throw UsageError("unexpected argument '" + args[1] + "'");
    std::cout << "drange " << kVersion << '\n';
    return kExitSuccess;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (first == "help") return run_help(rest);
  if (first.size() > 1 && first[0] == '-') throw UsageError("unknown option '" + first + "'");
  const Command* command = find_command(first);
  if (command == nullptr) unknown_command(first);
  command_name = command->name;
  if (processes().count() > 1 && command_name != "delaunay")
    throw UsageError("only drange delaunay runs across processes (mpirun); run drange " + command_name + " as one process");
  if (asks_for_help(rest)) {
    std::cout << command->help();
    return kExitSuccess;
  }
  return command->run(rest);
}

}  // namespace

int report_failure(std::exception_ptr failure, const std::string& command_name, bool print) {
  std::ostringstream message;
  int code = kExitInternal;
  try {
    std::rethrow_exception(failure);
  } catch (const UsageError& e) {
    message << "drange: " << e.what() << "\nTry 'drange " << (command_name.empty() ? "" : command_name + " ") << "--help'.\n";
    code = kExitUsage;
  } catch (const InputError& e) {
    message << "drange: " << e.what() << '\n';
    code = kExitInput;
  } catch (const DegenerateInputError& e) {
    message << "drange: " << e.what() << '\n';
    code = kExitDegenerate;
  } catch (const std::bad_alloc&) {
    message << "drange: out of memory\n";
    code = kExitOutOfMemory;
  } catch (const std::exception& e) {
    message << "drange: internal error: " << e.what() << '\n';
  } catch (...) {
    message << "drange: internal error: an exception of unknown type\n";
  }
  if (print) std::cerr << message.str();
  return code;
}

}  // namespace drange::cli

int main(int argc, char** argv) {
  using namespace drange::cli;
  std::string command_name;
  // Under mpirun every process runs the same command line; the messages come from process 0.
  bool speaks = launched_rank() == 0;
  try {
    const Processes processes(&argc, &argv);
    speaks = processes.rank() == 0;
    try {
      return dispatch(std::vector<std::string>(argv + 1, argv + argc), command_name);
    } catch (...) {
      return report_failure(std::current_exception(), command_name, speaks);
    }
  } catch (...) {
    return report_failure(std::current_exception(), command_name, speaks);
  }
}
