// diffuv bench: a tiny line-plot writer (PNG), with nothing to install.
//
// Axes, grid, ticks and tick numbers, one coloured polyline per series and a
// legend, drawn into an RGB buffer with an embedded 5x7 bitmap font (letters
// a-z, digits and a few signs), then written with `diffuv::write_png_file()`.
// Enough for a benchmark's curves; not a plotting library.
#ifndef DIFFUV_BENCH_PLOT_PNG_H
#define DIFFUV_BENCH_PLOT_PNG_H

#include <diffuv/core/color.h>
#include <diffuv/render/texture.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace diffuv_bench {

using diffuv::Color;

/// One curve: a name for the legend, a colour, points in data units.
struct Plot_series {
  std::string name;
  Color color{0, 0, 0};
  std::vector<std::pair<double, double>> points;  ///< (x, y), drawn in this order
};

/// A line plot. Ticks are placed at multiples of `x_step` / `y_step`
/// (0: a "nice" step of 1, 2 or 5 times a power of ten, about 5 intervals).
struct Line_plot {
  int width = 640, height = 420;
  double x_min = 0., x_max = 1., y_min = 0., y_max = 1.;
  double x_step = 0., y_step = 0.;
  std::string title, x_label, y_label;
  std::vector<Plot_series> series;
  enum class Legend { lower_right, upper_left } legend = Legend::lower_right;
};

/// A colour for series `i`: ten distinguishable colours, then again.
inline Color series_color(std::size_t i)
{
  static const Color palette[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40},
                                  {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127},
                                  {188, 189, 34}, {23, 190, 207}};
  return palette[i % 10];
}

namespace internal {

// The glyphs as pictures, 5 columns x 9 rows each ('#' on; rows 7 and 8 for
// descenders), side by side with one column between them, in blocks of
// nine rows: block b draws the characters of glyph_chars[b], in that order.
inline constexpr const char* glyph_chars[] = {
    "abcdefghijklmnopq", "rstuvwxyz01234567", "89.,-+%:/()<>=_"};
inline constexpr const char* glyph_strip[] = {
    // a     b     c     d     e     f     g     h     i     j     k     l     m     n     o     p     q
    "..... #.... ..... ....# ..... ..##. ..... #.... ..#.. ...#. #.... .##.. ..... ..... ..... ..... .....",
    "..... #.... ..... ....# ..... .#..# ..... #.... ..... ..... #.... ..#.. ..... ..... ..... ..... .....",
    ".###. #.##. .###. .##.# .###. .#... .#### #.##. .##.. ..##. #..#. ..#.. ##.#. #.##. .###. ####. .####",
    "....# ##..# #.... #..## #...# ###.. #...# ##..# ..#.. ...#. #.#.. ..#.. #.#.# ##..# #...# #...# #...#",
    ".#### #...# #.... #...# ##### .#... #...# #...# ..#.. ...#. ##... ..#.. #.#.# #...# #...# #...# #...#",
    "#...# #...# #...# #...# #.... .#... #...# #...# ..#.. ...#. #.#.. ..#.. #...# #...# #...# #...# #...#",
    ".#### ####. .###. .#### .###. .#... .#### #...# .###. ...#. #..#. .###. #...# #...# .###. ####. .####",
    "..... ..... ..... ..... ..... ..... ....# ..... ..... #..#. ..... ..... ..... ..... ..... #.... ....#",
    "..... ..... ..... ..... ..... ..... .###. ..... ..... .##.. ..... ..... ..... ..... ..... #.... ....#",
    // r     s     t     u     v     w     x     y     z     0     1     2     3     4     5     6     7
    "..... ..... .#... ..... ..... ..... ..... ..... ..... .###. ..#.. .###. ##### ...#. ##### ..##. #####",
    "..... ..... .#... ..... ..... ..... ..... ..... ..... #...# .##.. #...# ...#. ..##. #.... .#... ....#",
    "#.##. .###. ###.. #...# #...# #...# #...# #...# ##### #..## ..#.. ....# ..#.. .#.#. ####. #.... ...#.",
    "##..# #.... .#... #...# #...# #...# .#.#. #...# ...#. #.#.# ..#.. ...#. ...#. #..#. ....# ####. ..#..",
    "#.... .###. .#... #...# #...# #.#.# ..#.. #...# ..#.. ##..# ..#.. ..#.. ....# ##### ....# #...# .#...",
    "#.... ....# .#..# #..## .#.#. #.#.# .#.#. #...# .#... #...# ..#.. .#... #...# ...#. #...# #...# .#...",
    "#.... ####. ..##. .##.# ..#.. .#.#. #...# .#### ##### .###. .###. ##### .###. ...#. .###. .###. .#...",
    "..... ..... ..... ..... ..... ..... ..... ....# ..... ..... ..... ..... ..... ..... ..... ..... .....",
    "..... ..... ..... ..... ..... ..... ..... .###. ..... ..... ..... ..... ..... ..... ..... ..... .....",
    // 8     9     .     ,     -     +     %     :     /     (     )     <     >     =     _
    ".###. .###. ..... ..... ..... ..... ##... ..... ..... ...#. .#... ...#. .#... ..... .....",
    "#...# #...# ..... ..... ..... ..#.. ##..# .##.. ....# ..#.. ..#.. ..#.. ..#.. ..... .....",
    "#...# #...# ..... ..... ..... ..#.. ...#. .##.. ...#. .#... ...#. .#... ...#. ##### .....",
    ".###. .#### ..... ..... ##### ##### ..#.. ..... ..#.. .#... ...#. #.... ....# ..... .....",
    "#...# ....# ..... ..... ..... ..#.. .#... .##.. .#... .#... ...#. .#... ...#. ##### .....",
    "#...# ...#. .##.. .##.. ..... ..#.. #..## .##.. #.... ..#.. ..#.. ..#.. ..#.. ..... .....",
    ".###. .##.. .##.. ..#.. ..... ..... ...## ..... ..... ...#. .#... ...#. .#... ..... #####",
    "..... ..... ..... .#... ..... ..... ..... ..... ..... ..... ..... ..... ..... ..... .....",
    "..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ..... .....",
};
inline constexpr std::size_t glyph_blocks = sizeof(glyph_chars) / sizeof(glyph_chars[0]);

// The 9 row masks (bit 4 = leftmost column) of `c`; all zero for a space or an
// unknown character. Upper case is drawn as lower case.
inline std::array<std::uint8_t, 9> glyph(char c)
{
  static const auto masks = [] {
    std::array<std::array<std::uint8_t, 9>, 128> m{};
    for(std::size_t b = 0; b < glyph_blocks; ++b)
      for(std::size_t g = 0; glyph_chars[b][g] != '\0'; ++g)
        for(std::size_t r = 0; r < 9; ++r) {
          const char* row = glyph_strip[9 * b + r] + 6 * g;
          std::uint8_t bits = 0;
          for(int k = 0; k < 5; ++k)
            if(row[k] == '#') bits |= static_cast<std::uint8_t>(1u << (4 - k));
          m[static_cast<unsigned char>(glyph_chars[b][g])][r] = bits;
        }
    return m;
  }();
  const unsigned char u = static_cast<unsigned char>(std::tolower(static_cast<unsigned char>(c)));
  return u < 128 ? masks[u] : std::array<std::uint8_t, 9>{};
}

// An RGB image with clipping and alpha blending.
class Canvas {
public:
  Canvas(int width, int height, Color background)
    : width_(width), height_(height), rgb_(static_cast<std::size_t>(width) * height * 3)
  {
    for(std::size_t i = 0; i < rgb_.size(); i += 3) {
      rgb_[i] = background.r;
      rgb_[i + 1] = background.g;
      rgb_[i + 2] = background.b;
    }
  }

  const std::vector<unsigned char>& rgb() const { return rgb_; }

  void blend(int x, int y, Color c, double alpha)
  {
    if(x < 0 || y < 0 || x >= width_ || y >= height_ || alpha <= 0.) return;
    if(x < clip_[0] || y < clip_[1] || x > clip_[2] || y > clip_[3]) return;
    alpha = std::min(alpha, 1.);
    unsigned char* p = &rgb_[(static_cast<std::size_t>(y) * width_ + x) * 3];
    const unsigned char rgb[3] = {c.r, c.g, c.b};
    for(int k = 0; k < 3; ++k) p[k] = static_cast<unsigned char>(std::lround(p[k] * (1. - alpha) + rgb[k] * alpha));
  }

  void set_clip(int x0, int y0, int x1, int y1) { clip_ = {{x0, y0, x1, y1}}; }
  void reset_clip() { clip_ = {{0, 0, width_ - 1, height_ - 1}}; }

  void fill_rect(int x0, int y0, int x1, int y1, Color c)
  {
    for(int y = y0; y <= y1; ++y)
      for(int x = x0; x <= x1; ++x) blend(x, y, c, 1.);
  }

  void hline(int x0, int x1, int y, Color c) { fill_rect(std::min(x0, x1), y, std::max(x0, x1), y, c); }
  void vline(int x, int y0, int y1, Color c) { fill_rect(x, std::min(y0, y1), x, std::max(y0, y1), c); }

  // An anti-aliased segment of width `w` pixels: coverage from the distance
  // of each pixel centre to the segment.
  void segment(double x0, double y0, double x1, double y1, double w, Color c)
  {
    const double r = 0.5 * w;
    const int xa = static_cast<int>(std::floor(std::min(x0, x1) - r - 1));
    const int xb = static_cast<int>(std::ceil(std::max(x0, x1) + r + 1));
    const int ya = static_cast<int>(std::floor(std::min(y0, y1) - r - 1));
    const int yb = static_cast<int>(std::ceil(std::max(y0, y1) + r + 1));
    const double dx = x1 - x0, dy = y1 - y0, len2 = dx * dx + dy * dy;
    for(int y = ya; y <= yb; ++y)
      for(int x = xa; x <= xb; ++x) {
        const double px = x + 0.5 - x0, py = y + 0.5 - y0;
        double t = len2 > 0. ? (px * dx + py * dy) / len2 : 0.;
        t = std::clamp(t, 0., 1.);
        const double ex = px - t * dx, ey = py - t * dy;
        const double coverage = r + 0.5 - std::sqrt(ex * ex + ey * ey);
        if(coverage > 0.) blend_max(x, y, c, std::min(coverage, 1.));
      }
  }

  // Text with its top-left corner at (x, y), each font pixel `scale` x `scale`.
  void text(int x, int y, const std::string& s, int scale, Color c)
  {
    for(char ch : s) {
      const auto g = glyph(ch);
      for(int r = 0; r < 9; ++r)
        for(int k = 0; k < 5; ++k)
          if(g[r] & (1u << (4 - k))) fill_rect(x + k * scale, y + r * scale, x + (k + 1) * scale - 1,
                                               y + (r + 1) * scale - 1, c);
      x += advance(scale);
    }
  }

  // Text turned a quarter anticlockwise (reads bottom to top), its glyphs'
  // top-left corner at (x, y) being the lower left of the string.
  void text_vertical(int x, int y, const std::string& s, int scale, Color c)
  {
    for(char ch : s) {
      const auto g = glyph(ch);
      for(int r = 0; r < 9; ++r)
        for(int k = 0; k < 5; ++k)
          if(g[r] & (1u << (4 - k)))
            fill_rect(x + r * scale, y - (k + 1) * scale + 1, x + (r + 1) * scale - 1, y - k * scale, c);
      y -= advance(scale);
    }
  }

  static int advance(int scale) { return 6 * scale; }
  static int text_width(const std::string& s, int scale)
  {
    return s.empty() ? 0 : static_cast<int>(s.size()) * advance(scale) - scale;
  }
  static int cap_height(int scale) { return 7 * scale; }

  // Starts a new stroke (a new polyline): coverage bookkeeping is reset.
  void begin_stroke() { stroke_.assign(static_cast<std::size_t>(width_) * height_, 0.f); }

private:
  // Blending that keeps the strongest coverage a pixel got within one stroke,
  // so the joints of a polyline are not blended twice: only the part of the
  // coverage not yet applied is added ((a - a0) / (1 - a0) of the way).
  void blend_max(int x, int y, Color c, double alpha)
  {
    if(x < 0 || y < 0 || x >= width_ || y >= height_) return;
    if(x < clip_[0] || y < clip_[1] || x > clip_[2] || y > clip_[3]) return;
    if(stroke_.empty()) begin_stroke();
    const std::size_t i = static_cast<std::size_t>(y) * width_ + x;
    if(alpha <= stroke_[i]) return;
    const double extra = (alpha - stroke_[i]) / (1. - stroke_[i]);
    stroke_[i] = static_cast<float>(alpha);
    blend(x, y, c, extra);
  }

  int width_, height_;
  std::vector<unsigned char> rgb_;
  std::vector<float> stroke_;
  std::array<int, 4> clip_{{0, 0, 1 << 30, 1 << 30}};
};

// A step of 1, 2 or 5 times a power of ten giving about `intervals` intervals over `span`.
inline double nice_step(double span, int intervals = 5)
{
  if(!(span > 0.)) return 1.;
  const double raw = span / intervals;
  const double p = std::pow(10., std::floor(std::log10(raw)));
  const double m = raw / p;
  return (m < 1.5 ? 1. : m < 3.5 ? 2. : m < 7.5 ? 5. : 10.) * p;
}

// A tick number without trailing zeros ("0", "0.05", "20").
inline std::string tick_text(double value, double step)
{
  int decimals = 0;
  while(decimals < 9 && std::fabs(step * std::pow(10., decimals) - std::round(step * std::pow(10., decimals))) > 1e-6)
    ++decimals;
  if(std::fabs(value) < 1e-9 * step) value = 0.; // no "-0"
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::string s = buffer;
  if(s.find('.') != std::string::npos) {
    while(s.back() == '0') s.pop_back();
    if(s.back() == '.') s.pop_back();
  }
  return s;
}

} // namespace internal

/// Draws `plot` into an RGB buffer (`width * height * 3` bytes, top row first).
inline std::vector<unsigned char> render_plot(const Line_plot& plot)
{
  using internal::Canvas;
  const Color white{255, 255, 255}, black{0, 0, 0}, grid{225, 225, 225}, grey{90, 90, 90};
  Canvas canvas(plot.width, plot.height, white);
  const int scale = 1;
  const int left = 62, right = plot.width - 18, top = plot.title.empty() ? 16 : 34, bottom = plot.height - 44;
  const double x_step = plot.x_step > 0. ? plot.x_step : internal::nice_step(plot.x_max - plot.x_min);
  const double y_step = plot.y_step > 0. ? plot.y_step : internal::nice_step(plot.y_max - plot.y_min);
  auto px = [&](double x) { return left + (x - plot.x_min) / (plot.x_max - plot.x_min) * (right - left); };
  auto py = [&](double y) { return bottom - (y - plot.y_min) / (plot.y_max - plot.y_min) * (bottom - top); };

  // Grid, ticks and tick numbers.
  const double eps = 1e-9;
  for(double x = std::ceil(plot.x_min / x_step - eps) * x_step; x <= plot.x_max + eps * x_step; x += x_step) {
    const int X = static_cast<int>(std::lround(px(x)));
    canvas.vline(X, top, bottom, grid);
    canvas.vline(X, bottom, bottom + 4, black);
    const std::string t = internal::tick_text(x, x_step);
    canvas.text(X - Canvas::text_width(t, scale) / 2, bottom + 8, t, scale, black);
  }
  for(double y = std::ceil(plot.y_min / y_step - eps) * y_step; y <= plot.y_max + eps * y_step; y += y_step) {
    const int Y = static_cast<int>(std::lround(py(y)));
    canvas.hline(left, right, Y, grid);
    canvas.hline(left - 4, left, Y, black);
    const std::string t = internal::tick_text(y, y_step);
    canvas.text(left - 8 - Canvas::text_width(t, scale), Y - Canvas::cap_height(scale) / 2, t, scale, black);
  }
  // Axes.
  canvas.hline(left, right, bottom, black);
  canvas.vline(left, top, bottom, black);
  canvas.hline(left, right, top, grey);
  canvas.vline(right, top, bottom, grey);

  // Labels and title.
  if(!plot.x_label.empty())
    canvas.text((left + right - Canvas::text_width(plot.x_label, scale)) / 2, bottom + 24, plot.x_label, scale, black);
  if(!plot.y_label.empty())
    canvas.text_vertical(12, (top + bottom + Canvas::text_width(plot.y_label, scale)) / 2, plot.y_label, scale, black);
  if(!plot.title.empty())
    canvas.text((left + right - Canvas::text_width(plot.title, 2)) / 2, 8, plot.title, 2, black);

  // Curves, clipped to the plot area.
  canvas.set_clip(left, top, right, bottom);
  for(const Plot_series& s : plot.series) {
    canvas.begin_stroke();
    for(std::size_t i = 1; i < s.points.size(); ++i)
      canvas.segment(px(s.points[i - 1].first), py(s.points[i - 1].second), px(s.points[i].first),
                     py(s.points[i].second), 2., s.color);
  }
  canvas.reset_clip();

  // Legend: a line sample and the name of each series, in a framed box.
  if(!plot.series.empty()) {
    const int line_height = 14, sample = 22;
    int name_width = 0;
    for(const Plot_series& s : plot.series) name_width = std::max(name_width, Canvas::text_width(s.name, scale));
    const int w = 8 + sample + 6 + name_width + 8;
    const int h = 6 + line_height * static_cast<int>(plot.series.size()) + 2;
    int x0 = right - 10 - w, y0 = bottom - 10 - h;
    if(plot.legend == Line_plot::Legend::upper_left) { x0 = left + 10; y0 = top + 10; }
    canvas.fill_rect(x0, y0, x0 + w, y0 + h, white);
    canvas.hline(x0, x0 + w, y0, grey);
    canvas.hline(x0, x0 + w, y0 + h, grey);
    canvas.vline(x0, y0, y0 + h, grey);
    canvas.vline(x0 + w, y0, y0 + h, grey);
    for(std::size_t i = 0; i < plot.series.size(); ++i) {
      const int y = y0 + 6 + line_height * static_cast<int>(i);
      canvas.begin_stroke();
      canvas.segment(x0 + 8, y + 4, x0 + 8 + sample, y + 4, 2., plot.series[i].color);
      canvas.text(x0 + 8 + sample + 6, y, plot.series[i].name, scale, black);
    }
  }
  return canvas.rgb();
}

/// Draws `plot` and writes it as a PNG file (`diffuv::write_png_file()`).
/// \throws diffuv::Output_error if the file cannot be written
inline void write_plot_png(const std::string& path, const Line_plot& plot)
{
  diffuv::write_png_file(path, plot.width, plot.height, render_plot(plot));
}

} // namespace diffuv_bench

#endif // DIFFUV_BENCH_PLOT_PNG_H
