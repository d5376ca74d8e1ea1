// diffuv: numbers written so that they read back exactly, and no longer than that.
#ifndef DIFFUV_INTERNAL_NUMBER_FORMAT_H
#define DIFFUV_INTERNAL_NUMBER_FORMAT_H

#include <charconv>
#include <ostream>

namespace diffuv {
namespace internal {

/// Writes `x` in the shortest form that reads back to the same double
/// (0.3346 stays 0.3346, where 17 significant digits would print 0.33460000000000001).
inline void write_shortest(std::ostream& out, double x)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), x);
  out.write(buffer, result.ptr - buffer);
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_INTERNAL_NUMBER_FORMAT_H
