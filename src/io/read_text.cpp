// io/read_text.cpp: whole-file loading with errno-precise messages (see read_text.hpp).
#include "io/read_text.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <istream>
#include <iostream>
#include <memory>

#include <sys/stat.h>

#include "drange/errors.hpp"
#include "util/huge_pages.hpp"

namespace drange::io {
namespace {

// Large reads: the per-call cost disappears, and the buffer is reused for the whole input.
constexpr std::size_t kChunk = std::size_t{1} << 20;

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

[[noreturn]] void fail_system(const char* action, const std::string& path, int error) {
  throw InputError(std::string("cannot ") + action + " '" + path + "': " + std::strerror(error));
}

}  // namespace

std::string display_name(const std::string& path) { return path == "-" ? kStdinName : path; }

std::string read_whole_file(const std::string& path) {
  if (path == "-") return read_whole_stream(std::cin, kStdinName);

  // stdio rather than ifstream: fopen and fread report the reason of a failure in errno,
  // which is what makes "No such file or directory" and "Is a directory" possible.
  errno = 0;
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) fail_system("open", path, errno);

  std::string text;
  // Knowing the size up front avoids regrowing (and copying) a buffer of hundreds of MB.
  struct stat info {};
  if (fstat(fileno(file.get()), &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0) {
    text.reserve(static_cast<std::size_t>(info.st_size) + kChunk);
    util::advise_huge_pages(text.data(), text.capacity());
  }
  std::size_t used = 0;
  for (;;) {
    text.resize(used + kChunk);
    const std::size_t got = std::fread(text.data() + used, 1, kChunk, file.get());
    used += got;
    if (got < kChunk) break;
  }
  text.resize(used);
  if (std::ferror(file.get())) fail_system("read", path, errno ? errno : EIO);
  return text;
}

std::size_t file_size(const std::string& path) {
  struct stat info {};
  errno = 0;
  if (stat(path.c_str(), &info) != 0) fail_system("open", path, errno);
  if (S_ISDIR(info.st_mode)) fail_system("read", path, EISDIR);
  return static_cast<std::size_t>(info.st_size);
}

std::string read_file_range(const std::string& path, std::size_t begin, std::size_t end) {
  errno = 0;
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) fail_system("open", path, errno);
  std::string text;
  if (end <= begin) return text;
  if (fseeko(file.get(), static_cast<off_t>(begin), SEEK_SET) != 0) fail_system("read", path, errno ? errno : EIO);
  text.resize(end - begin);
  util::advise_huge_pages(text.data(), text.capacity());
  const std::size_t got = std::fread(text.data(), 1, text.size(), file.get());
  if (std::ferror(file.get())) fail_system("read", path, errno ? errno : EIO);
  text.resize(got);
  return text;
}

std::string read_whole_stream(std::istream& in, const std::string& name) {
  std::string text;
  std::size_t used = 0;
  std::streambuf* buffer = in.rdbuf();
  if (buffer == nullptr) throw InputError("cannot read '" + name + "': no stream buffer");
  for (;;) {
    text.resize(used + kChunk);
    errno = 0;
    const std::streamsize got = buffer->sgetn(text.data() + used, static_cast<std::streamsize>(kChunk));
    if (got <= 0) break;
    used += static_cast<std::size_t>(got);
  }
  text.resize(used);
  // sgetn cannot tell an error from the end of the input; stdin's underlying FILE can.
  if (&in == &std::cin && std::ferror(stdin)) fail_system("read", name, errno ? errno : EIO);
  return text;
}

}  // namespace drange::io
