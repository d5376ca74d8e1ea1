// diffuv: every patch of a segmented mesh parameterized onto its own unit square
// (the paper's section 2.8: "the diffusion processes each region on the mesh
// separately").
#ifndef DIFFUV_PARAMETERIZATION_PARAMETERIZE_PATCHES_H
#define DIFFUV_PARAMETERIZATION_PARAMETERIZE_PATCHES_H

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/core/error.h>
#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/heap_tags.h>
#include <diffuv/parameterization/chart_rectangle.h>
#include <diffuv/parameterization/diffusion_coordinates.h>
#include <diffuv/parameterization/known_charts.h>
#include <diffuv/parameterization/repair_folds.h>
#include <diffuv/patches/patch_mesh.h>
#include <diffuv/patches/region_sides.h>
#include <diffuv/patches/segmentation.h>

#include <diffuv/graph/patch_graph.h>

#include <CGAL/boost/graph/Face_filtered_graph.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>
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
  double milliseconds = 0;           ///< sides, four distance runs, (u,v), repair and chart (kd-tree), on its thread (for a map taken from `known_charts`: the disc check, sides and chart)
};

namespace internal {

// What one patch leaves for the atlas; filled in parallel, added in patch order.
template <class TriangleMesh>
struct Patch_chart {
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vertices;
  std::vector<typename Uv_atlas<TriangleMesh>::Point_2> uv;
};

// The scratch of one thread: kept from one patch to the next.
template <class TriangleMesh, class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>
struct Patch_scratch {
  Patch_graph<TriangleMesh> graph;
  Patch_mesh<TriangleMesh, VertexPointMap> mesh;
  Four_sides<typename Patch_mesh<TriangleMesh, VertexPointMap>::vertex_descriptor> mesh_sides;  // the sides on `mesh`
};

// Runs `body(p, scratch)` for every patch, on `threads` threads (0: as many
// as oneTBB's default arena; 1 or no oneTBB: one after the other).
template <class TriangleMesh, class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type,
          class Body>
void for_each_patch(std::size_t patches, std::size_t threads, Body body)
{
  using Scratch = Patch_scratch<TriangleMesh, VertexPointMap>;
#ifdef CGAL_LINKED_WITH_TBB
  if(threads != 1 && patches > 1) {
    tbb::enumerable_thread_specific<Scratch> scratch;
    auto loop = [&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, patches, 1), [&](const tbb::blocked_range<std::size_t>& r) {
        Scratch& local = scratch.local();
        for(std::size_t p = r.begin(); p != r.end(); ++p) body(p, local);
      });
    };
    if(threads == 0) {
      loop();
    } else {
      tbb::task_arena arena(static_cast<int>(threads));
      arena.execute(loop);
    }
    return;
  }
#endif
  (void)threads;
  Scratch scratch;
  for(std::size_t p = 0; p < patches; ++p) body(p, scratch);
}

} // namespace internal

/// Options of `parameterize_patches()`.
struct Patch_parameterization_options {
  Repair_options repair;  ///< whether and how folds are repaired (`repair_folds()`); on by default
  /// If given, #P entries: for each patch, the corners of the same region on
  /// another mesh to follow (see `region_sides()`; correspondence).
  const std::vector<Corner_names>* corner_names = nullptr;
  bool move_corners_off_ears = true;  ///< see `Region_sides_options`
  /// How many threads map patches: 0 as many as the machine has, 1 one after the other.
  std::size_t threads = 0;
  /// How each chart is drawn on its rectangle (`fit_chart_drawing()`): the
  /// warps of u and v; `drawing.pieces` 0 keeps the rectangle of least L2
  /// stretch and no warp.
  Chart_drawing_options drawing;
  /// If given, maps made before (by the layout's judge: `Raw_map_judge_options::known_charts`):
  /// a patch whose faces, sides, distances, heap and repair options match one
  /// of them takes its map instead of being mapped again (the same chart bit
  /// for bit; its rectangle and warps are fitted as for any other).
  const Known_charts* known_charts = nullptr;
};

namespace internal {

// The preconditions of parameterize_patches() (see its \throws).
template <class TriangleMesh>
void check_patch_inputs(const TriangleMesh& tm, const Segmentation<TriangleMesh>& seg,
                        const Uv_atlas<TriangleMesh>& atlas, const Patch_parameterization_options& options)
{
  auto fail = [](const std::string& what) { throw std::invalid_argument("parameterize_patches: " + what); };
  if(&atlas.mesh() != &tm) fail("the atlas maps another mesh");
  const std::size_t faces_of_mesh = static_cast<std::size_t>(num_faces(tm)), patches = seg.number_of_patches();
  auto count_text = [](std::size_t n, const std::string& one, const std::string& many = "") {
    return std::to_string(n) + " " + (n == 1 ? one : many.empty() ? one + "s" : many);
  };
  const std::string segmentation_has = "the segmentation has " + count_text(patches, "patch", "patches") + " but ";
  if(seg.face_patch.size() != faces_of_mesh)
    fail("the segmentation has " + count_text(seg.face_patch.size(), "face entry", "face entries") + ", the mesh " +
         count_text(faces_of_mesh, "face"));
  if(seg.patch_label.size() != patches || seg.patch_part.size() != patches)
    fail(segmentation_has + count_text(seg.patch_label.size(), "label") + " and " +
         count_text(seg.patch_part.size(), "part number"));
  if(!seg.patch_corners.empty() && seg.patch_corners.size() != patches)
    fail(segmentation_has + count_text(seg.patch_corners.size(), "corner entry", "corner entries"));
  auto findex = get(boost::face_index, tm);
  for(std::size_t p = 0; p < patches; ++p)
    for(auto f : seg.patch_faces[p])
      if(f == boost::graph_traits<TriangleMesh>::null_face() || static_cast<std::size_t>(get(findex, f)) >= faces_of_mesh)
        fail("patch " + std::to_string(p) + " lists a face that is not a face of the mesh");
  if(options.corner_names && options.corner_names->size() != patches)
    fail("options.corner_names has " + count_text(options.corner_names->size(), "entry", "entries") + ", the segmentation " +
         count_text(patches, "patch", "patches"));
}

} // namespace internal

/// Parameterizes every patch of `seg` as a chart of `atlas`: canonical sides
/// from the neighbouring regions (`region_sides()`), then the diffusion
/// coordinates on the patch, with edge lengths computed once for the whole
/// mesh, and distances of the kind `DistanceTag` (`Default_distance_tag` =
/// `Fmm_distance_tag` by default; `Graph_distance_tag`, the paper's;
/// `Exact_distance_tag`).
///
/// Folds are then repaired (`repair_folds()`) unless `options.repair.enabled` is false.
///
/// With graph distances and no repair (the paper's method) each patch is
/// copied into a compact graph (`Patch_graph`) for its four runs; otherwise
/// the runs and the repair walk a `CGAL::Face_filtered_graph` of the mesh.
/// Patches are mapped in parallel when oneTBB is linked (CMake option
/// `DIFFUV_WITH_TBB`), and the four passes of a single patch on two threads
/// (with fast marching, both engines share one set of tables); the charts are
/// added in patch order, so the atlas and the results do not depend on the
/// number of threads.
///
/// A patch that fails (not a disc, too short a boundary) gets no chart; the
/// others are still mapped. A patch whose map is in `options.known_charts`
/// takes it from there (its disc check and sides are still made).
///
/// \tparam DistanceTag the distance diffused from each side (graph/distance_tags.h)
/// \tparam HeapTag the Dijkstra's heap (graph/heap_tags.h)
/// \returns #P results, one per patch
/// \throws std::invalid_argument, before anything is mapped, if `atlas` maps
///         another mesh than `tm`, if `seg` is not a segmentation of `tm` (its
///         `face_patch` has not one entry per face, `patch_label` or
///         `patch_part` not one per patch, `patch_corners` neither none nor one
///         per patch, or a patch lists a face that `tm` does not have), or if
///         `options.corner_names` is given without one entry per patch
template <class DistanceTag = Default_distance_tag, class HeapTag = Fibonacci_heap_tag, class TriangleMesh,
          class VertexPointMap>
std::vector<Patch_result<TriangleMesh>> parameterize_patches(const TriangleMesh& tm, VertexPointMap vpm,
                                                             const Segmentation<TriangleMesh>& seg,
                                                             Uv_atlas<TriangleMesh>& atlas,
                                                             const Patch_parameterization_options& options = {})
{
  internal::check_patch_inputs(tm, seg, atlas, options);
  const Repair_options& repair = options.repair;
  const std::size_t threads = options.threads;
  using Patch = CGAL::Face_filtered_graph<TriangleMesh>;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const auto lengths = edge_length_map(tm, vpm);
  const auto findex_of_mesh = get(boost::face_index, tm);
  const bool compact_graph = std::is_same<DistanceTag, Graph_distance_tag>::value && !repair.enabled;
  std::vector<Patch_result<TriangleMesh>> results(seg.number_of_patches());
  std::vector<internal::Patch_chart<TriangleMesh>> charts(seg.number_of_patches());
  // Known maps name their vertices by index.
  const Known_charts* known_charts = options.known_charts && !options.known_charts->empty() ? options.known_charts : nullptr;
  std::vector<vertex_descriptor> vertex_by_index;
  if(known_charts) {
    auto vindex = get(boost::vertex_index, tm);
    for(vertex_descriptor v : vertices(tm)) {
      const std::size_t i = static_cast<std::size_t>(get(vindex, v));
      if(i >= vertex_by_index.size()) vertex_by_index.resize(i + 1, boost::graph_traits<TriangleMesh>::null_vertex());
      vertex_by_index[i] = v;
    }
  }

  // One patch (a disc mesh): its four distance passes on two threads instead,
  // the second engine sharing the first's tables (same distances).
  const bool parallel_passes = threads != 1 && seg.number_of_patches() == 1;
  internal::for_each_patch<TriangleMesh, VertexPointMap>(seg.number_of_patches(), threads, [&](std::size_t p, auto& scratch) {
    Patch_result<TriangleMesh>& r = results[p];
    internal::Patch_chart<TriangleMesh>& chart = charts[p];
    const auto start = std::chrono::steady_clock::now();
    r.status = check_patch_disc(tm, seg, p);
    if(r.status)
      r.status = region_sides(tm, vpm, seg, p, r.sides,
                              Region_sides_options{options.corner_names ? &(*options.corner_names)[p] : nullptr,
                                                   options.move_corners_off_ears},
                              &r.side_report);
    if(!r.status) return;

    if(known_charts) {
      const Known_charts::Chart* known =
          known_charts->find<DistanceTag, HeapTag>(Known_charts::key(tm, seg.patch_faces[p], r.sides), repair);
      // (Every index a vertex of the mesh, as it is for a map of this mesh.)
      if(known && std::all_of(known->vertices.begin(), known->vertices.end(), [&](std::size_t i) {
           return i < vertex_by_index.size() && vertex_by_index[i] != boost::graph_traits<TriangleMesh>::null_vertex();
         })) {
        chart.vertices.reserve(known->vertices.size());
        for(std::size_t i : known->vertices) chart.vertices.push_back(vertex_by_index[i]);
        chart.uv.reserve(known->uv.size());
        for(const auto& q : known->uv) chart.uv.emplace_back(q[0], q[1]);
        r.repair = known->repair;
        r.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        return;
      }
    }

    if(compact_graph) {
      auto findex = get(boost::face_index, tm);
      auto& pg = scratch.graph;
      pg.build(tm, seg.patch_faces[p],
               [&](auto f) { return f != boost::graph_traits<TriangleMesh>::null_face() && seg.face_patch[get(findex, f)] == p; },
               lengths);
      const auto local_sides = pg.local_sides(tm, r.sides);
      chart.uv.resize(pg.number_of_vertices());
      Diffusion_coordinates<typename Patch_graph<TriangleMesh>::Graph, Graph_distance_tag, HeapTag> coordinates(
          pg.graph());
      r.status = coordinates.compute(local_sides, pg.length_map(),
                                     boost::make_iterator_property_map(chart.uv.begin(),
                                                                       get(boost::vertex_index, pg.graph())),
                                     parallel_passes);
      if(!r.status) return;
      chart.vertices = pg.mesh_vertices();
    } else if(auto& pm = scratch.mesh; pm.build(tm, vpm, seg.patch_faces[p], [&](auto f) {
                return f != boost::graph_traits<TriangleMesh>::null_face() && seg.face_patch[get(findex_of_mesh, f)] == p;
              }) && pm.local_sides(tm, r.sides, scratch.mesh_sides)) {
      // The patch copied as a mesh of its own: its walks cost O(patch), not
      // O(mesh) as on a Face_filtered_graph (kept below for a patch that
      // cannot be copied).
      const auto& patch = pm.mesh();
      chart.uv.resize(num_vertices(patch));
      auto uv = boost::make_iterator_property_map(chart.uv.begin(), get(boost::vertex_index, patch));
      Diffusion_coordinates<std::decay_t<decltype(patch)>, DistanceTag, HeapTag> coordinates(patch);
      r.status = coordinates.compute(scratch.mesh_sides, edge_length_map(patch), uv, parallel_passes);
      if(!r.status) return;
      repair_folds(patch, patch.points(), scratch.mesh_sides, uv, repair, &r.repair);
      chart.vertices = pm.mesh_vertices();
    } else {
      const Patch patch(tm, seg.patch_faces[p]);
      auto pindex = get(boost::vertex_index, patch);
      chart.uv.resize(num_vertices(patch));
      Diffusion_coordinates<Patch, DistanceTag, HeapTag> coordinates(patch);
      r.status = coordinates.compute(r.sides, lengths, boost::make_iterator_property_map(chart.uv.begin(), pindex));
      if(!r.status) return;
      repair_folds(patch, vpm, r.sides, boost::make_iterator_property_map(chart.uv.begin(), pindex), repair, &r.repair);
      chart.vertices.resize(num_vertices(patch));
      for(vertex_descriptor v : vertices(patch)) chart.vertices[get(pindex, v)] = v;
    }
    r.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  });

  // Every chart first, then their rectangles: a look-up after add_chart()
  // re-indexes the atlas's vertices, once per chart if the two alternated
  // (5 % of man's whole run, measured).
  std::vector<double> add_milliseconds(seg.number_of_patches(), 0.);
  for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
    if(!results[p].status) continue;
    const auto start = std::chrono::steady_clock::now();
    results[p].chart = atlas.add_chart(seg.patch_faces[p], std::move(charts[p].vertices), std::move(charts[p].uv));
    add_milliseconds[p] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  // Each chart touches only its own rectangle and warps: in parallel, once
  // the atlas's look-ups are built (a look-up after add_chart() builds them,
  // which is not thread-safe).
  atlas.prepare_lookups();
  internal::for_each_patch<TriangleMesh, VertexPointMap>(seg.number_of_patches(), options.threads,
                                                         [&](std::size_t p, auto&) {
    if(!results[p].status) return;
    const auto start = std::chrono::steady_clock::now();
    const std::size_t c = results[p].chart;
    const auto size = stretch_optimal_rectangle(tm, vpm, atlas.chart(c).faces, atlas.chart_uv_map(c),
                                                side_length_rectangle(results[p].sides, vpm));
    draw_chart(atlas, c, vpm, size, options.drawing);
    results[p].milliseconds += add_milliseconds[p] +
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  });
  return results;
}

} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_PARAMETERIZE_PATCHES_H
