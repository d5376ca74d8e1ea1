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

namespace internal {

// The faces reached from `start` across edges, breadth first, `start` first:
// a neighbour g joins when `join(face index of g)` says so (and marks it
// taken). One search for patches_from_labels() and connected_parts(), so
// that both give the same components with their faces in the same order.
template <class TriangleMesh, class Join>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
grow_component(const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::face_descriptor start, Join join)
{
  auto findex = get(boost::face_index, tm);
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> queue = {start};
  for(std::size_t q = 0; q < queue.size(); ++q)
    for(auto h : CGAL::halfedges_around_face(halfedge(queue[q], tm), tm)) {
      const auto g = face(opposite(h, tm), tm);
      if(g != boost::graph_traits<TriangleMesh>::null_face() && join(static_cast<std::size_t>(get(findex, g))))
        queue.push_back(g);
    }
  return queue;
}

// The canonical order of components: by `labels` first if given (one per
// component), then by decreasing 3D area, then by lowest face index.
template <class TriangleMesh, class VertexPointMap>
std::vector<std::size_t>
canonical_component_order(const TriangleMesh& tm, VertexPointMap vpm,
                          const std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>>& members,
                          const std::vector<int>* labels = nullptr)
{
  auto findex = get(boost::face_index, tm);
  std::vector<double> area(members.size(), 0.);
  std::vector<std::size_t> lowest(members.size(), (std::numeric_limits<std::size_t>::max)());
  for(std::size_t c = 0; c < members.size(); ++c)
    for(auto f : members[c]) {
      area[c] += CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(f, tm, CGAL::parameters::vertex_point_map(vpm)));
      lowest[c] = (std::min)(lowest[c], static_cast<std::size_t>(get(findex, f)));
    }
  std::vector<std::size_t> order(members.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if(labels && (*labels)[a] != (*labels)[b]) return (*labels)[a] < (*labels)[b];
    if(area[a] != area[b]) return area[a] > area[b];
    return lowest[a] < lowest[b];
  });
  return order;
}

} // namespace internal

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
    const int label = face_labels[start];
    labels.push_back(label);
    component[start] = c;
    members.push_back(internal::grow_component(tm, face_of[start], [&](std::size_t g) {
      if(component[g] != none || face_labels[g] != label) return false;
      component[g] = c;
      return true;
    }));
  }

  // Canonical order: label, then decreasing area, then lowest face index.
  const std::vector<std::size_t> order = internal::canonical_component_order(tm, vpm, members, &labels);

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
    marks[start] = c;
    members.push_back(internal::grow_component(tm, start_face, [&](std::size_t g) {
      if(marks[g] != unvisited) return false;
      marks[g] = c;
      return true;
    }));
  }
  for(const auto& entry : by_index) marks[entry.first] = none;
  const std::vector<std::size_t> order = internal::canonical_component_order(tm, vpm, members);
  std::vector<std::vector<face_descriptor>> parts;
  parts.reserve(order.size());
  for(std::size_t c : order) parts.push_back(std::move(members[c]));
  return parts;
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_PATCHES_FROM_LABELS_H
