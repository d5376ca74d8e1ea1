// diffuv: the four sides of a patch from the regions around it.
//
// The paper (section 2.7): "the borders between two regions already form
// suitable edges". Walking a disc patch's boundary counter-clockwise, each
// maximal run of edges with the same neighbouring patch (or the mesh border)
// is a natural side, and the vertices where the neighbour changes (where three
// or more regions meet) are natural corners.
#ifndef DIFFUV_PATCHES_REGION_SIDES_H
#define DIFFUV_PATCHES_REGION_SIDES_H

#include <diffuv/core/error.h>
#include <diffuv/patches/corners.h>
#include <diffuv/patches/segmentation.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

namespace diffuv {

/// A corner named by the regions around it, so that the same corner can be
/// found on another mesh with the same regions: the neighbouring region
/// (label, part) before and after it counter-clockwise, or, for a corner put in
/// the middle of a run of one neighbour, that neighbour twice and `middle`.
struct Corner_name {
  std::pair<long long, int> before{0, 0}, after{0, 0};
  bool middle = false;
  friend bool operator==(const Corner_name& a, const Corner_name& b)
  {
    return a.before == b.before && a.after == b.after && a.middle == b.middle;
  }
};

/// The names of a patch's four corners, in side order (corner 0 is (0,0)).
struct Corner_names {
  bool valid = false;                 ///< false: a corner has no unique name (equal arcs, a repeated junction)
  std::array<Corner_name, 4> corners;
};

/// How the four corners of a patch were found.
struct Side_report {
  std::size_t runs = 0;     ///< runs of neighbours along the boundary (0: one neighbour all around)
  std::size_t merged = 0;   ///< junctions dropped (more than four runs)
  std::size_t split = 0;    ///< runs split at their middle (fewer than four runs)
  bool equal_arcs = false;  ///< no junction: corners by equal arc lengths from the sharpest vertex
  std::size_t moved = 0;    ///< corners moved onto an ear so that no triangle is flat (separate_flat_triangles())
  Corner_names names;       ///< the corners by their regions (before any move onto an ear)
  bool named = false;       ///< the corners followed the names given to `region_sides()`
  bool chosen = false;      ///< the corners came with the patch (`Segmentation::patch_corners`, the four-sided layout)
};

/// Options of `region_sides()`.
struct Region_sides_options {
  /// If given, the corners of the same region on another mesh (its
  /// `Side_report::names`), to follow (see `region_sides()`).
  const Corner_names* names = nullptr;
  /// Move a corner onto an ear's tip, or a few vertices along the border, so
  /// that no triangle is flat (`separate_flat_triangles()`).
  bool move_corners_off_ears = true;
};

/// Computes the four sides of disc patch `p` from the runs of its neighbours.
///
/// Rule (deterministic):
/// - four runs: the junctions are the corners;
/// - more: repeatedly drop the junction between the shortest run and the
///   shorter of its two neighbouring runs (arc length), merging them;
/// - two: each run is split at the vertex nearest to its middle;
///   three: the longest run is split so;
/// - none (one neighbour all around, or the mesh border all around):
///   `equal_arc_corners()`.
///
/// Side order is canonical: each side gets the key (the label of the region
/// along most of its arc length, the mesh border below every label), and the
/// side whose key sequence, read counter-clockwise, is lexicographically
/// smallest becomes `v1` (v = 0), its first corner (0,0). Ties (symmetric label sequences) are broken by the
/// sides' arc lengths, then by the first corner found. The order therefore
/// depends only on the labels and the surface orientation, not on vertex
/// or face order.
///
/// Given `options.names` (the corners of the same region on another mesh, from its
/// `Side_report::names`), the corners are the junctions and run middles of
/// those names instead, in the same order, whenever each name is found exactly
/// once here and the four keep their counter-clockwise order; else the rule
/// above applies. Two meshes whose labels differ a little along region borders
/// (painted, transferred) then still get the same corners, where the rule's
/// choices among nearly equal run lengths could differ.
///
/// With `options.move_corners_off_ears` (default), a corner (the layout's too) may then move
/// onto the tip of an ear, or a few vertices along the border, so that no
/// triangle is flat (`separate_flat_triangles()`); such a move
/// can go half a side away, so correspondence turns it off on both meshes.
///
/// \pre patch `p` is a topological disc (`check_patch_disc()`)
/// \returns `border_too_short` if the boundary has fewer than four vertices, else `ok`
template <class TriangleMesh, class VertexPointMap>
Status region_sides(const TriangleMesh& tm, VertexPointMap vpm, const Segmentation<TriangleMesh>& seg, std::size_t p,
                    Four_sides<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& sides,
                    const Region_sides_options& options = Region_sides_options(), Side_report* report = nullptr)
{
  const Corner_names* names = options.names;
  const bool move_off_ears = options.move_corners_off_ears;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const auto loops = patch_loops(tm, vpm, seg, p);
  if(loops.size() != 1)
    return Status(Status_code::several_borders, "", "patch " + std::to_string(p));
  const Patch_loop<TriangleMesh>& loop = loops.front();
  const std::size_t n = loop.vertices.size();
  if(n < 4) return Status(Status_code::border_too_short, "", "patch " + std::to_string(p));
  Side_report local_report;
  Side_report& r = report ? *report : local_report;
  r = Side_report();
  for(std::size_t i = 0; i < n; ++i)
    if(loop.neighbour[(i + n - 1) % n] != loop.neighbour[i]) ++r.runs;
  if(const auto* chosen = seg.corners(p)) {
    // The layout chose them; (0,0) first, the others in counter-clockwise
    // order. Where they would leave a triangle flat (a quad whose corner sits
    // next to an ear, measured on elephant), that patch's corners move.
    r.chosen = true;
    std::vector<vertex_descriptor> given(chosen->begin(), chosen->end());
    std::array<std::size_t, 4> at{};
    bool on_loop = true;
    for(std::size_t c = 0; c < 4 && on_loop; ++c) {
      at[c] = static_cast<std::size_t>(std::find(loop.vertices.begin(), loop.vertices.end(), given[c]) - loop.vertices.begin());
      on_loop = at[c] < n;
    }
    if(on_loop && move_off_ears) {
      const auto fim = get(boost::face_index, tm);
      r.moved = separate_flat_triangles(tm, loop.vertices, at, [&](auto f) { return seg.face_patch[get(fim, f)] == p; },
                                        loop.length);
      for(std::size_t c = 0; c < 4; ++c) given[c] = loop.vertices[at[c]];
    }
    return sides_from_corners(loop.vertices, given, sides);
  }

  std::vector<double> at(n + 1, 0.); // arc length at each loop position
  for(std::size_t i = 0; i < n; ++i) at[i + 1] = at[i] + loop.length[i];
  auto arc = [&](std::size_t a, std::size_t b) { return b > a ? at[b] - at[a] : at[n] - at[a] + at[b]; };

  std::vector<std::size_t> corners; // loop positions, increasing
  for(std::size_t i = 0; i < n; ++i)
    if(loop.neighbour[(i + n - 1) % n] != loop.neighbour[i]) corners.push_back(i);

  std::size_t sharpest = n; // loop position of equal_arc_corners()'s first corner
  if(corners.empty()) {
    r.equal_arcs = true;
    const auto chosen = equal_arc_corners(tm, vpm, loop.vertices);
    sharpest = static_cast<std::size_t>(std::find(loop.vertices.begin(), loop.vertices.end(), chosen.front()) -
                                        loop.vertices.begin());
    for(auto v : chosen)
      corners.push_back(static_cast<std::size_t>(std::find(loop.vertices.begin(), loop.vertices.end(), v) -
                                                 loop.vertices.begin()));
    std::sort(corners.begin(), corners.end());
  }
  // More than four runs: merge the shortest run into its shorter neighbour.
  while(corners.size() > 4) {
    const std::size_t k = corners.size();
    std::size_t shortest = 0;
    for(std::size_t c = 1; c < k; ++c)
      if(arc(corners[c], corners[(c + 1) % k]) < arc(corners[shortest], corners[(shortest + 1) % k])) shortest = c;
    const double before = arc(corners[(shortest + k - 1) % k], corners[shortest]);
    const double after = arc(corners[(shortest + 1) % k], corners[(shortest + 2) % k]);
    corners.erase(corners.begin() + static_cast<std::ptrdiff_t>(before <= after ? shortest : (shortest + 1) % k));
    ++r.merged;
  }
  // Fewer than four: split runs at the vertex nearest to their middle.
  auto middle = [&](std::size_t a, std::size_t b) { // loop position, or n if the run has one edge
    std::size_t best = n;
    double best_gap = std::numeric_limits<double>::infinity();
    for(std::size_t i = (a + 1) % n; i != b; i = (i + 1) % n) {
      const double gap = std::abs(arc(a, i) - arc(a, b) / 2);
      if(gap < best_gap) { best_gap = gap; best = i; }
    }
    return best;
  };
  if(corners.size() == 2) { // two runs: split both, so neither is favoured
    const std::size_t m0 = middle(corners[0], corners[1]), m1 = middle(corners[1], corners[0]);
    for(std::size_t m : {m0, m1})
      if(m != n) { corners.push_back(m); ++r.split; }
    std::sort(corners.begin(), corners.end());
  }
  while(corners.size() < 4) { // split the longest run that has a middle vertex
    const std::size_t k = corners.size();
    std::size_t best_run = k, best_middle = n;
    for(std::size_t c = 0; c < k; ++c) {
      const std::size_t m = middle(corners[c], corners[(c + 1) % k]);
      if(m != n && (best_run == k || arc(corners[c], corners[(c + 1) % k]) >
                                         arc(corners[best_run], corners[(best_run + 1) % k]))) {
        best_run = c;
        best_middle = m;
      }
    }
    if(best_run == k) return Status(Status_code::border_too_short, "", "patch " + std::to_string(p));
    corners.push_back(best_middle);
    std::sort(corners.begin(), corners.end());
    ++r.split;
  }

  // Names of the corners chosen, and of the corners asked for.
  auto region_of = [&](std::size_t i) { // the neighbour across loop edge i, as (label, part)
    const std::size_t q = loop.neighbour[i];
    return q == Patch_loop<TriangleMesh>::mesh_border ? std::make_pair(std::numeric_limits<long long>::min(), 0)
                                                      : std::make_pair(static_cast<long long>(seg.patch_label[q]), seg.patch_part[q]);
  };
  auto name_at = [&](std::size_t i) {
    Corner_name name;
    name.before = region_of((i + n - 1) % n);
    name.after = region_of(i);
    name.middle = name.before == name.after;
    return name;
  };
  // Where `name` is on this loop: the junction, or the middle of the one run of
  // that neighbour; n if it is not there exactly once.
  auto find_name = [&](const Corner_name& name) {
    std::size_t found = n, count = 0;
    for(std::size_t i = 0; i < n; ++i) {
      if(loop.neighbour[(i + n - 1) % n] == loop.neighbour[i]) continue; // not a junction
      if(!name.middle) {
        if(name_at(i) == name) { found = i; ++count; }
      } else if(region_of(i) == name.after) {  // a run of that neighbour starts here
        std::size_t end = (i + 1) % n;
        while(loop.neighbour[end] == loop.neighbour[i]) end = (end + 1) % n;
        found = middle(i, end);
        ++count;
      }
    }
    return count == 1 ? found : n;
  };
  // A junction X -> Y that is not here exactly, but with short runs of other
  // regions between the end of a run of X and the start of a run of Y (a
  // corner of a third region that reaches the border on this mesh only): the
  // vertex halfway between them, if there is exactly one such place.
  auto find_name_loosely = [&](const Corner_name& name) {
    if(name.middle) return n;
    std::size_t found = n, count = 0;
    for(std::size_t i = 0; i < n; ++i) {
      if(loop.neighbour[(i + n - 1) % n] == loop.neighbour[i] || region_of((i + n - 1) % n) != name.before) continue;
      std::size_t k = i;
      while(region_of(k) != name.after && region_of(k) != name.before && (k + 1) % n != i) k = (k + 1) % n;
      if(region_of(k) != name.after || k == i || arc(i, k) > 0.1 * at[n]) continue;
      const std::size_t m = middle(i, k);
      found = m == n ? i : m;
      ++count;
    }
    return count == 1 ? found : n;
  };
  bool names_unique = !r.equal_arcs;
  for(std::size_t c = 0; c < 4 && names_unique; ++c) names_unique = find_name(name_at(corners[c])) == corners[c];

  std::size_t given_first = 4;  // with names: the sorted position of the named corner 0
  if(names && names->valid && !r.equal_arcs) {
    std::array<std::size_t, 4> at_name;
    bool ok = true;
    for(std::size_t c = 0; c < 4 && ok; ++c) {
      at_name[c] = find_name(names->corners[c]);
      if(at_name[c] == n) at_name[c] = find_name_loosely(names->corners[c]);
      ok = at_name[c] != n;
    }
    // Counter-clockwise and distinct: offsets from corner 0 strictly increase.
    if(ok) {
      std::array<std::size_t, 4> offset;
      for(std::size_t c = 0; c < 4; ++c) offset[c] = (at_name[c] + n - at_name[0]) % n;
      ok = 0 < offset[1] && offset[1] < offset[2] && offset[2] < offset[3];
    }
    if(ok) {
      corners.assign(at_name.begin(), at_name.end());
      std::sort(corners.begin(), corners.end());
      given_first = static_cast<std::size_t>(std::find(corners.begin(), corners.end(), at_name[0]) - corners.begin());
      names_unique = true;
      r.named = true;
    }
  }
  // In sorted order until the rotation is known.
  std::array<Corner_name, 4> sorted_names;
  for(std::size_t c = 0; c < 4; ++c) sorted_names[c] = name_at(corners[c]);

  // No triangle flat on one side: a corner may move onto an ear's tip.
  const auto fim = get(boost::face_index, tm);
  std::array<std::size_t, 4> corner_at = {corners[0], corners[1], corners[2], corners[3]};
  const std::size_t sharp_index = static_cast<std::size_t>(std::find(corners.begin(), corners.end(), sharpest) - corners.begin());
  if(move_off_ears)
    r.moved = separate_flat_triangles(tm, loop.vertices, corner_at, [&](auto f) { return seg.face_patch[get(fim, f)] == p; },
                                    loop.length);
  corners.assign(corner_at.begin(), corner_at.end());

  // Canonical rotation: the sides' region keys, then their lengths.
  // A side's key is the label along most of its length: a few jagged edges of
  // another region on it (painted or transferred labels) do not change it, so
  // the rotation stays the same on two meshes whose labels nearly agree.
  auto key_of = [&](std::size_t c) {
    std::map<long long, double> length_of;
    for(std::size_t i = corners[c]; i != corners[(c + 1) % 4]; i = (i + 1) % n) {
      const long long label = loop.neighbour[i] == Patch_loop<TriangleMesh>::mesh_border
                                  ? std::numeric_limits<long long>::min()
                                  : seg.patch_label[loop.neighbour[i]];
      length_of[label] += loop.length[i];
    }
    long long dominant = 0;
    double longest = -1.;
    for(const auto& [label, length] : length_of)
      if(length > longest) { longest = length; dominant = label; }
    return dominant;
  };
  std::array<long long, 4> keys;
  std::array<double, 4> lengths;
  for(std::size_t c = 0; c < 4; ++c) {
    keys[c] = key_of(c);
    lengths[c] = arc(corners[c], corners[(c + 1) % 4]);
  }
  auto rotation_key = [&](std::size_t s) {
    return std::make_tuple(std::array<long long, 4>{keys[s], keys[(s + 1) % 4], keys[(s + 2) % 4], keys[(s + 3) % 4]},
                           std::array<double, 4>{lengths[s], lengths[(s + 1) % 4], lengths[(s + 2) % 4], lengths[(s + 3) % 4]});
  };
  // With no junction, all four keys are equal: the sharpest vertex stays (0,0).
  std::size_t first = 0;
  if(r.equal_arcs) {
    first = sharp_index;
  } else if(r.named) {
    first = given_first;
  } else {
    for(std::size_t s = 1; s < 4; ++s)
      if(rotation_key(s) < rotation_key(first)) first = s;
  }

  r.names.valid = names_unique;
  for(std::size_t c = 0; c < 4; ++c) r.names.corners[c] = sorted_names[(first + c) % 4];
  std::vector<vertex_descriptor> ordered;
  for(std::size_t c = 0; c < 4; ++c) ordered.push_back(loop.vertices[corners[(first + c) % 4]]);
  return sides_from_corners(loop.vertices, ordered, sides);
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_REGION_SIDES_H
