// diffuv: faces that every map onto the square flattens, and handing them to
// a neighbouring patch.
//
// A face whose three vertices lie on one side of its patch is flat in any map
// that sends that side onto a straight edge of the square.
// `region_sides()` first tries to move a corner onto the face's middle vertex
// (`separate_flat_triangles()`); where that would leave another face flat
// (a junction face between two runs that the side merges, measured on man),
// the face changes patch instead: it joins a neighbour across one of its
// border edges, if that leaves fewer flat triangles in every patch it touches.
#ifndef DIFFUV_PATCHES_FLAT_TRIANGLES_H
#define DIFFUV_PATCHES_FLAT_TRIANGLES_H

#include <diffuv/patches/corners.h>
#include <diffuv/patches/region_sides.h>
#include <diffuv/patches/segmentation.h>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace diffuv {

/// The faces of patch `p` whose three vertices all lie on one of `sides`
/// (a corner lies on its two sides).
template <class TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
flat_triangles(const TriangleMesh& tm, const Segmentation<TriangleMesh>& seg, std::size_t p,
           const Four_sides<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& sides)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  // Border vertex -> bit set of its sides, as a sorted vector (a patch's border is short).
  std::vector<std::pair<vertex_descriptor, std::uint8_t>> side_mask;
  for(Side s : all_sides)
    for(vertex_descriptor v : sides[s]) side_mask.emplace_back(v, static_cast<std::uint8_t>(1u << static_cast<int>(s)));
  std::sort(side_mask.begin(), side_mask.end());
  auto mask_of = [&](vertex_descriptor v) {
    std::uint8_t m = 0;
    for(auto it = std::lower_bound(side_mask.begin(), side_mask.end(), std::make_pair(v, std::uint8_t(0)));
        it != side_mask.end() && it->first == v; ++it)
      m |= it->second;
    return m;
  };
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> flat;
  for(auto f : seg.patch_faces[p]) {
    std::uint8_t common = 0xF;
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm)) common &= mask_of(v);
    if(common != 0) flat.push_back(f);
  }
  return flat;
}

/// Hands each face that stays flat after `region_sides()` (corners moved off
/// ears included) to a neighbouring patch across one of its edges, when the
/// patches it touches all stay discs with four sides, have fewer flat triangles
/// together, and keep their corners except for moves onto the face's own
/// vertices (so a hand-off never re-routes a side far from the face). Faces
/// still flat after that may then also go to a neighbour with corners moved
/// anywhere. A face in or next to a quad of the layout (corners chosen by
/// the layout) is never handed: the layout stays conforming. Patches are visited in order, a patch's flat triangles by
/// their centroids, neighbours in patch order, so the result depends only on
/// the segmentation and the geometry. Labels and the number and
/// order of patches are unchanged; a handed face takes its new patch's label.
///
/// \param keep_labels hand faces only to patches of the same label (the
///        sub-patches of one labelled region), so regions keep their borders
/// \returns how many faces changed patch
template <class TriangleMesh, class VertexPointMap>
std::size_t hand_flat_triangles_to_neighbours(const TriangleMesh& tm, VertexPointMap vpm, Segmentation<TriangleMesh>& seg,
                                          bool keep_labels = false, std::size_t max_rounds = 4)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  constexpr std::size_t unusable = std::numeric_limits<std::size_t>::max();
  auto findex = get(boost::face_index, tm);

  // The flat triangles of patch q, or `unusable` when it is no disc or has no
  // four sides; `corners` receives its corners.
  std::vector<face_descriptor> flat;
  std::vector<vertex_descriptor> corners;
  auto count_flat = [&](std::size_t q) -> std::size_t {
    flat.clear();
    corners.clear();
    if(!check_patch_disc(tm, seg, q)) return unusable;
    Four_sides<vertex_descriptor> sides;
    if(!region_sides(tm, vpm, seg, q, sides)) return unusable;
    flat = flat_triangles(tm, seg, q, sides);
    corners.assign(sides.corners.begin(), sides.corners.end());
    return flat.size();
  };
  // Whether a face of patch q has an edge with a face of another patch.
  auto has_neighbour = [&](std::size_t q) {
    for(face_descriptor f : seg.patch_faces[q])
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
        const face_descriptor g = face(opposite(h, tm), tm);
        if(g != boost::graph_traits<TriangleMesh>::null_face() && seg.face_patch[get(findex, g)] != q) return true;
      }
    return false;
  };
  // Moves face f from patch `from` to the end of patch `to`; returns its old position.
  auto move = [&](face_descriptor f, std::size_t from, std::size_t to) {
    auto& faces_from = seg.patch_faces[from];
    const auto at = std::find(faces_from.begin(), faces_from.end(), f);
    const auto position = static_cast<std::size_t>(at - faces_from.begin());
    faces_from.erase(at);
    seg.patch_faces[to].push_back(f);
    seg.face_patch[get(findex, f)] = to;
    return position;
  };
  auto move_back = [&](face_descriptor f, std::size_t from, std::size_t to, std::size_t position) {
    seg.patch_faces[to].pop_back();
    seg.patch_faces[from].insert(seg.patch_faces[from].begin() + static_cast<std::ptrdiff_t>(position), f);
    seg.face_patch[get(findex, f)] = from;
  };

  // First only hand-offs that keep every corner near the face; then, for
  // faces still flat (no corner placement can mend them: more ears than
  // corners, measured on anchor), also hand-offs wherever the corners go: a
  // chart with a flat triangle is not one-to-one, which no distortion
  // outweighs. Never in or next to a quad of the layout.
  std::size_t handed = 0;
  for(const bool near_only : {true, false}) {
    for(std::size_t round = 0; round < max_rounds; ++round) {
      std::size_t this_round = 0;
      for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
        // A quad of the layout hands off nothing (below), nor does a patch
        // with no neighbour (a disc kept whole): not measured.
        if(seg.corners(p) || !has_neighbour(p)) continue;
        if(count_flat(p) == unusable || flat.empty()) continue;
        // In the order of their centroids, not of their indices: the result
        // then does not depend on the face numbering.
        std::vector<std::pair<std::array<double, 3>, face_descriptor>> candidates;
        for(face_descriptor f : flat) {
          std::array<double, 3> c{0., 0., 0.};
          for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
            const auto q = get(vpm, v);
            c[0] += CGAL::to_double(q.x());
            c[1] += CGAL::to_double(q.y());
            c[2] += CGAL::to_double(q.z());
          }
          candidates.emplace_back(c, f);
        }
        std::sort(candidates.begin(), candidates.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        for(const auto& candidate : candidates) {
          const face_descriptor f = candidate.second;
          if(seg.face_patch[get(findex, f)] != p) continue;
          // Every patch across an edge of f: their sides may change with the move.
          std::vector<std::size_t> touched;
          for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
            const face_descriptor g = face(opposite(h, tm), tm);
            if(g != boost::graph_traits<TriangleMesh>::null_face() && seg.face_patch[get(findex, g)] != p)
              touched.push_back(seg.face_patch[get(findex, g)]);
          }
          std::sort(touched.begin(), touched.end());
          touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
          // Next to a quad nothing is handed (below): the patches are not measured.
          if(std::any_of(touched.begin(), touched.end(), [&](std::size_t t) { return seg.corners(t) != nullptr; }))
            continue;
          // The flat triangles of p and the touched patches together, and their
          // corners (p's first, then the touched patches' in order).
          std::vector<vertex_descriptor> all_corners;
          auto total_flat = [&]() {
            all_corners.clear();
            std::size_t total = 0;
            for(std::size_t k = 0; k <= touched.size(); ++k) {
              const std::size_t c = count_flat(k == 0 ? p : touched[k - 1]);
              if(c == unusable) return unusable;
              total += c;
              all_corners.insert(all_corners.end(), corners.begin(), corners.end());
            }
            return total;
          };
          const std::size_t before = total_flat();
          if(before == unusable) continue;
          const std::vector<vertex_descriptor> corners_before = all_corners;
          std::vector<vertex_descriptor> face_vertices;
          for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm)) face_vertices.push_back(v);
          // The move must stay local: a corner may only go to a vertex of f.
          // Without this, a new run of neighbours at f can re-route a patch's
          // side rule and move its corners far away (measured on man with
          // height bands: a patch's mean angle distortion from 2.8 to 61).
          // (Four corners per patch, in the same patch order before and after.)
          auto corners_stay = [&]() {
            for(std::size_t k = 0; k < all_corners.size(); ++k) {
              const auto old_begin = corners_before.begin() + static_cast<std::ptrdiff_t>(k / 4 * 4);
              if(std::find(old_begin, old_begin + 4, all_corners[k]) == old_begin + 4 &&
                 std::find(face_vertices.begin(), face_vertices.end(), all_corners[k]) == face_vertices.end())
                return false;
            }
            return true;
          };
          for(std::size_t q : touched) {
            if(keep_labels && seg.patch_label[q] != seg.patch_label[p]) continue;
            // A quad of the layout keeps its faces and its neighbours along
            // its sides (a hand-off there would give a side two patches):
            // p and the touched patches have no chosen corners, as tested above.
            const std::size_t position = move(f, p, q);
            if(total_flat() < before && (!near_only || corners_stay())) {
              ++this_round;
              break;
            }
            move_back(f, p, q, position);
          }
        }
      }
      handed += this_round;
      if(this_round == 0) break;
    }
  }
  return handed;
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_FLAT_TRIANGLES_H
