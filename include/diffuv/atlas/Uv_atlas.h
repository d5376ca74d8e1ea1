// diffuv: the uv-map of a mesh, patch by patch (the paper's section 2.5).
//
// Two ways in, as the paper asks: a linear array gives the (u,v) of a
// (patch, vertex) pair in O(1), and a kd-tree per patch gives the vertex
// nearest to a given (u,v) in O(log n). On top of the kd-tree, point location
// finds the triangle containing (u,v) and hence a point on the surface.
#ifndef DIFFUV_ATLAS_UV_ATLAS_H
#define DIFFUV_ATLAS_UV_ATLAS_H

#include <diffuv/atlas/axis_warp.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Orthogonal_incremental_neighbor_search.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/function_property_map.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <type_traits>
#include <vector>

namespace diffuv {

/// A point of the uv plane located on a chart: the face, its barycentric
/// coordinates (CGAL's `Face_location` order: source(halfedge(f)),
/// target(halfedge(f)), target(next(halfedge(f)))), and whether (u,v) lies in
/// the face or is only the nearest point of the chart to it.
template <class TriangleMesh>
struct Uv_location {
  CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> location;
  bool inside = false;       ///< (u,v) is in the triangle (not only nearest to it)
  double uv_distance = 0.;   ///< distance in the uv plane from (u,v) to the located point
};

/// The uv-map of a mesh cut into charts (one per patch).
///
/// \tparam TriangleMesh a model of `FaceGraph` with internal vertex, halfedge and face indices
/// \tparam Kernel a CGAL kernel giving `Point_2` (default: `Exact_predicates_inexact_constructions_kernel`)
template <class TriangleMesh, class Kernel = CGAL::Exact_predicates_inexact_constructions_kernel>
class Uv_atlas {
public:
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Point_2 = typename Kernel::Point_2;
  using Local_index = std::uint32_t;
  static constexpr std::size_t no_chart = std::numeric_limits<std::size_t>::max();

  /// A (chart, local vertex) pair: where one vertex sits in one chart.
  struct Entry {
    std::size_t chart;
    Local_index local;
  };

private:
  // Kd-tree over chart-local vertex ids, reading their (u,v) through this map.
  struct Local_uv_map {
    using key_type = Local_index;
    using value_type = Point_2;
    using reference = const Point_2&;
    using category = boost::lvalue_property_map_tag;
    const Point_2* uv = nullptr;
    friend reference get(const Local_uv_map& m, key_type i) { return m.uv[i]; }
  };
  using Base_traits = CGAL::Search_traits_2<Kernel>;
  using Traits = CGAL::Search_traits_adapter<Local_index, Local_uv_map, Base_traits>;
  using Distance = CGAL::Distance_adapter<Local_index, Local_uv_map, CGAL::Euclidean_distance<Base_traits>>;
  using Incremental_search = CGAL::Orthogonal_incremental_neighbor_search<Traits, Distance>;
  using Nearest_search = CGAL::Orthogonal_k_neighbor_search<Traits, Distance>;
  using Tree = typename Incremental_search::Tree;
  static_assert(std::is_same<Tree, typename Nearest_search::Tree>::value, "one kd-tree serves both searches");

public:
  /// One patch: its vertices, their (u,v), its faces and its search structure.
  struct Chart {
    std::vector<vertex_descriptor> vertices;            ///< #V_c entries: local index -> mesh vertex
    std::vector<Point_2> uv;                            ///< #V_c entries: local index -> (u,v)
    std::vector<face_descriptor> faces;                 ///< #F_c entries
    std::vector<std::array<Local_index, 3>> triangles;  ///< #F_c entries: local vertices in CGAL face order
    std::vector<std::size_t> star_offsets;              ///< #V_c + 1 entries into star_faces
    std::vector<Local_index> star_faces;                ///< faces (positions in `faces`) around each local vertex
    double longest_uv_edge = 0.;
    std::unique_ptr<Tree> tree;
    /// The chart's rectangle in a texture: (u,v) in [0,1]^2 is drawn at
    /// (f(u) * size[0], g(v) * size[1]), f and g the warps below; (1,1) and
    /// no warps draw every chart on the unit square.
    std::array<double, 2> size{{1., 1.}};
    /// The warps of u and v (`Axis_warp`; the identity unless set).
    std::array<Axis_warp, 2> warp;
  };

  explicit Uv_atlas(const TriangleMesh& tm)
    : mesh_(tm), vertex_offsets_(num_vertices(tm) + 1, 0), face_chart_(num_faces(tm), no_chart) {}

  Uv_atlas(const Uv_atlas&) = delete;
  Uv_atlas& operator=(const Uv_atlas&) = delete;
  Uv_atlas(Uv_atlas&&) = default;

  /// Adds a chart made of `faces`, whose vertices `vertices` have the (u,v) `uv`.
  ///
  /// \param faces the faces of the patch (each face belongs to one chart only)
  /// \param vertices the vertices of the patch, #V_c entries
  /// \param uv their (u,v), #V_c entries, same order
  /// \returns the chart's index
  /// \throws std::invalid_argument if a face is already in a chart, a face vertex is not in
  ///         `vertices`, or the sizes differ
  std::size_t add_chart(std::vector<face_descriptor> faces, std::vector<vertex_descriptor> vertices,
                        std::vector<Point_2> uv)
  {
    if(vertices.size() != uv.size())
      throw std::invalid_argument("Uv_atlas::add_chart: vertices and uv differ in size");
    const std::size_t id = charts_.size();
    auto chart = std::make_unique<Chart>();
    chart->vertices = std::move(vertices);
    chart->uv = std::move(uv);
    chart->faces = std::move(faces);

    // Mesh vertex -> local id, in an array of the mesh's size kept between
    // charts and never cleared: an entry counts only if it points back to its
    // vertex, so stale entries of earlier charts are harmless.
    auto vindex = get(boost::vertex_index, mesh_);
    auto findex = get(boost::face_index, mesh_);
    if(local_of_.size() != num_vertices(mesh_)) local_of_.assign(num_vertices(mesh_), 0);
    for(std::size_t i = 0; i < chart->vertices.size(); ++i)
      local_of_[get(vindex, chart->vertices[i])] = static_cast<Local_index>(i);

    const std::size_t nv = chart->vertices.size();
    std::vector<std::size_t> star_count(nv + 1, 0);
    chart->triangles.reserve(chart->faces.size());
    for(face_descriptor f : chart->faces) {
      if(face_chart_[get(findex, f)] != no_chart)
        throw std::invalid_argument("Uv_atlas::add_chart: a face is already in a chart");
      face_chart_[get(findex, f)] = id;
      std::array<Local_index, 3> t{};
      const halfedge_descriptor h = halfedge(f, mesh_);
      const vertex_descriptor corner[3] = {source(h, mesh_), target(h, mesh_), target(next(h, mesh_), mesh_)};
      for(int k = 0; k < 3; ++k) {
        const Local_index local = local_of_[get(vindex, corner[k])];
        if(local >= chart->vertices.size() || chart->vertices[local] != corner[k])
          throw std::invalid_argument("Uv_atlas::add_chart: a face vertex is not a chart vertex");
        t[k] = local;
        ++star_count[t[k] + 1];
      }
      chart->triangles.push_back(t);
    }
    // Stars (faces around each vertex) in compressed rows, for point location.
    chart->star_offsets.assign(nv + 1, 0);
    for(std::size_t i = 0; i < nv; ++i) chart->star_offsets[i + 1] = chart->star_offsets[i] + star_count[i + 1];
    chart->star_faces.resize(chart->star_offsets[nv]);
    std::vector<std::size_t> fill(chart->star_offsets.begin(), chart->star_offsets.end() - 1);
    for(std::size_t f = 0; f < chart->triangles.size(); ++f)
      for(Local_index v : chart->triangles[f]) chart->star_faces[fill[v]++] = static_cast<Local_index>(f);
    for(const auto& t : chart->triangles)
      for(int k = 0; k < 3; ++k)
        chart->longest_uv_edge = (std::max)(chart->longest_uv_edge,
            std::sqrt(CGAL::to_double(CGAL::squared_distance(chart->uv[t[k]], chart->uv[t[(k + 1) % 3]]))));

    // The kd-tree over local ids (sliding midpoint splits, built at once).
    std::vector<Local_index> ids(nv);
    for(std::size_t i = 0; i < nv; ++i) ids[i] = static_cast<Local_index>(i);
    chart->tree = std::make_unique<Tree>(ids.begin(), ids.end(), typename Tree::Splitter(),
                                         Traits(Local_uv_map{chart->uv.data()}));
    chart->tree->build();

    charts_.push_back(std::move(chart));
    entries_stale_ = true; // rebuilt once, on the first look-up after the last chart
    return id;
  }

  /// The mesh this atlas maps.
  const TriangleMesh& mesh() const { return mesh_; }

  std::size_t number_of_charts() const { return charts_.size(); }
  /// Chart `c`. \throws std::out_of_range if there is no such chart.
  const Chart& chart(std::size_t c) const { return *charts_.at(c); }

  /// The (u,v) of local vertex `local` of chart `c`: O(1).
  const Point_2& uv(std::size_t c, Local_index local) const { return charts_[c]->uv[local]; }

  /// Builds the vertex look-up (`entries()`, the vertex and corner maps)
  /// now; otherwise the first look-up after the last `add_chart()` builds
  /// it. After this call, and until the next `add_chart()`, every const
  /// member function only reads, so several threads may use the atlas at once.
  void prepare_lookups() const
  {
    if(entries_stale_) index_vertices();
  }

  /// Every (chart, local vertex) pair of mesh vertex `v`: one for an interior
  /// vertex, one per chart for a vertex on patch borders, none for a vertex on no chart.
  std::pair<const Entry*, const Entry*> entries(vertex_descriptor v) const
  {
    if(entries_stale_) index_vertices();
    const std::size_t i = get(get(boost::vertex_index, mesh_), v);
    return {entries_.data() + vertex_offsets_[i], entries_.data() + vertex_offsets_[i + 1]};
  }

  /// The chart of face `f`, or `no_chart`.
  std::size_t chart_of(face_descriptor f) const { return face_chart_[get(get(boost::face_index, mesh_), f)]; }

  /// A vertex property map: the (u,v) of each vertex in its first chart ((NaN, NaN) if in none).
  auto vertex_uv_map() const
  {
    return boost::make_function_property_map<vertex_descriptor>([this](vertex_descriptor v) {
      auto e = entries(v);
      if(e.first == e.second) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return Point_2(nan, nan);
      }
      return uv(e.first->chart, e.first->local);
    });
  }

  /// A vertex property map: the (u,v) of each vertex in chart `c` ((NaN, NaN) for a
  /// vertex not in it). Feeds per-chart algorithms such as `measure_distortion()`.
  auto chart_uv_map(std::size_t c) const
  {
    return boost::make_function_property_map<vertex_descriptor>(
        [this, c](vertex_descriptor v) { return uv_in_chart(v, c); });
  }

  /// A vertex property map: the index of each vertex's first chart (`no_chart` if in none).
  auto vertex_chart_map() const
  {
    return boost::make_function_property_map<vertex_descriptor>([this](vertex_descriptor v) {
      auto e = entries(v);
      return e.first == e.second ? no_chart : e.first->chart;
    });
  }

  /// A halfedge property map: the (u,v) of `target(h)` in the chart of `face(h)`
  /// (per-corner uv, which keeps seams between charts). Border halfedges and
  /// faces in no chart give (NaN, NaN).
  auto corner_uv_map() const
  {
    return corner_map([this](vertex_descriptor v, std::size_t c) { return uv_in_chart(v, c); });
  }

  /// Sets the rectangle chart `c` is drawn in (`Chart::size`), e.g. the
  /// patch's own aspect, so that a texture is not stretched across it.
  /// \pre `width` and `height` are positive and finite
  void set_chart_size(std::size_t c, double width, double height) { charts_.at(c)->size = {width, height}; }

  /// Sets the warps of chart `c`'s u and v (`Chart::warp`).
  void set_chart_warp(std::size_t c, Axis_warp u, Axis_warp v)
  {
    charts_.at(c)->warp = {std::move(u), std::move(v)};
  }

  /// Where (u,v) of chart `c` is drawn on the unit square: (f(u), g(v)), the chart's warps.
  Point_2 drawn_uv(std::size_t c, const Point_2& q) const
  {
    const Chart& chart = *charts_[c];
    if(chart.warp[0].is_identity() && chart.warp[1].is_identity()) return q;
    return Point_2(chart.warp[0](CGAL::to_double(q.x())), chart.warp[1](CGAL::to_double(q.y())));
  }

  /// A halfedge property map like `corner_uv_map()`, warped (`drawn_uv()`):
  /// where each corner is drawn on its chart's unit square.
  auto corner_drawn_uv_map() const
  {
    return corner_map([this](vertex_descriptor v, std::size_t c) { return drawn_uv(c, uv_in_chart(v, c)); });
  }

  /// A halfedge property map like `corner_uv_map()`, in each chart's rectangle
  /// (`Chart::size`, warped): the texture coordinates an OBJ or glTF file carries.
  auto corner_texture_map() const
  {
    return corner_map([this](vertex_descriptor v, std::size_t c) { return texture_point(c, uv_in_chart(v, c)); });
  }

  /// A vertex property map like `chart_uv_map(c)`, in the chart's rectangle (`Chart::size`, warped).
  auto chart_texture_map(std::size_t c) const
  {
    return boost::make_function_property_map<vertex_descriptor>(
        [this, c](vertex_descriptor v) { return texture_point(c, uv_in_chart(v, c)); });
  }

  /// The local vertex of chart `c` whose (u,v) is nearest to `q`, in O(log n).
  /// \throws std::out_of_range if there is no chart `c`
  Local_index nearest_vertex(std::size_t c, const Point_2& q) const
  {
    const Chart& chart = this->chart(c);
    // The k-nearest search with k = 1 (a bounded depth-first descent) is
    // several times faster than the incremental search's priority queue.
    const Nearest_search search(*chart.tree, q, 1, 0., true, Distance(Local_uv_map{chart.uv.data()}));
    return search.begin()->first;
  }

  /// Locates `q` in chart `c`: the triangle containing it (with barycentric
  /// coordinates), or, if no triangle contains it (outside the chart, in a
  /// fold's gap), the nearest point of the chart.
  ///
  /// Vertices are visited by increasing distance to `q` from the kd-tree and
  /// their faces tested; the walk stops once no unvisited face can be nearer
  /// than the best one (a face's vertices are within the longest uv edge of any
  /// of its points), so the answer is exact. A q held by a triangle of the
  /// first star that has one is returned from that star (on a fold: the sheet
  /// whose vertex is nearest in uv); within it, the positively oriented
  /// triangle of largest uv area wins, so that q on an edge or at a vertex, or
  /// in a triangle flat in uv, does not depend on the numbering.
  /// \throws std::out_of_range if there is no chart `c`
  Uv_location<TriangleMesh> locate(std::size_t c, const Point_2& q) const
  {
    const Chart& chart = this->chart(c);
    double best = std::numeric_limits<double>::infinity();
    double best_area = 0.;  // signed uv area of the best triangle
    std::size_t best_face = 0;
    std::array<double, 3> best_bary{1., 0., 0.};
    std::vector<Local_index> tested;
    auto test_star = [&](Local_index v) {
      for(std::size_t k = chart.star_offsets[v]; k < chart.star_offsets[v + 1]; ++k) {
        const Local_index f = chart.star_faces[k];
        if(std::find(tested.begin(), tested.end(), f) != tested.end()) continue;
        tested.push_back(f);
        std::array<double, 3> bary;
        double area = 0.;
        const double d = distance_to_triangle(chart, f, q, bary, area);
        // Several triangles of a star can hold q: those around an edge or a
        // vertex it is on, a triangle flat in uv (its three vertices on one
        // side), a folded one. The choice must not depend on which is met
        // first (the numbering): nearest, then positively oriented, then the
        // largest uv area.
        if(d < best || (d == best && (area > 0.) > (best_area > 0.)) ||
           (d == best && (area > 0.) == (best_area > 0.) && std::abs(area) > std::abs(best_area))) {
          best = d;
          best_area = area;
          best_face = f;
          best_bary = bary;
        }
      }
    };
    // Found in the star of the nearest vertex that has one: the sheet of a
    // fold nearest to q in uv, which for q at a vertex's (u,v) is that vertex.
    // "Found" allows a rounding error: a vertex on a fold does not have its
    // whole neighbourhood in its star, and q computed on another mesh may
    // miss it by 1e-14 (then another sheet would hold q exactly).
    // Most queries inside a chart end in the nearest vertex's star, which the
    // fast k = 1 search finds; the incremental search goes on from there.
    test_star(nearest_vertex(c, q));
    if(best <= 1e-12) return make_location(chart, best_face, best_bary, true, best);
    Incremental_search search(*chart.tree, q, 0., true, Distance(Local_uv_map{chart.uv.data()}));
    for(auto it = search.begin(); it != search.end(); ++it) {
      const double r = std::sqrt(CGAL::to_double(it->second));
      if(r > best + chart.longest_uv_edge) break;
      test_star(it->first);
      if(best <= 1e-12) return make_location(chart, best_face, best_bary, true, best);
    }
    return make_location(chart, best_face, best_bary, best == 0., best);
  }

  /// The 3D point of a located (u,v), through the mesh's vertex point map.
  auto point(const Uv_location<TriangleMesh>& loc) const
  {
    return CGAL::Polygon_mesh_processing::construct_point(loc.location, mesh_);
  }

private:
  // A halfedge map giving `at(target(h), chart of face(h))`; (NaN, NaN) on
  // border halfedges and faces in no chart.
  template <class At>
  auto corner_map(At at) const
  {
    return boost::make_function_property_map<halfedge_descriptor>([this, at](halfedge_descriptor h) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      if(is_border(h, mesh_)) return Point_2(nan, nan);
      const std::size_t c = chart_of(face(h, mesh_));
      if(c == no_chart) return Point_2(nan, nan);
      return at(target(h, mesh_), c);
    });
  }

  // (u,v) of chart c in its rectangle: warped, then scaled.
  Point_2 texture_point(std::size_t c, const Point_2& q) const
  {
    const Point_2 d = drawn_uv(c, q);
    return Point_2(d.x() * charts_[c]->size[0], d.y() * charts_[c]->size[1]);
  }

  Point_2 uv_in_chart(vertex_descriptor v, std::size_t c) const
  {
    auto e = entries(v);
    for(const Entry* it = e.first; it != e.second; ++it)
      if(it->chart == c) return uv(c, it->local);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return Point_2(nan, nan);
  }

  Uv_location<TriangleMesh> make_location(const Chart& chart, std::size_t f, const std::array<double, 3>& bary,
                                          bool inside, double distance) const
  {
    Uv_location<TriangleMesh> loc;
    loc.location = {chart.faces[f], bary};
    loc.inside = inside;
    loc.uv_distance = distance;
    return loc;
  }

  // Distance from q to triangle f of the chart (0 inside), and the barycentric
  // coordinates of the nearest point. Degenerate uv triangles are only reached
  // through their edges.
  static double distance_to_triangle(const Chart& chart, std::size_t f, const Point_2& q, std::array<double, 3>& bary,
                                     double& signed_area)
  {
    const auto& t = chart.triangles[f];
    const double ax = chart.uv[t[0]].x(), ay = chart.uv[t[0]].y();
    const double bx = chart.uv[t[1]].x(), by = chart.uv[t[1]].y();
    const double cx = chart.uv[t[2]].x(), cy = chart.uv[t[2]].y();
    const double qx = q.x(), qy = q.y();
    const double area = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
    signed_area = area;
    if(area != 0.) {
      const double l0 = ((bx - qx) * (cy - qy) - (cx - qx) * (by - qy)) / area;
      const double l1 = ((cx - qx) * (ay - qy) - (ax - qx) * (cy - qy)) / area;
      const double l2 = 1. - l0 - l1;
      if(l0 >= 0. && l1 >= 0. && l2 >= 0.) {
        bary = {l0, l1, l2};
        return 0.;
      }
    }
    // Outside, or a flat triangle: the nearest point is on one of the three
    // edges. On a flat triangle a corner can also lie inside the opposite
    // edge: q at a corner is that corner, not a point of that edge.
    double best = std::numeric_limits<double>::infinity();
    const double px[3] = {ax, bx, cx}, py[3] = {ay, by, cy};
    for(int k = 0; k < 3; ++k)
      if(px[k] == qx && py[k] == qy) {
        bary = {0., 0., 0.};
        bary[k] = 1.;
        return 0.;
      }
    for(int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3;
      const double ex = px[k1] - px[k], ey = py[k1] - py[k];
      const double len2 = ex * ex + ey * ey;
      double s = len2 > 0. ? ((qx - px[k]) * ex + (qy - py[k]) * ey) / len2 : 0.;
      s = std::clamp(s, 0., 1.);
      const double dx = px[k] + s * ex - qx, dy = py[k] + s * ey - qy;
      const double d = std::sqrt(dx * dx + dy * dy);
      if(d < best) {
        best = d;
        bary = {0., 0., 0.};
        bary[k] = 1. - s;
        bary[k1] = s;
      }
    }
    return best;
  }

  // Rebuilds the vertex -> (chart, local) entries in compressed rows.
  // Not thread-safe on the first call after add_chart() (prepare_lookups()
  // makes that call on one thread); later calls only read.
  void index_vertices() const
  {
    auto vindex = get(boost::vertex_index, mesh_);
    const std::size_t n = num_vertices(mesh_);
    std::vector<std::size_t> count(n + 1, 0);
    for(const auto& chart : charts_)
      for(vertex_descriptor v : chart->vertices) ++count[get(vindex, v) + 1];
    vertex_offsets_.assign(n + 1, 0);
    for(std::size_t i = 0; i < n; ++i) vertex_offsets_[i + 1] = vertex_offsets_[i] + count[i + 1];
    entries_.resize(vertex_offsets_[n]);
    std::vector<std::size_t> fill(vertex_offsets_.begin(), vertex_offsets_.end() - 1);
    for(std::size_t c = 0; c < charts_.size(); ++c)
      for(std::size_t i = 0; i < charts_[c]->vertices.size(); ++i)
        entries_[fill[get(vindex, charts_[c]->vertices[i])]++] = Entry{c, static_cast<Local_index>(i)};
    entries_stale_ = false;
  }

  const TriangleMesh& mesh_;
  std::vector<std::unique_ptr<Chart>> charts_;
  mutable std::vector<std::size_t> vertex_offsets_; // #V + 1 entries into entries_
  mutable std::vector<Entry> entries_;
  mutable bool entries_stale_ = false;
  std::vector<std::size_t> face_chart_;     // #F entries
  std::vector<Local_index> local_of_;       // #V entries, add_chart()'s scratch
};

} // namespace diffuv

#endif // DIFFUV_ATLAS_UV_ATLAS_H
