// diffuv: one colour type for every use (painted regions, vertex colours,
// pictures), and the palette that gives each label its colour.
#ifndef DIFFUV_CORE_COLOR_H
#define DIFFUV_CORE_COLOR_H

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <tuple>

namespace diffuv {

/// A colour: red, green and blue, 8 bits each (0-255). Ordered by (r, g, b),
/// the order in which painted colours are ranked into labels.
struct Color {
  unsigned char r = 0, g = 0, b = 0;

  friend bool operator==(const Color& x, const Color& y) { return x.r == y.r && x.g == y.g && x.b == y.b; }
  friend bool operator!=(const Color& x, const Color& y) { return !(x == y); }
  friend bool operator<(const Color& x, const Color& y)
  {
    return std::tie(x.r, x.g, x.b) < std::tie(y.r, y.g, y.b);
  }
  /// Writes "(r,g,b)".
  friend std::ostream& operator<<(std::ostream& os, const Color& c)
  {
    return os << '(' << int(c.r) << ',' << int(c.g) << ',' << int(c.b) << ')';
  }
};

/// Returns the colour of `label` in diffuv's fixed palette: labels 0-19 get
/// well-separated colours (matplotlib's tab10, then its light variants),
/// larger labels a scrambled colour. Distinct labels below 2^24 get distinct
/// colours, so the same label has the same colour on every mesh.
inline Color label_color(int label)
{
  static constexpr std::uint32_t palette[20] = {
    0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd, 0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf,
    0xaec7e8, 0xffbb78, 0x98df8a, 0xff9896, 0xc5b0d5, 0xc49c94, 0xf7b6d2, 0xc7c7c7, 0xdbdb8d, 0x9edae5};
  // An odd multiplier makes this a bijection of the 24-bit colours.
  auto scramble = [](std::uint32_t k) { return (k * 0x9E3779u + 0x5BD1E9u) & 0xffffffu; };
  std::uint32_t c;
  if(label >= 0 && label < 20) {
    c = palette[label];
  } else {
    // Cycle walking: a scrambled colour taken by the palette is replaced by
    // the scrambled colour of that palette entry's label, which no other
    // label uses; this keeps the map one-to-one.
    c = scramble(static_cast<std::uint32_t>(label));
    for(const std::uint32_t* p = std::find(palette, palette + 20, c); p != palette + 20;
        p = std::find(palette, palette + 20, c))
      c = scramble(static_cast<std::uint32_t>(p - palette));
  }
  return Color{static_cast<unsigned char>(c >> 16), static_cast<unsigned char>((c >> 8) & 0xff),
               static_cast<unsigned char>(c & 0xff)};
}

} // namespace diffuv

#endif // DIFFUV_CORE_COLOR_H
