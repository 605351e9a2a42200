// io/output_buffer.hpp: text output built in a large buffer and handed to the stream in big
// blocks. Formatting numbers with std::to_chars into memory and writing megabytes at a time
// is an order of magnitude faster than `out << value` per number.
#pragma once

#include <charconv>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

namespace drange::io {

class OutputBuffer {
 public:
  explicit OutputBuffer(std::ostream& out) : out_(out) { buffer_.reserve(kFlushAt + kSlack); }
  OutputBuffer(const OutputBuffer&) = delete;
  OutputBuffer& operator=(const OutputBuffer&) = delete;
  // Not flushed here: a destructor cannot report a failure; callers call flush().
  ~OutputBuffer() = default;

  void put(char c) {
    buffer_.push_back(c);
    if (buffer_.size() >= kFlushAt) flush();
  }

  void put_text(std::string_view text) {
    buffer_.append(text.data(), text.size());
    if (buffer_.size() >= kFlushAt) flush();
  }

  // Integers and doubles in their shortest exact form ("0.1", "1e+300", "-0").
  template <typename Number>
  void put_number(Number value) {
    char digits[32];
    const auto result = std::to_chars(digits, digits + sizeof digits, value);
    buffer_.append(digits, result.ptr);
    if (buffer_.size() >= kFlushAt) flush();
  }

  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kFlushAt = std::size_t{1} << 20;
  static constexpr std::size_t kSlack = 64;
  std::ostream& out_;
  std::string buffer_;
};

}  // namespace drange::io
