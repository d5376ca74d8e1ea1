// diffuv: every patch of a segmented mesh parameterized onto its own unit square
// (the paper's section 2.8: "the diffusion processes each region on the mesh
// separately").
#ifndef DIFFUV_PARAMETERIZATION_PARAMETERIZE_PATCHES_H
#define DIFFUV_PARAMETERIZATION_PARAMETERIZE_PATCHES_H

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/error.h>
#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/heap_tags.h>
#include <diffuv/parameterization/diffusion_coordinates.h>
#include <diffuv/parameterization/repair_folds.h>
#include <diffuv/patches/region_sides.h>
#include <diffuv/patches/segmentation.h>

#include <CGAL/boost/graph/Face_filtered_graph.h>

#include <chrono>
#include <vector>

namespace diffuv {

/// The outcome of one patch of `parameterize_patches()`.
template <class TriangleMesh>
struct Patch_result {
  Status status;                     ///< `ok`, or why the patch has no chart
  std::size_t chart = Uv_atlas<TriangleMesh>::no_chart;  ///< the patch's chart in the atlas
  Four_sides<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> sides;
  Side_report side_report;           ///< how the corners were found
  Repair_report repair;              ///< what the fold repair did
  double milliseconds = 0;           ///< sides, four distance runs, (u,v), repair and chart (kd-tree)
};

/// Parameterizes every patch of `seg` as a chart of `atlas`: canonical sides
/// from the neighbouring regions (`region_sides()`), then the diffusion
/// coordinates on the patch (a `CGAL::Face_filtered_graph`), with edge lengths
/// computed once for the whole mesh, and distances of the kind `DistanceTag`
/// (`Default_distance_tag` = `Fmm_distance_tag` by default; `Graph_distance_tag`, the paper's; `Exact_distance_tag`).
///
/// Folds are then repaired (`repair_folds()`) unless `repair.enabled` is false.
///
/// A patch that fails (not a disc, too short a boundary) gets no chart; the
/// others are still mapped.
///
/// \param corner_names if given, #P entries: corners to follow (see `region_sides()`)
/// \param move_corners_off_ears see `region_sides()`
/// \returns #P results, one per patch
template <class TriangleMesh, class VertexPointMap, class DistanceTag = Default_distance_tag,
          class HeapTag = Fibonacci_heap_tag>
std::vector<Patch_result<TriangleMesh>> parameterize_patches(const TriangleMesh& tm,
                                                             const Segmentation<TriangleMesh>& seg,
                                                             VertexPointMap vpm, Uv_atlas<TriangleMesh>& atlas,
                                                             DistanceTag = DistanceTag(), HeapTag = HeapTag(),
                                                             const Repair_options& repair = Repair_options(),
                                                             const std::vector<Corner_names>* corner_names = nullptr,
                                                             bool move_corners_off_ears = true)
{
  using Patch = CGAL::Face_filtered_graph<TriangleMesh>;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point_2 = typename Uv_atlas<TriangleMesh>::Point_2;
  const auto lengths = edge_length_map(tm, vpm);
  std::vector<Patch_result<TriangleMesh>> results(seg.number_of_patches());

  for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
    Patch_result<TriangleMesh>& r = results[p];
    const auto start = std::chrono::steady_clock::now();
    r.status = check_patch_disc(tm, seg, p);
    if(r.status)
      r.status = region_sides(tm, seg, p, vpm, r.sides, &r.side_report,
                              corner_names && p < corner_names->size() ? &(*corner_names)[p] : nullptr,
                              move_corners_off_ears);
    if(!r.status) continue;

    const Patch patch(tm, seg.patch_faces[p]);
    auto pindex = get(boost::vertex_index, patch);
    std::vector<Point_2> uv(num_vertices(patch));
    Diffusion_coordinates<Patch, HeapTag, DistanceTag> coordinates(patch);
    r.status = coordinates.compute(r.sides, lengths, boost::make_iterator_property_map(uv.begin(), pindex));
    if(!r.status) continue;
    repair_folds(patch, vpm, r.sides, boost::make_iterator_property_map(uv.begin(), pindex), &r.repair, repair);

    std::vector<vertex_descriptor> chart_vertices(num_vertices(patch));
    for(vertex_descriptor v : vertices(patch)) chart_vertices[get(pindex, v)] = v;
    r.chart = atlas.add_chart(seg.patch_faces[p], std::move(chart_vertices), std::move(uv));
    r.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  return results;
}

} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_PARAMETERIZE_PATCHES_H
