// io/parse_number.cpp: field parsing with std::from_chars (fast, and independent of the C
// locale, unlike strtod, which reads "1,5" in a German locale).
#include "io/parse_number.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

namespace drange::io {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// from_chars does not take a leading '+', which people and programs do write.
std::string_view without_plus(std::string_view field) {
  if (field.size() >= 2 && field[0] == '+' && field[1] != '+' && field[1] != '-') field.remove_prefix(1);
  return field;
}

// For a decimal that from_chars found out of range: true when its magnitude is below 1
// (an underflow), false when above (an overflow). The decimal exponent of the leading
// nonzero digit decides, and out-of-range values are hundreds of orders away from 1.
bool magnitude_below_one(std::string_view field) {
  std::size_t i = 0;
  if (i < field.size() && (field[i] == '-' || field[i] == '+')) ++i;
  long long leading_exponent = 0;
  bool seen_nonzero = false;
  bool after_point = false;
  for (; i < field.size() && field[i] != 'e' && field[i] != 'E'; ++i) {
    const char c = field[i];
    if (c == '.') {
      after_point = true;
    } else if (!seen_nonzero) {
      if (c != '0') {
        seen_nonzero = true;
      } else if (after_point) {
        --leading_exponent;
      }
    } else if (!after_point) {
      ++leading_exponent;
    }
  }
  long long exponent = 0;
  if (i < field.size()) {
    std::string_view digits = without_plus(field.substr(i + 1));
    // The exponent itself may be absurdly long; only its sign matters then.
    if (std::from_chars(digits.data(), digits.data() + digits.size(), exponent).ec != std::errc()) {
      exponent = (!digits.empty() && digits[0] == '-') ? -1000000 : 1000000;
    }
  }
  return leading_exponent + exponent < 0;
}

}  // namespace

NumberStatus parse_double(std::string_view field, double& value) {
  field = without_plus(field);
  if (field.empty()) return NumberStatus::NotANumber;
  const char* end = field.data() + field.size();
  const auto result = std::from_chars(field.data(), end, value);
  if (result.ptr != end) return NumberStatus::NotANumber;
  if (result.ec == std::errc::result_out_of_range) {
    if (!magnitude_below_one(field)) return NumberStatus::TooLarge;
    value = field[0] == '-' ? -0.0 : 0.0;
    return NumberStatus::Ok;
  }
  if (result.ec != std::errc()) return NumberStatus::NotANumber;
  if (std::isnan(value)) return NumberStatus::NaN;
  if (std::isinf(value)) return NumberStatus::Infinite;
  return NumberStatus::Ok;
}

NumberStatus parse_unsigned(std::string_view field, std::uint64_t max, std::uint64_t& value) {
  field = without_plus(field);
  const bool negative = !field.empty() && field[0] == '-';
  std::string_view digits = negative ? field.substr(1) : field;
  if (digits.empty()) return NumberStatus::NotANumber;
  for (char c : digits) {
    if (!is_digit(c)) return NumberStatus::NotANumber;
  }
  if (negative) {
    // "-0" is zero, harmless; any other negative value is not an index or a count.
    for (char c : digits) {
      if (c != '0') return NumberStatus::Negative;
    }
    value = 0;
    return NumberStatus::Ok;
  }
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (result.ec == std::errc::result_out_of_range || value > max) return NumberStatus::TooLarge;
  return NumberStatus::Ok;
}

}  // namespace drange::io
