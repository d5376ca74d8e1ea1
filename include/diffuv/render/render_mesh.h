// diffuv: pictures of a mesh and its uv-map, without a GPU or a window system.
//
// `render_mesh()` rasterises a triangle mesh into an RGB `Image` with an
// orthographic camera, a z-buffer, flat per-face colours under a headlight,
// and the isolines of the (u,v) of each face corner (a checkerboard of lines
// every 1/N in u and in v: the usual way to look at a parameterization).
// `write_png()` saves the image (through stb_image_write and an
// `Atomic_output_file`). `patch_color()`, `heat_color()` and
// `draw_color_bar()` colour patches and scalar fields (distortion, distance).
//
// Camera conventions (a right-handed frame, +y up):
//   front: from +z looking towards -z, +x to the right, +y up
//   back:  from -z looking towards +z (+x to the left)
//   right: from +x looking towards -x (-z to the right)
//   left:  from -x looking towards +x (+z to the right)
//   top:   from +y looking down, +x to the right, -z up in the image
//   iso:   azimuth 45, elevation 30
// With `use_angles`, the camera sits in the direction
// (cos(e) sin(a), sin(e), cos(e) cos(a)) from the mesh (a = azimuth, e =
// elevation, in degrees): azimuth 0 elevation 0 is `front`, azimuth 90 is
// `right`, elevation 90 is `top`.
// A mesh modelled with another axis up (`Render_options::up`: z for man,
// hand and most scans, as in Blender) is first turned so that this axis
// points up: z up is seen as (x, z, -y), so that `front` looks from -y along
// +y, as Blender's front view does; x up as (-y, x, z). `guess_up_axis()`
// guesses the axis from the mesh's extent.
#ifndef DIFFUV_RENDER_RENDER_MESH_H
#define DIFFUV_RENDER_RENDER_MESH_H

#include <diffuv/core/color.h>
#include <diffuv/core/error.h>
#include <diffuv/io/atomic_file.h>
#include <diffuv/render/texture.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

// stb_image_write, compiled once per translation unit with static linkage so
// that several translation units (or a user's own copy of stb) do not clash.
// A translation unit that defines STB_IMAGE_WRITE_IMPLEMENTATION itself for a
// non-static copy must not also include this header.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb/stb_easy_font.h> // all static: quads for a few characters of text
#pragma GCC diagnostic pop

namespace diffuv {

/// An RGB image: `width * height * 3` bytes in `rgb`, row-major, top row
/// first, channels in the order r, g, b. Pixel (0, 0) is the top-left one.
struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;

  Image() = default;
  /// Makes a `width` x `height` image filled with `fill`.
  /// \throws std::invalid_argument if a size is negative
  Image(int w, int h, Color fill = {255, 255, 255}) : width(w), height(h)
  {
    if(w < 0 || h < 0) throw std::invalid_argument("diffuv::Image: negative size");
    rgb.resize(std::size_t(w) * std::size_t(h) * 3);
    for(std::size_t i = 0; i < rgb.size(); i += 3) { rgb[i] = fill.r; rgb[i + 1] = fill.g; rgb[i + 2] = fill.b; }
  }

  /// Returns whether (x, y) is a pixel of the image.
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }

  /// Returns the colour of pixel (x, y). \throws std::out_of_range outside the image
  Color at(int x, int y) const
  {
    if(!contains(x, y)) throw std::out_of_range("diffuv::Image::at: pixel outside the image");
    const std::size_t i = offset(x, y);
    return Color{rgb[i], rgb[i + 1], rgb[i + 2]};
  }

  /// Sets the colour of pixel (x, y). \throws std::out_of_range outside the image
  void set(int x, int y, Color c)
  {
    if(!contains(x, y)) throw std::out_of_range("diffuv::Image::set: pixel outside the image");
    const std::size_t i = offset(x, y);
    rgb[i] = c.r; rgb[i + 1] = c.g; rgb[i + 2] = c.b;
  }

private:
  std::size_t offset(int x, int y) const { return (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3; }
};

/// A colour with channels in [0,1] (a texture's sample, a baking sampler's value).
using Rgb = std::array<double, 3>;

/// The colour `c` as an `Rgb`.
inline Rgb to_rgb(const Color& c) { return Rgb{c.r / 255., c.g / 255., c.b / 255.}; }

/// The colour of `image` at texture point (s, t) (v up, as texture
/// coordinates), filtered bilinearly between the four nearest texel centres
/// as a GPU does (clamped to the edge): what a renderer shows there.
inline Rgb sample_bilinear(const Image& image, double s, double t)
{
  if(image.width <= 0 || image.height <= 0) throw std::invalid_argument("sample_bilinear: empty image");
  const double x = s * image.width - 0.5, y = (1. - t) * image.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  auto clamp = [](double i, int n) { return static_cast<int>((std::min)((std::max)(i, 0.), double(n - 1))); };
  const int xs[2] = {clamp(fx, image.width), clamp(fx + 1., image.width)};
  const int ys[2] = {clamp(fy, image.height), clamp(fy + 1., image.height)};
  Rgb c{0., 0., 0.};
  for(int j = 0; j < 2; ++j)
    for(int i = 0; i < 2; ++i) {
      const double weight = (i ? ax : 1. - ax) * (j ? ay : 1. - ay);
      const std::size_t at = 3 * (std::size_t(ys[j]) * std::size_t(image.width) + std::size_t(xs[i]));
      for(int k = 0; k < 3; ++k) c[std::size_t(k)] += weight * image.rgb[at + std::size_t(k)] / 255.;
    }
  return c;
}

/// The standard camera directions (see the conventions at the top of this header).
enum class View { front, back, left, right, top, iso };

/// Which axis of the mesh points up in the picture.
enum class Up_axis { y, z, x };

/// How `render_mesh()` draws.
struct Render_options {
  Up_axis up = Up_axis::y;            ///< the mesh's up axis (see the conventions at the top of this header)
  int width = 800, height = 600;      ///< image size in pixels (both > 0)
  View view = View::iso;              ///< the camera, unless `use_angles`
  bool use_angles = false;            ///< use `azimuth` and `elevation` instead of `view`
  double azimuth = 30, elevation = 20;///< degrees, see the conventions at the top of this header
  Color background{255, 255, 255};
  int isolines = 10;                  ///< u and v isolines every 1/isolines (0: none)
  double line_width = 1.0;            ///< isoline width in pixels (approximately)
  Color u_line_color{10, 40, 130};     ///< colour of the lines u = k / isolines (dark blue)
  Color v_line_color{130, 20, 20};     ///< colour of the lines v = k / isolines (dark red)
  /// Isolines closer together than this on the screen (pixels) are not drawn
  /// on that triangle: on a chart a few pixels wide they would paint it over
  /// (0: always drawn). For pictures whose face colour is the message.
  double min_line_spacing = 0.;
  double margin = 0.05;               ///< fraction of the width and height left empty on each side
  double ambient = 0.25;              ///< shade of a face seen edge-on; a face facing the camera gets its full colour
  /// If set, faces take this texture's colour (`sample_bilinear()`) at the
  /// corners' (u,v), read as texture coordinates, instead of `face_color`
  /// and isolines; faces with no (u,v) keep `face_color`. Must outlive the call.
  const Image* texture = nullptr;
};

/// A guess at a mesh's up axis from its extent: z when the mesh is much
/// taller along z than deep along y (more than `ratio` times: a standing
/// figure modelled z-up, as man.off at 3.4), else y, the convention of most
/// meshes. The ratio is high because animals modelled y-up often lie long
/// along z (pig.off: z 2.1 times y, camel 1.0, lion 1.05); a z-up mesh that
/// is not that tall (hand.off: 1.25) needs its axis given.
/// \returns `Up_axis::y` for an empty mesh
template <class TriangleMesh, class VertexPointMap>
Up_axis guess_up_axis(const TriangleMesh& tm, VertexPointMap vpm, double ratio = 2.5)
{
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for(auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    const double yz[2] = {CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for(int k = 0; k < 2; ++k) {
      lo[k] = (std::min)(lo[k], yz[k]);
      hi[k] = (std::max)(hi[k], yz[k]);
    }
  }
  return hi[1] - lo[1] > ratio * (hi[0] - lo[0]) ? Up_axis::z : Up_axis::y;
}

namespace internal {

struct Vec3 {
  double x, y, z;
};
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// The orthonormal camera frame: `right` and `up` span the image, `toward`
/// points from the mesh to the camera (a larger dot product is nearer).
struct Camera_frame {
  Vec3 right, up, toward;
};

inline Camera_frame camera_frame(const Render_options& o)
{
  double az = o.azimuth, el = o.elevation;
  if(!o.use_angles) {
    switch(o.view) {
      case View::front: az = 0; el = 0; break;
      case View::back: az = 180; el = 0; break;
      case View::left: az = -90; el = 0; break;
      case View::right: az = 90; el = 0; break;
      case View::top: az = 0; el = 90; break;
      case View::iso: az = 45; el = 30; break;
    }
  }
  const double deg = 3.14159265358979323846 / 180.;
  const double a = az * deg, e = el * deg;
  Camera_frame f;
  f.toward = {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
  // `right` stays horizontal, which also keeps it defined when looking straight down.
  f.right = {std::cos(a), 0., -std::sin(a)};
  f.up = cross(f.toward, f.right);
  return f;
}

inline unsigned char to_byte(double c)
{
  return static_cast<unsigned char>(std::lround(std::clamp(c, 0., 255.)));
}

/// A corner uv map that has no uv: every corner gets (NaN, NaN), so no isoline.
template <class HalfedgeDescriptor>
struct No_corner_uv_map {
  struct Uv {
    double u, v;
    double x() const { return u; }
    double y() const { return v; }
  };
  using key_type = HalfedgeDescriptor;
  using value_type = Uv;
  using reference = Uv;
  using category = boost::readable_property_map_tag;
  friend Uv get(const No_corner_uv_map&, const HalfedgeDescriptor&)
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return Uv{nan, nan};
  }
};

/// The length of the image-space gradient of a value `t` given at a
/// triangle's three corners (x, y in pixels; `twice_area` the signed doubled
/// area of the triangle in pixels): units of t per pixel.
inline double gradient_length(const double* x, const double* y, const double* t, double twice_area)
{
  const double d1x = x[1] - x[0], d1y = y[1] - y[0], d2x = x[2] - x[0], d2y = y[2] - y[0];
  const double dt1 = t[1] - t[0], dt2 = t[2] - t[0];
  const double gx = (dt1 * d2y - dt2 * d1y) / twice_area, gy = (dt2 * d1x - dt1 * d2x) / twice_area;
  return std::sqrt(gx * gx + gy * gy);
}

/// Distance in pixels from the value `t` (u or v) to the nearest isoline
/// k / n, given the length of the screen gradient of t in units per pixel.
inline double isoline_pixel_distance(double t, int n, double gradient_length)
{
  const double s = t * n;
  const double d = std::abs(s - std::round(s)) / n; // in u (or v) units
  if(!(gradient_length > 0.)) return d == 0. ? 0. : std::numeric_limits<double>::infinity();
  return d / gradient_length;
}

/// Calls `visit(px, py, w0, w1, w2)` for every pixel of a `width` x `height`
/// image whose centre (px + 0.5, py + 0.5) lies in the triangle (x[i], y[i])
/// (pixel units, either orientation, `twice_area` its signed doubled area,
/// not zero), with the centre's barycentric weights; a centre on an edge
/// (within `eps` of it, in weight) counts as inside.
template <class Visit>
void for_each_pixel_in_triangle(const double* x, const double* y, double twice_area, int width, int height,
                                double eps, Visit visit)
{
  const int x0 = (std::max)(0, int(std::floor((std::min)({x[0], x[1], x[2]}) - 0.5)));
  const int x1 = (std::min)(width - 1, int(std::ceil((std::max)({x[0], x[1], x[2]}) - 0.5)));
  const int y0 = (std::max)(0, int(std::floor((std::min)({y[0], y[1], y[2]}) - 0.5)));
  const int y1 = (std::min)(height - 1, int(std::ceil((std::max)({y[0], y[1], y[2]}) - 0.5)));
  for(int py = y0; py <= y1; ++py)
    for(int px = x0; px <= x1; ++px) {
      const double qx = px + 0.5, qy = py + 0.5;
      const double w0 = ((x[1] - qx) * (y[2] - qy) - (x[2] - qx) * (y[1] - qy)) / twice_area;
      const double w1 = ((x[2] - qx) * (y[0] - qy) - (x[0] - qx) * (y[2] - qy)) / twice_area;
      const double w2 = 1. - w0 - w1;
      if(w0 < -eps || w1 < -eps || w2 < -eps) continue;
      visit(px, py, w0, w1, w2);
    }
}

} // namespace internal

/// Renders `tm` seen from the camera of `options` into a new image.
///
/// Each face is filled with `face_color(f)` times a two-sided Lambert shade
/// from a headlight (`ambient + (1 - ambient) |cos|` of the angle between the
/// face normal and the view direction); a z-buffer keeps the nearest face.
/// The orthographic camera is fitted to the bounding box of the mesh as seen
/// in the view (its extent along the image axes), centred, with
/// `options.margin` left free on each side, the same scale along both axes.
/// Where the corners of a face have a (u,v), the lines u = k / N and
/// v = k / N (N = `options.isolines`) are drawn about `options.line_width`
/// pixels wide, whatever the zoom: the distance of a pixel to a line is
/// measured with the screen-space gradient of u (or v) over the triangle.
/// Faces with more than three corners are drawn as fans.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexPointMap a readable property map, vertex_descriptor -> a CGAL `Point_3`
/// \tparam FaceColor a callable face_descriptor -> `Color`
/// \tparam CornerUvMap a readable property map, halfedge_descriptor -> a point with
///         `x()` (u) and `y()` (v) giving the (u,v) of `target(h)` in `face(h)`, such as
///         `Uv_atlas::corner_uv_map()`; a NaN on any corner of a face means no isolines there
/// \param options image size, camera, isolines
/// \returns the image, `options.width` x `options.height`
/// \throws std::invalid_argument if the image size is not positive or `options.isolines` is negative
template <class TriangleMesh, class VertexPointMap, class FaceColor, class CornerUvMap>
Image render_mesh(const TriangleMesh& tm, VertexPointMap vpm, FaceColor face_color, CornerUvMap corner_uv,
                  const Render_options& options = {})
{
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  static_assert(std::is_invocable_r_v<Color, FaceColor&, face_descriptor>,
                "render_mesh: face_color must be callable as face_color(face_descriptor) -> diffuv::Color");
  using internal::Vec3;

  if(options.width <= 0 || options.height <= 0)
    throw std::invalid_argument("render_mesh: the image size must be positive");
  if(options.isolines < 0)
    throw std::invalid_argument("render_mesh: options.isolines must not be negative");

  const int W = options.width, H = options.height;
  Image image(W, H, options.background);
  const internal::Camera_frame cam = internal::camera_frame(options);

  auto point_of = [&](vertex_descriptor v) {
    const auto& p = get(vpm, v);
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    // Turned so that the mesh's up axis is +y (rotations: the faces keep their turn).
    switch(options.up) {
      case Up_axis::z: return Vec3{x, z, -y};
      case Up_axis::x: return Vec3{-y, x, z};
      default: return Vec3{x, y, z};
    }
  };

  // Fit: the extent of the mesh along the image axes.
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  for(vertex_descriptor v : vertices(tm)) {
    const Vec3 p = point_of(v);
    const double sx = internal::dot(p, cam.right), sy = internal::dot(p, cam.up);
    xmin = (std::min)(xmin, sx); xmax = (std::max)(xmax, sx);
    ymin = (std::min)(ymin, sy); ymax = (std::max)(ymax, sy);
  }
  if(!(xmin <= xmax)) return image; // no vertex
  const double margin = std::clamp(options.margin, 0., 0.45);
  const double avail_x = W * (1. - 2. * margin), avail_y = H * (1. - 2. * margin);
  const double ex = xmax - xmin, ey = ymax - ymin;
  double scale = 1.;
  if(ex > 0. && ey > 0.) scale = (std::min)(avail_x / ex, avail_y / ey);
  else if(ex > 0.) scale = avail_x / ex;
  else if(ey > 0.) scale = avail_y / ey;
  const double cx = 0.5 * (xmin + xmax), cy = 0.5 * (ymin + ymax);
  // Pixel (i, j) covers [i, i+1) x [j, j+1); its centre is (i + 0.5, j + 0.5). Image y goes down.
  auto project = [&](const Vec3& p) {
    return Vec3{0.5 * W + (internal::dot(p, cam.right) - cx) * scale,
                0.5 * H - (internal::dot(p, cam.up) - cy) * scale,
                internal::dot(p, cam.toward)};
  };

  std::vector<double> depth(std::size_t(W) * std::size_t(H), -std::numeric_limits<double>::infinity());
  const int N = options.isolines;
  // A tiny tolerance: a 1-pixel line centred on a pixel boundary (as u = 1/2 on an
  // even width) would otherwise hit or miss the two columns by rounding alone.
  const double half_width = 0.5 * options.line_width + 1e-6;
  const double ambient = std::clamp(options.ambient, 0., 1.);

  std::vector<halfedge_descriptor> corners;
  for(face_descriptor f : faces(tm)) {
    corners.clear();
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) corners.push_back(h);
    if(corners.size() < 3) continue;
    const Color base = face_color(f);

    for(std::size_t k = 1; k + 1 < corners.size(); ++k) {
      const halfedge_descriptor hs[3] = {corners[0], corners[k], corners[k + 1]};
      Vec3 p3[3], s[3];
      double u[3], v[3];
      bool has_uv = N > 0 || options.texture;
      for(int i = 0; i < 3; ++i) {
        p3[i] = point_of(target(hs[i], tm));
        s[i] = project(p3[i]);
        const auto uv = get(corner_uv, hs[i]);
        u[i] = CGAL::to_double(uv.x());
        v[i] = CGAL::to_double(uv.y());
        if(!std::isfinite(u[i]) || !std::isfinite(v[i])) has_uv = false;
      }
      // Signed doubled area in pixels; an edge-on triangle covers no pixel centre.
      const double area = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[2].x - s[0].x) * (s[1].y - s[0].y);
      if(!(std::abs(area) > 1e-12)) continue;

      // Two-sided headlight: |cos| between the face normal and the view direction.
      const Vec3 n = internal::cross(p3[1] - p3[0], p3[2] - p3[0]);
      const double nn = std::sqrt(internal::dot(n, n));
      const double cosine = nn > 0. ? std::abs(internal::dot(n, cam.toward)) / nn : 0.;
      const double shade = ambient + (1. - ambient) * cosine;
      const Color shaded{internal::to_byte(base.r * shade), internal::to_byte(base.g * shade),
                        internal::to_byte(base.b * shade)};

      // Screen gradients of u and v (units per pixel), for line widths in pixels.
      double grad_u = 0., grad_v = 0.;
      if(has_uv) {
        const double sx[3] = {s[0].x, s[1].x, s[2].x}, sy[3] = {s[0].y, s[1].y, s[2].y};
        grad_u = internal::gradient_length(sx, sy, u, area);
        grad_v = internal::gradient_length(sx, sy, v, area);
      }

      const double sx[3] = {s[0].x, s[1].x, s[2].x}, sy[3] = {s[0].y, s[1].y, s[2].y};
      internal::for_each_pixel_in_triangle(sx, sy, area, W, H, 1e-9, [&](int px, int py, double w0, double w1, double w2) {
        const double z = w0 * s[0].z + w1 * s[1].z + w2 * s[2].z;
        double& zb = depth[std::size_t(py) * std::size_t(W) + std::size_t(px)];
        if(!(z > zb)) return;
        zb = z;
        Color c = shaded;
        if(has_uv && options.texture) {
          const Rgb t = sample_bilinear(*options.texture, w0 * u[0] + w1 * u[1] + w2 * u[2],
                                        w0 * v[0] + w1 * v[1] + w2 * v[2]);
          c = Color{internal::to_byte(255. * t[0] * shade), internal::to_byte(255. * t[1] * shade),
                    internal::to_byte(255. * t[2] * shade)};
        } else if(has_uv) {
          const double du = internal::isoline_pixel_distance(w0 * u[0] + w1 * u[1] + w2 * u[2], N, grad_u);
          const double dv = internal::isoline_pixel_distance(w0 * v[0] + w1 * v[1] + w2 * v[2], N, grad_v);
          const bool u_lines = du <= half_width && !(options.min_line_spacing * N * grad_u > 1.);
          const bool v_lines = dv <= half_width && !(options.min_line_spacing * N * grad_v > 1.);
          if(u_lines && (!v_lines || du <= dv)) c = options.u_line_color;
          else if(v_lines) c = options.v_line_color;
        }
        image.set(px, py, c);
      });
    }
  }
  return image;
}

/// Renders `tm` as `render_mesh(tm, vpm, face_color, corner_uv, options)` with no uv (no isolines).
template <class TriangleMesh, class VertexPointMap, class FaceColor>
Image render_mesh(const TriangleMesh& tm, VertexPointMap vpm, FaceColor face_color, const Render_options& options = {})
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  return render_mesh(tm, vpm, face_color, internal::No_corner_uv_map<halfedge_descriptor>{}, options);
}

/// Returns the colour of patch `patch`: a fixed palette of 12 light, distinct
/// colours (isolines stay readable on them), then golden-ratio hues for larger indices.
inline Color patch_color(std::size_t patch)
{
  static const Color palette[12] = {
    {141, 211, 199}, {255, 237, 111}, {190, 186, 218}, {251, 128, 114}, {128, 177, 211}, {253, 180, 98},
    {179, 222, 105}, {252, 205, 229}, {188, 128, 189}, {204, 235, 197}, {217, 217, 217}, {255, 179, 71}};
  if(patch < 12) return palette[patch];
  // HSV with hue stepping by the golden ratio, saturation and value cycling.
  const double h = std::fmod(0.1 + double(patch) * 0.6180339887498949, 1.) * 6.;
  const double sat = 0.35 + 0.15 * double(patch % 3), val = 0.95 - 0.1 * double((patch / 3) % 3);
  const int i = int(h) % 6;
  const double fr = h - std::floor(h);
  const double p = val * (1 - sat), q = val * (1 - sat * fr), t = val * (1 - sat * (1 - fr));
  double r = 0, g = 0, b = 0;
  switch(i) {
    case 0: r = val; g = t; b = p; break;
    case 1: r = q; g = val; b = p; break;
    case 2: r = p; g = val; b = t; break;
    case 3: r = p; g = q; b = val; break;
    case 4: r = t; g = p; b = val; break;
    default: r = val; g = p; b = q; break;
  }
  return Color{internal::to_byte(255 * r), internal::to_byte(255 * g), internal::to_byte(255 * b)};
}

/// Returns the colour of `t` on a viridis ramp (nine stops of matplotlib's
/// viridis, linearly interpolated): dark purple at 0, yellow at 1. The green
/// channel increases strictly with `t`. `t` is clamped to [0, 1]; NaN gives grey (128, 128, 128).
inline Color heat_color(double t)
{
  static const double stops[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},  {44, 113, 142}, {33, 144, 141},
                                     {39, 173, 129}, {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  if(std::isnan(t)) return Color{128, 128, 128};
  const double x = std::clamp(t, 0., 1.) * 8.;
  const int i = (std::min)(int(x), 7);
  const double f = x - i;
  return Color{internal::to_byte(stops[i][0] + f * (stops[i + 1][0] - stops[i][0])),
              internal::to_byte(stops[i][1] + f * (stops[i + 1][1] - stops[i][1])),
              internal::to_byte(stops[i][2] + f * (stops[i + 1][2] - stops[i][2]))};
}

namespace internal {

/// Draws `text` (printable ASCII) with stb_easy_font, its top-left corner at
/// (x, y), each font unit `zoom` pixels; pixels outside the image are skipped.
inline void draw_text(Image& image, int x, int y, const std::string& text, Color color, int zoom = 1)
{
  std::vector<char> chars;
  for(char ch : text) chars.push_back(ch >= 32 && ch < 127 ? ch : '?');
  chars.push_back('\0');
  std::vector<float> buffer(chars.size() * 300); // 16 bytes per vertex, 4 vertices per quad
  const int quads = stb_easy_font_print(0.f, 0.f, chars.data(), nullptr, buffer.data(),
                                        int(buffer.size() * sizeof(float)));
  for(int q = 0; q < quads; ++q) {
    const float* v = &buffer[std::size_t(q) * 16]; // x, y, z, colour: 4 floats per vertex
    const float qx0 = (std::min)(v[0], v[8]), qx1 = (std::max)(v[0], v[8]);
    const float qy0 = (std::min)(v[1], v[9]), qy1 = (std::max)(v[1], v[9]);
    for(int py = y + int(std::lround(qy0 * zoom)); py < y + int(std::lround(qy1 * zoom)); ++py)
      for(int px = x + int(std::lround(qx0 * zoom)); px < x + int(std::lround(qx1 * zoom)); ++px)
        if(image.contains(px, py)) image.set(px, py, color);
  }
}

inline int text_width(const std::string& text)
{
  std::vector<char> chars;
  for(char ch : text) chars.push_back(ch >= 32 && ch < 127 ? ch : '?');
  chars.push_back('\0');
  return stb_easy_font_width(chars.data());
}

inline std::string format_value(double value)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

} // namespace internal

/// Draws a vertical `heat_color()` ramp at the right edge of `image`
/// (`max_value` at the top, `min_value` at the bottom, black frame), the two
/// values written to its left and `label` above it.
/// Parts that do not fit in a small image are clipped.
inline void draw_color_bar(Image& image, double min_value, double max_value, const std::string& label = "")
{
  const int W = image.width, H = image.height;
  if(W <= 0 || H <= 0) return;
  const int bar_width = (std::max)(6, W / 40);
  const int gap = (std::max)(4, W / 100);
  const int bx1 = W - gap, bx0 = bx1 - bar_width;   // columns [bx0, bx1)
  const int by0 = int(H * 0.15), by1 = int(H * 0.85); // rows [by0, by1)
  const Color black{0, 0, 0};
  for(int y = by0; y < by1; ++y) {
    const double t = by1 - by0 > 1 ? double(by1 - 1 - y) / double(by1 - by0 - 1) : 0.5;
    for(int x = bx0; x < bx1; ++x)
      if(image.contains(x, y)) image.set(x, y, heat_color(t));
  }
  for(int x = bx0 - 1; x <= bx1; ++x)
    for(int y : {by0 - 1, by1})
      if(image.contains(x, y)) image.set(x, y, black);
  for(int y = by0 - 1; y <= by1; ++y)
    for(int x : {bx0 - 1, bx1})
      if(image.contains(x, y)) image.set(x, y, black);

  const int zoom = H >= 400 ? 2 : 1;
  const int text_height = 7 * zoom;
  const std::string top = internal::format_value(max_value), bottom = internal::format_value(min_value);
  internal::draw_text(image, bx0 - 4 - internal::text_width(top) * zoom, by0, top, black, zoom);
  internal::draw_text(image, bx0 - 4 - internal::text_width(bottom) * zoom, by1 - text_height, bottom, black, zoom);
  if(!label.empty())
    internal::draw_text(image, (std::min)(bx0, W - gap - internal::text_width(label) * zoom),
                        by0 - 6 - text_height, label, black, zoom);
}

/// Writes `image` as a PNG file at `path`, through a temporary file renamed
/// onto `path` once complete (see `Atomic_output_file`).
/// \throws Output_error naming `path` if the image is empty, the folder does
///         not exist or is not writable, or writing fails
/// Writes `image` as PNG to `out`; `name` names the output in errors.
/// \throws Output_error if the image is empty or malformed, or encoding fails
inline void write_png(std::ostream& out, const Image& image, const std::string& name = "the PNG output")
{
  if(image.width <= 0 || image.height <= 0 ||
     image.rgb.size() != std::size_t(image.width) * std::size_t(image.height) * 3)
    throw Output_error(name, "cannot write an empty or malformed image as PNG");
  if(!write_png(out, image.width, image.height, image.rgb)) // the encoder of write_texture.h
    throw Output_error(name, "PNG encoding failed");
}

/// Same as above, into the file `path` through `Atomic_output_file`.
/// \throws Output_error naming `path`
inline void write_png(const std::string& path, const Image& image)
{
  Atomic_output_file file(path);
  write_png(file.stream(), image, path);
  file.commit();
}

} // namespace diffuv

#endif // DIFFUV_RENDER_RENDER_MESH_H
