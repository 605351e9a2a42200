// cli/args.cpp: the command-line parser of args.hpp.
#include "args.hpp"

#include <charconv>
#include <string_view>

#include "drange/errors.hpp"

namespace drange::cli {
namespace {

const OptionSpec* find_long(const std::vector<OptionSpec>& specs, std::string_view name) {
  for (const OptionSpec& spec : specs) {
    if (name == spec.long_name) return &spec;
  }
  return nullptr;
}

const OptionSpec* find_short(const std::vector<OptionSpec>& specs, char name) {
  for (const OptionSpec& spec : specs) {
    if (spec.short_name != 0 && spec.short_name == name) return &spec;
  }
  return nullptr;
}

std::string spelled(const OptionSpec& spec, bool as_short) {
  return as_short ? std::string("-") + spec.short_name : std::string("--") + spec.long_name;
}

// Handles args[i], an option word; advances i past a separate value.
void take_option(const std::vector<std::string>& args, std::size_t& i, const std::vector<OptionSpec>& specs,
                 Arguments& out) {
  const std::string& word = args[i];
  const bool is_long = word.compare(0, 2, "--") == 0;
  const OptionSpec* spec = nullptr;
  bool has_inline_value = false;
  std::string inline_value;
  if (is_long) {
    const std::size_t equals = word.find('=');
    spec = find_long(specs, std::string_view(word).substr(2, equals == std::string::npos ? std::string::npos : equals - 2));
    if (equals != std::string::npos) {
      has_inline_value = true;
      inline_value = word.substr(equals + 1);
    }
  } else {
    spec = find_short(specs, word[1]);
    if (word.size() > 2) {
      has_inline_value = true;
      inline_value = word.substr(2);
    }
  }
  if (spec == nullptr) throw UsageError("unknown option '" + word + "'");
  const std::string name = spelled(*spec, !is_long);
  if (!spec->takes_value) {
    if (has_inline_value) {
      throw UsageError(is_long ? "option '" + name + "' takes no value" : "unknown option '" + word + "'");
    }
    out.options[spec->long_name] = "";
    return;
  }
  if (has_inline_value) {
    out.options[spec->long_name] = inline_value;
    return;
  }
  if (i + 1 >= args.size()) throw UsageError("option '" + name + "' needs a value");
  out.options[spec->long_name] = args[++i];
}

}  // namespace

std::string Arguments::value_or(const std::string& long_name, const std::string& fallback) const {
  const auto found = options.find(long_name);
  return found == options.end() ? fallback : found->second;
}

Arguments parse_arguments(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs) {
  Arguments out;
  bool options_ended = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& word = args[i];
    if (options_ended || word.size() < 2 || word[0] != '-') {
      out.positionals.push_back(word);
    } else if (word == "--") {
      options_ended = true;
    } else {
      take_option(args, i, specs, out);
    }
  }
  return out;
}

bool asks_for_help(const std::vector<std::string>& args) {
  for (const std::string& word : args) {
    if (word == "--") return false;
    if (word == "--help" || word == "-h") return true;
  }
  return false;
}

void expect_positionals(const Arguments& arguments, const std::vector<const char*>& names, std::size_t required) {
  const std::size_t given = arguments.positionals.size();
  if (given < required) throw UsageError(std::string("missing argument ") + names[given]);
  if (given > names.size()) throw UsageError("unexpected argument '" + arguments.positionals[names.size()] + "'");
}

std::uint64_t parse_integer_argument(const std::string& what, const std::string& text, std::uint64_t min,
                                     std::uint64_t max) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  if (text.empty() || result.ec != std::errc() || result.ptr != end || value < min || value > max) {
    throw UsageError(what + " must be an integer from " + std::to_string(min) + " to " + std::to_string(max) +
                     ", got '" + text + "'");
  }
  return value;
}

}  // namespace drange::cli
