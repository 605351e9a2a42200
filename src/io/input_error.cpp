// io/input_error.cpp: the uniform InputError messages of the readers (see input_error.hpp).
#include "io/input_error.hpp"

#include <cstdio>

#include "drange/errors.hpp"

namespace drange::io {

void fail_at_line(const std::string& name, std::size_t line, const std::string& what) {
  throw InputError(name + ":" + std::to_string(line) + ": " + what);
}

void fail_in_file(const std::string& name, const std::string& what) {
  throw InputError(name + ": " + what);
}

std::string quoted(std::string_view token) {
  // Long enough for any sensible number, short enough for one terminal line.
  constexpr std::size_t kMaxShown = 40;
  std::string out = "\"";
  for (std::size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    } else if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else {
      out += static_cast<char>(c);
    }
  }
  if (token.size() > kMaxShown) out += "...";
  out += '"';
  return out;
}

std::string count_of(std::size_t n, const char* singular, const char* plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

}  // namespace drange::io
