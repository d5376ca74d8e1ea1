// diffuv: region labels carried from one mesh to another that lies on top of
// it (a remeshed, repaired or re-exported copy), by nearest face.
//
// This is the one place where 3D positions of one mesh are used against the
// other, and only to give the second mesh labels when it has none; the
// correspondence itself then uses (region, u, v) alone.
#ifndef DIFFUV_CORRESPONDENCE_NEAREST_FACE_LABELS_H
#define DIFFUV_CORRESPONDENCE_NEAREST_FACE_LABELS_H

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace diffuv {

/// How far the target lies from the source: labels carried by nearest face
/// mean something only for a target on top of the source.
struct Nearest_face_report {
  double median_distance = 0.;  ///< median over the target's faces of the distance from its centroid to the source
  double source_diagonal = 0.;  ///< the diagonal of the source's bounding box

  /// The median distance as a fraction of the source's diagonal.
  double median_fraction() const { return source_diagonal > 0. ? median_distance / source_diagonal : 0.; }
  /// True when most of the target lies on the source: the median distance
  /// within `fraction` of the source's diagonal (a remeshed or simplified
  /// copy stays well under the default 1 %; a moved or rotated copy does not).
  bool lies_on_source(double fraction = 0.01) const { return median_fraction() <= fraction; }
};

/// The label of each face of `target`: the label of the face of `source`
/// nearest to its centroid (Euclidean, through an AABB tree of `source`).
///
/// \tparam SourceMesh a `FaceListGraph` with internal face index and vertex points (Epick points)
/// \param source_labels #F(source) entries, by face index
/// \param report if given, receives how far the target lies from the source
/// \returns #F(target) entries, by face index
template <class SourceMesh, class TargetMesh>
std::vector<int> nearest_face_labels(const SourceMesh& source, const std::vector<int>& source_labels,
                                     const TargetMesh& target, Nearest_face_report* report = nullptr)
{
  using Point_3 = typename boost::property_traits<
      typename boost::property_map<SourceMesh, CGAL::vertex_point_t>::const_type>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point_3>::Kernel;
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<SourceMesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

  Tree tree(faces(source).first, faces(source).second, source);
  tree.accelerate_distance_queries();
  auto source_index = get(boost::face_index, source);
  auto target_index = get(boost::face_index, target);
  auto target_points = get(CGAL::vertex_point, target);
  std::vector<int> labels(num_faces(target), 0);
  std::vector<double> distances;
  if(report) distances.reserve(num_faces(target));
  for(auto f : faces(target)) {
    double x = 0., y = 0., z = 0.;
    int n = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, target), target)) {
      const auto& p = get(target_points, v);
      x += CGAL::to_double(p.x());
      y += CGAL::to_double(p.y());
      z += CGAL::to_double(p.z());
      ++n;
    }
    const Point_3 centroid(x / n, y / n, z / n);
    const auto nearest = tree.closest_point_and_primitive(centroid);
    labels[get(target_index, f)] = source_labels[get(source_index, nearest.second)];
    if(report) distances.push_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(centroid, nearest.first))));
  }
  if(report) {
    *report = Nearest_face_report();
    if(!distances.empty()) {
      auto middle = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2);
      std::nth_element(distances.begin(), middle, distances.end());
      report->median_distance = *middle;
    }
    const auto box = tree.bbox();
    report->source_diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                        CGAL::square(box.zmax() - box.zmin()));
  }
  return labels;
}

} // namespace diffuv

#endif // DIFFUV_CORRESPONDENCE_NEAREST_FACE_LABELS_H
