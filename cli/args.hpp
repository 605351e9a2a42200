// cli/args.hpp: a small command-line parser, enough for drange's commands.
//
// Options: "--name VALUE", "--name=VALUE", "-x VALUE", "-xVALUE" for options with a value,
// "--name" or "-x" for flags. "--" ends the options; "-" alone is an argument (standard
// input or output). A later occurrence of an option overrides an earlier one. Every mistake
// throws drange::UsageError naming the offending word.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace drange::cli {

struct OptionSpec {
  const char* long_name;  // without the dashes: "output"
  char short_name;        // 'o', or 0 for none
  bool takes_value;
};

struct Arguments {
  std::vector<std::string> positionals;
  std::map<std::string, std::string> options;  // long name -> value ("" for flags)

  bool has(const std::string& long_name) const { return options.count(long_name) != 0; }
  // The option's value, or `fallback` when it was not given.
  std::string value_or(const std::string& long_name, const std::string& fallback) const;
};

Arguments parse_arguments(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs);

// True when "--help" or "-h" appears before any "--": help wins over every other mistake.
bool asks_for_help(const std::vector<std::string>& args);

// Checks the number of positional arguments: throws UsageError "missing argument NAME" or
// "unexpected argument 'word'". `names` lists every positional; the first `required` must be
// present.
void expect_positionals(const Arguments& arguments, const std::vector<const char*>& names, std::size_t required);

// A decimal integer argument in [min, max]; throws UsageError
// "<what> must be an integer from <min> to <max>, got 'text'".
std::uint64_t parse_integer_argument(const std::string& what, const std::string& text, std::uint64_t min,
                                     std::uint64_t max);

}  // namespace drange::cli
