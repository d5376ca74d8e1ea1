// diffuv: labelled regions split into four-sided sub-patches by a rule on
// their borders alone, so that two meshes with the same labels get the same
// sub-patches.
//
// A region bounded by k runs of neighbours (k = 3, or 5 and more) cannot be
// mapped onto a square without merging or splitting runs, and the map then
// folds (measured on the fallback patches of the four-sided layout). Split as
// in Catmull-Clark: cuts from a centre to the midpoint of each run give k
// sectors, each bounded by two half runs and two cuts, with its corners at
// the centre, the two midpoints and the junction between them. Every choice
// depends on the region's border and the surface only:
// - a run's midpoint is its vertex nearest to half its arc length, summed
//   from the end whose point is smaller, so the region on the other side of
//   the run picks the same vertex (no T-junction between two split regions);
// - the centre and the cuts come from `fan_split()` (least-squares centre of
//   the midpoints, cuts straight in a mean value flattening), which numbers
//   vertices by their points;
// - sectors are numbered from the run that starts the smallest rotation of
//   the neighbours' (label, part) sequence, so two meshes number them alike.
#ifndef DIFFUV_LAYOUT_SUB_PATCHES_H
#define DIFFUV_LAYOUT_SUB_PATCHES_H

#include <diffuv/layout/fan_split.h>
#include <diffuv/patches/corners.h>
#include <diffuv/patches/region_sides.h>
#include <diffuv/patches/segmentation.h>

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace diffuv {

/// Options of `split_regions_into_quads()`.
struct Sub_patch_options {
  /// Regions with more runs of neighbours stay whole (their sectors would be
  /// thin wedges); `region_sides()` then merges runs as before.
  std::size_t max_runs = 9;
  bool split_three = true;  ///< also split regions with three runs (into three quads)
  /// Runs shorter than this share of the region's perimeter do not count:
  /// where four regions meet at one vertex on one mesh, another tessellation
  /// of the same labels has two junctions with a run of an edge or two
  /// between them (doc/correspondence.md, measured on man's remeshed copy),
  /// and the two meshes must count alike. The
  /// sector's corner is then the vertex halfway along such runs.
  double min_run_fraction = 0.1;
};

/// A run of neighbours by its neighbour's (label, part); the mesh border is
/// below every label.
using Run_key = std::pair<long long, int>;

/// What `split_regions_into_quads()` did.
struct Sub_patch_report {
  std::size_t regions_split = 0;  ///< regions replaced by their sectors
  std::size_t sub_patches = 0;    ///< sectors made
  std::size_t not_split = 0;      ///< regions that qualified but could not be fanned (a run without a middle vertex, no centre, a sector not a disc)
  std::size_t corners_kept = 0;   ///< whole regions next to a split one whose corners were fixed before the split
  /// #P entries (the patches given, before the split): the runs each region
  /// was split along, by their neighbours' keys, sector 0's run first; empty
  /// for a patch left whole. What another mesh follows (`follow`).
  std::vector<std::vector<Run_key>> runs;
};

namespace internal {

// The runs of neighbours of a loop: the loop positions where the neighbour changes.
template <class TriangleMesh>
std::vector<std::size_t> junction_positions(const Patch_loop<TriangleMesh>& loop)
{
  std::vector<std::size_t> junctions;
  const std::size_t n = loop.vertices.size();
  for(std::size_t i = 0; i < n; ++i)
    if(loop.neighbour[(i + n - 1) % n] != loop.neighbour[i]) junctions.push_back(i);
  return junctions;
}

// The loop position of the midpoint of the run from loop position a to b
// (exclusive ends), or n if the run has no inner vertex. Lengths are summed
// from the end with the smaller point, so that the patch across the run,
// which walks it the other way, finds the same vertex.
template <class TriangleMesh, class VertexPointMap>
std::size_t run_midpoint(const Patch_loop<TriangleMesh>& loop, std::size_t a, std::size_t b, VertexPointMap vpm)
{
  const std::size_t n = loop.vertices.size();
  std::vector<std::size_t> run;  // positions a .. b
  for(std::size_t i = a;; i = (i + 1) % n) {
    run.push_back(i);
    if(i == b) break;
  }
  if(run.size() < 3) return n;
  std::vector<double> edge;  // edge j joins run[j] and run[j+1]
  for(std::size_t j = 0; j + 1 < run.size(); ++j) edge.push_back(loop.length[run[j]]);
  if(get(vpm, loop.vertices[b]) < get(vpm, loop.vertices[a])) {
    std::reverse(run.begin(), run.end());
    std::reverse(edge.begin(), edge.end());
  }
  std::vector<double> at(run.size(), 0.);
  for(std::size_t j = 0; j + 1 < run.size(); ++j) at[j + 1] = at[j] + edge[j];
  const double half = at.back() / 2;
  std::size_t best = 1;
  for(std::size_t j = 2; j + 1 < run.size(); ++j)
    if(std::abs(at[j] - half) < std::abs(at[best] - half)) best = j;
  return run[best];
}

} // namespace internal

/// Splits every disc patch of `seg` bounded by three or by five to
/// `max_runs` runs of neighbours into that many four-sided sectors (see the
/// top of this file), with their corners chosen (`Segmentation::patch_corners`,
/// the centre as (0,0)). Patches with four runs, with fewer than three, with
/// corners already chosen, or that are not discs stay whole; a whole patch
/// next to a split one gets the corners `region_sides()` gives it before the
/// split (without moves onto ears), so that the new junctions where the
/// neighbour's sectors meet it do not change its sides.
///
/// Sector s of a region of part `q` with k runs gets part 100·q + 10·k + s + 1,
/// so two meshes whose regions have different run counts pair no sector
/// wrongly (their keys differ).
template <class TriangleMesh, class VertexPointMap>
Sub_patch_report split_regions_into_quads(const TriangleMesh& tm, VertexPointMap vpm, Segmentation<TriangleMesh>& seg,
                                          const Sub_patch_options& options = Sub_patch_options(),
                                          const std::vector<std::vector<Run_key>>* follow = nullptr)
{
  if(follow && follow->size() != seg.number_of_patches())
    throw std::invalid_argument("split_regions_into_quads: follow must have one entry per patch");
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  Sub_patch_report report;
  const std::size_t P = seg.number_of_patches();
  auto findex = get(boost::face_index, tm);
  auto vindex = get(boost::vertex_index, tm);
  constexpr std::size_t border = Patch_loop<TriangleMesh>::mesh_border;

  struct Split {
    std::vector<std::vector<face_descriptor>> sectors;     // in canonical order
    std::vector<std::array<vertex_descriptor, 4>> corners;  // centre, midpoint, junction, midpoint
    std::size_t runs = 0;
    std::vector<Run_key> keys;                              // the runs, sector 0's first
  };
  std::vector<Split> splits(P);
  std::vector<int> scratch(num_vertices(tm), -1);
  for(std::size_t p = 0; p < P; ++p) {
    if(seg.corners(p) || !check_patch_disc(tm, seg, p)) continue;
    const auto loops = patch_loops(tm, vpm, seg, p);
    if(loops.size() != 1) continue;
    const auto& loop = loops.front();
    const std::size_t n = loop.vertices.size();
    const std::vector<std::size_t> all_junctions = internal::junction_positions(loop);
    auto key_of = [&](std::size_t position) {
      const std::size_t q = loop.neighbour[position];
      return q == border ? Run_key(std::numeric_limits<long long>::min(), 0)
                         : Run_key(static_cast<long long>(seg.patch_label[q]), seg.patch_part[q]);
    };
    auto length_of = [&](std::size_t a, std::size_t b) {
      double length = 0.;
      for(std::size_t i = a; i != b; i = (i + 1) % n) length += loop.length[i];
      return length;
    };
    // The runs that count: run a goes from start[a] to end[a], along one
    // neighbour; the runs that do not count lie between end[a] and start[a + 1].
    std::vector<std::size_t> start, end;
    if(follow) {
      // The other mesh's runs, in its order: runs here with the same
      // neighbours in the same cyclic order, the longest such choice (runs of
      // a neighbour met twice must each find their own).
      const std::vector<Run_key>& wanted = (*follow)[p];
      const std::size_t m = all_junctions.size();
      if(wanted.empty() || m < wanted.size()) { if(!wanted.empty()) ++report.not_split; continue; }
      std::vector<Run_key> here(m);
      std::vector<double> here_length(m);
      for(std::size_t j = 0; j < m; ++j) {
        here[j] = key_of(all_junctions[j]);
        here_length[j] = length_of(all_junctions[j], all_junctions[(j + 1) % m]);
      }
      const std::size_t k = wanted.size();
      const double none = -std::numeric_limits<double>::infinity();
      double best_total = none;
      std::vector<std::size_t> chosen;
      for(std::size_t s0 = 0; s0 < m; ++s0) {
        if(here[s0] != wanted[0]) continue;
        // best[a][t]: wanted[0..a] matched, wanted[a] at offset t from s0.
        std::vector<std::vector<double>> best(k, std::vector<double>(m, none));
        std::vector<std::vector<std::size_t>> from(k, std::vector<std::size_t>(m, 0));
        best[0][0] = here_length[s0];
        for(std::size_t a = 1; a < k; ++a)
          for(std::size_t t = a; t < m; ++t) {
            if(here[(s0 + t) % m] != wanted[a]) continue;
            for(std::size_t u = a - 1; u < t; ++u)
              if(best[a - 1][u] != none && best[a - 1][u] + here_length[(s0 + t) % m] > best[a][t]) {
                best[a][t] = best[a - 1][u] + here_length[(s0 + t) % m];
                from[a][t] = u;
              }
          }
        for(std::size_t t = k - 1; t < m; ++t)
          if(best[k - 1][t] != none && best[k - 1][t] > best_total) {
            best_total = best[k - 1][t];
            chosen.assign(k, 0);
            for(std::size_t a = k, u = t; a-- > 0;) {
              chosen[a] = (s0 + u) % m;
              u = from[a][u];
            }
          }
      }
      if(chosen.empty()) { ++report.not_split; continue; }
      // A run reaches over the runs of its neighbour next to it that were not
      // chosen, as the rule below joins them.
      for(std::size_t a = 0; a < k; ++a) {
        std::size_t first_run = chosen[a], last_run = chosen[a];
        const std::size_t before = chosen[(a + k - 1) % k], after = chosen[(a + 1) % k];
        for(std::size_t j = (chosen[a] + m - 1) % m; j != before; j = (j + m - 1) % m)
          if(here[j] == wanted[a]) first_run = j;
        for(std::size_t j = (chosen[a] + 1) % m; j != after; j = (j + 1) % m)
          if(here[j] == wanted[a]) last_run = j;
        start.push_back(all_junctions[first_run]);
        end.push_back(all_junctions[(last_run + 1) % m]);
      }
    } else {
      // Four runs: four-sided already.
      if(all_junctions.size() < 3 || all_junctions.size() == 4) continue;
      double perimeter = 0.;
      for(double l : loop.length) perimeter += l;
      for(std::size_t j = 0; j < all_junctions.size(); ++j) {
        const std::size_t a = all_junctions[j], b = all_junctions[(j + 1) % all_junctions.size()];
        if(length_of(a, b) < options.min_run_fraction * perimeter) continue;
        start.push_back(a);
        end.push_back(b);
      }
      // Two runs of one neighbour with only short runs between them are one.
      for(std::size_t a = 0; start.size() > 1 && a < start.size();) {
        const std::size_t b = (a + 1) % start.size();
        if(loop.neighbour[start[a]] != loop.neighbour[start[b]]) { ++a; continue; }
        end[a] = end[b];
        start.erase(start.begin() + static_cast<std::ptrdiff_t>(b));
        end.erase(end.begin() + static_cast<std::ptrdiff_t>(b));
        if(b < a) --a;
      }
    }
    const std::size_t k = start.size();
    if(!follow && !((k == 3 && options.split_three) || (k >= 5 && k <= options.max_runs))) continue;
    std::vector<std::size_t> mid(k), corner(k);  // corner[a]: between run a and run a + 1
    bool ok = true;
    for(std::size_t a = 0; a < k && ok; ++a) {
      mid[a] = internal::run_midpoint(loop, start[a], end[a], vpm);
      ok = mid[a] < n;
      const std::size_t from = end[a], to = start[(a + 1) % k];
      if(from == to) corner[a] = from;
      else {
        const std::size_t inner = internal::run_midpoint(loop, from, to, vpm);
        // A single edge of short runs: its end with the smaller point.
        corner[a] = inner < n ? inner : (get(vpm, loop.vertices[to]) < get(vpm, loop.vertices[from]) ? to : from);
      }
    }
    // Sectors numbered from the smallest rotation of the neighbours' keys
    // (the mesh border below every label); equal rotations by the longer first run.
    // (Followed runs come in the other mesh's order already.)
    std::vector<Run_key> key(k);
    std::vector<double> run_length(k, 0.);
    for(std::size_t a = 0; a < k; ++a) {
      key[a] = key_of(start[a]);
      run_length[a] = length_of(start[a], end[a]);
    }
    std::size_t first = 0;
    for(std::size_t r = 1; r < k && !follow; ++r) {
      int order = 0;
      for(std::size_t j = 0; j < k && order == 0; ++j)
        order = key[(r + j) % k] < key[(first + j) % k] ? -1 : (key[(first + j) % k] < key[(r + j) % k] ? 1 : 0);
      if(order < 0 || (order == 0 && run_length[r] > run_length[first])) first = r;
    }
    if(!ok) { ++report.not_split; continue; }
    const auto region = internal::make_local_region(tm, vpm, seg.patch_faces[p], loop.vertices, scratch);
    std::vector<int> targets(k);
    for(std::size_t a = 0; a < k; ++a) targets[a] = region.local(get(vindex, loop.vertices[mid[(first + a) % k]]));
    internal::Fan fan;
    if(internal::fan_split(region, targets, fan, 1.5, -1, 0) != internal::Fan_failure::none) { ++report.not_split; continue; }
    Split& split = splits[p];
    split.runs = k;
    for(std::size_t a = 0; a < k; ++a) split.keys.push_back(key[(first + a) % k]);
    split.sectors.assign(k, {});
    for(std::size_t f = 0; f < region.faces.size(); ++f)
      split.sectors[static_cast<std::size_t>(fan.sector_of_face[f])].push_back(region.faces[f]);
    const vertex_descriptor centre = region.verts[static_cast<std::size_t>(fan.centre)];
    for(std::size_t s = 0; s < k; ++s) {
      // Sector s runs from the midpoint of run first + s to that of the next,
      // across the junction that starts the next run.
      const vertex_descriptor junction = loop.vertices[corner[(first + s) % k]];
      split.corners.push_back({centre, loop.vertices[mid[(first + s) % k]], junction, loop.vertices[mid[(first + s + 1) % k]]});
    }
  }

  // Check each split on its own: its sectors discs, each with its four corners on its border.
  for(std::size_t p = 0; p < P; ++p) {
    if(splits[p].sectors.empty()) continue;
    Segmentation<TriangleMesh> trial;
    trial.face_patch.assign(num_faces(tm), Segmentation<TriangleMesh>::no_patch);
    bool ok = true;
    for(std::size_t s = 0; s < splits[p].sectors.size() && ok; ++s) {
      trial.patch_faces.push_back(splits[p].sectors[s]);
      trial.patch_label.push_back(0);
      trial.patch_part.push_back(static_cast<int>(s));
      for(face_descriptor f : splits[p].sectors[s]) trial.face_patch[get(findex, f)] = s;
      ok = !splits[p].sectors[s].empty();
    }
    for(std::size_t s = 0; s < splits[p].sectors.size() && ok; ++s) {
      ok = static_cast<bool>(check_patch_disc(tm, trial, s));
      if(!ok) break;
      const auto loops = patch_loops(tm, vpm, trial, s);
      Four_sides<vertex_descriptor> sides;
      const auto& c = splits[p].corners[s];
      ok = loops.size() == 1 &&
           static_cast<bool>(sides_from_corners(loops.front().vertices, std::vector<vertex_descriptor>(c.begin(), c.end()), sides));
    }
    if(!ok) {
      splits[p] = Split();
      ++report.not_split;
    }
  }

  // Whole patches next to a split one keep the corners they have now.
  std::vector<std::array<vertex_descriptor, 4>> kept(P, Segmentation<TriangleMesh>::no_corners());
  for(std::size_t p = 0; p < P; ++p) {
    if(!splits[p].sectors.empty() || seg.corners(p) || !check_patch_disc(tm, seg, p)) continue;
    const auto loops = patch_loops(tm, vpm, seg, p);
    bool next_to_split = false;
    for(const auto& loop : loops)
      for(std::size_t q : loop.neighbour) next_to_split = next_to_split || (q != border && !splits[q].sectors.empty());
    if(!next_to_split) continue;
    Four_sides<vertex_descriptor> sides;
    if(region_sides(tm, vpm, seg, p, sides, Region_sides_options{nullptr, false})) {
      kept[p] = sides.corners;
      ++report.corners_kept;
    }
  }

  // Rebuild: sectors in place of their regions, in order.
  Segmentation<TriangleMesh> out;
  out.face_patch.assign(num_faces(tm), Segmentation<TriangleMesh>::no_patch);
  auto add = [&](std::vector<face_descriptor> faces, int label, int part, const std::array<vertex_descriptor, 4>& corners) {
    for(face_descriptor f : faces) out.face_patch[get(findex, f)] = out.patch_faces.size();
    out.patch_faces.push_back(std::move(faces));
    out.patch_label.push_back(label);
    out.patch_part.push_back(part);
    out.patch_corners.push_back(corners);
  };
  report.runs.assign(P, {});
  for(std::size_t p = 0; p < P; ++p) {
    Split& split = splits[p];
    report.runs[p] = split.keys;
    if(split.sectors.empty()) {
      add(seg.patch_faces[p], seg.patch_label[p], seg.patch_part[p], seg.corners(p) ? *seg.corners(p) : kept[p]);
      continue;
    }
    ++report.regions_split;
    report.sub_patches += split.sectors.size();
    for(std::size_t s = 0; s < split.sectors.size(); ++s)
      add(std::move(split.sectors[s]), seg.patch_label[p],
          100 * seg.patch_part[p] + 10 * static_cast<int>(split.runs) + static_cast<int>(s) + 1, split.corners[s]);
  }
  seg = std::move(out);
  return report;
}

} // namespace diffuv

#endif // DIFFUV_LAYOUT_SUB_PATCHES_H
