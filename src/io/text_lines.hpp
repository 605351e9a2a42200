// io/text_lines.hpp: the line and field structure shared by every text reader.
//
// A line's content is what remains after dropping blank lines and comment lines (first
// non-blank character '#'). Fields are separated by whitespace, by a comma, or by a comma
// with whitespace around it; two commas in a row (or one at either end of the line) enclose
// an empty field, which the caller reports. Line numbers count every physical line, so that
// messages point at the line an editor shows. Windows line ends ("\r\n") and a UTF-8 byte
// order mark (spreadsheets write one) are accepted.
#pragma once

#include <cstddef>
#include <cstring>
#include <string_view>
#include <vector>

namespace drange::io {

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// The line without blanks at either end, for messages.
inline std::string_view trimmed(std::string_view line) {
  while (!line.empty() && is_blank(line.front())) line.remove_prefix(1);
  while (!line.empty() && is_blank(line.back())) line.remove_suffix(1);
  return line;
}

// Walks the content lines of a text held in memory.
class LineScanner {
 public:
  explicit LineScanner(std::string_view text) : LineScanner(text, 1, true) {}

  // A part of a text made of whole lines: `first_line` is the number of its first physical
  // line; a byte order mark is skipped only at the start of the whole text (`at_text_start`).
  LineScanner(std::string_view text, std::size_t first_line, bool at_text_start)
      : text_(text), line_number_(first_line - 1) {
    constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
    if (at_text_start && text_.substr(0, kByteOrderMark.size()) == kByteOrderMark) pos_ = kByteOrderMark.size();
  }

  // The byte offset, in the text given, of the next line to read.
  std::size_t position() const { return pos_; }

  // The next content line (without its line end) and its 1-based number; false at the end.
  bool next(std::string_view& line, std::size_t& line_number) {
    while (pos_ < text_.size()) {
      const char* begin = text_.data() + pos_;
      const std::size_t rest = text_.size() - pos_;
      const void* newline = std::memchr(begin, '\n', rest);
      const std::size_t length = newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - begin) : rest;
      pos_ += length + (newline ? 1 : 0);
      ++line_number_;
      std::string_view candidate(begin, length);
      if (is_content(candidate)) {
        line = candidate;
        line_number = line_number_;
        return true;
      }
    }
    return false;
  }

  // An upper bound for the number of content lines left (one pass over the rest of the
  // text, cheap next to parsing it): lets readers size their arrays once. memchr from line
  // end to line end: std::count would go byte by byte.
  std::size_t remaining_lines_bound() const {
    std::size_t lines = 1;
    const char* at = text_.data() + pos_;
    const char* const end = text_.data() + text_.size();
    while (const void* newline = std::memchr(at, '\n', static_cast<std::size_t>(end - at))) {
      ++lines;
      at = static_cast<const char*>(newline) + 1;
    }
    return lines;
  }

 private:
  static bool is_content(std::string_view line) {
    for (char c : line) {
      if (!is_blank(c)) return c != '#';
    }
    return false;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_number_ = 0;
};

// Splits a content line into fields (see the file comment); empty fields are kept as empty
// views so that the caller can name them. `fields` is cleared first and reused across lines.
inline void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
  fields.clear();
  const std::size_t n = line.size();
  std::size_t i = 0;
  auto skip_blanks = [&] {
    while (i < n && is_blank(line[i])) ++i;
  };
  skip_blanks();
  if (i == n) return;
  for (;;) {
    // At the start of a field, possibly an empty one.
    const std::size_t start = i;
    while (i < n && !is_blank(line[i]) && line[i] != ',') ++i;
    fields.push_back(line.substr(start, i - start));
    skip_blanks();
    if (i == n) return;
    if (line[i] == ',') {
      ++i;
      skip_blanks();
      if (i == n) {  // a trailing comma announces one more (empty) field
        fields.push_back(std::string_view());
        return;
      }
    }
  }
}

}  // namespace drange::io
