// diffuv: disc cells split into four-sided patches, the heart of the
// four-sided layout (layout/quad_layout.h):
//
//   arcs between junctions, a midpoint on each (where the two cells' centres
//   are nearest each other across it), short arcs collapsed
//     (internal/cell_complex.h, internal/arc_collapses.h)
//   -> each cell fanned from its centre to the midpoints of its arcs, or, for
//      an extremity, framed by walls (internal/cell_fans.h, internal/frame_cell.h)
//   -> the sectors holding one junction form a dual region (a triangle of the
//      dual of the cells, or a quadrilateral where an arc collapsed), fanned
//      from its own centre to the midpoints on its border (internal/dual_regions.h)
//   -> quads (cell centre, midpoint, region centre, midpoint), checked and ordered.
#ifndef DIFFUV_LAYOUT_QUADS_FROM_CELLS_H
#define DIFFUV_LAYOUT_QUADS_FROM_CELLS_H

#include <diffuv/core/error.h>
#include <diffuv/layout/fan_split.h>
#include <diffuv/layout/internal/arc_collapses.h>
#include <diffuv/layout/internal/cell_centres.h>
#include <diffuv/layout/internal/cell_complex.h>
#include <diffuv/layout/internal/cell_fans.h>
#include <diffuv/layout/internal/dual_regions.h>
#include <diffuv/layout/internal/frame_cell.h>
#include <diffuv/layout/quad_layout_options.h>
#include <diffuv/patches/patches_from_labels.h>
#include <diffuv/patches/segmentation.h>
#include <diffuv/patches/split_at_junctions.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace diffuv {
namespace internal {

/// What `quad_layout()` keeps from one refinement round to the next.
template <class TriangleMesh>
struct Quads_memo {
  Fan_memo<TriangleMesh> fans;
  Centre_distance_memo centre_distances;
};

} // namespace internal

/// Splits disc cells into four-sided patches (see the top of this header).
///
/// \param cells the cells: discs of faces; faces with no cell are left out
/// \param quads receives the patches: quads with their corners in
///        `patch_corners` ((0,0) at the cell centre), then the fallback
///        patches (null corners); labels are patch numbers
/// \returns `ok`; the report says how many patches are fallbacks
template <class TriangleMesh, class VertexPointMap>
Status quads_from_cells(const TriangleMesh& tm, VertexPointMap vpm, const Segmentation<TriangleMesh>& cells,
                        Segmentation<TriangleMesh>& quads, const Quad_layout_options& options = Quad_layout_options(),
                        Quad_layout_report* report = nullptr, const std::vector<std::size_t>* region_of_cell = nullptr,
                        internal::Quads_memo<TriangleMesh>* memo = nullptr)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  Quad_layout_report local_report;
  Quad_layout_report& r = report ? *report : local_report;
  auto findex = get(boost::face_index, tm);
  const std::size_t nc = cells.number_of_patches();
  r.cells = nc;
  std::vector<int> scratch(num_vertices(tm), -1);
  internal::Quads_memo<TriangleMesh> own_memo;
  internal::Fan_memo<TriangleMesh>& fans_made = memo ? memo->fans : own_memo.fans;

  const std::vector<double> centre_distance = internal::distance_to_cell_centres(tm, vpm, cells, memo ? &memo->centre_distances : nullptr);
  internal::Cell_complex<TriangleMesh> complex = internal::cell_complex(tm, vpm, cells, centre_distance);
  internal::mark_deep_cells(tm, vpm, cells, options.frame_depth, complex, scratch);
  internal::Arc_collapses<TriangleMesh> collapses(complex, region_of_cell, r.collapsed_arcs);
  collapses.collapse_short_arcs(options);
  internal::Quad_pieces<TriangleMesh> framed_quads;
  const std::vector<std::size_t> framed_count = internal::frame_deep_cells(tm, vpm, cells, complex, scratch, framed_quads, r.framed_cells);
  const auto fans = internal::fan_cells(tm, vpm, cells, complex, collapses, options, fans_made, scratch);
  // A fallback cell's arcs keep their cuts on the other side: its neighbours' fans stand.
  for(std::size_t c = 0; c < nc; ++c)
    if(complex.fallback[c]) ++r.cell_fallbacks;

  internal::Quad_list<TriangleMesh> list;
  for(std::size_t c = 0, next = 0; c < nc; ++c) {
    if(!complex.framed[c]) continue;
    // frame_deep_cells() appended the quads of the framed cells in cell order.
    const std::size_t count = framed_count[c];
    for(std::size_t q = next; q < next + count; ++q) list.add(std::move(framed_quads[q].first), framed_quads[q].second, c);
    next += count;
  }
  internal::split_dual_regions(tm, vpm, cells, complex, fans, region_of_cell, fans_made, scratch, list, r);

  // ---- order: quads by the cell of their centre corner (the cells' order), then by decreasing area
  std::vector<std::size_t> order(list.faces.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> area(order.size(), 0.);
  for(std::size_t q = 0; q < order.size(); ++q)
    for(face_descriptor f : list.faces[q])
      area[q] += CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(f, tm, CGAL::parameters::vertex_point_map(vpm)));
  auto cell_of = [&](std::size_t q) { return list.cell[q]; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if(cell_of(a) != cell_of(b)) return cell_of(a) < cell_of(b);
    return area[a] > area[b];
  });
  Segmentation<TriangleMesh> sorted;
  sorted.face_patch.assign(num_faces(tm), Segmentation<TriangleMesh>::no_patch);
  for(std::size_t q : order) {
    sorted.patch_faces.push_back(std::move(list.faces[q]));
    sorted.patch_corners.push_back(list.corners[q]);
  }
  r.quads = sorted.patch_faces.size();
  std::vector<std::size_t> marks;  // connected_parts()'s, shared by the pieces
  for(auto& piece : list.fallback_pieces) {
    // A piece may be in several components: each is a patch.
    for(auto& part : connected_parts(tm, vpm, piece, marks)) {
      sorted.patch_faces.push_back(std::move(part));
      sorted.patch_corners.push_back(Segmentation<TriangleMesh>::no_corners());
      ++r.fallback_patches;
    }
  }
  for(std::size_t p = 0; p < sorted.patch_faces.size(); ++p) {
    sorted.patch_label.push_back(static_cast<int>(p));
    sorted.patch_part.push_back(0);
    for(face_descriptor f : sorted.patch_faces[p]) sorted.face_patch[get(findex, f)] = p;
  }
  // A quad must be a disc with its four corners on its border, counter-
  // clockwise; one that is not keeps its faces as an ordinary patch.
  std::size_t invalid = 0;
  std::vector<Patch_loop<TriangleMesh>> loops;
  for(std::size_t p = 0; p < r.quads; ++p) {
    const auto& corner = sorted.patch_corners[p];
    bool valid = static_cast<bool>(check_patch_disc(tm, vpm, sorted, p, loops));
    if(valid) {
      const auto& loop = loops.front().vertices;
      std::array<std::size_t, 4> at{};
      for(std::size_t k = 0; k < 4 && valid; ++k) {
        at[k] = static_cast<std::size_t>(std::find(loop.begin(), loop.end(), corner[k]) - loop.begin());
        valid = at[k] < loop.size();
      }
      for(std::size_t k = 1; k < 4 && valid; ++k)
        valid = (at[k] + loop.size() - at[0]) % loop.size() > (at[k - 1] + loop.size() - at[0]) % loop.size();
    }
    if(!valid) {
      sorted.patch_corners[p] = Segmentation<TriangleMesh>::no_corners();
      ++invalid;
    }
  }
  r.quads -= invalid;
  r.fallback_patches += invalid;
  // A fallback patch that needs more corners than four (junctions, ear tips)
  // is cut between junctions, so that each piece can have them all.
  if(options.split_at_junctions)
    for(std::size_t p = 0; p < sorted.number_of_patches(); ++p) {
      if(sorted.corners(p)) continue;
      const std::size_t pieces = split_at_junctions(tm, vpm, sorted, p, options.max_cut_ratio);
      if(pieces > 1) {
        ++r.split_fallbacks;
        r.fallback_patches += pieces - 1;
        p += pieces - 1;
      }
    }
  for(std::size_t p = 0; p < sorted.number_of_patches(); ++p) {
    sorted.patch_label[p] = static_cast<int>(p);
    sorted.patch_part[p] = 0;
  }
  quads = std::move(sorted);
  return Status();
}

} // namespace diffuv

#endif // DIFFUV_LAYOUT_QUADS_FROM_CELLS_H
