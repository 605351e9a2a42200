// io/fd_output.hpp: an output stream buffer over a POSIX file descriptor that remembers why
// a write failed (errno), so that "No space left on device" reaches the user; std::ofstream
// only reports that something failed.
#pragma once

#include <streambuf>
#include <vector>

namespace drange::io {

class FdOutputBuffer : public std::streambuf {
 public:
  explicit FdOutputBuffer(int fd);
  FdOutputBuffer(const FdOutputBuffer&) = delete;
  FdOutputBuffer& operator=(const FdOutputBuffer&) = delete;

  // The errno of the first failed write, 0 while every write succeeded.
  int error() const { return error_; }

 protected:
  int_type overflow(int_type ch) override;
  std::streamsize xsputn(const char* data, std::streamsize n) override;
  int sync() override;

 private:
  bool drain();
  bool write_all(const char* data, std::size_t n);

  int fd_;
  int error_ = 0;
  std::vector<char> buffer_;
};

}  // namespace drange::io
