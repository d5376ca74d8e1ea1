// diffuv: a whole disc mesh parameterized as one patch with four corners.
#ifndef DIFFUV_PARAMETERIZATION_PARAMETERIZE_DISC_H
#define DIFFUV_PARAMETERIZATION_PARAMETERIZE_DISC_H

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/core/error.h>
#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/heap_tags.h>
#include <diffuv/parameterization/chart_rectangle.h>
#include <diffuv/parameterization/diffusion_coordinates.h>
#include <diffuv/parameterization/repair_folds.h>
#include <diffuv/patches/disc_topology.h>
#include <diffuv/patches/patch_mesh.h>
#include <diffuv/patches/corners.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace diffuv {

/// Options of `parameterize_disc()`.
struct Disc_parameterization_options {
  /// Whether and how folds are repaired (`repair_folds()`); on by default,
  /// `Repair_options{false}` gives the paper's raw method.
  Repair_options repair;
  /// How the chart is drawn on its rectangle (`fit_chart_drawing()`);
  /// `drawing.pieces` 0: the rectangle of least L2 stretch, no warp.
  Chart_drawing_options drawing;
};

/// What `parameterize_disc()` did.
template <class TriangleMesh>
struct Disc_parameterization_report {
  Four_sides<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> sides;  ///< the four sides used
  Repair_report repair;                                                          ///< what the fold repair did
};

namespace internal {
template <class DistanceTag, class HeapTag, class TriangleMesh, class VertexPointMap>
Status parameterize_disc_without_isolated_vertices(
    const TriangleMesh& tm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& corners,
    Uv_atlas<TriangleMesh>& atlas, const Disc_parameterization_options& options,
    Disc_parameterization_report<TriangleMesh>* report);
} // namespace internal

/// Parameterizes the disc mesh `tm` as a single chart of `atlas`.
///
/// The mesh is checked to be a disc (`check_disc()`; vertices on no face are
/// allowed and left out of the chart), its boundary loop is cut
/// into four sides at `corners` (`corners[0]` goes to (0,0), the others follow
/// counter-clockwise, see four_sides.h) or, if `corners` is empty, at
/// `equal_arc_corners()` moved by `separate_flat_triangles()`; the diffusion coordinates of every vertex fill the chart.
///
/// \tparam DistanceTag the distance diffused from each side (graph/distance_tags.h), `Default_distance_tag` (fast marching) by default
/// \tparam HeapTag the Dijkstra's heap (graph/heap_tags.h), `Fibonacci_heap_tag` by default
/// \tparam TriangleMesh a model of `FaceListGraph` with internal indices and vertex points
///         (e.g. `CGAL::Surface_mesh`)
/// \param tm the mesh, which `atlas` maps
/// \param vpm its points: edge lengths, corners, the repair and the chart's
///        rectangle (fast marching and exact distances read the mesh's internal points)
/// \param corners four boundary vertices, or none to choose them automatically
/// \param atlas receives one chart holding every face and vertex of `tm`
/// \param report if not null, receives the four sides used and what the repair
///        did; a map that still folds after the repair (numerically degenerate
///        input only) is kept and reported there (`repair.remaining_folded_faces`), not an error
/// \returns the first problem met (not a disc, bad corners, ...) or `ok`; on failure
///          `atlas` is unchanged
/// \throws std::invalid_argument if `atlas` maps another mesh than `tm`
template <class DistanceTag = Default_distance_tag, class HeapTag = Fibonacci_heap_tag, class TriangleMesh,
          class VertexPointMap>
Status parameterize_disc(const TriangleMesh& tm, VertexPointMap vpm,
                         const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& corners,
                         Uv_atlas<TriangleMesh>& atlas, const Disc_parameterization_options& options = {},
                         Disc_parameterization_report<TriangleMesh>* report = nullptr)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point_2 = typename Uv_atlas<TriangleMesh>::Point_2;
  if(&atlas.mesh() != &tm) throw std::invalid_argument("parameterize_disc: the atlas maps another mesh");

  Status status = check_disc(tm, true);
  if(!status) return status;

  // Vertices on no face (reading's repair leaves the points it merged so, to
  // keep the file's numbering) have no place in the chart: the disc of the
  // others is mapped as a mesh of its own and its chart given back in `tm`'s
  // vertices.
  if(std::any_of(vertices(tm).begin(), vertices(tm).end(), [&](vertex_descriptor v) {
       return halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge();
     }))
    return internal::parameterize_disc_without_isolated_vertices<DistanceTag, HeapTag>(tm, vpm, corners, atlas,
                                                                                    options, report);

  const std::vector<vertex_descriptor> loop = counterclockwise_boundary(tm, boundary_loops(tm).front());
  if(loop.size() < 4)
    return Status(Status_code::border_too_short, internal::count_text(loop.size(), "boundary vertex", "boundary vertices"));
  std::vector<vertex_descriptor> chosen = corners;
  if(corners.empty()) {
    // Equal arcs, then no triangle left flat on one side (see separate_flat_triangles()).
    chosen = equal_arc_corners(tm, vpm, loop);
    std::array<std::size_t, 4> at{};
    for(std::size_t c = 0; c < 4; ++c)
      at[c] = static_cast<std::size_t>(std::find(loop.begin(), loop.end(), chosen[c]) - loop.begin());
    std::vector<double> loop_lengths(loop.size());
    for(std::size_t i = 0; i < loop.size(); ++i)
      loop_lengths[i] = std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, loop[i]), get(vpm, loop[(i + 1) % loop.size()]))));
    separate_flat_triangles(tm, loop, at, [](auto) { return true; }, loop_lengths);
    for(std::size_t c = 0; c < 4; ++c) chosen[c] = loop[at[c]];
  }

  Four_sides<vertex_descriptor> four;
  status = sides_from_corners(loop, chosen, four);
  if(!status) return status;

  auto index = get(boost::vertex_index, tm);
  std::vector<Point_2> uv_of(num_vertices(tm));
  Diffusion_coordinates<TriangleMesh, DistanceTag, HeapTag> coordinates(tm);
  status = coordinates.compute(four, edge_length_map(tm, vpm), boost::make_iterator_property_map(uv_of.begin(), index));
  if(!status) return status;
  Disc_parameterization_report<TriangleMesh> local;
  Disc_parameterization_report<TriangleMesh>& r = report ? *report : local;
  repair_folds(tm, vpm, four, boost::make_iterator_property_map(uv_of.begin(), index), options.repair, &r.repair);

  std::vector<vertex_descriptor> chart_vertices;
  std::vector<Point_2> chart_uv;
  chart_vertices.reserve(num_vertices(tm));
  chart_uv.reserve(num_vertices(tm));
  for(vertex_descriptor v : vertices(tm)) {
    chart_vertices.push_back(v);
    chart_uv.push_back(uv_of[get(index, v)]);
  }
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> chart_faces(faces(tm).begin(), faces(tm).end());
  const std::size_t chart = atlas.add_chart(std::move(chart_faces), std::move(chart_vertices), std::move(chart_uv));
  const auto size = stretch_optimal_rectangle(tm, vpm, atlas.chart(chart).faces, atlas.chart_uv_map(chart),
                                              side_length_rectangle(four, vpm));
  draw_chart(atlas, chart, vpm, size, options.drawing);
  r.sides = std::move(four);
  return Status();
}

namespace internal {

/// parameterize_disc() on the faces of `tm`, copied without its isolated
/// vertices (a `Patch_mesh`); the chart and the sides come back in `tm`'s vertices.
template <class DistanceTag, class HeapTag, class TriangleMesh, class VertexPointMap>
Status parameterize_disc_without_isolated_vertices(
    const TriangleMesh& tm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& corners,
    Uv_atlas<TriangleMesh>& atlas, const Disc_parameterization_options& options,
    Disc_parameterization_report<TriangleMesh>* report)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  Patch_mesh<TriangleMesh, VertexPointMap> copy;
  std::vector<face_descriptor> all_faces(faces(tm).begin(), faces(tm).end());
  if(!copy.build(tm, vpm, all_faces, [](face_descriptor f) { return f != boost::graph_traits<TriangleMesh>::null_face(); }))
    return Status(Status_code::non_manifold, "the faces cannot be copied into a mesh of their own");
  using Copy = typename Patch_mesh<TriangleMesh, VertexPointMap>::Mesh;
  using copy_vertex = typename boost::graph_traits<Copy>::vertex_descriptor;
  auto vindex = get(boost::vertex_index, tm);
  std::vector<copy_vertex> local_corners;
  for(vertex_descriptor c : corners) {
    if(get(vindex, c) >= num_vertices(tm)) return Status(Status_code::corner_out_of_range);
    if(!copy.has(tm, c))
      return Status(Status_code::corner_not_on_border, "vertex " + std::to_string(get(vindex, c)) + " is on no face");
    local_corners.push_back(copy.local(tm, c));
  }
  const Copy& disc = copy.mesh();
  Uv_atlas<Copy> local_atlas(disc);
  Disc_parameterization_report<Copy> local_report;
  const Status status =
      parameterize_disc<DistanceTag, HeapTag>(disc, disc.points(), local_corners, local_atlas, options, &local_report);
  if(!status) return status;

  const auto& mesh_vertex = copy.mesh_vertices();
  const auto to_mesh = [&](const std::vector<copy_vertex>& side) {
    std::vector<vertex_descriptor> out;
    out.reserve(side.size());
    for(copy_vertex v : side) out.push_back(mesh_vertex[v.idx()]);
    return out;
  };
  std::vector<typename Uv_atlas<TriangleMesh>::Point_2> chart_uv;
  chart_uv.reserve(num_vertices(disc));
  const auto uv = local_atlas.chart_uv_map(0);
  for(copy_vertex v : vertices(disc)) {
    const auto q = get(uv, v);
    chart_uv.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
  }
  const std::size_t chart = atlas.add_chart(std::move(all_faces), mesh_vertex, std::move(chart_uv));
  atlas.set_chart_size(chart, local_atlas.chart(0).size[0], local_atlas.chart(0).size[1]);
  atlas.set_chart_warp(chart, local_atlas.chart(0).warp[0], local_atlas.chart(0).warp[1]);
  if(report) {
    report->repair = local_report.repair;
    report->sides.u1 = to_mesh(local_report.sides.u1);
    report->sides.u2 = to_mesh(local_report.sides.u2);
    report->sides.v1 = to_mesh(local_report.sides.v1);
    report->sides.v2 = to_mesh(local_report.sides.v2);
    for(std::size_t k = 0; k < 4; ++k) report->sides.corners[k] = mesh_vertex[local_report.sides.corners[k].idx()];
  }
  return Status();
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_PARAMETERIZE_DISC_H
