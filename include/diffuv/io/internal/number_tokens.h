// diffuv: numbers as the text mesh formats write them, read one token at a
// time, and what tells a bad number from a number the reader refuses.
#ifndef DIFFUV_IO_INTERNAL_NUMBER_TOKENS_H
#define DIFFUV_IO_INTERNAL_NUMBER_TOKENS_H

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
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

/// Reads a number from `at` as `std::istream >> T` reads it for a floating
/// point T (libstdc++'s `num_get`, C locale), for readers that copy a
/// stream-based reader without its stream: white space skipped, then the
/// longest prefix of the form [+-]digits[.digits][(e|E)[+-]digits] taken
/// ("1-2" is 1, then -2), which must convert whole, straight to T (strtof for
/// a float: no rounding through double); a value beyond the range of T
/// fails, one too small gives 0 or a subnormal. Moves `at` past what the
/// stream consumes.
template <class T>
bool extract_floating(const char*& at, const char* end, T& value)
{
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);
  const char* p = at;
  while(p < end && is_blank(*p))
    ++p;
  const char* const start = p;
  if(p < end && (*p == '+' || *p == '-'))
    ++p;
  bool digits = false, point = false, exponent = false;
  for(; p < end; ++p) {
    const char c = *p;
    if(c >= '0' && c <= '9') {
      digits = true;
    } else if(c == '.' && !point && !exponent) {
      point = true;
    } else if((c == 'e' || c == 'E') && digits && !exponent) {
      exponent = true;
      if(p + 1 < end && (p[1] == '+' || p[1] == '-'))
        ++p; // the exponent's sign
    } else {
      break;
    }
  }
  at = p;
  // from_chars reads the same syntax as strtod here, apart from a leading '+'.
  const char* const first = start < p && *start == '+' ? start + 1 : start;
  const auto [stop, ec] = std::from_chars(first, p, value);
  if(stop != p || first == p)
    return false;
  if(ec == std::errc())
    return true;
  if(ec != std::errc::result_out_of_range)
    return false;
  // Too large or too small for from_chars: the stream keeps strtod's 0 or
  // subnormal, and fails on an infinity.
  const std::string text(start, p);
  if constexpr(std::is_same_v<T, float>)
    value = std::strtof(text.c_str(), nullptr);
  else
    value = std::strtod(text.c_str(), nullptr);
  return std::isfinite(value);
}

/// `extract_floating()` for a double: what `>> double` takes.
inline bool extract_double(const char*& at, const char* end, double& value)
{
  return extract_floating(at, end, value);
}

/// Reads an integer from `at` as `std::istream >> T` reads it (libstdc++,
/// C locale): white space skipped, an optional sign, decimal digits ("0x10"
/// is 0, then "x10"); fails without digits or beyond the range of T. A
/// signed T is read through a long and checked against T's range; an
/// unsigned one takes a minus sign as strtoul does ("-1" is the largest
/// value, "-65535" is 1 for an unsigned short) within its range. Moves `at`
/// past what the stream consumes.
template <class T>
bool extract_integer(const char*& at, const char* end, T& value)
{
  static_assert(std::is_integral_v<T> && sizeof(T) <= 4);
  const char* p = at;
  while(p < end && is_blank(*p))
    ++p;
  bool negative = false;
  if(p < end && (*p == '+' || *p == '-'))
    negative = *p++ == '-';
  const char* const digits = p;
  // The largest magnitude that fits, and the digits beyond it no longer matter.
  const unsigned long long most = static_cast<unsigned long long>(std::numeric_limits<T>::max()) +
                                  (std::is_signed_v<T> && negative ? 1 : 0);
  unsigned long long magnitude = 0;
  for(; p < end && *p >= '0' && *p <= '9'; ++p)
    if(magnitude <= most)
      magnitude = magnitude * 10 + static_cast<unsigned long long>(*p - '0');
  at = p;
  if(p == digits || magnitude > most)
    return false;
  if constexpr(std::is_signed_v<T>)
    value = static_cast<T>(negative ? -static_cast<long long>(magnitude) : static_cast<long long>(magnitude));
  else
    value = static_cast<T>(negative ? 0 - magnitude : magnitude); // modulo 2^bits, as strtoul
  return true;
}

/// Reads an integer from `at` as `std::istream >> int` reads it: see
/// `extract_integer()`.
inline bool extract_int(const char*& at, const char* end, int& value)
{
  return extract_integer(at, end, value);
}

/// Moves `at` as `std::istream::ignore(256, ' ')` does (libstdc++): past up
/// to 256 characters that are not a space, then past the space that stopped
/// it, if one did.
inline void ignore_to_space(const char*& at, const char* end)
{
  const std::size_t most = 256;
  std::size_t skipped = 0;
  while(at < end && *at != ' ' && skipped < most) {
    ++at;
    ++skipped;
  }
  if(at < end && skipped < most)
    ++at;
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
