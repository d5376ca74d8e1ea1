// diffuv: patches from region labels: the connected components of faces of
// one label, in a canonical order.
#ifndef DIFFUV_PATCHES_PATCHES_FROM_LABELS_H
#define DIFFUV_PATCHES_PATCHES_FROM_LABELS_H

#include <diffuv/patches/segmentation.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/centroid.h>
#include <CGAL/squared_distance_3.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace diffuv {

/// Groups faces into patches: the connected components (across edges) of
/// faces with equal labels. Faces labelled `ignore_label` get no patch.
///
/// Patches are ordered by label, then by decreasing 3D area (a canonical order
/// when a label has several components; equal areas fall back on the lowest face index).
///
/// \tparam TriangleMesh a model of `FaceListGraph` with internal face index
/// \param face_labels #F entries, by face index
template <class TriangleMesh, class VertexPointMap>
Segmentation<TriangleMesh> patches_from_labels(const TriangleMesh& tm, VertexPointMap vpm,
                                               const std::vector<int>& face_labels,
                                               int ignore_label = std::numeric_limits<int>::min())
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  constexpr std::size_t none = Segmentation<TriangleMesh>::no_patch;
  auto findex = get(boost::face_index, tm);
  std::vector<face_descriptor> face_of(num_faces(tm));
  for(face_descriptor f : faces(tm)) face_of[get(findex, f)] = f;

  // Components by breadth-first search over edges joining equal labels.
  std::vector<std::size_t> component(num_faces(tm), none);
  std::vector<std::vector<face_descriptor>> members;
  std::vector<int> labels;
  for(std::size_t start = 0; start < face_of.size(); ++start) {
    if(component[start] != none || face_labels[start] == ignore_label) continue;
    const std::size_t c = members.size();
    members.emplace_back();
    labels.push_back(face_labels[start]);
    std::vector<std::size_t> queue = {start};
    component[start] = c;
    for(std::size_t q = 0; q < queue.size(); ++q) {
      const face_descriptor f = face_of[queue[q]];
      members[c].push_back(f);
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
        const auto g = face(opposite(h, tm), tm);
        if(g == boost::graph_traits<TriangleMesh>::null_face()) continue;
        const std::size_t gi = get(findex, g);
        if(component[gi] == none && face_labels[gi] == labels[c]) {
          component[gi] = c;
          queue.push_back(gi);
        }
      }
    }
  }

  // Canonical order: label, then decreasing area, then lowest face index.
  std::vector<double> area(members.size(), 0.);
  std::vector<std::size_t> lowest(members.size(), none);
  for(std::size_t c = 0; c < members.size(); ++c)
    for(face_descriptor f : members[c]) {
      area[c] += CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(f, tm, CGAL::parameters::vertex_point_map(vpm)));
      lowest[c] = (std::min)(lowest[c], static_cast<std::size_t>(get(findex, f)));
    }
  std::vector<std::size_t> order(members.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if(labels[a] != labels[b]) return labels[a] < labels[b];
    if(area[a] != area[b]) return area[a] > area[b];
    return lowest[a] < lowest[b];
  });

  Segmentation<TriangleMesh> seg;
  seg.face_patch.assign(num_faces(tm), none);
  for(std::size_t p = 0; p < order.size(); ++p) {
    seg.patch_label.push_back(labels[order[p]]);
    seg.patch_part.push_back(0);
    seg.patch_faces.push_back(std::move(members[order[p]]));
    for(face_descriptor f : seg.patch_faces.back()) seg.face_patch[get(findex, f)] = p;
  }
  return seg;
}

/// The connected components (across edges) of a set of faces, as
/// `patches_from_labels()` gives them for labels that are one value on these
/// faces and `ignore_label` elsewhere: by decreasing 3D area, then lowest
/// face index; each component's faces in breadth-first order from its lowest
/// face index. Costs O(faces), not O(mesh), per call.
///
/// \param marks #F entries, all `Segmentation<TriangleMesh>::no_patch` (or
///        empty: it is then sized); returned in that state, so that one array
///        serves many calls
template <class TriangleMesh, class VertexPointMap>
std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>>
connected_parts(const TriangleMesh& tm, VertexPointMap vpm,
                const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& faces,
                std::vector<std::size_t>& marks)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  constexpr std::size_t none = Segmentation<TriangleMesh>::no_patch, unvisited = none - 1;
  auto findex = get(boost::face_index, tm);
  if(marks.size() != num_faces(tm)) marks.assign(num_faces(tm), none);
  std::vector<std::pair<std::size_t, face_descriptor>> by_index;
  by_index.reserve(faces.size());
  for(face_descriptor f : faces) {
    by_index.emplace_back(get(findex, f), f);
    marks[by_index.back().first] = unvisited;
  }
  std::sort(by_index.begin(), by_index.end(), [](const auto& a, const auto& b) { return a.first < b.first; });

  // The same search as patches_from_labels(): starts in increasing face index.
  std::vector<std::vector<face_descriptor>> members;
  for(const auto& [start, start_face] : by_index) {
    if(marks[start] != unvisited) continue;
    const std::size_t c = members.size();
    members.emplace_back();
    std::vector<face_descriptor>& queue = members[c];
    queue.push_back(start_face);
    marks[start] = c;
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(auto h : CGAL::halfedges_around_face(halfedge(queue[q], tm), tm)) {
        const auto g = face(opposite(h, tm), tm);
        if(g == boost::graph_traits<TriangleMesh>::null_face()) continue;
        const std::size_t gi = get(findex, g);
        if(marks[gi] == unvisited) {
          marks[gi] = c;
          queue.push_back(g);
        }
      }
  }
  for(const auto& entry : by_index) marks[entry.first] = none;

  std::vector<double> area(members.size(), 0.);
  std::vector<std::size_t> lowest(members.size(), none);
  for(std::size_t c = 0; c < members.size(); ++c)
    for(face_descriptor f : members[c]) {
      area[c] += CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(f, tm, CGAL::parameters::vertex_point_map(vpm)));
      lowest[c] = (std::min)(lowest[c], static_cast<std::size_t>(get(findex, f)));
    }
  std::vector<std::size_t> order(members.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if(area[a] != area[b]) return area[a] > area[b];
    return lowest[a] < lowest[b];
  });
  std::vector<std::vector<face_descriptor>> parts;
  parts.reserve(order.size());
  for(std::size_t c : order) parts.push_back(std::move(members[c]));
  return parts;
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_PATCHES_FROM_LABELS_H
