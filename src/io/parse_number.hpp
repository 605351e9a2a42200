// io/parse_number.hpp: strict, locale-independent parsing of one whole field.
#pragma once

#include <cstdint>
#include <string_view>

namespace drange::io {

enum class NumberStatus {
  Ok,
  NotANumber,  // the field is not entirely a decimal number
  NaN,         // "nan" and its spellings
  Infinite,    // "inf", "infinity"
  TooLarge,    // a finite decimal beyond the range of double (or of the integer type)
  Negative,    // an integer field with a minus sign where none is allowed
};

// Parses a decimal floating-point field ("1", "-2.5e-3", "+.5"); the whole field must be
// consumed. A value too small for a double rounds to a signed zero, as strtod does; one too
// large is TooLarge. On NaN and Infinite, `value` is still set.
NumberStatus parse_double(std::string_view field, double& value);

// Parses a field of decimal digits (an optional '+' allowed) into a value no larger than
// `max`. "-3" is Negative, "1.0" NotANumber, "99999999999" with max 2^31-1 TooLarge.
NumberStatus parse_unsigned(std::string_view field, std::uint64_t max, std::uint64_t& value);

}  // namespace drange::io
