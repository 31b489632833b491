// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// What the strict readers share: a bounded line reader that drops comments and blank lines and
// names the file and line in every error, a token reader on top of it for formats whose values
// may be spread over lines (Medit), strict number parsing, a bound on what a count announced by a
// file may reserve, the escaping of quoted file content in messages, and the lower-case extension
// of a path.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_INTERNAL_LINE_READER_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_INTERNAL_LINE_READER_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {
namespace internal {

// The longest line a reader accepts. Far more than any mesh line needs, and small enough that a
// file without a line break (a link to /dev/zero, a corrupt download) fails at once instead of
// filling the memory.
constexpr std::size_t max_line_bytes = std::size_t(1) << 20;

enum class Line_status { line, end_of_stream, too_long };

// Reads the next line of `in` into `buffer` (grown as needed, never beyond `max_bytes` + 1 bytes,
// so that memory follows the longest line read), without its '\n', and its length into
// `length`: `too_long` as soon as the line has more than `max_bytes` bytes (the rest of it is left
// unread). `end_of_stream` (and failbit, as std::getline) when nothing is left. Any reader of a
// file the user gives should read its lines through this or Line_reader. istream::getline copies
// straight out of the stream's buffer (a character at a time through the streambuf was a large
// part of reading a mesh).
inline Line_status read_bounded_line(std::istream& in, std::string& buffer, std::size_t& length, std::size_t max_bytes = max_line_bytes)
{
  length = 0;
  if(buffer.size() < 2) buffer.resize(std::min<std::size_t>(4096, max_bytes + 1));
  for(;;) {
    // Room for the rest of the buffer, the terminating NUL getline writes included.
    in.getline(&buffer[length], static_cast<std::streamsize>(std::min(buffer.size(), max_bytes + 1) - length));
    const std::size_t count = static_cast<std::size_t>(in.gcount());
    if(in.bad()) return Line_status::end_of_stream;
    if(in.eof()) { // the last line, without a line break, or nothing
      length += count;
      return length == 0 ? Line_status::end_of_stream : Line_status::line;
    }
    if(!in.fail()) { // the line break is counted, not stored
      length += count - 1;
      return Line_status::line;
    }
    // The buffer is full and no line break came yet.
    if(count == 0) return Line_status::end_of_stream; // a stream that had failed already
    length += count;
    if(length >= max_bytes) return Line_status::too_long;
    in.clear(in.rdstate() & ~std::ios::failbit);
    buffer.resize(std::min(2 * buffer.size(), max_bytes + 1));
  }
}

// `text` with control bytes (C0, DEL, C1) and bytes that are not UTF-8 written as \xNN, so that
// a message quoting a file cannot send escape sequences to a terminal.
inline std::string printable(const std::string& text)
{
  auto byte = [&](std::size_t i) { return i < text.size() ? static_cast<unsigned char>(text[i]) : 0u; };
  auto continuation = [&](std::size_t i, unsigned lo = 0x80, unsigned hi = 0xBF) { return byte(i) >= lo && byte(i) <= hi; };
  std::string out;
  out.reserve(text.size());
  for(std::size_t i = 0; i < text.size();) {
    const unsigned c = byte(i);
    // Length of a well-formed UTF-8 sequence starting at i that is not a control character, or 0.
    std::size_t n = 0;
    if(c >= 0x20 && c < 0x7F) n = 1;
    else if(c == 0xC2) n = continuation(i + 1, 0xA0) ? 2 : 0; // U+0080 to U+009F are C1 controls
    else if(c > 0xC2 && c <= 0xDF) n = continuation(i + 1) ? 2 : 0;
    else if(c >= 0xE0 && c <= 0xEF)
      n = continuation(i + 1, c == 0xE0 ? 0xA0 : 0x80, c == 0xED ? 0x9F : 0xBF) && continuation(i + 2) ? 3 : 0;
    else if(c >= 0xF0 && c <= 0xF4)
      n = continuation(i + 1, c == 0xF0 ? 0x90 : 0x80, c == 0xF4 ? 0x8F : 0xBF) && continuation(i + 2) && continuation(i + 3) ? 4 : 0;
    if(n == 0) {
      static const char digits[] = "0123456789abcdef";
      out += "\\x";
      out += digits[c >> 4];
      out += digits[c & 15];
      n = 1;
    } else {
      out.append(text, i, n);
    }
    i += n;
  }
  return out;
}

// Whether `token` is entirely a number as strtod reads it (integers, reals, infinities, NaN): a
// NUL or other byte after the number makes it not one. std::from_chars reads the decimal forms
// several times faster (and to the same double: both round correctly); strtod takes what it
// does not (a leading '+', hexadecimal).
inline bool parse_number(std::string_view token, double& x)
{
  const std::from_chars_result fast = std::from_chars(token.data(), token.data() + token.size(), x);
  if(fast.ec == std::errc() && fast.ptr == token.data() + token.size()) return true;
  const std::string copy(token);   // strtod needs the terminating NUL
  const char* begin = copy.c_str();
  char* end = nullptr;
  errno = 0;
  x = std::strtod(begin, &end);
  return end != begin && end == begin + copy.size();
}

inline bool is_number(std::string_view token)
{
  double x;
  return parse_number(token, x);
}

// How many of the `count` entries a file announces to reserve room for: no more than the rest of
// the stream can hold (`remaining_bytes`, -1 if unknown) at `min_entry_bytes` each, and a few
// thousand when the size is unknown (the vector grows as entries are read), so that a corrupt
// count allocates nothing before it is found wrong.
inline std::size_t plausible_reserve(long long count, long long remaining_bytes, long long min_entry_bytes)
{
  const long long bound = remaining_bytes < 0 ? 4096 : remaining_bytes / std::max(1LL, min_entry_bytes) + 1;
  return static_cast<std::size_t>(std::max(0LL, std::min(count, bound)));
}

// Reads a stream line by line (at most max_line_bytes a line), dropping a UTF-8 byte order mark
// at the start, comments ('#' to the end of the line) and blank lines, and turns what is left
// into whitespace-separated tokens; errors name the file and line, with control bytes escaped.
class Line_reader
{
public:
  Line_reader(std::istream& in, const std::string& name) : in_(in), name_(name)
  {
    // The size of a seekable stream bounds the counts a file may announce (remaining_bytes()).
    const std::ios::iostate state = in_.rdstate();
    const std::istream::pos_type here = in_.tellg();
    if(here == std::istream::pos_type(-1)) return;
    in_.seekg(0, std::ios::end);
    const std::istream::pos_type end = in_.fail() ? std::istream::pos_type(-1) : in_.tellg();
    in_.clear(state);
    in_.seekg(here);
    if(in_.fail()) fail("cannot seek back in the stream");
    if(end != std::istream::pos_type(-1)) end_ = static_cast<long long>(end);
  }

  // Next non-empty line's tokens; false at the end of the stream.
  bool next(std::vector<std::string>& tokens)
  {
    if(!next(views_)) return false;
    tokens.resize(views_.size());   // into the strings' memory the lines before left them
    for(std::size_t i = 0; i < views_.size(); ++i) tokens[i].assign(views_[i]);
    return true;
  }

  // The same, as views into the line, valid until the next call.
  bool next(std::vector<std::string_view>& tokens)
  {
    for(;;) {
      std::size_t length = 0;
      const Line_status status = read_bounded_line(in_, line_, length);
      if(status == Line_status::end_of_stream) break;
      ++line_number_;
      if(status == Line_status::too_long)
        throw Invalid_input(printable(name_) + ": line " + std::to_string(line_number_) + " longer than " +
                            std::to_string(max_line_bytes) + " bytes");
      const char* line = line_.data();
      if(line_number_ == 1 && length >= 3 && std::memcmp(line, "\xEF\xBB\xBF", 3) == 0) line += 3, length -= 3;
      if(const void* hash = std::memchr(line, '#', length)) length = static_cast<std::size_t>(static_cast<const char*>(hash) - line);
      split(line, length, tokens);
      if(!tokens.empty()) return true;
    }
    if(in_.bad()) fail("read error");
    return false;
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw Invalid_input(printable(name_ + ":" + std::to_string(line_number_) + ": " + what));
  }

  // `what` names the number in the message (a coordinate, a weight), whose magnitude is at most
  // `largest` (for coordinates, the package's bound).
  double coordinate(std::string_view token, const char* what = "coordinate",
                    double largest = Distortion_optimization::internal::largest_coordinate) const
  {
    double x;
    if(!parse_number(token, x)) fail("'" + std::string(token) + "' is not a number");
    // strtod sets ERANGE for subnormals too (which the writers produce): only a result that is not
    // finite is refused.
    if(!std::isfinite(x)) fail(std::string(what) + " '" + std::string(token) + "' is not a finite number");
    if(std::abs(x) > largest)
      fail(std::string(what) + " '" + std::string(token) + "' is beyond " + Distortion_optimization::internal::shown_number(largest) +
           " in magnitude");
    return x;
  }

  long long integer(std::string_view token) const
  {
    // from_chars first: strtoll, which consults the locale, was a large part of reading a mesh.
    // strtoll takes what from_chars does not (a leading '+') and tells an overflow.
    long long i;
    const std::from_chars_result fast = std::from_chars(token.data(), token.data() + token.size(), i);
    if(fast.ec == std::errc() && fast.ptr == token.data() + token.size()) return i;
    const std::string copy(token);   // strtoll needs the terminating NUL
    const char* begin = copy.c_str();
    char* end = nullptr;
    errno = 0;
    i = std::strtoll(begin, &end, 10);
    if(end == begin || end != begin + copy.size()) fail("'" + copy + "' is not an integer");
    if(errno == ERANGE) fail("integer '" + copy + "' is out of range");
    return i;
  }

  // Tokens from `first` on (optional values such as colors) must be numbers, not garbage.
  void check_numbers(const std::vector<std::string>& tokens, std::size_t first) const
  {
    for(std::size_t i = first; i < tokens.size(); ++i)
      if(!is_number(tokens[i])) fail("'" + tokens[i] + "' is not a number");
  }

  // The line the last token came from (1-based; 0 before the first line).
  std::size_t line_number() const { return line_number_; }

  // An upper bound on the bytes after the last line read, or -1 if the stream cannot tell.
  long long remaining_bytes() const
  {
    if(end_ < 0) return -1;
    if(in_.eof()) return 0;
    const std::istream::pos_type here = in_.tellg();
    if(here == std::istream::pos_type(-1)) return -1;
    return std::max(0LL, end_ - static_cast<long long>(here));
  }

private:
  // The whitespace of the "C" locale, as istream's >> splits.
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }

  static void split(const char* line, std::size_t length, std::vector<std::string_view>& tokens)
  {
    tokens.clear();
    for(std::size_t i = 0; i < length;) {
      if(is_space(line[i])) {
        ++i;
        continue;
      }
      const std::size_t begin = i;
      while(i < length && !is_space(line[i])) ++i;
      tokens.emplace_back(line + begin, i - begin);
    }
  }

  std::istream& in_;
  std::string name_;
  std::string line_;   // the line being read, its first `length` bytes
  std::vector<std::string_view> views_;
  std::size_t line_number_ = 0;
  long long end_ = -1;
};

// The tokens of a stream one at a time, whatever the lines they sit on (read as by Line_reader);
// an error names the line of the last token read.
class Token_reader
{
public:
  Token_reader(std::istream& in, const std::string& name) : lines_(in, name) {}

  // Next token, a view valid until a later call reads a new line; false at the end of the stream.
  bool next(std::string_view& token)
  {
    while(position_ == tokens_.size()) {
      if(!lines_.next(tokens_)) {
        tokens_.clear();
        position_ = 0;
        return false;
      }
      position_ = 0;
    }
    token = tokens_[position_++];
    return true;
  }

  bool next(std::string& token)
  {
    std::string_view view;
    if(!next(view)) return false;
    token.assign(view);
    return true;
  }

  // An upper bound on the bytes left after the last token read, or -1 if the stream cannot tell.
  long long remaining_bytes() const
  {
    long long rest = lines_.remaining_bytes();
    if(rest < 0) return -1;
    for(std::size_t i = position_; i < tokens_.size(); ++i) rest += static_cast<long long>(tokens_[i].size()) + 1;
    return rest;
  }

  [[noreturn]] void fail(const std::string& what) const { lines_.fail(what); }
  double coordinate(std::string_view token, const char* what = "coordinate",
                    double largest = Distortion_optimization::internal::largest_coordinate) const
  {
    return lines_.coordinate(token, what, largest);
  }
  long long integer(std::string_view token) const { return lines_.integer(token); }

  // Whether `token` is a whole number, integer or real (infinities and NaN included).
  static bool is_number(std::string_view token) { return internal::is_number(token); }

  std::size_t line_number() const { return lines_.line_number(); }

private:
  Line_reader lines_;
  std::vector<std::string_view> tokens_;
  std::size_t position_ = 0;
};

inline std::string to_lower(std::string s)
{
  for(char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

inline std::string extension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return to_lower(path.substr(dot + 1));
}

} // namespace internal
} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_INTERNAL_LINE_READER_H
