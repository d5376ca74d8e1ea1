// diffuv: which arcs of the cell complex lose their cut. A collapsed arc has
// no midpoint and no cut: the dual regions at its two ends merge into one
// with four midpoints. Arcs without an interior vertex must collapse; short
// ones, or crossed next to a junction, do when both cells keep two cuts and
// neither junction is in another collapse (so that dual regions keep at most
// four midpoints).
#ifndef DIFFUV_LAYOUT_INTERNAL_ARC_COLLAPSES_H
#define DIFFUV_LAYOUT_INTERNAL_ARC_COLLAPSES_H

#include <diffuv/layout/internal/cell_complex.h>
#include <diffuv/layout/quad_layout_options.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace diffuv {
namespace internal {

/// The collapses made so far and the rules for more. Reads the complex's
/// `framed` flags when asked, so cells framed later are seen.
template <class TriangleMesh>
class Arc_collapses {
public:
  using Arc = Cell_arc<TriangleMesh>;
  static constexpr std::size_t none = Cell_complex<TriangleMesh>::none;

  /// `region_of_cell`: each cell's labelled region, or null (no labels);
  /// `collapsed` counts the collapses.
  Arc_collapses(Cell_complex<TriangleMesh>& complex, const std::vector<std::size_t>* region_of_cell, std::size_t& collapsed)
      : complex_(complex), region_of_cell_(region_of_cell), collapsed_(collapsed),
        cuts_(complex.cell.size(), 0), mean_arc_(complex.cell.size(), 0.)
  {
    for(std::size_t c = 0; c < complex.cell.size(); ++c) {
      if(complex.fallback[c]) continue;
      for(std::size_t a : complex.cell[c].arc) mean_arc_[c] += complex.arcs[a].length;
      mean_arc_[c] /= static_cast<double>(complex.cell[c].arc.size());
      cuts_[c] = complex.cell[c].arc.size();
    }
  }

  /// Whether `arc` may collapse with both its cells keeping more than `min_cuts` cuts.
  bool may_collapse(const Arc& arc, std::size_t min_cuts) const
  {
    // Arcs along the mesh border (or the edge of the faces laid out) keep
    // their midpoints: collapsing one would leave a quad with two corners on
    // one straight stretch of border.
    if(arc.collapsed || arc.cell[0] == none || arc.cell[1] == none || complex_.framed[arc.cell[0]] || complex_.framed[arc.cell[1]])
      return false;
    // Arcs on a labelled region's border too: the dual regions there must
    // split into the cells' own sectors (a fan across the border would cross it).
    if(region_of_cell_ && (*region_of_cell_)[arc.cell[0]] != (*region_of_cell_)[arc.cell[1]]) return false;
    for(std::size_t c : arc.cell)
      if(c != none && cuts_[c] <= min_cuts) return false;
    for(std::size_t v : arc.end)
      if(junction_in_collapse_.count(v)) return false;
    return true;
  }

  void collapse(Arc& arc)
  {
    arc.collapsed = true;
    ++collapsed_;
    for(std::size_t c : arc.cell)
      if(c != none) --cuts_[c];
    for(std::size_t v : arc.end) junction_in_collapse_[v] = 1;
  }

  /// The collapses made before any fan: arcs without a midpoint, short arcs
  /// and arcs crossed next to a junction (shortest first, relative to their
  /// cells' mean arc), then arcs of cells with more than `max_cuts` cuts.
  void collapse_short_arcs(const Quad_layout_options& options)
  {
    auto& arcs = complex_.arcs;
    std::vector<std::size_t> by_length(arcs.size());
    std::iota(by_length.begin(), by_length.end(), 0);
    std::sort(by_length.begin(), by_length.end(), [&](std::size_t x, std::size_t y) {
      return arcs[x].length / reference(arcs[x]) < arcs[y].length / reference(arcs[y]);
    });
    for(std::size_t a : by_length)
      if(!arcs[a].has_mid) collapse(arcs[a]);
    for(std::size_t a : by_length)
      if((arcs[a].length < options.short_arc_fraction * reference(arcs[a]) || (options.collapse_near_junction && arcs[a].near_junction)) &&
         may_collapse(arcs[a], 2))
        collapse(arcs[a]);
    if(options.max_cuts > 0)
      for(std::size_t a : by_length) {
        bool over = false;
        for(std::size_t c : arcs[a].cell)
          if(c != none && cuts_[c] > options.max_cuts) over = true;
        if(over && may_collapse(arcs[a], 3)) collapse(arcs[a]);
      }
  }

private:
  // The shorter mean arc of the arc's cells: what "short" is measured against.
  double reference(const Arc& arc) const
  {
    double ref = std::numeric_limits<double>::infinity();
    for(std::size_t c : arc.cell)
      if(c != none) ref = std::min(ref, mean_arc_[c]);
    return ref;
  }

  Cell_complex<TriangleMesh>& complex_;
  const std::vector<std::size_t>* region_of_cell_;
  std::size_t& collapsed_;
  std::vector<std::size_t> cuts_;   // by cell: arcs still cut
  std::vector<double> mean_arc_;    // by cell
  std::unordered_map<std::size_t, char> junction_in_collapse_;
};

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_LAYOUT_INTERNAL_ARC_COLLAPSES_H
