// diffuv: from a mesh (and perhaps region labels) to disc patches ready to map.
#ifndef DIFFUV_LAYOUT_DISC_PATCHES_H
#define DIFFUV_LAYOUT_DISC_PATCHES_H

#include <diffuv/core/error.h>
#include <diffuv/layout/cut_into_discs.h>
#include <diffuv/layout/quad_layout.h>
#include <diffuv/layout/voronoi_discs.h>
#include <diffuv/patches/disc_topology.h>
#include <diffuv/patches/flat_triangles.h>
#include <diffuv/patches/merge_small_patches.h>
#include <diffuv/patches/patches_from_labels.h>
#include <diffuv/patches/segmentation.h>
#include <diffuv/patches/split_cap.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <algorithm>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace diffuv {

/// How `disc_patches()` makes patches where the labels (or their absence) leave it free.
enum class Patch_layout {
  quads,   ///< the four-sided layout (layout/quad_layout.h): conforming quads from Voronoi cells (default)
  voronoi  ///< Voronoi cells refined until discs, their runs of neighbours merged into four sides (diffuv 0.1)
};

/// What `disc_patches()` does with a connected component that is a disc (no
/// labels, or one label on all of it; quads layout).
enum class Disc_components {
  whole,     ///< one patch, its corners by equal arcs (diffuv 0.1)
  /// one patch if the judge finds its map good, else laid out like any other
  /// component (default; without a judge that maps, `No_refinement`, every disc stays whole)
  judged,
  laid_out   ///< laid out like any other component (e.g. when the user asks for a number of patches)
};

/// Options of `disc_patches()`.
struct Patching_options {
  Patch_layout layout = Patch_layout::quads;  ///< automatic patches, and how labelled regions are split
  Disc_components discs = Disc_components::judged;  ///< (quads layout) components that are discs, labelled as one region or not
  bool split_caps = true;        ///< (voronoi layout) split caps (one neighbour all around) in two, as the paper recommends
  bool strict = false;           ///< report a labelled region that is not a disc instead of cutting it
  /// hand a face left flat by its patch's four sides to a neighbouring patch
  /// (`hand_flat_triangles_to_neighbours()`); with labels and the quads
  /// layout, also let a face that juts out of its region join the region it
  /// juts into first (`Quad_layout_options::move_region_ears`)
  bool hand_off_flat_triangles = true;
  Voronoi_options automatic;     ///< (voronoi layout) automatic patches: how many seeds to start from
  Quad_layout_options quads;     ///< (quads layout) cells, collapses, refinement
};

/// What `disc_patches()` did.
struct Patching_report {
  bool automatic = false;          ///< no labels were given: patches were made automatically
  Quad_layout_report layout;       ///< what the four-sided layout did (quads layout)
  std::size_t components = 1;      ///< connected components of the mesh (counted when no labels were given)
  std::size_t whole_components = 0;  ///< components that were discs, kept as one patch each
  std::size_t discs_laid_out = 0;    ///< components that were discs, laid out (`Disc_components`)
  std::size_t merged = 0;          ///< patches with fewer than four boundary vertices merged into a neighbour
  std::size_t cut = 0;             ///< non-disc patches cut into discs
  std::size_t caps_split = 0;      ///< caps split in two
  std::size_t flat_triangles_handed = 0;  ///< faces flat on one side of their patch, handed to a neighbouring patch
  /// patches without corners of the layout given corners by their maps (a
  /// judge with `choose_corners()`, e.g. `Raw_map_judge`)
  std::size_t corners_chosen = 0;
  std::vector<std::size_t> not_discs;  ///< patches left that are not discs (none unless `strict` or a cut failed)
  /// The four-sided layout left a patch that is not a disc (e.g. a closed mesh
  /// of a few faces, whose one-face patches merge into a closed one), so the
  /// Voronoi layout made the patches instead.
  bool voronoi_instead = false;
};

namespace internal {

// A patch with fewer than four boundary vertices (a lone face of a tiny closed
// mesh) cannot be mapped onto a square: it joins a neighbour
// (`merge_small_patches()`). The patches left whole keep their label, part
// and corners; one that grew keeps its label and part, and loses its corners.
template <class TriangleMesh, class VertexPointMap>
std::size_t merge_unmappable_patches(const TriangleMesh& tm, VertexPointMap vpm, Segmentation<TriangleMesh>& seg)
{
  bool any = false;
  for(std::size_t p = 0; p < seg.number_of_patches() && !any; ++p) {
    std::size_t boundary_vertices = 0;
    for(const auto& loop : patch_loops(tm, vpm, seg, p)) boundary_vertices += loop.vertices.size();
    any = boundary_vertices < 4;
  }
  if(!any) return 0;
  auto findex = get(boost::face_index, tm);
  std::vector<int> labels(num_faces(tm), std::numeric_limits<int>::min());
  for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
    for(auto f : seg.patch_faces[p]) labels[get(findex, f)] = static_cast<int>(p);
  Segmentation<TriangleMesh> merged = patches_from_labels(tm, vpm, labels);
  const std::size_t count = merge_small_patches(tm, vpm, labels, merged);
  merged.patch_corners.assign(merged.number_of_patches(), Segmentation<TriangleMesh>::no_corners());
  for(std::size_t q = 0; q < merged.number_of_patches(); ++q) {
    const std::size_t old = static_cast<std::size_t>(merged.patch_label[q]);
    merged.patch_label[q] = seg.patch_label[old];
    merged.patch_part[q] = seg.patch_part[old];
    if(merged.patch_faces[q].size() == seg.patch_faces[old].size() && seg.corners(old)) merged.patch_corners[q] = *seg.corners(old);
  }
  seg = std::move(merged);
  return count;
}

// Whether a judge offers `choose_corners(Segmentation&)`.
template <class Judge, class Seg, class = void>
struct has_choose_corners : std::false_type {};
template <class Judge, class Seg>
struct has_choose_corners<Judge, Seg, std::void_t<decltype(std::declval<const Judge&>().choose_corners(std::declval<Seg&>()))>>
  : std::true_type {};

// Whether a judge offers `whole_patches_to_lay_out(const Segmentation&, const std::vector<char>&)`.
template <class Judge, class Seg, class = void>
struct has_whole_patch_judgement : std::false_type {};
template <class Judge, class Seg>
struct has_whole_patch_judgement<Judge, Seg, std::void_t<decltype(std::declval<const Judge&>().whole_patches_to_lay_out(
                                                 std::declval<const Seg&>(), std::declval<const std::vector<char>&>()))>>
  : std::true_type {};

// The patches flagged in `candidates` that the judge would not keep whole:
// by their whole map if it offers that judgement, else by its verdict on a layout.
template <class Judge, class TriangleMesh>
std::vector<std::size_t> whole_patches_to_lay_out(const Judge& judge, const Segmentation<TriangleMesh>& seg,
                                                  const std::vector<char>& candidates)
{
  if constexpr(has_whole_patch_judgement<Judge, Segmentation<TriangleMesh>>::value)
    return judge.whole_patches_to_lay_out(seg, candidates);
  else
    return judge_candidates(judge, seg, candidates);
}

// Which of the patches flagged in `disc` (each a whole component and a disc)
// stay one patch, as `options.discs` says; counts the others in
// `r.discs_laid_out`.
template <class TriangleMesh, class Judge>
std::vector<char> discs_kept_whole(const Segmentation<TriangleMesh>& seg, const std::vector<char>& disc,
                                   const Patching_options& options, Patching_report& r, const Judge& judge)
{
  std::vector<char> whole = disc;
  if(options.discs == Disc_components::whole || std::find(disc.begin(), disc.end(), 1) == disc.end()) return whole;
  std::vector<std::size_t> laid_out;
  if(options.discs == Disc_components::laid_out) {
    for(std::size_t p = 0; p < disc.size(); ++p)
      if(disc[p]) laid_out.push_back(p);
  } else {
    laid_out = whole_patches_to_lay_out(judge, seg, disc);
  }
  r.discs_laid_out += laid_out.size();
  for(std::size_t p : laid_out) whole[p] = 0;
  return whole;
}

// The patches of `laid` (a layout of some of the mesh's faces), then each
// patch of `from` flagged in `whole`, as one patch without corners. With
// `renumber`, every patch's label is its index (part 0); otherwise the laid
// patches keep theirs and the whole ones take their label in `from`.
template <class TriangleMesh>
Segmentation<TriangleMesh> with_whole_patches(const TriangleMesh& tm, Segmentation<TriangleMesh> laid,
                                              const Segmentation<TriangleMesh>& from, const std::vector<char>& whole,
                                              bool renumber)
{
  using Seg = Segmentation<TriangleMesh>;
  auto findex = get(boost::face_index, tm);
  laid.patch_corners.resize(laid.patch_faces.size(), Seg::no_corners());
  for(std::size_t p = 0; p < from.number_of_patches(); ++p) {
    if(!whole[p]) continue;
    laid.patch_label.push_back(from.patch_label[p]);
    laid.patch_part.push_back(0);
    laid.patch_faces.push_back(from.patch_faces[p]);
    laid.patch_corners.push_back(Seg::no_corners());
  }
  laid.face_patch.assign(num_faces(tm), Seg::no_patch);
  for(std::size_t p = 0; p < laid.patch_faces.size(); ++p) {
    for(auto f : laid.patch_faces[p]) laid.face_patch[get(findex, f)] = p;
    if(renumber) {
      laid.patch_label[p] = static_cast<int>(p);
      laid.patch_part[p] = 0;
    }
  }
  return laid;
}

// disc_patches() with the four-sided layout.
template <class TriangleMesh, class VertexPointMap, class Judge>
Status four_sided_patches(const TriangleMesh& tm, std::vector<int> face_labels, VertexPointMap vpm,
                          Segmentation<TriangleMesh>& seg, const Patching_options& options, Patching_report& r, Judge judge)
{
  auto findex = get(boost::face_index, tm);
  const bool labelled = !face_labels.empty();
  std::vector<std::size_t> component(num_faces(tm));
  r.components = CGAL::Polygon_mesh_processing::connected_components(
      tm, boost::make_iterator_property_map(component.begin(), findex));
  if(labelled) {
    // Regions with fewer than four boundary vertices join a neighbour, as with
    // the Voronoi layout; with `strict`, a region that is not a disc is reported.
    seg = patches_from_labels(tm, vpm, face_labels);
    r.merged = merge_small_patches(tm, vpm, face_labels, seg);
    std::vector<char> is_disc(seg.number_of_patches(), 0);
    for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
      is_disc[p] = check_patch_disc(tm, seg, p).ok();
      if(!is_disc[p]) {
        if(options.strict) r.not_discs.push_back(p);
        else ++r.cut;  // its cells are discs
      }
    }
    if(!r.not_discs.empty()) return check_patch_disc(tm, seg, r.not_discs.front());
    // A region that is a whole component and a disc follows the rule for disc
    // components below, so that labels read back from `segment` (one label on
    // a disc kept whole) give the same patches.
    std::vector<std::size_t> component_faces(r.components, 0);
    for(std::size_t c : component) ++component_faces[c];
    std::vector<char> disc(seg.number_of_patches(), 0);
    for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
      disc[p] = is_disc[p] && !seg.patch_faces[p].empty() &&
                seg.patch_faces[p].size() == component_faces[component[get(findex, seg.patch_faces[p].front())]];
    const std::vector<char> whole = discs_kept_whole(seg, disc, options, r, judge);
    bool any = false;
    for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
      if(!whole[p]) { any = true; continue; }
      ++r.whole_components;
      for(auto f : seg.patch_faces[p]) face_labels[get(findex, f)] = std::numeric_limits<int>::min();
    }
    Segmentation<TriangleMesh> laid;
    Quad_layout_options quads = options.quads;
    quads.move_region_ears = quads.move_region_ears && options.hand_off_flat_triangles;
    if(any) quad_layout(tm, vpm, face_labels, laid, quads, &r.layout, judge);
    seg = with_whole_patches(tm, std::move(laid), seg, whole, false);
  } else {
    // A component that is a disc may stay one patch (its corners by equal
    // arcs): with `judged`, if the judge finds its map good (a disc whose
    // square map folds or stretches, like a relief with a ragged border, is
    // served better by the layout). Any other component is laid out.
    const std::vector<int> component_labels(component.begin(), component.end());
    const Segmentation<TriangleMesh> by_component = patches_from_labels(tm, vpm, component_labels);
    const std::size_t nc = by_component.number_of_patches();
    std::vector<char> disc(nc, 0);
    for(std::size_t c = 0; c < nc; ++c) disc[c] = check_patch_disc(tm, by_component, c).ok();
    const std::vector<char> whole = discs_kept_whole(by_component, disc, options, r, judge);
    face_labels.assign(num_faces(tm), std::numeric_limits<int>::min());
    bool any = false;
    for(std::size_t c = 0; c < nc; ++c) {
      if(whole[c]) { ++r.whole_components; continue; }
      any = true;
      for(auto f : by_component.patch_faces[c]) face_labels[get(findex, f)] = static_cast<int>(c);
    }
    r.automatic = any;
    Segmentation<TriangleMesh> laid;
    // quad_layout() of the non-disc components only; the discs come after, whole.
    if(any) quad_layout(tm, vpm, face_labels, laid, options.quads, &r.layout, judge, Region_labels::areas);
    seg = with_whole_patches(tm, std::move(laid), by_component, whole, true);
  }
  // Labelled regions keep their borders (but for the ear faces moved by the
  // layout): faces move only between their sub-patches.
  if(options.hand_off_flat_triangles) r.flat_triangles_handed = hand_flat_triangles_to_neighbours(tm, vpm, seg, labelled);
  const std::size_t unmappable = merge_unmappable_patches(tm, vpm, seg);
  r.merged += unmappable;
  if(unmappable > 0 && r.layout.kept_regions == 0) {
    // The layout's counts, of the patches left.
    r.layout.quads = 0;
    for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
      if(seg.corners(p)) ++r.layout.quads;
    r.layout.fallback_patches = seg.number_of_patches() - r.layout.quads;
  }
  r.not_discs.clear();
  for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
    if(!check_patch_disc(tm, seg, p)) r.not_discs.push_back(p);
  if(!r.not_discs.empty()) return check_patch_disc(tm, seg, r.not_discs.front());
  // A judge that can map patches may also choose the fallback patches' corners.
  if constexpr(has_choose_corners<Judge, Segmentation<TriangleMesh>>::value) r.corners_chosen = judge.choose_corners(seg);
  return Status();
}

} // namespace internal

/// Cuts `tm` into disc patches.
///
/// With `face_labels` (#F entries), each connected component of a label is a
/// patch; patches with fewer than four boundary vertices are merged into a
/// neighbour; a patch that is not a disc is cut into discs (or, with `strict`,
/// reported); the regions are split into four-sided patches, except a region
/// that is a whole connected component and a disc, which follows the rule for
/// disc components below. Without labels (empty vector), any
/// connected component that is not a disc is cut automatically
/// (`quad_layout()`, or `voronoi_discs()` with the Voronoi layout); one that
/// is a disc is one patch, or, with the quads layout, as `options.discs`
/// says: by default laid out too if `judge` finds its map as one patch bad
/// (`Raw_map_judge`: it folds or stretches). Last, a face that the patch's four
/// sides would leave flat is handed to a neighbouring patch
/// (`hand_flat_triangles_to_neighbours()`, `hand_off_flat_triangles`).
///
/// \returns `not_a_disc` (detail: the first bad patch) if a patch that is not a
///          disc is left, `ok` otherwise; `seg` is filled in both cases
template <class TriangleMesh, class VertexPointMap, class Judge = No_refinement>
Status disc_patches(const TriangleMesh& tm, VertexPointMap vpm, std::vector<int> face_labels,
                    Segmentation<TriangleMesh>& seg, const Patching_options& options = Patching_options(),
                    Patching_report* report = nullptr, Judge judge = Judge())
{
  Patching_report local;
  Patching_report& r = report ? *report : local;
  r = Patching_report();
  auto findex = get(boost::face_index, tm);
  // `strict` is about the given regions: automatic patches are ours to cut
  // further (voronoi_discs() may stop at max_patches with a non-disc left).
  const bool labelled = !face_labels.empty();
  if(options.layout == Patch_layout::quads) {
    const Status status = internal::four_sided_patches(tm, face_labels, vpm, seg, options, r, judge);
    if(status || (options.strict && labelled)) return status;
    Patching_options voronoi = options;
    voronoi.layout = Patch_layout::voronoi;
    const Status again = disc_patches(tm, vpm, std::move(face_labels), seg, voronoi, &r);
    r.voronoi_instead = true;
    return again;
  }

  if(face_labels.empty()) {
    face_labels.assign(num_faces(tm), 0);
    if(!check_disc(tm)) {
      // Component by component: a component that is a disc stays whole (one
      // patch), any other one is cut automatically.
      std::vector<std::size_t> component(num_faces(tm));
      r.components = CGAL::Polygon_mesh_processing::connected_components(
          tm, boost::make_iterator_property_map(component.begin(), findex));
      std::vector<int> component_labels(component.begin(), component.end());
      const Segmentation<TriangleMesh> by_component = patches_from_labels(tm, vpm, component_labels);
      int next_label = 0;
      for(std::size_t c = 0; c < by_component.number_of_patches(); ++c) {
        const auto& part = by_component.patch_faces[c];
        if(check_patch_disc(tm, by_component, c)) {
          for(auto f : part) face_labels[get(findex, f)] = next_label;
          ++next_label;
          ++r.whole_components;
          continue;
        }
        r.automatic = true;
        voronoi_discs(tm, vpm, part, face_labels, next_label, options.automatic);
        for(auto f : part) next_label = (std::max)(next_label, face_labels[get(findex, f)] + 1);
      }
    } else {
      r.whole_components = 1;
    }
  }

  seg = patches_from_labels(tm, vpm, face_labels);
  r.merged = merge_small_patches(tm, vpm, face_labels, seg);

  for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
    if(check_patch_disc(tm, seg, p)) continue;
    if(options.strict && labelled) { r.not_discs.push_back(p); continue; }
    const std::size_t pieces = cut_into_discs(tm, vpm, seg, p, options.automatic);
    if(pieces > 1) {
      ++r.cut;
      p += pieces - 1;
    } else {
      r.not_discs.push_back(p);
    }
  }
  if(options.split_caps) {
    // Caps are found first, then split: splitting one cap must not change
    // whether its neighbour counts as one (two caps side by side both split).
    std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> caps;
    for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
      if(is_cap(tm, vpm, seg, p)) caps.push_back(seg.patch_faces[p].front());
    for(auto f : caps)
      if(split_cap(tm, vpm, seg, seg.face_patch[get(findex, f)])) ++r.caps_split;
  }
  if(options.hand_off_flat_triangles) r.flat_triangles_handed = hand_flat_triangles_to_neighbours(tm, vpm, seg);
  // Indices of the bad patches may have moved with the splits: recompute them.
  r.not_discs.clear();
  for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
    if(!check_patch_disc(tm, seg, p)) r.not_discs.push_back(p);
  if(!r.not_discs.empty())
    return check_patch_disc(tm, seg, r.not_discs.front());
  return Status();
}

} // namespace diffuv

#endif // DIFFUV_LAYOUT_DISC_PATCHES_H
