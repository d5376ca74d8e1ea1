// diffuv: the second split of the four-sided layout. The sectors of the
// cells' fans (cell_fans.h) that hold one junction (or two, across a
// collapsed arc) form a dual region; each dual region is fanned from its own
// centre to the midpoints on its border, and each of its sectors is a quad
// (cell centre, midpoint, region centre, midpoint). Where a region cannot be
// fanned, the cells' own sectors are the quads when each holds one junction
// (corner at the junction); otherwise the region's faces become ordinary
// patches.
#ifndef DIFFUV_LAYOUT_INTERNAL_DUAL_REGIONS_H
#define DIFFUV_LAYOUT_INTERNAL_DUAL_REGIONS_H

#include <diffuv/layout/fan_split.h>
#include <diffuv/layout/internal/cell_complex.h>
#include <diffuv/layout/internal/cell_fans.h>
#include <diffuv/layout/quad_layout_options.h>
#include <diffuv/patches/patches_from_labels.h>
#include <diffuv/patches/segmentation.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace diffuv {
namespace internal {

// Cells with fewer faces are not given more seeds to mend the cell complex.

// Union-find over indices.
class Disjoint_sets {
public:
  explicit Disjoint_sets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t x)
  {
    while(parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

private:
  std::vector<std::size_t> parent_;
};

/// The quads made so far, and the faces left to ordinary patches.
template <class TriangleMesh>
struct Quad_list {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  std::vector<std::vector<face_descriptor>> faces;
  std::vector<std::array<vertex_descriptor, 4>> corners;  // counter-clockwise
  std::vector<std::size_t> cell;  // the cell of each quad's first corner (its centre), #cells if none
  std::vector<std::vector<face_descriptor>> fallback_pieces;

  void add(std::vector<face_descriptor> quad_faces, const std::array<vertex_descriptor, 4>& quad_corners, std::size_t of_cell)
  {
    faces.push_back(std::move(quad_faces));
    corners.push_back(quad_corners);
    cell.push_back(of_cell);
  }
};

/// Splits the dual regions of the fanned cells into quads, appended to
/// `quads`; the faces of regions that give no quads, then those of the
/// fallback cells, go to `quads.fallback_pieces`. `region_of_cell`: each
/// cell's labelled region (a sector must keep to one), or null.
template <class TriangleMesh, class VertexPointMap>
void split_dual_regions(const TriangleMesh& tm, VertexPointMap vpm, const Segmentation<TriangleMesh>& cells,
                        const Cell_complex<TriangleMesh>& complex, const std::vector<Cell_fan<TriangleMesh>>& fans,
                        const std::vector<std::size_t>* region_of_cell, Fan_memo<TriangleMesh>& fans_made,
                        std::vector<int>& scratch, Quad_list<TriangleMesh>& quads, Quad_layout_report& r)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  constexpr std::size_t none = Cell_complex<TriangleMesh>::none;
  constexpr int no_dual_region = std::numeric_limits<int>::min();
  auto vindex = get(boost::vertex_index, tm);
  auto findex = get(boost::face_index, tm);
  const std::size_t nc = cells.number_of_patches();
  std::unordered_map<std::size_t, std::size_t> junction_number;
  auto number_of = [&](std::size_t v) { return junction_number.emplace(v, junction_number.size()).first->second; };
  for(const auto& arc : complex.arcs) { number_of(arc.end[0]); number_of(arc.end[1]); }
  Disjoint_sets regions(junction_number.size());
  for(const auto& arc : complex.arcs)
    if(arc.collapsed) regions.unite(number_of(arc.end[0]), number_of(arc.end[1]));
  std::vector<char> is_mid(num_vertices(tm), 0), is_centre(num_vertices(tm), 0), is_junction(num_vertices(tm), 0);
  for(const auto& arc : complex.arcs) {
    if(!arc.collapsed) is_mid[get(vindex, arc.mid)] = 1;
    is_junction[arc.end[0]] = is_junction[arc.end[1]] = 1;
  }
  std::vector<int> dual_label(num_faces(tm), no_dual_region);
  std::vector<std::size_t> cell_of_centre(num_vertices(tm), none);
  std::vector<char> framed_junction(num_vertices(tm), 0);
  for(std::size_t c = 0; c < nc; ++c)
    if(complex.framed[c])
      for(std::size_t j : complex.cell[c].junctions) framed_junction[get(vindex, complex.cell[c].loop.vertices[j])] = 1;
  for(std::size_t c = 0; c < nc; ++c) {
    if(complex.fallback[c] || complex.framed[c]) continue;
    is_centre[get(vindex, fans[c].centre)] = 1;
    cell_of_centre[get(vindex, fans[c].centre)] = c;
    const Cell_rim<TriangleMesh>& cc = complex.cell[c];
    const std::size_t k = cc.arc.size();
    const auto& with_cut = fans[c].cut_arcs;
    for(std::size_t f = 0; f < cells.patch_faces[c].size(); ++f) {
      // Sector s lies between the cuts on arcs with_cut[s] and with_cut[s+1]:
      // it holds the junction that ends arc with_cut[s].
      const std::size_t s = static_cast<std::size_t>(fans[c].sector_of_face[f]);
      const std::size_t junction = cc.junctions[(with_cut[s] + 1) % k];
      dual_label[get(findex, cells.patch_faces[c][f])] =
          static_cast<int>(regions.find(number_of(get(vindex, cc.loop.vertices[junction]))));
    }
  }
  auto cell_of = [&](vertex_descriptor centre) {
    const std::size_t c = cell_of_centre[get(vindex, centre)];
    return c == none ? nc : c;
  };
  const Segmentation<TriangleMesh> duals = patches_from_labels(tm, vpm, dual_label, no_dual_region);
  std::vector<std::size_t> position_in_cell(num_faces(tm), 0);
  for(std::size_t c = 0; c < nc; ++c)
    for(std::size_t f = 0; f < cells.patch_faces[c].size(); ++f) position_in_cell[get(findex, cells.patch_faces[c][f])] = f;

  // Each dual region fanned from its centre to its midpoints.
  // The corner between two midpoints along a loop: the one cell centre there,
  // else the one junction (next to a fallback cell or the mesh border).
  auto corner_between = [&](const std::vector<vertex_descriptor>& loop, std::size_t from, std::size_t to) {
    vertex_descriptor centre = boost::graph_traits<TriangleMesh>::null_vertex(), junction = centre;
    std::size_t centres = 0, junctions = 0;
    for(std::size_t i = (from + 1) % loop.size(); i != to; i = (i + 1) % loop.size()) {
      if(is_centre[get(vindex, loop[i])]) { centre = loop[i]; ++centres; }
      if(is_junction[get(vindex, loop[i])]) { junction = loop[i]; ++junctions; }
    }
    if(centres == 1) return centre;
    if(centres == 0 && junctions == 1) return junction;
    return boost::graph_traits<TriangleMesh>::null_vertex();
  };
  // Each region's border loop, walked once by the disc check (empty if the
  // region is not a disc).
  std::vector<Patch_loop<TriangleMesh>> loop_of(duals.number_of_patches());
  {
    // The fans the loop below asks for, made in parallel beforehand (the same
    // tests pick the regions and their targets).
    std::vector<typename Fan_memo<TriangleMesh>::Request> wanted;
    std::vector<Patch_loop<TriangleMesh>> loops;
    for(std::size_t t = 0; t < duals.number_of_patches(); ++t) {
      if(!check_patch_disc(tm, vpm, duals, t, loops)) continue;
      loop_of[t] = std::move(loops.front());
      std::vector<vertex_descriptor> targets;
      bool framed = false;
      for(vertex_descriptor v : loop_of[t].vertices) {
        framed = framed || framed_junction[get(vindex, v)];
        if(is_mid[get(vindex, v)]) targets.push_back(v);
      }
      if(!framed && targets.size() >= 2) wanted.push_back({&duals.patch_faces[t], &loop_of[t].vertices, std::move(targets)});
    }
    fans_made.prefetch(tm, vpm, wanted);
  }
  for(std::size_t t = 0; t < duals.number_of_patches(); ++t) {
    bool ok = !loop_of[t].vertices.empty();
    if(ok) {
      // Next to a framed cell, the walls end at the junction: keep the plain sectors.
      for(vertex_descriptor v : loop_of[t].vertices)
        if(framed_junction[get(vindex, v)]) ok = false;
    }
    std::vector<std::array<vertex_descriptor, 4>> corners;
    const Fan* fan_of_region = nullptr;
    if(ok) {
      const auto& loop = loop_of[t];
      const std::size_t n = loop.vertices.size();
      std::vector<std::size_t> mids;
      for(std::size_t i = 0; i < n; ++i)
        if(is_mid[get(vindex, loop.vertices[i])]) mids.push_back(i);
      ok = mids.size() >= 2;
      if(ok) {
        std::vector<vertex_descriptor> targets;
        for(std::size_t m : mids) targets.push_back(loop.vertices[m]);
        const auto& made = fans_made.fan(tm, vpm, duals.patch_faces[t], loop.vertices, targets, scratch);
        ok = made.failure == Fan_failure::none;
        fan_of_region = &made.fan;
        for(std::size_t s = 0; ok && s < mids.size(); ++s) {
          // Sector s: centre -> mids[s] -> (corner) -> mids[s+1] -> centre, counter-clockwise.
          const vertex_descriptor m0 = loop.vertices[mids[s]], m1 = loop.vertices[mids[(s + 1) % mids.size()]];
          const vertex_descriptor z = corner_between(loop.vertices, mids[s], mids[(s + 1) % mids.size()]);
          if(z == boost::graph_traits<TriangleMesh>::null_vertex()) { ok = false; break; }
          corners.push_back({z, m1, made.centre, m0});
        }
      }
    }
    if(ok && region_of_cell) {
      // A sector must keep to one region (labelled regions keep their borders).
      std::vector<std::size_t> region_of_sector(corners.size(), none);
      for(std::size_t f = 0; ok && f < duals.patch_faces[t].size(); ++f) {
        const std::size_t here = (*region_of_cell)[cells.face_patch[get(findex, duals.patch_faces[t][f])]];
        std::size_t& there = region_of_sector[static_cast<std::size_t>(fan_of_region->sector_of_face[f])];
        if(there == none) there = here;
        ok = there == here;
      }
    }
    if(ok) {
      std::vector<std::vector<face_descriptor>> sectors(corners.size());
      for(std::size_t f = 0; f < duals.patch_faces[t].size(); ++f)
        sectors[static_cast<std::size_t>(fan_of_region->sector_of_face[f])].push_back(duals.patch_faces[t][f]);
      for(std::size_t s = 0; s < corners.size(); ++s) quads.add(std::move(sectors[s]), corners[s], cell_of(corners[s][0]));
      continue;
    }
    // No fan: where each cell's sector in the region holds one junction, the
    // sectors are the quads (the plain Catmull-Clark split: cell centre,
    // midpoint, junction, midpoint); else the region's faces, cell by cell,
    // become ordinary patches.
    std::map<std::size_t, std::vector<face_descriptor>> by_cell;
    for(face_descriptor f : duals.patch_faces[t]) by_cell[cells.face_patch[get(findex, f)]].push_back(f);
    bool direct = true;
    std::vector<std::array<vertex_descriptor, 4>> sector_corners;
    for(const auto& [c, sector_faces] : by_cell) {
      const Cell_rim<TriangleMesh>& cc = complex.cell[c];
      const auto& with_cut = fans[c].cut_arcs;
      const std::size_t k = cc.arc.size(), m = with_cut.size();
      const std::size_t s = static_cast<std::size_t>(fans[c].sector_of_face[position_in_cell[get(findex, sector_faces.front())]]);
      for(face_descriptor f : sector_faces)  // the piece must be one sector of its cell
        if(static_cast<std::size_t>(fans[c].sector_of_face[position_in_cell[get(findex, f)]]) != s) direct = false;
      if(!direct) break;
      if((with_cut[s] + 1) % k != with_cut[(s + 1) % m]) { direct = false; break; }  // the sector holds two junctions or more
      sector_corners.push_back({fans[c].centre, complex.arcs[cc.arc[with_cut[s]]].mid, cc.loop.vertices[cc.junctions[(with_cut[s] + 1) % k]],
                                complex.arcs[cc.arc[with_cut[(s + 1) % m]]].mid});
    }
    if(direct) {
      ++r.plain_regions;
      std::size_t i = 0;
      for(auto& piece : by_cell) {
        quads.add(std::move(piece.second), sector_corners[i], cell_of(sector_corners[i][0]));
        ++i;
      }
      continue;
    }
    ++r.region_fallbacks;
    for(auto& piece : by_cell) quads.fallback_pieces.push_back(std::move(piece.second));
  }
  for(std::size_t c = 0; c < nc; ++c)
    if(complex.fallback[c]) quads.fallback_pieces.push_back(cells.patch_faces[c]);
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_LAYOUT_INTERNAL_DUAL_REGIONS_H
