// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the strict readers share: a line reader that drops comments and blank lines and names the
// file and line in every error, a token reader on top of it for formats whose values may be
// spread over lines (Medit), and the lower-case extension of a path.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_INTERNAL_LINE_READER_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_INTERNAL_LINE_READER_H

#include <CGAL/Distortion_optimization/errors.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {
namespace internal {

// Reads a stream line by line, dropping comments ('#' to the end of the line) and blank lines,
// and turns what is left into whitespace-separated tokens; errors name the file and line.
class Line_reader
{
public:
  Line_reader(std::istream& in, const std::string& name) : in_(in), name_(name) {}

  // Next non-empty line's tokens; false at the end of the stream.
  bool next(std::vector<std::string>& tokens)
  {
    std::string line;
    while(std::getline(in_, line)) {
      ++line_number_;
      const std::size_t hash = line.find('#');
      if(hash != std::string::npos) line.erase(hash);
      std::istringstream words(line);
      tokens.clear();
      for(std::string w; words >> w;) tokens.push_back(w);
      if(!tokens.empty()) return true;
    }
    if(in_.bad()) fail("read error");
    return false;
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw Invalid_input(name_ + ":" + std::to_string(line_number_) + ": " + what);
  }

  double coordinate(const std::string& token) const
  {
    const char* begin = token.c_str();
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(begin, &end);
    if(end == begin || *end != '\0') fail("'" + token + "' is not a number");
    if(!std::isfinite(x) || errno == ERANGE) fail("coordinate '" + token + "' is not a finite number");
    return x;
  }

  long long integer(const std::string& token) const
  {
    const char* begin = token.c_str();
    char* end = nullptr;
    errno = 0;
    const long long i = std::strtoll(begin, &end, 10);
    if(end == begin || *end != '\0' || errno == ERANGE) fail("'" + token + "' is not an integer");
    return i;
  }

  // The line the last token came from (1-based; 0 before the first line).
  std::size_t line_number() const { return line_number_; }

private:
  std::istream& in_;
  std::string name_;
  std::size_t line_number_ = 0;
};

// The tokens of a stream one at a time, whatever the lines they sit on (comments and blank lines
// dropped as by Line_reader); an error names the line of the last token read.
class Token_reader
{
public:
  Token_reader(std::istream& in, const std::string& name) : in_(in), lines_(in, name)
  {
    // The size of a seekable stream bounds the counts a file may announce (remaining_bytes()).
    const std::ios::iostate state = in_.rdstate();
    const std::istream::pos_type here = in_.tellg();
    if(here == std::istream::pos_type(-1)) return;
    in_.seekg(0, std::ios::end);
    const std::istream::pos_type end = in_.fail() ? std::istream::pos_type(-1) : in_.tellg();
    in_.clear(state);
    in_.seekg(here);
    if(in_.fail()) lines_.fail("cannot seek back in the stream");
    if(end != std::istream::pos_type(-1)) end_ = static_cast<long long>(end);
  }

  // Next token; false at the end of the stream.
  bool next(std::string& token)
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

  // An upper bound on the bytes left after the last token read, or -1 if the stream cannot tell.
  long long remaining_bytes() const
  {
    if(end_ < 0) return -1;
    long long rest = 0;
    if(!in_.eof()) {
      const std::istream::pos_type here = in_.tellg();
      if(here == std::istream::pos_type(-1)) return -1;
      rest = end_ - static_cast<long long>(here);
    }
    for(std::size_t i = position_; i < tokens_.size(); ++i) rest += static_cast<long long>(tokens_[i].size()) + 1;
    return rest < 0 ? 0 : rest;
  }

  [[noreturn]] void fail(const std::string& what) const { lines_.fail(what); }
  double coordinate(const std::string& token) const { return lines_.coordinate(token); }
  long long integer(const std::string& token) const { return lines_.integer(token); }

  // Whether `token` is a whole number, integer or real (infinities and NaN included).
  static bool is_number(const std::string& token)
  {
    const char* begin = token.c_str();
    char* end = nullptr;
    std::strtod(begin, &end);
    return end != begin && *end == '\0';
  }

  std::size_t line_number() const { return lines_.line_number(); }

private:
  std::istream& in_;
  Line_reader lines_;
  std::vector<std::string> tokens_;
  std::size_t position_ = 0;
  long long end_ = -1;
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
