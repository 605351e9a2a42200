// io/atomic_file.cpp: all-or-nothing output files.
//
// The content goes to a temporary file in the same directory as the destination (so that
// the final rename stays within one file system, where POSIX makes it atomic). Only a
// complete, flushed and fsync'ed file is renamed over the destination; on any failure the
// temporary file is removed and the destination is left as it was. Readers of the
// destination thus see either the old file or the whole new one, never a prefix.
//
// Destinations that are not regular files are written in place, because renaming over them
// would be wrong: "/dev/null", "/dev/stdout", a named pipe. A symbolic link to a regular file
// is followed, so that the link survives and its target receives the new content.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <ostream>
#include <string>

#include "drange/errors.hpp"
#include "drange/io.hpp"
#include "io/fd_output.hpp"

namespace drange {
namespace {

[[noreturn]] void fail_write(const std::string& path, int error) {
  throw InputError("cannot write '" + path + "': " + std::strerror(error != 0 ? error : EIO));
}

// Closes a descriptor once; a failing close() can mean lost data, so commit() checks it.
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  // 0 on success, else the errno of close().
  int close() {
    const int result = ::close(fd_);
    fd_ = -1;
    return result == 0 ? 0 : errno;
  }

 private:
  int fd_;
};

// The temporary file: removed on destruction unless it was renamed into place.
class TemporaryFile {
 public:
  explicit TemporaryFile(std::string path) : path_(std::move(path)) {}
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    if (!path_.empty()) ::unlink(path_.c_str());
  }
  const std::string& path() const { return path_; }
  void release() { path_.clear(); }

 private:
  std::string path_;
};

// Runs `write` on a stream over `fd`, then flushes. Returns the errno of a failed write or
// flush (0 when all went well); exceptions from `write` propagate.
int write_through(int fd, const std::function<void(std::ostream&)>& write) {
  io::FdOutputBuffer buffer(fd);
  std::ostream stream(&buffer);
  write(stream);
  stream.flush();
  if (buffer.error() != 0) return buffer.error();
  return stream.good() ? 0 : EIO;
}

void write_to_stdout(const std::function<void(std::ostream&)>& write) {
  write(std::cout);
  errno = 0;
  std::cout.flush();
  if (!std::cout.good()) {
    const int error = errno;
    throw InputError(std::string("cannot write to standard output") + (error ? std::string(": ") + std::strerror(error) : ""));
  }
}

// A device, pipe or socket: written directly, there is nothing to replace atomically.
void write_in_place(const std::string& path, const std::function<void(std::ostream&)>& write) {
  FileDescriptor fd(::open(path.c_str(), O_WRONLY | O_CLOEXEC));
  if (fd.get() < 0) fail_write(path, errno);
  if (const int error = write_through(fd.get(), write)) fail_write(path, error);
  if (const int error = fd.close()) fail_write(path, error);
}

// The file that will be replaced: the target of a symbolic link, else `path` itself.
std::string resolve_destination(const std::string& path) {
  struct stat link_info {};
  if (::lstat(path.c_str(), &link_info) != 0 || !S_ISLNK(link_info.st_mode)) return path;
  char resolved[PATH_MAX];
  if (::realpath(path.c_str(), resolved) == nullptr) return path;  // a dangling link is replaced
  return resolved;
}

// Creates `<destination>.tmp.<pid>` exclusively; a leftover of that name (from a crashed run
// with the same pid) is not overwritten, a numbered variant is tried instead.
int create_temporary(const std::string& destination, const std::string& path, std::string& temp_path) {
  const std::string base = destination + ".tmp." + std::to_string(::getpid());
  constexpr int kAttempts = 100;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    temp_path = attempt == 0 ? base : base + "." + std::to_string(attempt);
    const int fd = ::open(temp_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    if (errno != EEXIST) fail_write(path, errno);
  }
  fail_write(path, EEXIST);
}

void write_replacing(const std::string& path, const struct stat* existing,
                     const std::function<void(std::ostream&)>& write) {
  const std::string destination = resolve_destination(path);
  std::string temp_path;
  FileDescriptor fd(create_temporary(destination, path, temp_path));
  TemporaryFile temp(temp_path);
  // The replacement keeps the permissions of the file it replaces.
  if (existing != nullptr) ::fchmod(fd.get(), existing->st_mode & 0777);

  if (const int error = write_through(fd.get(), write)) fail_write(path, error);
  if (::fsync(fd.get()) != 0 && errno != EINVAL) fail_write(path, errno);  // EINVAL: no fsync here, nothing to sync
  if (const int error = fd.close()) fail_write(path, error);
  if (::rename(temp.path().c_str(), destination.c_str()) != 0) fail_write(path, errno);
  temp.release();
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  if (path == "-") {
    write_to_stdout(write);
    return;
  }
  if (path.empty()) throw InputError("cannot write '': No such file or directory");

  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    write_replacing(path, nullptr, write);
    return;
  }
  if (S_ISDIR(info.st_mode)) fail_write(path, EISDIR);
  if (!S_ISREG(info.st_mode)) {
    write_in_place(path, write);
    return;
  }
  // A read-only file stays untouched, as `cp` or a shell redirection would leave it.
  if (::access(path.c_str(), W_OK) != 0) fail_write(path, errno);
  write_replacing(path, &info, write);
}

}  // namespace drange
