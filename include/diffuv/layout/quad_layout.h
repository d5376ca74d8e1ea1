// diffuv: a layout of four-sided patches.
//
// The paper maps each patch onto the unit square from four sides; its map is
// clean where a patch is compact with four sides meeting near right angles,
// and collapses where the four sides all lie around one end of a tube. This
// header builds such patches from a cell complex:
//
//   Voronoi cells (layout/voronoi_cells.h: farthest-point seeds, relaxed),
//   then quads_from_cells() (layout/quads_from_cells.h):
//     -> arcs between junctions, a midpoint on each (where the two cells'
//        centres are nearest each other across it), short arcs collapsed
//     -> each cell fanned from its centre to the midpoints of its arcs
//        (layout/fan_split.h): its sectors each hold a junction
//     -> the sectors holding one junction form a dual region (a triangle of
//        the dual of the cells, or a quadrilateral where an arc collapsed),
//        fanned from its own centre to the midpoints on its border
//     -> quads (cell centre, midpoint, region centre, midpoint).
//
// It is the Catmull-Clark split of the cell complex with the Voronoi
// junctions replaced by well-centred vertices: every arc's midpoint is shared
// by the two cells, so the layout is conforming (each side of a quad is a
// whole border with one neighbour) and every quad has exactly four sides.
// Where a fan cannot be made (a cell too small for its arcs, a region that is
// not a disc), its faces become ordinary patches whose corners come from their
// neighbours (`region_sides()`), and the report counts them.
#ifndef DIFFUV_LAYOUT_QUAD_LAYOUT_H
#define DIFFUV_LAYOUT_QUAD_LAYOUT_H

#include <diffuv/core/error.h>
#include <diffuv/layout/quad_layout_options.h>
#include <diffuv/layout/quads_from_cells.h>
#include <diffuv/layout/voronoi_cells.h>
#include <diffuv/patches/patches_from_labels.h>
#include <diffuv/patches/segmentation.h>
#include <diffuv/patches/smooth_region_borders.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <type_traits>
#include <vector>

namespace diffuv {
namespace internal {

// A cell smaller than `min_faces` joins the neighbour of the same region it
// shares the longest border with, if the union is a disc; smallest first.
template <class TriangleMesh, class VertexPointMap>
void merge_small_cells(const TriangleMesh& tm, VertexPointMap vpm, std::vector<int>& labels, Segmentation<TriangleMesh>& cells,
                       const Segmentation<TriangleMesh>& regions, std::size_t min_faces)
{
  auto findex = get(boost::face_index, tm);
  for(bool merged = true; merged && min_faces > 0;) {
    merged = false;
    std::vector<std::size_t> small;
    for(std::size_t c = 0; c < cells.number_of_patches(); ++c)
      if(cells.patch_faces[c].size() < min_faces) small.push_back(c);
    std::stable_sort(small.begin(), small.end(), [&](std::size_t a, std::size_t b) {
      return cells.patch_faces[a].size() < cells.patch_faces[b].size();
    });
    for(std::size_t c : small) {
      const std::size_t region = regions.face_patch[get(findex, cells.patch_faces[c].front())];
      std::map<std::size_t, double> shared;
      for(const auto& loop : patch_loops(tm, vpm, cells, c))
        for(std::size_t i = 0; i < loop.vertices.size(); ++i) {
          const std::size_t q = loop.neighbour[i];
          if(q != Patch_loop<TriangleMesh>::mesh_border && regions.face_patch[get(findex, cells.patch_faces[q].front())] == region)
            shared[q] += loop.length[i];
        }
      std::vector<std::pair<std::size_t, double>> by_length(shared.begin(), shared.end());
      std::stable_sort(by_length.begin(), by_length.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
      for(const auto& candidate : by_length) {
        std::vector<int> trial = labels;
        for(auto f : cells.patch_faces[c]) trial[get(findex, f)] = cells.patch_label[candidate.first];
        Segmentation<TriangleMesh> joined = patches_from_labels(tm, vpm, trial, std::numeric_limits<int>::min());
        const std::size_t p = joined.face_patch[get(findex, cells.patch_faces[c].front())];
        if(joined.number_of_patches() + 1 != cells.number_of_patches() || !check_patch_disc(tm, joined, p)) continue;
        labels = std::move(trial);
        cells = std::move(joined);
        merged = true;
        break;
      }
      if(merged) break;
    }
  }
}

} // namespace internal


/// What the labels given to `quad_layout()` are.
enum class Region_labels {
  regions,  ///< the user's regions: patches keep their region's label (and a part number); four-sided regions may stay whole
  areas     ///< only what to lay out apart (e.g. components); patches are numbered; faces labelled INT_MIN are left out
};

/// A judge that finds nothing to refine: `quad_layout()` without refinement.
struct No_refinement {
  template <class TriangleMesh>
  std::vector<std::size_t> operator()(const Segmentation<TriangleMesh>&) const { return {}; }
};

namespace internal {

template <class Judge, class Seg, class = void>
struct judges_candidates : std::false_type {};
template <class Judge, class Seg>
struct judges_candidates<Judge, Seg, std::void_t<decltype(std::declval<const Judge&>()(
                                         std::declval<const Seg&>(), std::declval<const std::vector<char>&>()))>>
  : std::true_type {};

// The judge's verdict on the patches flagged in `candidates` (a judge that
// takes no flags judges them all; only flagged ones are kept).
template <class Judge, class TriangleMesh>
std::vector<std::size_t> judge_candidates(const Judge& judge, const Segmentation<TriangleMesh>& layout,
                                          const std::vector<char>& candidates)
{
  if constexpr(judges_candidates<Judge, Segmentation<TriangleMesh>>::value) {
    return judge(layout, candidates);
  } else {
    std::vector<std::size_t> bad = judge(layout);
    bad.erase(std::remove_if(bad.begin(), bad.end(), [&](std::size_t p) { return p >= candidates.size() || !candidates[p]; }),
              bad.end());
    return bad;
  }
}

// The cells of one region: Voronoi cells of its faces, seeds kept between rounds.
template <class TriangleMesh, class VertexPointMap>
struct Region_cells {
  int label = 0;
  std::unique_ptr<Voronoi_cells<TriangleMesh, VertexPointMap>> voronoi;
};

} // namespace internal

/// Lays out a mesh in four-sided patches (see the top of this header).
///
/// Each region — a connected set of faces with one label, or, without
/// labels, each connected component — is cut into graph-Voronoi cells
/// (farthest-point seeds, about one per `faces_per_cell` faces, relaxed; a
/// cell that is not a disc gets one more seed, a cell smaller than
/// `min_cell_faces` joins a neighbour of its region), and all cells are split
/// into quads at once (`quads_from_cells()`), so the layout is conforming
/// across region borders too. When the regions are a layout already (all
/// discs, at least `keep_layout_fraction` of the faces in regions with exactly
/// four runs of neighbours, e.g. what `diffuv segment` writes), they are kept
/// whole.
///
/// Refinement: `judge(layout)` returns patches whose map is not good enough;
/// the cell holding most of each gets one more seed, at the patch's face
/// farthest from the seeds (cells of fewer than `min_split_faces` faces are
/// not refined), for at most `refine_rounds` rounds. The parameterization
/// layer provides a judge that maps each patch (`raw_map_judge()`).
///
/// \tparam Judge callable as `std::vector<std::size_t>(const Segmentation<TriangleMesh>&)`;
///         if also callable with a second argument `const std::vector<char>&` (one flag per
///         patch), it is asked about the patches that could be refined only
/// \param face_labels #F labels, or empty: the components are the regions;
///        faces labelled `std::numeric_limits<int>::min()` are left out
/// \param kind what the labels are
/// \param layout receives the patches: each quad with its corners in
///        `patch_corners` ((0,0) at a cell centre), then fallback patches with
///        null corners; a patch's label is its region's label (its number
///        without labels), its part its rank in the region (0 without labels)
template <class TriangleMesh, class VertexPointMap, class Judge = No_refinement>
Status quad_layout(const TriangleMesh& tm, VertexPointMap vpm, const std::vector<int>& face_labels,
                   Segmentation<TriangleMesh>& layout, const Quad_layout_options& options = Quad_layout_options(),
                   Quad_layout_report* report = nullptr, Judge judge = Judge(),
                   Region_labels kind = Region_labels::regions)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Cells = Voronoi_cells<TriangleMesh, VertexPointMap>;
  Quad_layout_report local_report;
  Quad_layout_report& r = report ? *report : local_report;
  r = Quad_layout_report();
  auto findex = get(boost::face_index, tm);
  const bool labelled = !face_labels.empty() && kind == Region_labels::regions;

  // Regions: labelled components, or the mesh's components.
  std::vector<int> region_labels = face_labels;
  if(face_labels.empty()) {
    std::vector<std::size_t> component(num_faces(tm));
    CGAL::Polygon_mesh_processing::connected_components(tm, boost::make_iterator_property_map(component.begin(), findex));
    region_labels.assign(component.begin(), component.end());
  }
  Segmentation<TriangleMesh> regions = patches_from_labels(tm, vpm, region_labels);
  if(labelled) {
    // A layout read back (what `diffuv segment` writes): every region a disc,
    // nearly all of the surface in regions with four runs of neighbours. Its
    // regions stay the patches.
    std::size_t four_sided = 0, all_faces = 0;  // faces in regions with four runs, in all
    std::size_t four_sided_regions = 0;
    bool all_discs = true;
    for(std::size_t p = 0; p < regions.number_of_patches() && all_discs; ++p) {
      if(!check_patch_disc(tm, regions, p)) { all_discs = false; break; }
      const auto loop = patch_loops(tm, vpm, regions, p).front();
      std::size_t runs = 0;
      for(std::size_t i = 0; i < loop.neighbour.size(); ++i)
        if(loop.neighbour[(i + loop.neighbour.size() - 1) % loop.neighbour.size()] != loop.neighbour[i]) ++runs;
      if(runs == 4) {
        four_sided += regions.patch_faces[p].size();
        ++four_sided_regions;
      }
      all_faces += regions.patch_faces[p].size();
    }
    if(all_discs && static_cast<double>(four_sided) >= options.keep_layout_fraction * static_cast<double>(all_faces)) {
      layout = regions;
      r.quads = four_sided_regions;
      r.fallback_patches = regions.number_of_patches() - four_sided_regions;
      r.kept_regions = regions.number_of_patches();
      return Status();
    }
    if(options.move_region_ears) {
      r.region_ears_moved = move_ear_faces_across_borders(tm, vpm, region_labels);
      if(r.region_ears_moved > 0) regions = patches_from_labels(tm, vpm, region_labels);
    }
  }

  std::size_t total_faces = 0;
  for(const auto& faces : regions.patch_faces) total_faces += faces.size();
  const double per_cell = options.target_patches > 0
                              ? std::max(1.0, static_cast<double>(total_faces) * 5.0 / static_cast<double>(options.target_patches))
                              : options.faces_per_cell;
  std::vector<internal::Region_cells<TriangleMesh, VertexPointMap>> region_cells(regions.number_of_patches());
  for(std::size_t p = 0; p < regions.number_of_patches(); ++p) {
    auto& rc = region_cells[p];
    rc.label = regions.patch_label[p];
    const std::size_t seeds =
        std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(static_cast<double>(regions.patch_faces[p].size()) / per_cell)));
    double area = 0;
    for(auto f : regions.patch_faces[p]) area += CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(f, tm, CGAL::parameters::vertex_point_map(vpm)));
    rc.voronoi = std::make_unique<Cells>(tm, regions.patch_faces[p], vpm, options.bend * std::sqrt(area / static_cast<double>(seeds)));
    rc.voronoi->farthest_point_seeds(seeds);
    rc.voronoi->relax(options.relax_steps);
  }
  auto seed_count = [&] {
    std::size_t count = 0;
    for(const auto& rc : region_cells) count += rc.voronoi->seeds().size();
    return count;
  };
  // The faces of one cell as a mask over its region's faces, and the face there farthest from the seeds.
  auto farthest_in = [&](std::size_t region, const std::vector<face_descriptor>& faces) {
    const Cells& voronoi = *region_cells[region].voronoi;
    std::vector<char> in(voronoi.faces().size(), 0);
    for(face_descriptor f : faces) {
      const std::size_t i = voronoi.position(f);
      if(i < in.size()) in[i] = 1;
    }
    return voronoi.farthest([&](std::size_t i) { return in[i] && voronoi.distance()[i] > 0.; });
  };

  Segmentation<TriangleMesh> cells;
  std::vector<std::size_t> region_of_cell;
  internal::Quads_memo<TriangleMesh> memo;  // across rounds: most cells and fans come back unchanged
  for(std::size_t round = 0;; ++round) {
    // Cells of every region, until each is a disc.
    while(true) {
      std::vector<int> labels(num_faces(tm), Cells::outside);
      int next = 0;
      std::vector<int> first_label(region_cells.size());
      for(std::size_t p = 0; p < region_cells.size(); ++p) {
        first_label[p] = next;
        const std::vector<int> local = region_cells[p].voronoi->labels();
        int largest = -1;
        for(face_descriptor f : regions.patch_faces[p]) {
          labels[get(findex, f)] = next + local[get(findex, f)];
          largest = std::max(largest, local[get(findex, f)]);
        }
        next += largest + 1;
      }
      cells = patches_from_labels(tm, vpm, labels, Cells::outside);
      region_of_cell.assign(cells.number_of_patches(), 0);
      for(std::size_t c = 0; c < cells.number_of_patches(); ++c)
        region_of_cell[c] = regions.face_patch[get(findex, cells.patch_faces[c].front())];
      // A cell complex to split: every cell a disc, with three junctions or
      // more (a cell with two would give quads with a straight corner at its
      // centre), sharing at most one arc with any neighbour. A cell that
      // breaks a rule is given seeds: a non-disc or a two-junction cell one at
      // its farthest face; a cap (one neighbour all around, like a finger tip)
      // three around its middle instead of its own; of two cells sharing two
      // arcs, the larger one at its face farthest from the seeds along their
      // shared border (on a tube, three cells around instead of two). Cells
      // too small to split are left to the fallbacks.
      std::vector<std::pair<std::size_t, std::size_t>> added;  // (region, face position)
      std::vector<std::pair<std::size_t, std::size_t>> caps;   // (region, seed)
      auto refine = [&](std::size_t c, const std::vector<face_descriptor>& where) {
        const std::size_t s = farthest_in(region_of_cell[c], where);
        if(s < region_cells[region_of_cell[c]].voronoi->faces().size()) added.emplace_back(region_of_cell[c], s);
      };
      std::vector<Patch_loop<TriangleMesh>> loops;  // of the cell checked
      if(seed_count() < options.max_cells)
        for(std::size_t c = 0; c < cells.number_of_patches(); ++c) {
          if(!check_patch_disc(tm, vpm, cells, c, loops)) { refine(c, cells.patch_faces[c]); continue; }
          if(cells.patch_faces[c].size() < options.min_fix_faces) continue;
          const auto& loop = loops.front();
          const std::size_t n = loop.neighbour.size();
          std::map<std::size_t, std::size_t> arcs_with;
          for(std::size_t i = 0; i < n; ++i)
            if(loop.neighbour[(i + n - 1) % n] != loop.neighbour[i]) ++arcs_with[loop.neighbour[i]];
          std::size_t junctions = 0, twice = Patch_loop<TriangleMesh>::mesh_border;
          for(const auto& [q, count] : arcs_with) {
            junctions += count;
            if(count > 1 && q != Patch_loop<TriangleMesh>::mesh_border &&
               (cells.patch_faces[c].size() > cells.patch_faces[q].size() ||
                (cells.patch_faces[c].size() == cells.patch_faces[q].size() && c < q)))
              twice = q;
          }
          if(junctions < 3) {
            caps.emplace_back(region_of_cell[c], static_cast<std::size_t>(cells.patch_label[c] - first_label[region_of_cell[c]]));
            continue;
          }
          if(twice == Patch_loop<TriangleMesh>::mesh_border) continue;
          std::vector<face_descriptor> along;  // faces of c with an edge on q
          for(face_descriptor f : cells.patch_faces[c])
            for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
              const auto g = face(opposite(h, tm), tm);
              if(g != boost::graph_traits<TriangleMesh>::null_face() && cells.face_patch[get(findex, g)] == twice) {
                along.push_back(f);
                break;
              }
            }
          refine(c, along);
        }
      std::size_t split_caps = 0;
      for(const auto& [region, seed] : caps)
        if(region_cells[region].voronoi->split_in_three(seed)) ++split_caps;
      if(added.empty() && split_caps == 0) {
        internal::merge_small_cells(tm, vpm, labels, cells, regions, options.min_cell_faces);
        region_of_cell.assign(cells.number_of_patches(), 0);
        for(std::size_t c = 0; c < cells.number_of_patches(); ++c)
          region_of_cell[c] = regions.face_patch[get(findex, cells.patch_faces[c].front())];
        break;
      }
      for(const auto& [region, s] : added) region_cells[region].voronoi->add_seed(s);
    }
    // Faces of each cell in an order of the surface, not of the face indices,
    // so that ties in the cells' fans break the same way on a shuffled copy.
    for(auto& faces_of_cell : cells.patch_faces) {
      std::vector<std::pair<typename boost::property_traits<VertexPointMap>::value_type, face_descriptor>> keyed;
      for(face_descriptor f : faces_of_cell) {
        const auto h = halfedge(f, tm);
        keyed.emplace_back(CGAL::centroid(get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm))), f);
      }
      std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      for(std::size_t i = 0; i < keyed.size(); ++i) faces_of_cell[i] = keyed[i].second;
    }
    Quad_layout_report round_report;
    quads_from_cells(tm, vpm, cells, layout, options, &round_report, labelled ? &region_of_cell : nullptr, &memo);
    const std::size_t refined_so_far = r.refined_cells, ears_moved = r.region_ears_moved;
    r = round_report;
    r.rounds = round;
    r.refined_cells = refined_so_far;
    r.region_ears_moved = ears_moved;
    if(round >= options.refine_rounds) break;
    // Only the cell holding most of a patch may be refined, and only if it is
    // large enough (or the patch is): the judge need not map patches of smaller cells.
    std::vector<std::size_t> cell_of_patch(layout.number_of_patches(), cells.number_of_patches());
    std::vector<char> refinable(layout.number_of_patches(), 0);
    for(std::size_t p = 0; p < layout.number_of_patches(); ++p) {
      std::map<std::size_t, std::size_t> count;
      for(face_descriptor f : layout.patch_faces[p]) ++count[cells.face_patch[get(findex, f)]];
      if(count.empty()) continue;
      const std::size_t c =
          std::max_element(count.begin(), count.end(), [](const auto& a, const auto& b) { return a.second < b.second; })->first;
      cell_of_patch[p] = c;
      refinable[p] = c < cells.number_of_patches() &&
                     (cells.patch_faces[c].size() >= options.min_split_faces ||
                      layout.patch_faces[p].size() >= options.min_split_patch_faces);
    }
    const std::vector<std::size_t> bad =
        internal::judge_candidates(judge, static_cast<const Segmentation<TriangleMesh>&>(layout), refinable);
    std::vector<char> refined(cells.number_of_patches(), 0);
    std::vector<std::pair<std::size_t, std::size_t>> added;
    for(std::size_t p : bad) {
      if(p >= layout.number_of_patches() || !refinable[p]) continue;
      const std::size_t c = cell_of_patch[p];
      if(refined[c]) continue;
      refined[c] = 1;
      const std::size_t s = farthest_in(region_of_cell[c], layout.patch_faces[p]);
      if(s < region_cells[region_of_cell[c]].voronoi->faces().size()) added.emplace_back(region_of_cell[c], s);
    }
    if(added.empty() || seed_count() >= options.max_cells) break;
    for(const auto& [region, s] : added) region_cells[region].voronoi->add_seed(s);
    r.refined_cells += added.size();
  }
  // Labels and parts: the region's label and the rank among the patches of
  // that label (a label may have several regions; they come in canonical order).
  if(labelled) {
    // Patches by label (stable: within a label, quads by cell, then the others).
    std::vector<std::size_t> order(layout.number_of_patches());
    std::iota(order.begin(), order.end(), 0);
    auto label_of = [&](std::size_t p) { return regions.patch_label[regions.face_patch[get(findex, layout.patch_faces[p].front())]]; };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return label_of(a) < label_of(b); });
    Segmentation<TriangleMesh> by_label;
    by_label.face_patch.assign(num_faces(tm), Segmentation<TriangleMesh>::no_patch);
    for(std::size_t p : order) {
      for(face_descriptor f : layout.patch_faces[p]) by_label.face_patch[get(findex, f)] = by_label.patch_faces.size();
      by_label.patch_faces.push_back(std::move(layout.patch_faces[p]));
      by_label.patch_corners.push_back(layout.patch_corners.empty() ? Segmentation<TriangleMesh>::no_corners() : layout.patch_corners[p]);
      by_label.patch_label.push_back(0);
      by_label.patch_part.push_back(0);
    }
    layout = std::move(by_label);
  }
  std::map<int, int> rank;
  for(std::size_t p = 0; p < layout.number_of_patches(); ++p) {
    const std::size_t region = regions.face_patch[get(findex, layout.patch_faces[p].front())];
    layout.patch_label[p] = labelled ? regions.patch_label[region] : static_cast<int>(p);
    layout.patch_part[p] = labelled ? ++rank[regions.patch_label[region]] : 0;
  }
  r.cells = cells.number_of_patches();
  r.fans_made = memo.fans.misses();
  r.fans_reused = memo.fans.hits();
  return Status();
}

} // namespace diffuv

#endif // DIFFUV_LAYOUT_QUAD_LAYOUT_H