// diffuv: numbers as the text mesh formats write them, read one token at a
// time, and what tells a bad number from a number the reader refuses.
#ifndef DIFFUV_IO_INTERNAL_NUMBER_TOKENS_H
#define DIFFUV_IO_INTERNAL_NUMBER_TOKENS_H

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace diffuv {
namespace internal {

/// White space as `std::isspace` sees it in the C locale, without the locale.
inline bool is_blank(char c)
{
  return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// True if the whole of `token` is a decimal integer that fits `value`.
inline bool parse_count(std::string_view token, long long& value)
{
  const char* first = token.data();
  const char* last = first + token.size();
  const auto [end, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && end == last;
}

/// True if the whole of `token` is a number for `std::strtod` (which takes
/// "nan", "inf" and hexadecimal too).
inline bool parse_number(std::string_view token, double& value)
{
  // A plain decimal number the quick way (both round correctly); anything
  // else ("+1", "0x1p3", "inf", "1e999") as strtod reads it.
  const auto [stop, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if(ec == std::errc() && stop == token.data() + token.size() && !token.empty() && token.front() != '+')
    return true;
  const std::string text(token);
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size();
}

/// `line` up to a `#` comment.
inline std::string before_comment(const std::string& line)
{
  return line.substr(0, line.find('#'));
}

/// True if the whole of `token` is a number in C syntax that is not finite
/// ("nan", "inf", "1e999"): `operator>>` refuses those, so CGAL's readers
/// report a syntax error where the user needs to hear about the value.
inline bool is_non_finite_number(const std::string& token)
{
  if(token.empty())
    return false;
  char* end = nullptr;
  const double d = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size() && !std::isfinite(d);
}

/// The numbers at the start of `line` (up to a `#` comment), read with
/// `operator>>` as CGAL's OFF scanner reads them; `stop` is the first
/// whitespace-separated token that was not read, if any (`operator>>`
/// consumes "1e999" before failing, so the token is not taken from the stream).
inline std::vector<double> leading_numbers(std::string line, std::string& stop)
{
  line = before_comment(line);
  std::istringstream in(line);
  std::vector<double> numbers;
  double d;
  while(in >> d)
    numbers.push_back(d);
  std::istringstream tokens(line);
  stop.clear();
  for(std::size_t k = 0; k <= numbers.size() && tokens >> stop; ++k) {}
  if(!tokens)
    stop.clear();
  return numbers;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_NUMBER_TOKENS_H
