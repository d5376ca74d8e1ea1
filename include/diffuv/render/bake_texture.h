// diffuv: baking data of the surface into the texture of a packed atlas.
//
// Every texel whose centre lies in a face (at the face's texture
// coordinates) takes the value of the surface point it stands for: a
// `sample(face, weights)` callback gets the face and the barycentric weights
// of the texel's centre and returns an RGB colour. Samplers for per-vertex
// values (colours, scalars), per-face colours (labels), vertex normals and
// another mesh of the same object (closest point through CGAL's AABB tree)
// are below.
//
// Two things make the texture usable with bilinear filtering:
//  - the four texels around each vertex's texture point take the vertex's own
//    value, so that a renderer reading the texture at a vertex gets the
//    vertex's value back (a texel there otherwise holds the value at its
//    centre, up to 0.7 texels away, across faces of different slopes);
//  - texels in no chart next to the charts (the gutters) take the mean of
//    their baked neighbours of the nearest chart, pass after pass
//    ("dilation"), so that filtering at a chart's border does not mix in the
//    background. Two charts packed a gutter of 2 texels apart share the
//    texels between them: each texel goes to the chart nearer its centre,
//    in the max-norm, which is the chart whose bilinear footprints reach it
//    (a chart's footprints reach less than a texel beyond it).
#ifndef DIFFUV_RENDER_BAKE_TEXTURE_H
#define DIFFUV_RENDER_BAKE_TEXTURE_H

#include <diffuv/render/render_mesh.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace diffuv {

/// What a texel of a baked texture holds.
enum class Texel_source : unsigned char {
  background = 0, ///< no chart: the background colour
  face,           ///< the value at the surface point of its centre
  vertex,         ///< a vertex's own value (one of the four texels around the vertex)
  gutter          ///< the mean of its baked neighbours of the nearest chart (dilation)
};

/// How `bake_texture()` bakes.
struct Bake_options {
  int size = 1024;                 ///< the texture's width and height in texels
  int dilation = 8;                ///< passes of gutter dilation (each fills the texels next to the filled ones)
  bool pin_vertices = true;        ///< the four texels around each vertex take the vertex's own value
  Color background{0, 0, 0};       ///< texels left in no chart and not dilated
};

/// A baked texture: the image (row 0 is the top, v = 1) and where each texel's value came from.
struct Baked_texture {
  Image image;
  std::vector<Texel_source> source; ///< per texel, `y * size + x`
  std::size_t face_texels = 0, vertex_texels = 0, gutter_texels = 0;
};

namespace internal {

inline unsigned char unit_to_byte(double c)
{
  if(!(c > 0.)) return 0;  // NaN too
  if(c >= 1.) return 255;
  return static_cast<unsigned char>(std::lround(c * 255.));
}

/// The max-norm distance from (x, y) to the triangle `t` (x0, y0, x1, y1,
/// x2, y2): 0 inside, else the least over its edges of the larger of |dx|
/// and |dy|, which along an edge is least at an end, where one of them is
/// 0, or where they are equal.
inline double max_norm_distance_to_triangle(double x, double y, const std::array<double, 6>& t)
{
  const auto side = [&](int a, int b) {
    return (t[2 * b] - t[2 * a]) * (y - t[2 * a + 1]) - (t[2 * b + 1] - t[2 * a + 1]) * (x - t[2 * a]);
  };
  const double s0 = side(0, 1), s1 = side(1, 2), s2 = side(2, 0);
  if((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0)) return 0.;
  double least = std::numeric_limits<double>::infinity();
  for(int e = 0; e < 3; ++e) {
    const double ax = t[2 * e] - x, ay = t[2 * e + 1] - y;
    const double dx = t[2 * ((e + 1) % 3)] - t[2 * e], dy = t[2 * ((e + 1) % 3) + 1] - t[2 * e + 1];
    const auto at = [&](double s) {
      s = (std::min)(1., (std::max)(0., s));
      return (std::max)(std::abs(ax + s * dx), std::abs(ay + s * dy));
    };
    least = (std::min)({least, at(0.), at(1.)});
    if(dx != 0.) least = (std::min)(least, at(-ax / dx));
    if(dy != 0.) least = (std::min)(least, at(-ay / dy));
    if(dx != dy) least = (std::min)(least, at((ay - ax) / (dx - dy)));
    if(dx != -dy) least = (std::min)(least, at(-(ax + ay) / (dx + dy)));
  }
  return least;
}

/// The charts of `baked_faces` under `corner_texture`: two faces sharing an edge
/// are in one chart when both ends of the edge have the same texture point
/// in both. Returns a chart number per entry of `baked_faces` (the smallest entry
/// number of its chart).
template <class TriangleMesh, class TextureMap, class FaceDescriptor>
std::vector<std::int32_t> texture_islands(const TriangleMesh& tm, TextureMap corner_texture,
                                          const std::vector<FaceDescriptor>& baked_faces)
{
  const auto findex = get(boost::face_index, tm);
  // Indices may run past num_faces() (a Surface_mesh with removed faces not yet collected).
  std::size_t indices = 0;
  for(auto f : faces(tm)) indices = (std::max)(indices, std::size_t(get(findex, f)) + 1);
  std::vector<std::int32_t> local(indices, -1), parent(baked_faces.size());
  for(std::size_t k = 0; k < baked_faces.size(); ++k) {
    local[std::size_t(get(findex, baked_faces[k]))] = std::int32_t(k);
    parent[k] = std::int32_t(k);
  }
  const auto find = [&](std::int32_t a) {
    while(parent[std::size_t(a)] != a) a = parent[std::size_t(a)] = parent[std::size_t(parent[std::size_t(a)])];
    return a;
  };
  for(std::size_t k = 0; k < baked_faces.size(); ++k)
    for(auto h : CGAL::halfedges_around_face(halfedge(baked_faces[k], tm), tm)) {
      const auto g = opposite(h, tm);
      if(is_border(g, tm)) continue;
      const std::int32_t other = local[std::size_t(get(findex, face(g, tm)))];
      if(other < 0) continue;
      // target(h) is source(g), and source(h) is target(g).
      if(!(get(corner_texture, h) == get(corner_texture, prev(g, tm)) &&
           get(corner_texture, prev(h, tm)) == get(corner_texture, g)))
        continue;
      const std::int32_t a = find(std::int32_t(k)), b = find(other);
      if(a != b) parent[std::size_t((std::max)(a, b))] = (std::min)(a, b);
    }
  std::vector<std::int32_t> chart(baked_faces.size());
  for(std::size_t k = 0; k < baked_faces.size(); ++k) chart[k] = find(std::int32_t(k));
  return chart;
}

} // namespace internal

/// Bakes `sample` into a texture of `options.size`^2 texels through the
/// texture coordinates `corner_texture` (halfedge h -> the 2D point in
/// [0,1]^2, v up, of target(h) in face(h)'s chart, e.g.
/// `packed_corner_map()`). For a texel whose centre lies in triangle f,
/// `sample(f, w)` gives its colour, with `w[i]` the weight of the target of
/// the i-th halfedge of f from `halfedge(f, tm)` on; the four texels around a
/// vertex's texture point take `sample(f, unit weight at that corner)` (the
/// nearest vertex, if two are that close), unless `options.pin_vertices` is
/// false. Then `options.dilation` passes fill the texels next to filled ones,
/// each with the mean of its filled neighbours that belong to the chart
/// nearest its centre (a chart: faces joined by edges whose two ends have
/// the same texture points in both faces).
/// Faces with a non-finite texture point, or of no area in the texture, are
/// skipped; only the first three corners of a face are used (a triangle mesh).
/// Samples are taken in parallel when CGAL is linked with oneTBB: `sample` must
/// be callable from several threads at once.
///
/// \throws std::invalid_argument if the size is not in [1, 16384] or the dilation is negative
template <class TriangleMesh, class TextureMap, class Sample>
Baked_texture bake_texture(const TriangleMesh& tm, TextureMap corner_texture, const Sample& sample,
                           const Bake_options& options = Bake_options())
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  if(options.size < 1 || options.size > 16384)  // texel numbers fit in 32 bits
    throw std::invalid_argument("bake_texture: the size must be in [1, 16384]");
  if(options.dilation < 0) throw std::invalid_argument("bake_texture: the dilation must not be negative");
  const int S = options.size;
  const std::size_t texels = std::size_t(S) * std::size_t(S);

  // Where each texel's value comes from is found on one thread (cheap);
  // the samples (the costly part with a closest-point sampler) are taken in
  // parallel, a batch of texels at a time so that memory stays small: the
  // faces' texels, then the vertices' texels over them.
  struct Texel_job {
    std::uint32_t texel;
    face_descriptor face;
    float w0, w1;  // the third weight is 1 - w0 - w1
  };
  std::vector<Texel_job> face_jobs, vertex_jobs;
  std::vector<Texel_source> source(texels, Texel_source::background);
  struct Corner {
    face_descriptor face;
    int index;
    double x, y;
    std::int32_t local;  // the face's number in `triangles`
  };
  // The rasterised faces, in texel coordinates, and the chart (island of
  // texture coordinates) of each; `owner` is the face a filled texel's value
  // came from (or, in the gutters, the nearest face of the chart it took).
  std::vector<std::array<double, 6>> triangles;
  std::vector<std::int32_t> owner(texels, -1);
  std::vector<Corner> corners;
  std::vector<face_descriptor> faces_baked;  // by local number
  Baked_texture baked;
  baked.image = Image(S, S, options.background);
  std::vector<unsigned char>& rgb = baked.image.rgb;
  auto run = [&](const std::vector<Texel_job>& jobs, std::size_t begin, std::size_t end) {
    for(std::size_t j = begin; j < end; ++j) {
      const Texel_job& job = jobs[j];
      const Rgb c = sample(job.face, std::array<double, 3>{double(job.w0), double(job.w1), 1. - double(job.w0) - double(job.w1)});
      unsigned char* out = &rgb[3 * std::size_t(job.texel)];
      for(int k = 0; k < 3; ++k) out[k] = internal::unit_to_byte(c[std::size_t(k)]);
    }
  };
  auto flush = [&](std::vector<Texel_job>& jobs) {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, jobs.size(), 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) { run(jobs, r.begin(), r.end()); });
#else
    run(jobs, 0, jobs.size());
#endif
    jobs.clear();
  };
  constexpr std::size_t batch = std::size_t(1) << 20;
  face_jobs.reserve(batch);
  for(face_descriptor f : faces(tm)) {
    const halfedge_descriptor h0 = halfedge(f, tm);
    const halfedge_descriptor hs[3] = {h0, next(h0, tm), next(next(h0, tm), tm)};
    double x[3], y[3];
    bool finite = true;
    for(int i = 0; i < 3; ++i) {
      const auto t = get(corner_texture, hs[i]);
      x[i] = CGAL::to_double(t.x()) * S;
      y[i] = (1. - CGAL::to_double(t.y())) * S;  // image rows go down
      finite = finite && std::isfinite(x[i]) && std::isfinite(y[i]);
    }
    if(!finite) continue;
    const double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    if(!(std::abs(area) > 1e-12)) continue;
    const std::int32_t local = std::int32_t(triangles.size());
    triangles.push_back({x[0], y[0], x[1], y[1], x[2], y[2]});
    faces_baked.push_back(f);
    for(int i = 0; i < 3; ++i) corners.push_back(Corner{f, i, x[i], y[i], local});
    internal::for_each_pixel_in_triangle(x, y, area, S, S, 1e-9, [&](int px, int py, double w0, double w1, double) {
      const std::size_t texel = std::size_t(py) * S + px;
      // A texel on an edge of two faces is taken once.
      if(source[texel] == Texel_source::face) return;
      source[texel] = Texel_source::face;
      owner[texel] = local;
      face_jobs.push_back(Texel_job{std::uint32_t(texel), f, float(w0), float(w1)});
    });
    if(face_jobs.size() >= batch) flush(face_jobs);
  }
  flush(face_jobs);
  if(options.pin_vertices) {
    // The bilinear footprint of a point: the texels whose centres are the
    // corners of the texel-sized square around it, less those a whole texel
    // away along an axis (weight 0 in its read: with a 1-texel gutter such a
    // texel can be the next chart's). A texel in two footprints goes to the
    // nearer point.
    std::vector<float> pin_distance(texels, std::numeric_limits<float>::infinity());
    auto footprint = [&](const Corner& c, auto visit) {
      const int bx = int(std::floor(c.x - 0.5)), by = int(std::floor(c.y - 0.5));
      for(int py = by; py <= by + 1; ++py)
        for(int px = bx; px <= bx + 1; ++px)
          if(px >= 0 && py >= 0 && px < S && py < S && std::abs(px + 0.5 - c.x) < 1. && std::abs(py + 0.5 - c.y) < 1.)
            visit(std::size_t(py) * S + px, float(std::hypot(px + 0.5 - c.x, py + 0.5 - c.y)));
    };
    for(const Corner& c : corners)
      footprint(c, [&](std::size_t texel, float d) { pin_distance[texel] = (std::min)(pin_distance[texel], d); });
    for(const Corner& c : corners)
      footprint(c, [&](std::size_t texel, float d) {
        if(d != pin_distance[texel]) return;
        pin_distance[texel] = -1.f;  // taken: an equally near corner (the same vertex in another face) adds nothing
        source[texel] = Texel_source::vertex;
        owner[texel] = c.local;
        vertex_jobs.push_back(Texel_job{std::uint32_t(texel), c.face, c.index == 0 ? 1.f : 0.f, c.index == 1 ? 1.f : 0.f});
      });
  }

  flush(vertex_jobs);

  // Dilation: each pass gives every empty texel next to a filled one (8
  // neighbours) the mean of its filled neighbours, as they were before the
  // pass, of the chart nearest its centre. Only the texels next to the last
  // pass's are looked at.
  const std::vector<std::int32_t> chart_of_face =
      options.dilation > 0 ? internal::texture_islands(tm, corner_texture, faces_baked) : std::vector<std::int32_t>();
  auto for_neighbours = [S](std::size_t texel, auto visit) {
    const int px = int(texel % std::size_t(S)), py = int(texel / std::size_t(S));
    for(int dy = -1; dy <= 1; ++dy)
      for(int dx = -1; dx <= 1; ++dx) {
        const int nx = px + dx, ny = py + dy;
        if((dx != 0 || dy != 0) && nx >= 0 && ny >= 0 && nx < S && ny < S) visit(std::size_t(ny) * S + nx);
      }
  };
  std::vector<std::size_t> candidates, next_candidates;
  std::vector<char> listed(options.dilation > 0 ? texels : 0, 0);
  if(options.dilation > 0)
    for(std::size_t texel = 0; texel < texels; ++texel)
      if(source[texel] == Texel_source::background) {
        bool next_to_filled = false;
        for_neighbours(texel, [&](std::size_t n) { next_to_filled = next_to_filled || source[n] != Texel_source::background; });
        if(next_to_filled) {
          candidates.push_back(texel);
          listed[texel] = 1;
        }
      }
  std::vector<std::array<unsigned char, 3>> fill;
  std::vector<std::int32_t> fill_owner;
  for(int pass = 0; pass < options.dilation && !candidates.empty(); ++pass) {
    fill.resize(candidates.size());
    fill_owner.resize(candidates.size());
    for(std::size_t i = 0; i < candidates.size(); ++i) {
      // The nearest face among the neighbours' (ties: the first met), then
      // the mean of the neighbours of its chart.
      const double cx = double(candidates[i] % std::size_t(S)) + 0.5, cy = double(candidates[i] / std::size_t(S)) + 0.5;
      std::int32_t nearest = -1;
      double least = std::numeric_limits<double>::infinity();
      for_neighbours(candidates[i], [&](std::size_t m) {
        if(source[m] == Texel_source::background || owner[m] == nearest) return;
        const double d = internal::max_norm_distance_to_triangle(cx, cy, triangles[std::size_t(owner[m])]);
        if(d < least) {
          least = d;
          nearest = owner[m];
        }
      });
      const std::int32_t chart = chart_of_face[std::size_t(nearest)];
      double sum[3] = {0., 0., 0.};
      int n = 0;
      for_neighbours(candidates[i], [&](std::size_t m) {
        if(source[m] == Texel_source::background || chart_of_face[std::size_t(owner[m])] != chart) return;
        for(int k = 0; k < 3; ++k) sum[k] += rgb[3 * m + std::size_t(k)];
        ++n;
      });
      for(int k = 0; k < 3; ++k) fill[i][std::size_t(k)] = static_cast<unsigned char>(std::lround(sum[k] / n));
      fill_owner[i] = nearest;
    }
    next_candidates.clear();
    for(std::size_t i = 0; i < candidates.size(); ++i) {
      source[candidates[i]] = Texel_source::gutter;
      owner[candidates[i]] = fill_owner[i];
      for(int k = 0; k < 3; ++k) rgb[3 * candidates[i] + std::size_t(k)] = fill[i][std::size_t(k)];
    }
    for(std::size_t texel : candidates)
      for_neighbours(texel, [&](std::size_t n) {
        if(source[n] == Texel_source::background && !listed[n]) {
          listed[n] = 1;
          next_candidates.push_back(n);
        }
      });
    candidates.swap(next_candidates);
  }
  for(Texel_source s : source) {
    if(s == Texel_source::face) ++baked.face_texels;
    else if(s == Texel_source::vertex) ++baked.vertex_texels;
    else if(s == Texel_source::gutter) ++baked.gutter_texels;
  }
  baked.source = std::move(source);
  return baked;
}

namespace internal {

/// The sum over the corners of triangle `f` (from `halfedge(f, tm)` on) of
/// `w[i] * value(vertex of corner i)`, `value` giving 3 numbers.
template <class TriangleMesh, class Value>
std::array<double, 3> weighted_corner_sum(const TriangleMesh& tm,
                                          typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                                          const std::array<double, 3>& w, Value value)
{
  auto h = halfedge(f, tm);
  std::array<double, 3> sum{0., 0., 0.};
  for(std::size_t i = 0; i < 3; ++i, h = next(h, tm)) {
    const std::array<double, 3> x = value(target(h, tm));
    for(std::size_t k = 0; k < 3; ++k) sum[k] += w[i] * x[k];
  }
  return sum;
}

} // namespace internal

/// A sampler for `bake_texture()`: per-vertex colours (`values`: vertex -> `Rgb`)
/// interpolated linearly across each face.
template <class TriangleMesh, class VertexRgbMap>
auto vertex_value_sampler(const TriangleMesh& tm, VertexRgbMap values)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  return [&tm, values](face_descriptor f, const std::array<double, 3>& w) {
    return internal::weighted_corner_sum(tm, f, w, [&](auto v) { return Rgb(get(values, v)); });
  };
}

/// A sampler for `bake_texture()`: vertex normals (`normals`: vertex -> 3D
/// vector) interpolated across each face, made unit and stored as an
/// object-space normal map, (n + 1) / 2 per channel.
template <class TriangleMesh, class VertexNormalMap>
auto vertex_normal_sampler(const TriangleMesh& tm, VertexNormalMap normals)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  return [&tm, normals](face_descriptor f, const std::array<double, 3>& w) {
    const std::array<double, 3> n = internal::weighted_corner_sum(tm, f, w, [&](auto v) {
      const auto normal = get(normals, v);
      return std::array<double, 3>{CGAL::to_double(normal.x()), CGAL::to_double(normal.y()), CGAL::to_double(normal.z())};
    });
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if(!(length > 0.)) return Rgb{0.5, 0.5, 0.5};
    return Rgb{0.5 * (n[0] / length + 1.), 0.5 * (n[1] / length + 1.), 0.5 * (n[2] / length + 1.)};
  };
}

/// A sampler for `bake_texture()` that takes its values from another mesh
/// of the same object (e.g. a high-resolution scan): the texel's point on
/// `tm` (weights of its face's corners), then the closest point on `source`
/// (CGAL's AABB tree), whose face and weights (same corner order) go to
/// `source_sample`. The tree is built once; calls may run in parallel.
template <class TriangleMesh, class VertexPointMap, class SourceMesh, class SourceSample>
class Closest_point_sampler {
  using Source_points = typename boost::property_map<SourceMesh, CGAL::vertex_point_t>::const_type;
  using Point_3 = typename boost::property_traits<Source_points>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point_3>::Kernel;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<SourceMesh>>>;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

public:
  Closest_point_sampler(const TriangleMesh& tm, VertexPointMap vpm, const SourceMesh& source, SourceSample source_sample)
      : tm_(&tm), vpm_(vpm), source_(&source), source_points_(get(CGAL::vertex_point, source)),
        source_sample_(std::move(source_sample)),
        tree_(std::make_shared<Tree>(faces(source).first, faces(source).second, source))
  {
    tree_->accelerate_distance_queries();
  }

  Rgb operator()(face_descriptor f, const std::array<double, 3>& w) const
  {
    const std::array<double, 3> p = internal::weighted_corner_sum(*tm_, f, w, [&](auto v) {
      const auto& q = get(vpm_, v);
      return std::array<double, 3>{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())};
    });
    const auto nearest = tree_->closest_point_and_primitive(Point_3(p[0], p[1], p[2]));
    const auto g = nearest.second;
    // The closest point's weights in g: from the areas of the sub-triangles,
    // projected onto the triangle's plane (the point lies on the triangle).
    auto s = halfedge(g, *source_);
    Point_3 c[3];
    for(int i = 0; i < 3; ++i, s = next(s, *source_)) c[i] = get(source_points_, target(s, *source_));
    const auto normal = CGAL::cross_product(c[1] - c[0], c[2] - c[0]);
    const double whole = CGAL::to_double(normal.squared_length());
    std::array<double, 3> ws{1. / 3, 1. / 3, 1. / 3};
    if(whole > 0.) {
      for(int i = 0; i < 3; ++i) {
        const auto sub = CGAL::cross_product(c[(i + 1) % 3] - nearest.first, c[(i + 2) % 3] - nearest.first);
        ws[std::size_t(i)] = (std::max)(0., CGAL::to_double(sub * normal) / whole);
      }
      const double sum = ws[0] + ws[1] + ws[2];
      if(sum > 0.)
        for(double& x : ws) x /= sum;
    }
    return source_sample_(g, ws);
  }

private:
  const TriangleMesh* tm_;
  VertexPointMap vpm_;
  const SourceMesh* source_;
  Source_points source_points_;
  SourceSample source_sample_;
  std::shared_ptr<Tree> tree_;
};

/// Makes a `Closest_point_sampler`.
template <class TriangleMesh, class VertexPointMap, class SourceMesh, class SourceSample>
Closest_point_sampler<TriangleMesh, VertexPointMap, SourceMesh, SourceSample>
closest_point_sampler(const TriangleMesh& tm, VertexPointMap vpm, const SourceMesh& source, SourceSample source_sample)
{
  return Closest_point_sampler<TriangleMesh, VertexPointMap, SourceMesh, SourceSample>(tm, vpm, source,
                                                                                       std::move(source_sample));
}

} // namespace diffuv

#endif // DIFFUV_RENDER_BAKE_TEXTURE_H
