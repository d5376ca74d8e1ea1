// diffuv: numbers written so that they read back exactly, and no longer than that.
#ifndef DIFFUV_INTERNAL_NUMBER_FORMAT_H
#define DIFFUV_INTERNAL_NUMBER_FORMAT_H

#include <charconv>
#include <cstddef>
#include <exception>
#include <ostream>
#include <string>
#include <string_view>

namespace diffuv {
namespace internal {

/// Formats `x` into `buffer` in the shortest form that reads back to the same
/// double (0.3346 stays 0.3346, where 17 significant digits would print
/// 0.33460000000000001); returns one past the last character.
inline char* format_shortest(char (&buffer)[32], double x) { return std::to_chars(buffer, buffer + sizeof(buffer), x).ptr; }

/// Writes `x` in that shortest form.
inline void write_shortest(std::ostream& out, double x)
{
  char buffer[32];
  out.write(buffer, format_shortest(buffer, x) - buffer);
}

/// Text made in memory and handed to a stream in blocks of 64 KB: one
/// `ostream::write()` per block instead of one formatted insertion (with its
/// sentry and locale) per number. Writing man's OBJ (2.8 MB) through `<<`
/// took about as long as mapping man (doc/performance.md).
class Text_writer {
public:
  explicit Text_writer(std::ostream& out) : out_(out), exceptions_(std::uncaught_exceptions())
  {
    text_.reserve(block + 64);
  }
  /// Call `flush()` at the end: this flushes only on a normal way out, and
  /// swallows what a stream with exceptions enabled would throw.
  ~Text_writer()
  {
    if(std::uncaught_exceptions() != exceptions_) return; // unwinding: the text is unfinished anyway
    try {
      flush();
    } catch(...) {
    }
  }
  Text_writer(const Text_writer&) = delete;
  Text_writer& operator=(const Text_writer&) = delete;

  Text_writer& put(char c)
  {
    text_.push_back(c);
    return full();
  }
  Text_writer& put(std::string_view s)
  {
    text_.append(s.data(), s.size());
    return full();
  }
  /// The shortest form that reads back to the same double (`write_shortest()`).
  Text_writer& number(double x)
  {
    char buffer[32];
    text_.append(buffer, static_cast<std::size_t>(format_shortest(buffer, x) - buffer));
    return full();
  }
  Text_writer& number(std::size_t n)
  {
    char buffer[24];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), n);
    text_.append(buffer, static_cast<std::size_t>(result.ptr - buffer));
    return full();
  }
  void flush()
  {
    if(!text_.empty()) out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
    text_.clear();
  }

private:
  static constexpr std::size_t block = std::size_t(1) << 16;
  Text_writer& full()
  {
    if(text_.size() >= block) flush();
    return *this;
  }
  std::ostream& out_;
  std::string text_;
  int exceptions_;
};

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_INTERNAL_NUMBER_FORMAT_H
