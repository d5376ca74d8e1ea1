// diffuv: a chart's uv layout as an SVG picture.
//
// To see at a glance what a parameterization did: every triangle of one chart
// of a `Uv_atlas` drawn in the uv plane, the folded (flipped) ones in red, the
// collapsed (degenerate) ones in orange, the unit square the chart should
// fill, and the four sides of the patch (paper, section 2.7) each in its own
// colour.
//
// Coordinates are written in uv units, in the shortest form that reads back to
// the same double (number_format.h), inside a group whose transform flips the
// y axis (SVG's y points down, v points up). So the `points` of a polygon are
// the exact (u,v) of its corners, and a zoomed viewer shows slivers as they are.
#ifndef DIFFUV_OUTPUT_WRITE_SVG_H
#define DIFFUV_OUTPUT_WRITE_SVG_H

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/core/error.h>
#include <diffuv/io/atomic_file.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/internal/number_format.h>
#include <diffuv/core/four_sides.h>

#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace diffuv {

/// The colours of `write_uv_layout_svg()` (SVG colour strings).
struct Uv_layout_colors {
  static constexpr const char* face = "#dce6f2";       ///< fill of a well-oriented face (light blue-grey)
  static constexpr const char* edge = "#808080";       ///< stroke of every face (grey)
  static constexpr const char* flipped = "#e02020";    ///< fill of a flipped face (red)
  static constexpr const char* degenerate = "#ff9900"; ///< fill and stroke of a degenerate face (orange)
  static constexpr const char* square = "#000000";     ///< the unit square's outline
  /// The sides v1 (v = 0), u2 (u = 1), v2 (v = 1), u1 (u = 0): in the order of `Side`.
  static constexpr std::array<const char*, 4> sides = {"#9467bd", "#2ca02c", "#17becf", "#1f77b4"};
};

namespace internal {

// Twice the signed area of a uv triangle: > 0 counter-clockwise.
inline double twice_signed_uv_area(double ax, double ay, double bx, double by, double cx, double cy)
{
  return (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
}

// How a uv triangle is drawn.
enum class Uv_face_kind { normal, flipped, degenerate };

// A triangle is degenerate when its area is zero up to rounding relative to
// its own size (|2A| <= 1e-12 * longest edge^2), or has a non-finite corner.
// Relative, because charts of very fine meshes have tiny but valid triangles.
inline bool is_degenerate_uv_triangle(double ax, double ay, double bx, double by, double cx, double cy, double area2)
{
  if(!std::isfinite(area2)) return true;
  const double l = (std::max)({(bx - ax) * (bx - ax) + (by - ay) * (by - ay),
                               (cx - bx) * (cx - bx) + (cy - by) * (cy - by),
                               (ax - cx) * (ax - cx) + (ay - cy) * (ay - cy)});
  return std::abs(area2) <= 1e-12 * l;
}

inline void write_svg_number(std::ostream& out, double x)
{
  write_shortest(out, x == 0. ? 0. : x); // no "-0"
}

} // namespace internal

/// Writes the uv triangles of chart `chart` of `atlas` to `out` as an SVG picture.
///
/// The picture shows, in the frame of the unit square (u to the right, v up;
/// the view grows to hold any uv outside it):
/// - one `<polygon>` per face of the chart, in the order of `chart(c).faces`,
///   with a thin grey stroke and a light fill; a face whose signed uv area has
///   the opposite sign to that of most faces of the chart is *flipped* and
///   filled red, a face of (nearly) zero area is *degenerate* and drawn
///   orange (fill and a thicker stroke, since it has no inside); flipped and
///   degenerate faces also carry `class="flipped"` / `class="degenerate"`
///   (colours in `Uv_layout_colors`);
/// - the outline of the unit square;
/// - if `sides` is given, each side as a thick `<polyline>` through the uv of
///   its vertices in this chart, in its own colour, and a legend (`<text>`)
///   naming the sides; vertices of a side that are not in the chart are skipped;
/// - a line of text with the numbers of faces, flipped and degenerate faces.
///
/// Faces with a non-finite uv corner (NaN) are counted as degenerate and
/// their polygon is not written (it would not be valid SVG).
///
/// \tparam TriangleMesh the mesh type of the atlas
/// \tparam Kernel the kernel of the atlas
/// \param out the stream to write to
/// \param atlas the atlas
/// \param chart the index of the chart to draw
/// \param sides if not null, the four sides of the chart's patch (vertices of the mesh)
/// \param size_px the width and height in pixels of the unit square in the picture
/// \throws std::out_of_range if `atlas` has no chart `chart`
/// \throws std::invalid_argument if `size_px` is not positive
template <class TriangleMesh, class Kernel>
void write_uv_layout_svg(std::ostream& out, const Uv_atlas<TriangleMesh, Kernel>& atlas, std::size_t chart,
                         const Four_sides<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>* sides = nullptr,
                         int size_px = 800)
{
  using internal::write_svg_number;
  using Kind = internal::Uv_face_kind;
  if(size_px <= 0)
    throw std::invalid_argument("write_uv_layout_svg: size_px must be positive");
  const auto& c = atlas.chart(chart); // throws std::out_of_range
  const std::size_t nf = c.triangles.size();

  // Signed areas, then the majority orientation (counter-clockwise on a tie):
  // a chart mirrored as a whole has all faces clockwise and none flipped.
  std::vector<double> area2(nf);
  std::vector<Kind> kind(nf, Kind::normal);
  std::size_t positive = 0, negative = 0;
  for(std::size_t f = 0; f < nf; ++f) {
    const auto& t = c.triangles[f];
    const double ax = CGAL::to_double(c.uv[t[0]].x()), ay = CGAL::to_double(c.uv[t[0]].y());
    const double bx = CGAL::to_double(c.uv[t[1]].x()), by = CGAL::to_double(c.uv[t[1]].y());
    const double cx = CGAL::to_double(c.uv[t[2]].x()), cy = CGAL::to_double(c.uv[t[2]].y());
    area2[f] = internal::twice_signed_uv_area(ax, ay, bx, by, cx, cy);
    if(internal::is_degenerate_uv_triangle(ax, ay, bx, by, cx, cy, area2[f])) kind[f] = Kind::degenerate;
    else if(area2[f] > 0.) ++positive;
    else ++negative;
  }
  const double majority = negative > positive ? -1. : 1.;
  std::size_t flipped = 0, degenerate = 0;
  for(std::size_t f = 0; f < nf; ++f) {
    if(kind[f] == Kind::degenerate) ++degenerate;
    else if(area2[f] * majority < 0.) { kind[f] = Kind::flipped; ++flipped; }
  }

  // The frame: the unit square, grown to hold every finite uv.
  double umin = 0., umax = 1., vmin = 0., vmax = 1.;
  for(const auto& p : c.uv) {
    const double u = CGAL::to_double(p.x()), v = CGAL::to_double(p.y());
    if(!std::isfinite(u) || !std::isfinite(v)) continue;
    umin = (std::min)(umin, u); umax = (std::max)(umax, u);
    vmin = (std::min)(vmin, v); vmax = (std::max)(vmax, v);
  }
  // Sizes in uv units: the unit square is size_px pixels wide.
  const double px = 1. / size_px;
  const double margin = 0.04;
  const double font = 0.028;
  const double legend = sides ? 2.6 * font : 1.4 * font; // room for the text lines below the square
  // In the y-down picture, uv (u,v) is at (u, 1 - v).
  const double x0 = umin - margin, y0 = 1. - vmax - margin;
  const double w = umax - umin + 2 * margin, h = vmax - vmin + 2 * margin + legend;

  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << std::lround(w * size_px)
      << "\" height=\"" << std::lround(h * size_px) << "\" viewBox=\"";
  write_svg_number(out, x0); out << ' ';
  write_svg_number(out, y0); out << ' ';
  write_svg_number(out, w); out << ' ';
  write_svg_number(out, h);
  out << "\">\n<title>uv layout of chart " << chart << "</title>\n";
  out << "<rect x=\""; write_svg_number(out, x0);
  out << "\" y=\""; write_svg_number(out, y0);
  out << "\" width=\""; write_svg_number(out, w);
  out << "\" height=\""; write_svg_number(out, h);
  out << "\" fill=\"#ffffff\"/>\n";

  // Everything in uv: flip y so that v goes up.
  out << "<g transform=\"matrix(1 0 0 -1 0 1)\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
  out << "<g id=\"faces\" fill=\"" << Uv_layout_colors::face << "\" stroke=\"" << Uv_layout_colors::edge
      << "\" stroke-width=\"";
  write_svg_number(out, 0.5 * px);
  out << "\">\n";
  for(std::size_t f = 0; f < nf; ++f) {
    const auto& t = c.triangles[f];
    bool finite = true;
    for(int k = 0; k < 3; ++k)
      finite = finite && std::isfinite(CGAL::to_double(c.uv[t[k]].x())) && std::isfinite(CGAL::to_double(c.uv[t[k]].y()));
    if(!finite) continue;
    out << "<polygon";
    if(kind[f] == Kind::flipped)
      out << " class=\"flipped\" fill=\"" << Uv_layout_colors::flipped << '"';
    else if(kind[f] == Kind::degenerate) {
      out << " class=\"degenerate\" fill=\"" << Uv_layout_colors::degenerate << "\" stroke=\""
          << Uv_layout_colors::degenerate << "\" stroke-width=\"";
      write_svg_number(out, 2 * px);
      out << '"';
    }
    out << " points=\"";
    for(int k = 0; k < 3; ++k) {
      if(k) out << ' ';
      write_svg_number(out, CGAL::to_double(c.uv[t[k]].x()));
      out << ',';
      write_svg_number(out, CGAL::to_double(c.uv[t[k]].y()));
    }
    out << "\"/>\n";
  }
  out << "</g>\n";

  out << "<rect id=\"unit_square\" x=\"0\" y=\"0\" width=\"1\" height=\"1\" fill=\"none\" stroke=\""
      << Uv_layout_colors::square << "\" stroke-width=\"";
  write_svg_number(out, 1.5 * px);
  out << "\"/>\n";

  if(sides) {
    const auto uv_map = atlas.chart_uv_map(chart);
    out << "<g id=\"sides\" fill=\"none\" stroke-width=\"";
    write_svg_number(out, 4 * px);
    out << "\" stroke-opacity=\"0.85\">\n";
    for(Side s : all_sides) {
      out << "<polyline class=\"side_" << side_name(s) << "\" stroke=\"" << Uv_layout_colors::sides[static_cast<std::size_t>(s)]
          << "\" points=\"";
      bool first = true;
      for(const auto& v : (*sides)[s]) {
        const auto p = get(uv_map, v);
        const double u = CGAL::to_double(p.x()), vv = CGAL::to_double(p.y());
        if(!std::isfinite(u) || !std::isfinite(vv)) continue; // not in this chart
        if(!first) out << ' ';
        first = false;
        write_svg_number(out, u);
        out << ',';
        write_svg_number(out, vv);
      }
      out << "\"/>\n";
    }
    out << "</g>\n";
  }
  out << "</g>\n";

  // Text below the square (y-down picture coordinates).
  const double text_x = umin;
  double text_y = 1. - vmin + margin + font;
  out << "<g font-family=\"sans-serif\" font-size=\"";
  write_svg_number(out, font);
  out << "\">\n";
  out << "<text x=\""; write_svg_number(out, text_x);
  out << "\" y=\""; write_svg_number(out, text_y);
  out << "\" fill=\"#000000\">chart " << chart << ": " << internal::count_text(nf, "face") << ", " << flipped << " flipped, "
      << degenerate << " degenerate</text>\n";
  if(sides) {
    text_y += 1.2 * font;
    static const char* const side_labels[4] = {"v1 (v = 0)", "u2 (u = 1)", "v2 (v = 1)", "u1 (u = 0)"};
    for(int s = 0; s < 4; ++s) {
      out << "<text x=\"";
      write_svg_number(out, text_x + s * 0.25 * (umax - umin));
      out << "\" y=\"";
      write_svg_number(out, text_y);
      out << "\" fill=\"" << Uv_layout_colors::sides[s] << "\">" << side_labels[s] << "</text>\n";
    }
  }
  out << "</g>\n</svg>\n";
}

/// Same as above, into the file `path`, through `Atomic_output_file`: on
/// error, an existing file at `path` is left as it was.
/// \throws Output_error naming `path` if the file cannot be created or written
///         (for instance, its folder does not exist)
/// \throws std::out_of_range, std::invalid_argument as above (nothing is written)
template <class TriangleMesh, class Kernel>
void write_uv_layout_svg(const std::string& path, const Uv_atlas<TriangleMesh, Kernel>& atlas, std::size_t chart,
                         const Four_sides<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>* sides = nullptr,
                         int size_px = 800)
{
  Atomic_output_file file(path);
  write_uv_layout_svg(file.stream(), atlas, chart, sides, size_px);
  file.commit();
}

} // namespace diffuv

#endif // DIFFUV_OUTPUT_WRITE_SVG_H
