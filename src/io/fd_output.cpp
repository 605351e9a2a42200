// io/fd_output.cpp: the buffered, errno-keeping output buffer of fd_output.hpp.
#include "io/fd_output.hpp"

#include <unistd.h>

#include <cerrno>

namespace drange::io {

namespace {
constexpr std::size_t kBufferSize = std::size_t{1} << 16;
}

FdOutputBuffer::FdOutputBuffer(int fd) : fd_(fd), buffer_(kBufferSize) {
  setp(buffer_.data(), buffer_.data() + buffer_.size());
}

FdOutputBuffer::int_type FdOutputBuffer::overflow(int_type ch) {
  if (!drain()) return traits_type::eof();
  if (!traits_type::eq_int_type(ch, traits_type::eof())) {
    *pptr() = traits_type::to_char_type(ch);
    pbump(1);
  }
  return traits_type::not_eof(ch);
}

std::streamsize FdOutputBuffer::xsputn(const char* data, std::streamsize n) {
  // Blocks at least as large as the buffer go straight to the file: no copy.
  if (n >= static_cast<std::streamsize>(buffer_.size())) {
    if (!drain() || !write_all(data, static_cast<std::size_t>(n))) return 0;
    return n;
  }
  return std::streambuf::xsputn(data, n);
}

int FdOutputBuffer::sync() { return drain() ? 0 : -1; }

bool FdOutputBuffer::drain() {
  const std::size_t pending = static_cast<std::size_t>(pptr() - pbase());
  const bool ok = write_all(pbase(), pending);
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  return ok;
}

bool FdOutputBuffer::write_all(const char* data, std::size_t n) {
  if (error_ != 0) return false;  // after a failure the file is incomplete: stop writing
  while (n > 0) {
    const ssize_t written = ::write(fd_, data, n);
    if (written < 0) {
      if (errno == EINTR) continue;
      error_ = errno;
      return false;
    }
    data += written;
    n -= static_cast<std::size_t>(written);
  }
  return true;
}

}  // namespace drange::io
