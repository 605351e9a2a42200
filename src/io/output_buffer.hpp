// io/output_buffer.hpp: text output built in a large buffer and handed to the stream in big
// blocks. Formatting numbers with std::to_chars into memory and writing megabytes at a time
// is an order of magnitude faster than `out << value` per number.
//
// The buffer is a plain array with a write position, not a std::string: every append to a
// string goes through its out-of-line _M_replace, which would cost more than the formatting
// itself. A number is formatted straight into the array, which keeps kSlack bytes free past
// kFlushAt for it.
#pragma once

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <ostream>
#include <string_view>

namespace drange::io {

class OutputBuffer {
 public:
  explicit OutputBuffer(std::ostream& out)
      : out_(out), buffer_(new char[kFlushAt + kSlack]), end_(buffer_.get()) {}
  OutputBuffer(const OutputBuffer&) = delete;
  OutputBuffer& operator=(const OutputBuffer&) = delete;
  // Not flushed here: a destructor cannot report a failure; callers call flush().
  ~OutputBuffer() = default;

  void put(char c) {
    *end_++ = c;
    flush_when_full();
  }

  void put_text(std::string_view text) {
    while (!text.empty()) {  // in pieces: a text may be longer than the room left
      const std::size_t piece = std::min(text.size(), room());
      std::memcpy(end_, text.data(), piece);
      end_ += piece;
      text.remove_prefix(piece);
      flush_when_full();
    }
  }

  // Integers and doubles in their shortest exact form ("0.1", "1e+300", "-0"): at most 24
  // characters (a double's shortest form), which the slack always has room for.
  template <typename Number>
  void put_number(Number value) {
    end_ = std::to_chars(end_, end_ + kNumberRoom, value).ptr;
    flush_when_full();
  }

  void flush() {
    out_.write(buffer_.get(), static_cast<std::streamsize>(end_ - buffer_.get()));
    end_ = buffer_.get();
  }

 private:
  static constexpr std::size_t kFlushAt = std::size_t{1} << 20;
  static constexpr std::size_t kNumberRoom = 32;
  static constexpr std::size_t kSlack = 64;
  static_assert(kSlack >= kNumberRoom, "a number must fit past kFlushAt");

  std::size_t room() const { return kFlushAt + kSlack - static_cast<std::size_t>(end_ - buffer_.get()); }
  void flush_when_full() {
    if (static_cast<std::size_t>(end_ - buffer_.get()) >= kFlushAt) flush();
  }

  std::ostream& out_;
  std::unique_ptr<char[]> buffer_;
  char* end_;
};

}  // namespace drange::io
