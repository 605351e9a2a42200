// io/input_error.hpp: building the InputError messages of the readers, so that every message
// has the same shape: "<file>:<line>: <what>" or "<file>: <what>".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace drange::io {

// Throws InputError("<name>:<line>: <what>").
[[noreturn]] void fail_at_line(const std::string& name, std::size_t line, const std::string& what);

// Throws InputError("<name>: <what>").
[[noreturn]] void fail_in_file(const std::string& name, const std::string& what);

// A token as it should appear in a message: in double quotes, control bytes escaped as \xNN,
// long tokens cut short with "...", so that a binary file cannot flood the terminal.
std::string quoted(std::string_view token);

// "1 point", "3 points": messages read better with the right number.
std::string count_of(std::size_t n, const char* singular, const char* plural);

}  // namespace drange::io
