// diffuv: the first split of the four-sided layout: each cell of the complex
// fanned from its centre to the midpoints of its cut arcs (fan_split.h), or,
// for an extremity, framed by walls (frame_cell.h). Where a fan fails or has a
// sector too thin, an arc of the cell collapses and the cells on both sides of
// it are fanned again.
#ifndef DIFFUV_LAYOUT_INTERNAL_CELL_FANS_H
#define DIFFUV_LAYOUT_INTERNAL_CELL_FANS_H

#include <diffuv/layout/fan_split.h>
#include <diffuv/layout/internal/arc_collapses.h>
#include <diffuv/layout/internal/cell_complex.h>
#include <diffuv/layout/internal/frame_cell.h>
#include <diffuv/layout/quad_layout_options.h>
#include <diffuv/patches/segmentation.h>

#include <array>
#include <cstddef>
#include <vector>

namespace diffuv {
namespace internal {

/// A cell's fan: its sectors, between the cuts to its arcs' midpoints.
template <class TriangleMesh>
struct Cell_fan {
  std::vector<std::size_t> cut_arcs;   // positions in Cell_rim::arc of the arcs with a cut, in loop order
  std::vector<int> sector_of_face;     // by position in cells.patch_faces[c]
  typename boost::graph_traits<TriangleMesh>::vertex_descriptor centre;
  bool done = false;
};

/// Frames the complex's deep cells (`framed`); a cell that cannot be framed
/// loses the flag. Appends the quads of the framed cells to `quads` in cell
/// order and returns how many each cell made.
template <class TriangleMesh, class VertexPointMap>
std::vector<std::size_t> frame_deep_cells(const TriangleMesh& tm, VertexPointMap vpm, const Segmentation<TriangleMesh>& cells,
                                          Cell_complex<TriangleMesh>& complex, std::vector<int>& scratch,
                                          Quad_pieces<TriangleMesh>& quads, std::size_t& framed_cells)
{
  std::vector<std::size_t> count(cells.number_of_patches(), 0);
  for(std::size_t c = 0; c < cells.number_of_patches(); ++c) {
    if(!complex.framed[c]) continue;
    const std::size_t before = quads.size();
    complex.framed[c] = frame_cell(tm, vpm, cells.patch_faces[c], complex.cell[c].loop.vertices, complex.cell[c].junctions,
                                   [&](std::size_t a) { return complex.arcs[complex.cell[c].arc[a]].mid; }, scratch, quads);
    count[c] = quads.size() - before;
    if(complex.framed[c]) ++framed_cells;
  }
  return count;
}

/// Fans every cell that is neither framed nor a fallback. A cell with fewer
/// than two cut arcs, or whose fan fails with no arc left to collapse,
/// becomes a fallback; a thin sector (below `options.min_opening`) is kept
/// when no arc beside it may collapse.
template <class TriangleMesh, class VertexPointMap>
std::vector<Cell_fan<TriangleMesh>> fan_cells(const TriangleMesh& tm, VertexPointMap vpm, const Segmentation<TriangleMesh>& cells,
                                              Cell_complex<TriangleMesh>& complex, Arc_collapses<TriangleMesh>& collapses,
                                              const Quad_layout_options& options, Fan_memo<TriangleMesh>& fans_made,
                                              std::vector<int>& scratch)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  constexpr std::size_t none = Cell_complex<TriangleMesh>::none;
  const std::size_t nc = cells.number_of_patches();
  auto& arcs = complex.arcs;
  std::vector<Cell_fan<TriangleMesh>> fans(nc);
  for(std::size_t c = 0; c < nc; ++c) fans[c].done = complex.framed[c];
  // The fans the first pass below asks for, made in parallel beforehand.
  std::vector<typename Fan_memo<TriangleMesh>::Request> first_pass;
  for(std::size_t c = 0; c < nc; ++c) {
    if(complex.fallback[c] || fans[c].done) continue;
    const Cell_rim<TriangleMesh>& cc = complex.cell[c];
    std::vector<vertex_descriptor> targets;
    for(std::size_t a = 0; a < cc.arc.size(); ++a)
      if(!arcs[cc.arc[a]].collapsed) targets.push_back(arcs[cc.arc[a]].mid);
    if(targets.size() >= 2) first_pass.push_back({&cells.patch_faces[c], &cc.loop.vertices, std::move(targets)});
  }
  fans_made.prefetch(tm, vpm, first_pass);
  for(bool again = true; again;) {
    again = false;
    for(std::size_t c = 0; c < nc; ++c) {
      if(complex.fallback[c] || fans[c].done) continue;
      const Cell_rim<TriangleMesh>& cc = complex.cell[c];
      std::vector<std::size_t> with_cut;
      for(std::size_t a = 0; a < cc.arc.size(); ++a)
        if(!arcs[cc.arc[a]].collapsed) with_cut.push_back(a);
      if(with_cut.size() < 2) { complex.fallback[c] = 1; continue; }
      std::vector<vertex_descriptor> targets;
      for(std::size_t a : with_cut) targets.push_back(arcs[cc.arc[a]].mid);
      const auto& made = fans_made.fan(tm, vpm, cells.patch_faces[c], cc.loop.vertices, targets, scratch);
      const Fan& fan = made.fan;
      const bool split = made.failure == Fan_failure::none;
      std::size_t thin = with_cut.size();
      if(split)
        for(std::size_t s = 0; s < fan.opening.size(); ++s)
          if(fan.opening[s] < options.min_opening && (thin == with_cut.size() || fan.opening[s] < fan.opening[thin])) thin = s;
      auto keep = [&] {
        fans[c].cut_arcs = with_cut;
        fans[c].sector_of_face = fan.sector_of_face;
        fans[c].centre = made.centre;
        fans[c].done = true;
      };
      if(split && thin == with_cut.size()) {
        keep();
        continue;
      }
      // Collapse an arc and try again: beside a thin sector, the shorter of its
      // two arcs; after a failure, the shortest arc that may collapse.
      std::size_t chosen = none;
      if(thin < with_cut.size()) {
        const std::size_t a0 = cc.arc[with_cut[thin]], a1 = cc.arc[with_cut[(thin + 1) % with_cut.size()]];
        for(std::size_t a : arcs[a0].length <= arcs[a1].length ? std::array<std::size_t, 2>{a0, a1} : std::array<std::size_t, 2>{a1, a0})
          if(chosen == none && collapses.may_collapse(arcs[a], 2)) chosen = a;
      } else {
        for(std::size_t a : with_cut)
          if(collapses.may_collapse(arcs[cc.arc[a]], 2) && (chosen == none || arcs[cc.arc[a]].length < arcs[chosen].length)) chosen = cc.arc[a];
      }
      if(chosen == none) {
        if(split) keep();  // a thin sector is better than no fan
        else complex.fallback[c] = 1;
        continue;
      }
      collapses.collapse(arcs[chosen]);
      for(std::size_t d : arcs[chosen].cell)
        if(d != none) fans[d].done = false;
      again = true;
    }
  }
  return fans;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_LAYOUT_INTERNAL_CELL_FANS_H
