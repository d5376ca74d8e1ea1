// diffuv: CGAL's own surface parameterizers, run on one of our disc patches
// with the same four corners, so that diffuv can be compared like-for-like.
//
// The patch (a range of faces of any mesh) is copied into a standalone
// `CGAL::Surface_mesh`, checked to be a topological disc, and given to
// `CGAL::Surface_mesh_parameterization::parameterize()`:
//
//   method              CGAL parameterizer                       border
//   tutte               Barycentric_mapping_parameterizer_3      square, our corners
//   mean_value          Mean_value_coordinates_parameterizer_3   square, our corners
//   discrete_authalic   Discrete_authalic_parameterizer_3        square, our corners
//   discrete_conformal  Discrete_conformal_map_parameterizer_3   square, our corners
//   lscm                LSCM_parameterizer_3                     free (two pinned vertices)
//   arap                ARAP_parameterizer_3                     free (LSCM start)
//
// The square border is `Square_border_arc_length_parameterizer_3`. CGAL
// ignores the order in which its four corners are given: it walks the border
// halfedges (`h -> next(h)`, clockwise around the patch) from the first corner
// it meets and puts the corners it passes at (0,0), (1,0), (1,1), (0,1). Its
// charts are therefore mirrored. Starting the walk at `corners[0]` and
// swapping u and v afterwards (an exact reflection) puts `corners[i]` exactly
// where diffuv puts it, with the same (counter-clockwise) orientation; see
// `diffuv/patches/corners.h`. LSCM and ARAP are not mirrored and their uv
// is left as CGAL returns it (not in the unit square: compare them with
// scale-normalised measures such as `measure_distortion()`).
//
// Needs Eigen 3 (CGAL's sparse solvers): CGAL 5.5 enables it by itself when
// <Eigen/Jacobi> is on the include path (e.g. through `Eigen3::Eigen`).
#ifndef DIFFUV_COMPARE_CGAL_PARAMETERIZERS_H
#define DIFFUV_COMPARE_CGAL_PARAMETERIZERS_H

#include <diffuv/patches/disc_topology.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Surface_mesh.h>

#if !defined(CGAL_EIGEN3_ENABLED)
#error "diffuv/compare/cgal_parameterizers.h needs Eigen 3: put /usr/include/eigen3 on the include path (link Eigen3::Eigen)"
#endif

#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/exceptions.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace diffuv {

/// The parameterizers of CGAL's `Surface_mesh_parameterization` package that
/// `cgal_parameterize_patch()` runs.
enum class Cgal_method {
  tutte,               ///< `Barycentric_mapping_parameterizer_3` (uniform weights), square border
  mean_value,          ///< `Mean_value_coordinates_parameterizer_3` (Floater), square border
  discrete_authalic,   ///< `Discrete_authalic_parameterizer_3` (Desbrun et al.), square border
  discrete_conformal,  ///< `Discrete_conformal_map_parameterizer_3` (cotangent weights), square border
  lscm,                ///< `LSCM_parameterizer_3` (Lévy et al.), free border
  arap                 ///< `ARAP_parameterizer_3` (Liu et al., lambda = 1000), free border
};

/// Every `Cgal_method`, in the order of the enum.
inline constexpr std::array<Cgal_method, 6> all_cgal_methods = {
    Cgal_method::tutte, Cgal_method::mean_value, Cgal_method::discrete_authalic,
    Cgal_method::discrete_conformal, Cgal_method::lscm, Cgal_method::arap};

/// A short stable name of `m`: "tutte", "mean_value", "authalic", "conformal", "lscm" or "arap".
inline const char* method_name(Cgal_method m)
{
  switch(m) { // no default: the compiler flags a method without a name
    case Cgal_method::tutte: return "tutte";
    case Cgal_method::mean_value: return "mean_value";
    case Cgal_method::discrete_authalic: return "authalic";
    case Cgal_method::discrete_conformal: return "conformal";
    case Cgal_method::lscm: return "lscm";
    case Cgal_method::arap: return "arap";
  }
  return "unknown";
}

/// The method whose `method_name()` is `name`, if any.
inline std::optional<Cgal_method> cgal_method_from_name(std::string_view name)
{
  for(Cgal_method m : all_cgal_methods)
    if(name == method_name(m)) return m;
  return std::nullopt;
}

/// Whether `m` maps the border onto the unit square with the four corners
/// (true), or leaves the border free and ignores the corners (LSCM, ARAP).
inline bool has_fixed_border(Cgal_method m)
{
  return m != Cgal_method::lscm && m != Cgal_method::arap;
}

/// What `cgal_parameterize_patch()` computed for one patch.
///
/// \tparam VertexDescriptor the vertex descriptor of the input mesh
template <class VertexDescriptor>
struct Cgal_patch_map {
  using Point_2 = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;

  CGAL::Surface_mesh_parameterization::Error_code error = CGAL::Surface_mesh_parameterization::OK;
  double milliseconds = 0;             ///< wall time of CGAL's `parameterize()` call only (0 if not reached)
  double extraction_milliseconds = 0;  ///< copying the patch into a `Surface_mesh` and checking it (and the corners)
  std::vector<VertexDescriptor> vertices;  ///< the patch's vertices in the input mesh, in order of first appearance in the faces
  std::vector<Point_2> uv;                 ///< `uv[i]` is the (u,v) of `vertices[i]`; empty unless `ok()`

  bool ok() const { return error == CGAL::Surface_mesh_parameterization::OK; }
};

namespace internal {

using Cgal_patch_mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

inline double milliseconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// The border halfedges of `sm` in `next()` order (clockwise around the patch)
/// if `sm` is a topological disc (`check_disc()`), empty otherwise. CGAL's
/// fixed-border parameterizers do not check this (holes would be treated as
/// interior vertices), so it is done here.
inline std::vector<Cgal_patch_mesh::Halfedge_index> disc_border(const Cgal_patch_mesh& sm)
{
  std::vector<Cgal_patch_mesh::Halfedge_index> loop;
  if(!check_disc(sm)) return loop;
  for(auto h : CGAL::halfedges_around_face(boundary_loops(sm).front(), sm)) loop.push_back(h);
  return loop;
}

/// Runs `parameterize()` and times that call alone. A CGAL assertion or
/// precondition that fails inside (only in builds without NDEBUG, on
/// degenerate input such as zero-length border edges) is reported as
/// `ERROR_WRONG_PARAMETER` rather than thrown.
template <class Parameterizer, class UvMap>
CGAL::Surface_mesh_parameterization::Error_code
timed_parameterize(Cgal_patch_mesh& sm, const Parameterizer& parameterizer, Cgal_patch_mesh::Halfedge_index bhd,
                   UvMap uv, double& milliseconds)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  const auto start = std::chrono::steady_clock::now();
  SMP::Error_code e = SMP::OK;
  try {
    e = SMP::parameterize(sm, parameterizer, bhd, uv);
  } catch(const CGAL::Failure_exception&) {
    e = SMP::ERROR_WRONG_PARAMETER;
  }
  milliseconds = milliseconds_since(start);
  return e;
}

} // namespace internal

/// Maps one disc patch of `tm` with one of CGAL's parameterizers.
///
/// The faces are copied into a standalone `CGAL::Surface_mesh` (positions
/// rounded to `double`), checked to be a topological disc, and parameterized
/// by `method` (see `Cgal_method`). With a fixed border (`has_fixed_border()`),
/// `corners[0]` lands on (0,0), `corners[1]` on (1,0), `corners[2]` on (1,1)
/// and `corners[3]` on (0,1), exactly, and the chart has the faces'
/// orientation (counter-clockwise), as in diffuv's own `parameterize_disc()`.
/// LSCM and ARAP ignore `corners`.
///
/// Nothing is thrown and nothing is printed: a failure is the returned
/// `error`, and then `uv_map` is not written.
///
/// \tparam TriangleMesh a model of `FaceGraph` whose `vertex_descriptor` has a
///         `std::hash` (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3`, `CGAL::Face_filtered_graph`, ...)
/// \tparam FaceRange a range of `boost::graph_traits<TriangleMesh>::face_descriptor`, each face once
/// \tparam VertexPointMap a `ReadablePropertyMap` from vertices to a 3D point with `x()`, `y()`, `z()`
/// \tparam VertexUvMap a `WritablePropertyMap` from vertices to `Epick::Point_2`
/// \param tm the mesh
/// \param faces the patch: all faces of a disc mesh, or the faces of one patch of a segmented mesh
/// \param vpm the 3D positions of the vertices
/// \param corners four distinct vertices on the patch's boundary, counter-clockwise
///        along it (the direction of the faces' orientation); the order of
///        `Four_sides::corners`
/// \param method the CGAL parameterizer
/// \param uv_map receives the (u,v) of every vertex of the patch, and of no other vertex
/// \returns the error code (`ERROR_EMPTY_MESH`: no face; `ERROR_NON_TRIANGULAR_MESH`;
///          `ERROR_NO_TOPOLOGICAL_DISC`: not connected, no or several boundary loops,
///          a non-manifold or pinched vertex, or a handle; `ERROR_WRONG_PARAMETER`:
///          with a fixed border, a corner not on the patch's boundary, given twice,
///          or out of counter-clockwise order; or CGAL's own code), the times, and
///          the patch's vertices with their (u,v)
template <class TriangleMesh, class FaceRange, class VertexPointMap, class VertexUvMap>
Cgal_patch_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
cgal_parameterize_patch(const TriangleMesh& tm, const FaceRange& faces, VertexPointMap vpm,
                        const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 4>& corners,
                        Cgal_method method, VertexUvMap uv_map)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Sm = internal::Cgal_patch_mesh;
  using Sm_vertex = Sm::Vertex_index;
  using Sm_halfedge = Sm::Halfedge_index;
  using Point_2 = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;
  using Point_3 = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

  Cgal_patch_map<vertex_descriptor> result;
  const auto start = std::chrono::steady_clock::now();
  auto fail = [&](SMP::Error_code e) {
    result.error = e;
    result.extraction_milliseconds = internal::milliseconds_since(start);
    return result;
  };

  // The copy. Its vertex i is result.vertices[i] (added in that order).
  Sm sm;
  std::unordered_map<vertex_descriptor, Sm_vertex> to_sm;
  for(auto f : faces) {
    std::array<Sm_vertex, 3> triangle;
    std::size_t n = 0;
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      if(n == 3) { n = 4; break; }
      auto [it, inserted] = to_sm.emplace(v, Sm_vertex());
      if(inserted) {
        const auto& p = get(vpm, v);
        it->second = sm.add_vertex(Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
        result.vertices.push_back(v);
      }
      triangle[n++] = it->second;
    }
    if(n != 3) return fail(SMP::ERROR_NON_TRIANGULAR_MESH);
    // add_face refuses a face that would make an edge or a vertex
    // non-manifold; a repeated vertex would make a loop edge.
    if(triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[2] == triangle[0] ||
       sm.add_face(triangle[0], triangle[1], triangle[2]) == Sm::null_face())
      return fail(SMP::ERROR_NO_TOPOLOGICAL_DISC);
  }
  if(sm.number_of_faces() == 0) return fail(SMP::ERROR_EMPTY_MESH);
  // All points in one place: CGAL 5.5's LSCM (its two pinned vertices) crashes
  // on it, and no method can map it; no linear system has a solution.
  const CGAL::Bbox_3 box = CGAL::bbox_3(sm.points().begin(), sm.points().end());
  if(!(box.xmax() > box.xmin()) && !(box.ymax() > box.ymin()) && !(box.zmax() > box.zmin()))
    return fail(SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM);

  const std::vector<Sm_halfedge> border = internal::disc_border(sm); // clockwise
  if(border.empty()) return fail(SMP::ERROR_NO_TOPOLOGICAL_DISC);

  Sm_halfedge bhd = border.front();
  std::array<Sm_vertex, 4> c;
  if(has_fixed_border(method)) {
    std::array<std::size_t, 4> position;
    for(std::size_t i = 0; i < 4; ++i) {
      const auto it = to_sm.find(corners[i]);
      if(it == to_sm.end()) return fail(SMP::ERROR_WRONG_PARAMETER);
      c[i] = it->second;
      position[i] = border.size();
      for(std::size_t k = 0; k < border.size(); ++k)
        if(sm.source(border[k]) == c[i]) position[i] = k;
      if(position[i] == border.size()) return fail(SMP::ERROR_WRONG_PARAMETER); // not on the boundary
      for(std::size_t j = 0; j < i; ++j)
        if(c[j] == c[i]) return fail(SMP::ERROR_WRONG_PARAMETER);
    }
    // CGAL's walk goes clockwise from the source of bhd: starting at
    // corners[0] it must meet corners[3], corners[2], corners[1] in turn.
    std::array<std::size_t, 4> offset;
    for(std::size_t i = 0; i < 4; ++i) offset[i] = (position[i] + border.size() - position[0]) % border.size();
    if(!(offset[3] < offset[2] && offset[2] < offset[1])) return fail(SMP::ERROR_WRONG_PARAMETER);
    bhd = border[position[0]];
  }

  auto uv = sm.add_property_map<Sm_vertex, Point_2>("v:diffuv_cgal_uv", Point_2(0, 0)).first;
  result.extraction_milliseconds = internal::milliseconds_since(start);

  using Square = SMP::Square_border_arc_length_parameterizer_3<Sm>;
  // CGAL only uses the set of corners; listed here in the order it walks them.
  auto square = [&]() { return Square(c[0], c[3], c[2], c[1]); };
  SMP::Error_code e = SMP::OK;
  switch(method) {
    case Cgal_method::tutte:
      e = internal::timed_parameterize(sm, SMP::Barycentric_mapping_parameterizer_3<Sm, Square>(square()), bhd, uv,
                                       result.milliseconds);
      break;
    case Cgal_method::mean_value:
      e = internal::timed_parameterize(sm, SMP::Mean_value_coordinates_parameterizer_3<Sm, Square>(square()), bhd, uv,
                                       result.milliseconds);
      break;
    case Cgal_method::discrete_authalic:
      e = internal::timed_parameterize(sm, SMP::Discrete_authalic_parameterizer_3<Sm, Square>(square()), bhd, uv,
                                       result.milliseconds);
      break;
    case Cgal_method::discrete_conformal:
      e = internal::timed_parameterize(sm, SMP::Discrete_conformal_map_parameterizer_3<Sm, Square>(square()), bhd, uv,
                                       result.milliseconds);
      break;
    case Cgal_method::lscm:
      e = internal::timed_parameterize(sm, SMP::LSCM_parameterizer_3<Sm>(), bhd, uv, result.milliseconds);
      break;
    case Cgal_method::arap:
      e = internal::timed_parameterize(sm, SMP::ARAP_parameterizer_3<Sm>(), bhd, uv, result.milliseconds);
      break;
  }
  result.error = e;
  if(e != SMP::OK) return result;

  // Swapping u and v undoes the mirror of CGAL's square border (see the top of the file).
  const bool swap = has_fixed_border(method);
  result.uv.reserve(result.vertices.size());
  for(std::size_t i = 0; i < result.vertices.size(); ++i) {
    const Point_2& p = uv[Sm_vertex(static_cast<Sm::size_type>(i))];
    result.uv.push_back(swap ? Point_2(p.y(), p.x()) : p);
    put(uv_map, result.vertices[i], result.uv.back());
  }
  return result;
}

/// Same as above, with the positions of `tm`'s internal vertex point map.
template <class TriangleMesh, class FaceRange, class VertexUvMap>
Cgal_patch_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
cgal_parameterize_patch(const TriangleMesh& tm, const FaceRange& faces,
                        const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 4>& corners,
                        Cgal_method method, VertexUvMap uv_map)
{
  return cgal_parameterize_patch(tm, faces, get(CGAL::vertex_point, tm), corners, method, uv_map);
}

} // namespace diffuv

#endif
