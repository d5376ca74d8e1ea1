// diffuv: a picture of an atlas in its texture: every chart's triangles
// drawn where the texture coordinates put them, in the chart's colour, with
// the isolines of the charts' own (u,v). It shows how the charts are packed
// (and what a painter of the texture would see).
#ifndef DIFFUV_RENDER_TEXTURE_LAYOUT_H
#define DIFFUV_RENDER_TEXTURE_LAYOUT_H

#include <diffuv/render/render_mesh.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace diffuv {

/// How `render_texture_layout()` draws.
struct Texture_layout_options {
  int size = 1024;                     ///< the picture's width and height in pixels: one pixel per texel at the texture's size
  int isolines = 8;                    ///< lines u = k / isolines and v = k / isolines of each chart's own (u,v) (0: none)
  Color background{70, 70, 70};        ///< texels in no chart
  Color u_line_color{10, 40, 130};
  Color v_line_color{130, 20, 20};
};

/// Draws the faces of `tm` at their per-corner texture coordinates
/// (`corner_texture`: halfedge -> 2D point in [0,1]^2, v up; the image's
/// top row is v = 1), each filled with `face_color(f)`, and the isolines of
/// `corner_uv` (halfedge -> the chart's own (u,v)) one pixel wide. Faces with
/// a corner whose texture point or uv is not finite are skipped (or drawn
/// without lines).
/// \throws std::invalid_argument if `options.size` is not positive or
///         `options.isolines` is negative
template <class TriangleMesh, class TextureMap, class FaceColor, class CornerUvMap>
Image render_texture_layout(const TriangleMesh& tm, TextureMap corner_texture, FaceColor face_color, CornerUvMap corner_uv,
                            const Texture_layout_options& options = Texture_layout_options())
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  if(options.size <= 0) throw std::invalid_argument("render_texture_layout: the size must be positive");
  if(options.isolines < 0) throw std::invalid_argument("render_texture_layout: isolines must not be negative");
  const int S = options.size, N = options.isolines;
  Image image(S, S, options.background);
  std::vector<halfedge_descriptor> corners;
  for(face_descriptor f : faces(tm)) {
    corners.clear();
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) corners.push_back(h);
    const Color base = face_color(f);
    for(std::size_t k = 1; k + 1 < corners.size(); ++k) {
      const halfedge_descriptor hs[3] = {corners[0], corners[k], corners[k + 1]};
      double x[3], y[3], u[3], v[3];
      bool drawn = true, lines = N > 0;
      for(int i = 0; i < 3; ++i) {
        const auto t = get(corner_texture, hs[i]);
        x[i] = CGAL::to_double(t.x()) * S;
        y[i] = (1. - CGAL::to_double(t.y())) * S;  // image rows go down
        const auto q = get(corner_uv, hs[i]);
        u[i] = CGAL::to_double(q.x());
        v[i] = CGAL::to_double(q.y());
        drawn = drawn && std::isfinite(x[i]) && std::isfinite(y[i]);
        lines = lines && std::isfinite(u[i]) && std::isfinite(v[i]);
      }
      if(!drawn) continue;
      const double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
      if(!(std::abs(area) > 1e-12)) continue;
      double grad_u = 0., grad_v = 0.;
      if(lines) {
        grad_u = internal::gradient_length(x, y, u, area);
        grad_v = internal::gradient_length(x, y, v, area);
      }
      internal::for_each_pixel_in_triangle(x, y, area, S, S, 1e-9, [&](int px, int py, double w0, double w1, double w2) {
        Color c = base;
        if(lines) {
          const double du = internal::isoline_pixel_distance(w0 * u[0] + w1 * u[1] + w2 * u[2], N, grad_u);
          const double dv = internal::isoline_pixel_distance(w0 * v[0] + w1 * v[1] + w2 * v[2], N, grad_v);
          if(du <= 0.5 || dv <= 0.5) c = du <= dv ? options.u_line_color : options.v_line_color;
        }
        image.set(px, py, c);
      });
    }
  }
  return image;
}

} // namespace diffuv

#endif // DIFFUV_RENDER_TEXTURE_LAYOUT_H
