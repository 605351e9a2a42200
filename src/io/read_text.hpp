// io/read_text.hpp: loading a whole text input into memory. The readers parse from one buffer
// because that is several times faster than extracting numbers from a stream one by one.
#pragma once

#include <iosfwd>
#include <string>

namespace drange::io {

// The name used in messages for standard input.
inline constexpr const char* kStdinName = "<stdin>";

// The name of `path` in messages: "<stdin>" for "-", else the path itself.
std::string display_name(const std::string& path);

// The whole content of `path` ("-" reads std::cin). Throws InputError
// "cannot open 'x.txt': No such file or directory" or "cannot read 'x.txt': ...".
std::string read_whole_file(const std::string& path);

// The size in bytes of the file `path`, and the bytes [begin, end) of it (fewer at its end):
// what each process of a split run reads. Throw InputError as read_whole_file does.
std::size_t file_size(const std::string& path);
std::string read_file_range(const std::string& path, std::size_t begin, std::size_t end);

// The whole remaining content of `in`. Throws InputError "cannot read '<name>'" when the
// stream reports an error (not merely the end of the input).
std::string read_whole_stream(std::istream& in, const std::string& name);

}  // namespace drange::io
