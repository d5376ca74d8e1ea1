// diffuv: counts and numbers as messages write them ("3 labels", "1 patch", "0.9").
#ifndef DIFFUV_INTERNAL_MESSAGE_TEXT_H
#define DIFFUV_INTERNAL_MESSAGE_TEXT_H

#include <cstddef>
#include <iomanip>
#include <sstream>
#include <string>

namespace diffuv {
namespace internal {

/// "1 label", "2 labels": `n` and `noun`, plural unless `n` is 1.
inline std::string count_text(std::size_t n, const std::string& noun)
{
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

/// "1 patch", "2 patches"; "1 face has", "0 faces have": `n` and `one` when
/// `n` is 1, else `n` and `many` (a plural that is not noun + "s", or a noun
/// with its verb).
inline std::string count_text(std::size_t n, const std::string& one, const std::string& many)
{
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

/// `value` with up to 15 significant digits: what a file wrote ("0.9", "300",
/// "1e+20"), without the noise of 17 digits.
inline std::string number_text(double value)
{
  std::ostringstream s;
  s << std::setprecision(15) << value;
  return s.str();
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_INTERNAL_MESSAGE_TEXT_H
