// diffuv: a mesh cut into patches (the paper's section 2.7).
//
// A segmentation gives every face a patch; a patch is a connected set of
// faces of one region label. Patches come from labels (painted by a person,
// or read from a file) or from an automatic graph-Voronoi partition refined
// until every patch is a topological disc.
#ifndef DIFFUV_PATCHES_SEGMENTATION_H
#define DIFFUV_PATCHES_SEGMENTATION_H

#include <diffuv/core/error.h>
#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/internal/index_marks.h>

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
#include <vector>

namespace diffuv {

/// The point type of a vertex point map.
template <class VertexPointMap>
using Point_of = typename boost::property_traits<VertexPointMap>::value_type;

/// Every face of a mesh assigned to a patch.
template <class TriangleMesh>
struct Segmentation {
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  static constexpr std::size_t no_patch = std::numeric_limits<std::size_t>::max();

  std::vector<std::size_t> face_patch;                    ///< #F entries (by face index): the face's patch
  std::vector<int> patch_label;                           ///< #P entries: the region label of each patch
  std::vector<int> patch_part;                            ///< #P entries: 0, or 1, 2, ... for the pieces of a region cut in parts
  std::vector<std::vector<face_descriptor>> patch_faces;  ///< #P entries: the faces of each patch
  /// Empty, or #P entries: the four corners of each patch, counter-clockwise
  /// with (0,0) first, when they were chosen together with the patch (the
  /// four-sided layout, layout/quad_layout.h). An entry of null vertices
  /// (`boost::graph_traits<TriangleMesh>::null_vertex()`) leaves the corners
  /// to `region_sides()`.
  std::vector<std::array<vertex_descriptor, 4>> patch_corners;

  std::size_t number_of_patches() const { return patch_faces.size(); }

  /// The corners chosen with patch `p`, or null if `region_sides()` chooses them.
  const std::array<vertex_descriptor, 4>* corners(std::size_t p) const
  {
    if(p >= patch_corners.size() || patch_corners[p][0] == boost::graph_traits<TriangleMesh>::null_vertex()) return nullptr;
    return &patch_corners[p];
  }
  /// No chosen corners: `region_sides()` picks them for every patch.
  static std::array<vertex_descriptor, 4> no_corners()
  {
    const vertex_descriptor none = boost::graph_traits<TriangleMesh>::null_vertex();
    return {none, none, none, none};
  }

  /// Replaces patch `p` by `pieces` (same label, parts 1, 2, ... in the given
  /// order), inserted where `p` was so that the order of the others is kept.
  template <class FaceIndexMap>
  void split(std::size_t p, std::vector<std::vector<face_descriptor>> pieces, FaceIndexMap findex)
  {
    const int label = patch_label[p];
    const int base = patch_part[p] == 0 ? 0 : patch_part[p] * 10; // a piece of a piece keeps a distinct part number
    patch_label.erase(patch_label.begin() + static_cast<std::ptrdiff_t>(p));
    patch_part.erase(patch_part.begin() + static_cast<std::ptrdiff_t>(p));
    patch_faces.erase(patch_faces.begin() + static_cast<std::ptrdiff_t>(p));
    if(!patch_corners.empty()) patch_corners.erase(patch_corners.begin() + static_cast<std::ptrdiff_t>(p));
    for(std::size_t k = 0; k < pieces.size(); ++k) {
      patch_label.insert(patch_label.begin() + static_cast<std::ptrdiff_t>(p + k), label);
      patch_part.insert(patch_part.begin() + static_cast<std::ptrdiff_t>(p + k), base + static_cast<int>(k) + 1);
      patch_faces.insert(patch_faces.begin() + static_cast<std::ptrdiff_t>(p + k), std::move(pieces[k]));
      if(!patch_corners.empty()) patch_corners.insert(patch_corners.begin() + static_cast<std::ptrdiff_t>(p + k), no_corners());
    }
    for(std::size_t q = 0; q < patch_faces.size(); ++q)
      for(face_descriptor f : patch_faces[q]) face_patch[get(findex, f)] = q;
  }
};

/// A boundary loop of a patch, walked counter-clockwise (interior on the left).
template <class TriangleMesh>
struct Patch_loop {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  static constexpr std::size_t mesh_border = std::numeric_limits<std::size_t>::max();

  std::vector<vertex_descriptor> vertices;      ///< n entries; edge i goes from vertices[i] to vertices[i+1 mod n]
  std::vector<halfedge_descriptor> halfedges;   ///< n entries: edge i as the patch's halfedge
  std::vector<std::size_t> neighbour;           ///< n entries: patch across edge i, or `mesh_border`
  std::vector<double> length;                   ///< n entries: 3D length of edge i
};

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

/// Returns the boundary loops of patch `p`, each counter-clockwise, with the
/// patch across each edge. A disc patch has exactly one.
template <class TriangleMesh, class VertexPointMap>
std::vector<Patch_loop<TriangleMesh>> patch_loops(const TriangleMesh& tm, VertexPointMap vpm,
                                                  const Segmentation<TriangleMesh>& seg, std::size_t p)
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  auto findex = get(boost::face_index, tm);
  auto hindex = get(boost::halfedge_index, tm);
  auto patch_of = [&](halfedge_descriptor h) {
    const auto f = face(h, tm);
    return f == boost::graph_traits<TriangleMesh>::null_face() ? Patch_loop<TriangleMesh>::mesh_border
                                                                : seg.face_patch[get(findex, f)];
  };
  // A boundary halfedge of p: in a face of p, its opposite in another patch or on the border.
  auto on_boundary = [&](halfedge_descriptor h) { return patch_of(h) == p && patch_of(opposite(h, tm)) != p; };

  std::vector<Patch_loop<TriangleMesh>> loops;
  // The boundary halfedges already walked, sorted: O(boundary) memory, where
  // a flag per halfedge of the mesh made each call O(mesh).
  std::vector<std::size_t> used;
  auto walked = [&](halfedge_descriptor h) {
    return std::binary_search(used.begin(), used.end(), static_cast<std::size_t>(get(hindex, h)));
  };
  for(auto f : seg.patch_faces[p])
    for(halfedge_descriptor start : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      if(!on_boundary(start) || walked(start)) continue;
      Patch_loop<TriangleMesh> loop;
      halfedge_descriptor h = start;
      do {
        loop.vertices.push_back(source(h, tm));
        loop.halfedges.push_back(h);
        loop.neighbour.push_back(patch_of(opposite(h, tm)));
        loop.length.push_back(std::sqrt(CGAL::to_double(
            CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm))))));
        // The next boundary halfedge leaves target(h): turn around it through p's faces.
        halfedge_descriptor g = next(h, tm);
        while(!on_boundary(g)) g = next(opposite(g, tm), tm);
        h = g;
      } while(h != start);
      for(halfedge_descriptor b : loop.halfedges) used.push_back(static_cast<std::size_t>(get(hindex, b)));
      std::sort(used.begin(), used.end());
      loops.push_back(std::move(loop));
    }
  return loops;
}

/// Relabels the faces of every patch whose boundary has fewer than
/// `min_boundary_vertices` vertices (a sliver or a lone face cannot have four
/// sides) with the label of the neighbouring patch that shares the longest
/// boundary with it, then rebuilds the patches; repeats until none is left.
///
/// \returns how many patches were merged
template <class TriangleMesh, class VertexPointMap>
std::size_t merge_small_patches(const TriangleMesh& tm, VertexPointMap vpm,
                                std::vector<int>& face_labels, Segmentation<TriangleMesh>& seg,
                                std::size_t min_boundary_vertices = 4)
{
  auto findex = get(boost::face_index, tm);
  std::size_t merged = 0;
  for(bool changed = true; changed;) {
    changed = false;
    for(std::size_t p = 0; p < seg.number_of_patches() && !changed; ++p) {
      const auto loops = patch_loops(tm, vpm, seg, p);
      std::size_t boundary_vertices = 0;
      std::map<std::size_t, double> shared; // neighbour patch -> shared length
      for(const auto& loop : loops) {
        boundary_vertices += loop.vertices.size();
        for(std::size_t i = 0; i < loop.vertices.size(); ++i)
          if(loop.neighbour[i] != Patch_loop<TriangleMesh>::mesh_border) shared[loop.neighbour[i]] += loop.length[i];
      }
      if(boundary_vertices >= min_boundary_vertices || shared.empty()) continue;
      // The neighbour sharing the longest border (the lowest on a tie) whose
      // union with p has enough boundary edges; if none has, the one sharing the
      // longest border. Without the first rule the faces of a tiny closed
      // component (a tetrahedron) pile up into one closed patch, one after the
      // other, where two two-triangle discs were possible.
      std::vector<std::pair<std::size_t, double>> candidates(shared.begin(), shared.end());
      std::stable_sort(candidates.begin(), candidates.end(),
                       [](const auto& a, const auto& b) { return a.second > b.second; });
      std::size_t best = candidates.front().first;
      for(const auto& candidate : candidates) {
        const std::size_t q = candidate.first;
        std::size_t edges = 0; // boundary edges of the union: p's not along q, then q's not along p
        for(const auto& loop : loops)
          for(std::size_t n : loop.neighbour) edges += n != q ? 1 : 0;
        for(auto f : seg.patch_faces[q]) {
          for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
            const auto g = face(opposite(h, tm), tm);
            const std::size_t across = g == boost::graph_traits<TriangleMesh>::null_face()
                                           ? Segmentation<TriangleMesh>::no_patch
                                           : seg.face_patch[get(findex, g)];
            if(across != q && across != p) ++edges;
          }
          if(edges >= min_boundary_vertices) break; // enough: a large neighbour stops early
        }
        if(edges >= min_boundary_vertices) {
          best = q;
          break;
        }
      }
      for(auto f : seg.patch_faces[p]) face_labels[get(findex, f)] = seg.patch_label[best];
      seg = patches_from_labels(tm, vpm, face_labels);
      ++merged;
      changed = true;
    }
  }
  return merged;
}

/// Checks that patch `p` is a topological disc: triangles only, connected,
/// one boundary loop that passes each vertex once, V - E + F = 1.
/// Costs O(patch size) (unlike `check_disc()` on a `Face_filtered_graph`,
/// which touches the whole mesh), so it can run on every patch of every
/// refinement step.
template <class TriangleMesh>
Status check_patch_disc(const TriangleMesh& tm, const Segmentation<TriangleMesh>& seg, std::size_t p)
{
  const auto& pf = seg.patch_faces[p];
  auto fail = [&](Status_code code, const std::string& what) {
    return Status(code, "patch " + std::to_string(p) + " (label " + std::to_string(seg.patch_label[p]) + ")" +
                            (what.empty() ? "" : ": " + what));
  };
  if(pf.empty()) return fail(Status_code::empty_mesh, "");
  auto findex = get(boost::face_index, tm);
  auto vindex = get(boost::vertex_index, tm);
  auto in_patch = [&](auto f) {
    return f != boost::graph_traits<TriangleMesh>::null_face() && seg.face_patch[get(findex, f)] == p;
  };

  // Triangles, vertices, boundary edges; connectivity by a walk over edges.
  // The marks are kept per thread from one call to the next (4 bytes per
  // vertex and per face of the largest mesh seen) so that a call is O(patch).
  thread_local internal::Index_marks seen_vertices, seen_faces;
  seen_vertices.reset(num_vertices(tm));
  seen_faces.reset(num_faces(tm));
  std::size_t V = 0, boundary_edges = 0;
  for(auto f : pf) {
    if(!CGAL::is_triangle(halfedge(f, tm), tm))
      return fail(Status_code::not_triangle_mesh, "face " + std::to_string(get(findex, f)));
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      if(seen_vertices.insert(get(vindex, target(h, tm)))) ++V;
      if(!in_patch(face(opposite(h, tm), tm))) ++boundary_edges;
    }
  }
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> queue = {pf.front()};
  queue.reserve(pf.size());
  seen_faces.insert(get(findex, pf.front()));
  for(std::size_t q = 0; q < queue.size(); ++q)
    for(auto h : CGAL::halfedges_around_face(halfedge(queue[q], tm), tm)) {
      const auto g = face(opposite(h, tm), tm);
      if(in_patch(g) && seen_faces.insert(get(findex, g))) queue.push_back(g);
    }
  if(queue.size() != pf.size())
    return fail(Status_code::disconnected_mesh, "");

  const auto loops = patch_loops(tm, get(CGAL::vertex_point, tm), seg, p);
  if(loops.empty()) return fail(Status_code::no_border, "");
  if(loops.size() > 1) return fail(Status_code::several_borders, std::to_string(loops.size()) + " boundary loops");
  std::vector<std::size_t> loop_ids;
  for(auto v : loops.front().vertices) loop_ids.push_back(get(vindex, v));
  std::sort(loop_ids.begin(), loop_ids.end());
  const auto repeat = std::adjacent_find(loop_ids.begin(), loop_ids.end());
  if(repeat != loop_ids.end())
    return fail(Status_code::non_manifold, "the boundary passes vertex " + std::to_string(*repeat) + " twice");
  const std::size_t F = pf.size(), E = (3 * F + boundary_edges) / 2;
  const long long euler = static_cast<long long>(V) - static_cast<long long>(E) + static_cast<long long>(F);
  if(euler != 1)
    return fail(Status_code::not_a_disc,
                "Euler characteristic " + std::to_string(euler) + ", genus " + std::to_string((1 - euler) / 2));
  return Status();
}

/// Moves "ear" faces across region borders: a face with two or more edges on
/// the border of its region towards one same other region joins that region.
/// Such a face has all three vertices on one side of its patch, so any map onto
/// the square flattens it; moving it also straightens the border.
///
/// \param face_labels #F entries, changed in place
/// \param ignore_label faces with this label are left alone, and no face takes it
/// \param order the faces to visit, in this order (default: `faces(tm)`)
/// \returns how many faces changed label
template <class TriangleMesh>
std::size_t smooth_region_borders(
    const TriangleMesh& tm, std::vector<int>& face_labels, std::size_t passes = 3,
    int ignore_label = std::numeric_limits<int>::min(),
    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>* order = nullptr)
{
  auto findex = get(boost::face_index, tm);
  const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> all =
      order ? std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>() :
              std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>(faces(tm).begin(), faces(tm).end());
  const auto& visit = order ? *order : all;
  std::size_t changed = 0;
  // Faces are visited one after the other (a move can make the next face an
  // ear): pass an `order` that does not depend on the face numbering for a
  // result that does not either.
  for(std::size_t pass = 0; pass < passes; ++pass) {
    std::size_t this_pass = 0;
    for(auto f : visit) {
      const int own = face_labels[get(findex, f)];
      if(own == ignore_label) continue; // outside the faces being cut
      int across[3];
      int k = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
        const auto g = face(opposite(h, tm), tm);
        across[k++] = g == boost::graph_traits<TriangleMesh>::null_face() ? own : face_labels[get(findex, g)];
        if(k == 3) break;
      }
      if(k != 3) continue;
      for(int a = 0; a < 3; ++a)
        if(across[a] != own && across[a] != ignore_label &&
           (across[a] == across[(a + 1) % 3] || across[a] == across[(a + 2) % 3])) {
          face_labels[get(findex, f)] = across[a];
          ++this_pass;
          break;
        }
    }
    changed += this_pass;
    if(this_pass == 0) break;
  }
  return changed;
}

namespace internal {

// The position in `region` of the face whose centroid (`centroids`, one per
// face of `region`) is farthest from the region's area-weighted centroid,
// `before(i, j)` deciding ties: the first seed of farthest-point sampling, the
// same face whatever the numbering, the position or the orientation of the mesh.
template <class TriangleMesh, class VertexPointMap, class Point, class Before>
std::size_t farthest_from_area_centroid(const TriangleMesh& tm,
                                        VertexPointMap vpm,
                                        const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& region, const std::vector<Point>& centroids, Before before)
{
  double cx = 0, cy = 0, cz = 0, area = 0;
  for(std::size_t i = 0; i < region.size(); ++i) {
    const double a = CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(region[i], tm, CGAL::parameters::vertex_point_map(vpm)));
    cx += a * CGAL::to_double(centroids[i].x());
    cy += a * CGAL::to_double(centroids[i].y());
    cz += a * CGAL::to_double(centroids[i].z());
    area += a;
  }
  if(area > 0) { cx /= area; cy /= area; cz /= area; }
  std::size_t first = 0;
  double far = -1;
  for(std::size_t i = 0; i < region.size(); ++i) {
    const double dx = CGAL::to_double(centroids[i].x()) - cx, dy = CGAL::to_double(centroids[i].y()) - cy,
                 dz = CGAL::to_double(centroids[i].z()) - cz;
    const double d = dx * dx + dy * dy + dz * dz;
    if(d > far || (d == far && before(i, first))) {
      far = d;
      first = i;
    }
  }
  return first;
}

} // namespace internal

/// Options of `voronoi_discs()`.
struct Voronoi_options {
  std::size_t patches = 12;       ///< how many seeds to start from (farthest-point sampling)
  std::size_t max_patches = 400;  ///< stop adding seeds beyond this many, even if some patch is not a disc
};

/// Cuts the faces `region` of `tm` into topological discs: farthest-point
/// seeds and a graph-Voronoi partition of the faces, computed by our
/// multi-source Dijkstra on the dual graph (faces joined across edges,
/// weighted by the distance between their centroids), region borders
/// smoothed (`smooth_region_borders()`), pieces with fewer than four boundary
/// vertices merged into a neighbour, and a new seed in each non-disc patch
/// (its face farthest from the seeds), until every patch is a disc.
///
/// Deterministic: the first seed is the face farthest from the region's
/// centroid, then farthest-point sampling, so the result does not depend on the
/// vertex or face order, nor on the mesh's position or orientation (except
/// when two faces are exactly equally far).
///
/// \param region the faces to cut (a connected set)
/// \param face_labels #F entries: receives, for the faces of `region`, labels
///        `first_label`, `first_label + 1`, ... (one per final patch); other faces untouched
/// \returns the number of seeds used
template <class TriangleMesh, class VertexPointMap>
std::size_t voronoi_discs(const TriangleMesh& tm,
                          VertexPointMap vpm,
                          const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& region, std::vector<int>& face_labels, int first_label,
                          const Voronoi_options& options = Voronoi_options())
{
  using Dual = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                     boost::property<boost::edge_weight_t, double>>;
  auto findex = get(boost::face_index, tm);
  const std::size_t n = region.size();
  if(n == 0) return 0;
  std::vector<std::size_t> local(num_faces(tm), n); // face index -> position in region
  for(std::size_t i = 0; i < n; ++i) local[get(findex, region[i])] = i;
  auto centroid = [&](auto f) {
    auto h = halfedge(f, tm);
    return CGAL::centroid(get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm)));
  };
  std::vector<Point_of<VertexPointMap>> centroids;
  for(std::size_t i = 0; i < n; ++i) centroids.push_back(centroid(region[i]));
  Dual dual(n);
  for(std::size_t i = 0; i < n; ++i)
    for(auto h : CGAL::halfedges_around_face(halfedge(region[i], tm), tm)) {
      const auto g = face(opposite(h, tm), tm);
      if(g == boost::graph_traits<TriangleMesh>::null_face()) continue;
      const std::size_t j = local[get(findex, g)];
      if(j < n && i < j)
        boost::add_edge(i, j, std::sqrt(CGAL::to_double(CGAL::squared_distance(centroids[i], centroids[j]))), dual);
    }

  Multi_source_dijkstra<Dual> dijkstra(dual);
  std::vector<double> distance(n);
  std::vector<std::size_t> origin(n, 0);
  auto dindex = get(boost::vertex_index, dual);
  auto dmap = boost::make_iterator_property_map(distance.begin(), dindex);
  auto omap = boost::make_iterator_property_map(origin.begin(), dindex);
  auto weight = get(boost::edge_weight, dual);
  auto farthest = [&](auto keep) { // the reached face with the largest distance among those kept, or n
    std::size_t best = n;
    for(std::size_t i = 0; i < n; ++i)
      if(keep(i) && distance[i] < std::numeric_limits<double>::infinity() && (best == n || distance[i] > distance[best]))
        best = i;
    return best;
  };
  auto all = [](std::size_t) { return true; };

  // The first seed (lowest face index on a tie).
  const std::size_t first_seed = internal::farthest_from_area_centroid(
      tm, vpm, region, centroids, [&](std::size_t i, std::size_t j) { return get(findex, region[i]) < get(findex, region[j]); });
  std::vector<std::size_t> seeds = {first_seed};
  const std::size_t target = options.patches > 0 ? options.patches : 1;
  dijkstra.run(seeds, weight, dmap, omap);
  // Each new seed only lowers the distances of the faces nearer to it: one
  // bounded run per seed instead of a whole run on all the seeds.
  auto add_seed = [&](std::size_t s) {
    seeds.push_back(s);
    dijkstra.add_source(s, seeds.size() - 1, weight, dmap, omap);
  };
  while(seeds.size() < target && seeds.size() < n) add_seed(farthest(all));

  while(true) {
    // Labels of the region's faces by cell; faces outside hidden behind one sentinel.
    std::vector<int> labels(num_faces(tm), std::numeric_limits<int>::min());
    for(std::size_t i = 0; i < n; ++i) labels[get(findex, region[i])] = static_cast<int>(origin[i]);
    // Visit faces farthest from the seeds first (an order of the surface, not of the numbering).
    std::vector<std::size_t> by_distance(n);
    std::iota(by_distance.begin(), by_distance.end(), 0);
    std::sort(by_distance.begin(), by_distance.end(), [&](std::size_t a, std::size_t b) {
      return distance[a] != distance[b] ? distance[a] > distance[b] : origin[a] < origin[b];
    });
    std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> order;
    for(std::size_t i : by_distance) order.push_back(region[i]);
    smooth_region_borders(tm, labels, 3, std::numeric_limits<int>::min(), &order);
    Segmentation<TriangleMesh> seg = patches_from_labels(tm, vpm, labels);
    merge_small_patches(tm, vpm, labels, seg);

    // One new seed in every patch that is not a disc, where it is farthest from the seeds.
    std::vector<std::size_t> added;
    if(seeds.size() < options.max_patches) {
      std::vector<std::size_t> bad_patch(n, seg.number_of_patches());
      for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
        if(!check_patch_disc(tm, seg, p))
          for(auto f : seg.patch_faces[p]) bad_patch[local[get(findex, f)]] = p;
      std::vector<std::size_t> best(seg.number_of_patches(), n);
      for(std::size_t i = 0; i < n; ++i) {
        const std::size_t p = bad_patch[i];
        if(p < seg.number_of_patches() && distance[i] > 0. &&
           (best[p] == n || distance[i] > distance[best[p]]))
          best[p] = i;
      }
      for(std::size_t i : best)
        if(i != n && seeds.size() + added.size() < options.max_patches) added.push_back(i);
    }
    if(added.empty()) { // every patch is a disc, or no seed can be added
      for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
        for(auto f : seg.patch_faces[p]) face_labels[get(findex, f)] = first_label + static_cast<int>(p);
      return seeds.size();
    }
    for(std::size_t i : added) add_seed(i);
  }
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_SEGMENTATION_H
