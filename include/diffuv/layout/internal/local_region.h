// diffuv: a disc region of a mesh with its own vertex numbers, and its mean
// value flattening: what a fan split (layout/fan_split.h) and a framed cell
// (layout/internal/frame_cell.h) work on. Local ids follow the vertices'
// positions, so every choice made on a region is the same on a renumbered
// copy of the mesh.
#ifndef DIFFUV_LAYOUT_INTERNAL_LOCAL_REGION_H
#define DIFFUV_LAYOUT_INTERNAL_LOCAL_REGION_H

#include <diffuv/internal/lazy_dijkstra.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace diffuv {
namespace internal {

/// A disc region of a mesh with local vertex numbers (0 .. #verts-1).
template <class TriangleMesh>
struct Local_region {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  std::vector<face_descriptor> faces;             ///< #F_r entries
  std::vector<vertex_descriptor> verts;           ///< #V_r entries: local id -> mesh vertex
  std::vector<std::array<double, 3>> points;      ///< #V_r entries
  std::vector<std::array<int, 3>> face_verts;     ///< #F_r entries, local ids in the faces' orientation
  std::vector<std::vector<int>> neighbours;       ///< #V_r entries: vertices joined by an edge of the region
  std::vector<char> on_border;                    ///< #V_r entries
  std::vector<int> loop;                          ///< the border, counter-clockwise, local ids
  std::vector<std::pair<std::size_t, int>> local_of_index;  ///< (mesh vertex index, local id), sorted

  /// The local id of a mesh vertex (by its index), or -1.
  int local(std::size_t vertex_index) const
  {
    const auto it = std::lower_bound(local_of_index.begin(), local_of_index.end(), std::make_pair(vertex_index, -1));
    return it != local_of_index.end() && it->first == vertex_index ? it->second : -1;
  }

  double length(int a, int b) const
  {
    const auto& p = points[a];
    const auto& q = points[b];
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  }
  bool adjacent(int a, int b) const
  {
    return std::find(neighbours[a].begin(), neighbours[a].end(), b) != neighbours[a].end();
  }

  /// Edge-path distances from `sources` over the region's edges.
  void dijkstra(const std::vector<int>& sources, std::vector<double>& dist) const
  {
    dist.assign(verts.size(), std::numeric_limits<double>::infinity());
    lazy_dijkstra(sources, dist, [this](int i, auto&& relax) {
      for(int j : neighbours[i]) relax(j, length(i, j));
    });
  }
};

/// Builds the local region of `faces` whose border is `loop` (counter-
/// clockwise). `local` is scratch of #V(tm) entries, all -1 on entry and on return.
///
/// Local ids follow the vertices' positions (lexicographic), not their
/// numbering, and the loop starts at its smallest id: every later choice (ties
/// in a shortest path, the order of a sum) is then the same whatever the order
/// of the mesh's vertices and faces. `faces` keeps the order given.
template <class TriangleMesh, class VertexPointMap>
Local_region<TriangleMesh> make_local_region(
    const TriangleMesh& tm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& faces,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& loop, std::vector<int>& local)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  Local_region<TriangleMesh> r;
  auto vindex = get(boost::vertex_index, tm);
  r.faces = faces;
  std::vector<std::pair<std::array<double, 3>, vertex_descriptor>> distinct;
  for(auto f : faces)
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      int& l = local[get(vindex, v)];
      if(l >= 0) continue;
      l = 0;
      const auto& p = get(vpm, v);
      distinct.push_back({{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}, v});
    }
  std::stable_sort(distinct.begin(), distinct.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for(const auto& [point, v] : distinct) {
    local[get(vindex, v)] = static_cast<int>(r.verts.size());
    r.verts.push_back(v);
    r.points.push_back(point);
  }
  for(auto f : faces) {
    std::array<int, 3> fv{};
    int k = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      if(k < 3) fv[k] = local[get(vindex, v)];
      ++k;
    }
    r.face_verts.push_back(fv);
  }
  // Neighbour lists in increasing order of id: the order ties are met in.
  r.neighbours.assign(r.verts.size(), {});
  for(const auto& fv : r.face_verts)
    for(int k = 0; k < 3; ++k) {
      const int a = fv[k], b = fv[(k + 1) % 3];
      if(!r.adjacent(a, b)) {
        r.neighbours[a].push_back(b);
        r.neighbours[b].push_back(a);
      }
    }
  for(auto& list : r.neighbours) std::sort(list.begin(), list.end());
  r.on_border.assign(r.verts.size(), 0);
  for(auto v : loop) {
    r.loop.push_back(local[get(vindex, v)]);
    r.on_border[r.loop.back()] = 1;
  }
  if(!r.loop.empty())
    std::rotate(r.loop.begin(), std::min_element(r.loop.begin(), r.loop.end()), r.loop.end());
  r.local_of_index.reserve(r.verts.size());
  for(std::size_t i = 0; i < r.verts.size(); ++i) r.local_of_index.emplace_back(static_cast<std::size_t>(get(vindex, r.verts[i])), static_cast<int>(i));
  std::sort(r.local_of_index.begin(), r.local_of_index.end());
  for(auto v : r.verts) local[get(vindex, v)] = -1;
  return r;
}

inline double ccw_gap(double from, double to)
{
  double d = to - from;
  while(d < 0) d += 2 * M_PI;
  while(d >= 2 * M_PI) d -= 2 * M_PI;
  return d;
}

/// A mean value flattening of a disc region (Floater 2003): the border on
/// the unit circle by arc length, every interior vertex the mean-value-weighted
/// average of its neighbours. With a convex border and positive weights this
/// is an embedding. Returns false if the solve failed.
template <class TriangleMesh>
bool flatten_region(const Local_region<TriangleMesh>& r, std::vector<double>& X, std::vector<double>& Y)
{
  const std::size_t nv = r.verts.size(), n = r.loop.size();
  X.assign(nv, 0.);
  Y.assign(nv, 0.);
  double total = 0;
  for(std::size_t i = 0; i < n; ++i) total += r.length(r.loop[i], r.loop[(i + 1) % n]);
  if(!(total > 0)) return false;
  double s = 0;
  for(std::size_t i = 0; i < n; ++i) {
    X[r.loop[i]] = std::cos(2 * M_PI * s / total);
    Y[r.loop[i]] = std::sin(2 * M_PI * s / total);
    s += r.length(r.loop[i], r.loop[(i + 1) % n]);
  }
  std::vector<int> unknown(nv, -1);
  int nu = 0;
  for(std::size_t i = 0; i < nv; ++i)
    if(!r.on_border[i]) unknown[i] = nu++;
  if(nu == 0) return true;
  // w_ij = (tan(a/2) + tan(b/2)) / |x_j - x_i|, with a, b the angles at i of the
  // two faces of edge ij; tan(a/2) = |u x v| / (|u||v| + u.v).
  // Sums in an order of the ids (faces by their sorted ids, weights in
  // increasing neighbour order), so the result does not depend on the order
  // the faces came in.
  std::vector<std::array<int, 3>> ordered = r.face_verts;
  for(auto& fv : ordered) std::sort(fv.begin(), fv.end());  // a face's weights do not depend on its orientation
  std::sort(ordered.begin(), ordered.end());
  // Each vertex's weights by neighbour, kept sorted: a flat list is cheaper
  // than a map and sums in the same order.
  std::vector<std::vector<std::pair<int, double>>> weight(nv);
  auto add_weight = [&](int i, int j, double w) {
    auto& wi = weight[i];
    auto it = std::lower_bound(wi.begin(), wi.end(), j, [](const std::pair<int, double>& e, int key) { return e.first < key; });
    if(it == wi.end() || it->first != j) it = wi.insert(it, {j, 0.});
    it->second += w;
  };
  for(const auto& fv : ordered)
    for(int e = 0; e < 3; ++e) {
      const int i = fv[e], a = fv[(e + 1) % 3], b = fv[(e + 2) % 3];
      if(r.on_border[i]) continue;
      const auto& p = r.points[i];
      const auto& pa = r.points[a];
      const auto& pb = r.points[b];
      const double ux = pa[0] - p[0], uy = pa[1] - p[1], uz = pa[2] - p[2];
      const double vx = pb[0] - p[0], vy = pb[1] - p[1], vz = pb[2] - p[2];
      const double lu = std::sqrt(ux * ux + uy * uy + uz * uz), lv = std::sqrt(vx * vx + vy * vy + vz * vz);
      const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
      const double denominator = lu * lv + (ux * vx + uy * vy + uz * vz);
      if(!(lu > 0 && lv > 0 && denominator > 0)) continue;
      const double half_tan = std::sqrt(cx * cx + cy * cy + cz * cz) / denominator;
      add_weight(i, a, half_tan / lu);
      add_weight(i, b, half_tan / lv);
    }
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd bx = Eigen::VectorXd::Zero(nu), by = Eigen::VectorXd::Zero(nu);
  for(std::size_t i = 0; i < nv; ++i) {
    if(r.on_border[i]) continue;
    double sum = 0;
    for(const auto& [j, w] : weight[i]) sum += w;
    triplets.emplace_back(unknown[i], unknown[i], sum > 0 ? sum : 1.);
    for(const auto& [j, w] : weight[i]) {
      if(unknown[j] >= 0) {
        triplets.emplace_back(unknown[i], unknown[j], -w);
      } else {
        bx[unknown[i]] += w * X[j];
        by[unknown[i]] += w * Y[j];
      }
    }
  }
  Eigen::SparseMatrix<double> A(nu, nu);
  A.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(A);
  if(lu.info() != Eigen::Success) return false;
  const Eigen::VectorXd sx = lu.solve(bx), sy = lu.solve(by);
  for(std::size_t i = 0; i < nv; ++i)
    if(unknown[i] >= 0) {
      X[i] = sx[unknown[i]];
      Y[i] = sy[unknown[i]];
    }
  return true;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_LAYOUT_INTERNAL_LOCAL_REGION_H
