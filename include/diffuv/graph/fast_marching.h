// diffuv: multi-source fast marching on triangle meshes.
//
// Graph (edge-path) distances follow the tessellation: from a side of a patch
// they overestimate the surface distance and bend the (u,v) iso-lines along
// the edges. The fast marching method (Kimmel and
// Sethian, "Computing geodesic paths on manifolds", PNAS 1998) keeps the
// multi-source Dijkstra's heap-driven order but computes a vertex from two
// known vertices of a triangle, as if a planar wavefront crossed it, so
// distances can cut through faces. This header gives it as a reusable object
// (buffers and per-mesh geometry kept between runs, four runs per patch) and
// as a one-shot function.
//
// Accuracy (first order): a straight front is reproduced exactly on flat
// meshes wherever the obtuse angles can be split; on real meshes it is much
// closer to the exact polyhedral distance than edge paths are (measured in
// doc/design.md, "Distances").
#ifndef DIFFUV_GRAPH_FAST_MARCHING_H
#define DIFFUV_GRAPH_FAST_MARCHING_H

#include <diffuv/core/error.h>
#include <diffuv/graph/heap_tags.h>

#include <CGAL/boost/graph/graph_concepts.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace diffuv {

/// Optional inputs of `Fast_marching`.
struct Fast_marching_options {
  /// How many triangles may be unfolded, across the edge opposite an obtuse
  /// angle, to find a vertex that splits that angle into two acute ones
  /// (Kimmel and Sethian 1998, section 4). Default 16; 0 leaves obtuse
  /// triangles as they are, and their vertices then fall back more often to
  /// edge (Dijkstra) updates.
  unsigned max_unfolding_steps = 16;
};

namespace internal {

using Fmm_vec2 = std::array<double, 2>;
using Fmm_vec3 = std::array<double, 3>;

inline double fmm_dot(const Fmm_vec2& a, const Fmm_vec2& b) { return a[0] * b[0] + a[1] * b[1]; }
inline double fmm_cross(const Fmm_vec2& a, const Fmm_vec2& b) { return a[0] * b[1] - a[1] * b[0]; }
inline Fmm_vec2 fmm_minus(const Fmm_vec2& a, const Fmm_vec2& b) { return {a[0] - b[0], a[1] - b[1]}; }
inline double fmm_distance(const Fmm_vec3& a, const Fmm_vec3& b)
{
  const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
  return std::sqrt(x * x + y * y + z * z);
}

/// The distance at a vertex C from the distances `d0` at P = (0,0) and `d1` at
/// Q = (L,0), with C = (cx,cy), cy > 0, in the plane of triangle PQC (or of an
/// unfolded virtual triangle), modelling the front as a plane wave
/// d(x) = d0 + n.x with |n| = 1 (Kimmel and Sethian 1998, section 3).
/// Returns +infinity when the update is not valid: no plane wave fits
/// (|d1 - d0| >= L), the triangle is degenerate, or the characteristic reaching
/// C does not come through the segment PQ (the update direction is not inside
/// the triangle: causality). The caller then keeps the edge updates.
inline double planar_wave_update(double d0, double d1, double L, double cx, double cy)
{
  constexpr double infinity = std::numeric_limits<double>::infinity();
  if(!(L > 0.) || !(cy > 0.)) return infinity;
  const double nx = (d1 - d0) / L; // n.(Q - P) = d1 - d0
  if(!(std::abs(nx) < 1.)) return infinity;
  const double ny = std::sqrt(1. - nx * nx); // the front moves towards C (cy > 0)
  // Trace the characteristic through C back to the line PQ: C - s n, s = cy / ny.
  const double foot = cx - cy * nx / ny;
  if(foot < 0. || foot > L) return infinity;
  return d0 + nx * cx + ny * cy;
}

} // namespace internal

/// Computes, for every vertex of a triangle mesh, an approximation of its
/// geodesic distance on the surface to the nearest of a set of source
/// vertices, with a first-order fast marching method, and keeps its buffers
/// for the next run.
///
/// **Method.** The heap-driven order of `Multi_source_dijkstra` (a vertex is
/// *accepted* when it leaves the heap; Boost.Heap heap with decrease-key
/// through handles). When a vertex `a` is accepted, each neighbour `c` not yet
/// accepted gets
/// - the edge update `d(a) + |ac|` (Dijkstra's relaxation), and
/// - for each triangle `(a, b, c)` whose vertex `b` is accepted too, the
///   planar-wave triangle update of Kimmel and Sethian (1998): the distance at
///   `c` of the plane wave that takes the values `d(a)` and `d(b)`, kept only
///   if the wave reaches `c` through the edge `ab` (causality) and is not
///   below `d(a)` (acceptance stays in increasing order).
///
/// **Obtuse angles.** The triangle update at a vertex whose angle is obtuse
/// is rarely causal, and such vertices would mostly get edge updates (the
/// error of plain fast marching on irregular meshes). As Kimmel and Sethian
/// propose (section 4), the triangles beyond the edge opposite the obtuse
/// angle are unfolded into its plane, one at a time (at most
/// `Fast_marching_options::max_unfolding_steps`), until a vertex `d` is found
/// inside the section where both angles `a c d` and `d c b` are acute; the two
/// virtual triangles `(a, d, c)` and `(d, b, c)`, laid out in the unfolded
/// plane, then update `c` *in addition to* `(a, b, c)` (Kimmel and Sethian
/// replace it; keeping it was measured better, see `add_corner()`). When no
/// such vertex is found (an obtuse angle facing the mesh or patch border, the
/// step limit), the edge updates remain the fallback. The unfolding is done
/// once, by the constructor; strips are short (doc/design.md, "Distances").
///
/// **Guarantees.** Sources get 0 and unreachable vertices `+infinity`. Since
/// every edge update is made, the result is never above the edge-path
/// (Dijkstra) distance: by induction on the graph distance, the predecessor
/// `a` of `c` on a shortest edge path either is accepted before `c` (and
/// offers `d(a) + |ac|`) or after it (and then `d(c) <= d(a)`, acceptance
/// being in increasing order). It can be below the exact polyhedral
/// distance: a triangle with two source vertices gets the distance to the
/// segment between them (the side as a polyline, not as a set of points), and
/// a plane wave on coarse curved triangles errs either way.
///
/// **Accuracy and cost** are measured in doc/design.md, "Distances"
/// (test/test_distances.cpp checks the bounds).
///
/// **Patches.** Only the faces of `g` are crossed: on a
/// `CGAL::Face_filtered_graph` the unfolding and the updates stop at the
/// patch border (`is_border(h, g)`), and scratch buffers are indexed by the
/// patch's compacted vertex indices.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph` with an
///         internal vertex index in `[0, num_vertices(g))` (`CGAL::Surface_mesh`,
///         `CGAL::Face_filtered_graph`); triangle faces
/// \tparam HeapTag `Fibonacci_heap_tag` (default) or another tag of heap_tags.h
/// \tparam VertexPointMap a `ReadablePropertyMap` from vertices to a CGAL `Point_3`
///         (default: the graph's internal `CGAL::vertex_point` map)
template <class TriangleMesh,
          class HeapTag = Fibonacci_heap_tag,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>
class Fast_marching {
  BOOST_CONCEPT_ASSERT((CGAL::concepts::FaceListGraphConcept<TriangleMesh>));
  BOOST_CONCEPT_ASSERT((boost::VertexListGraphConcept<TriangleMesh>));

public:
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

private:
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using Index = std::uint32_t;
  using Vec2 = internal::Fmm_vec2;
  using Vec3 = internal::Fmm_vec3;

  using Node = internal::Distance_node<Index>;
  using Heap = internal::Min_distance_heap<HeapTag, Index>;
  using Handle = typename Heap::handle_type;
  enum State : std::uint8_t { unseen, queued, accepted };

  // One way of computing vertex c from two others p and q: a real triangle or
  // a virtual one from the unfolding, laid out with p = (0,0), q = (L,0),
  // c = (cx, cy), cy > 0.
  struct Update {
    Index c, p, q;
    double L, cx, cy;
  };
  // A neighbour of a vertex and the length of the edge to it.
  struct Neighbour {
    Index vertex;
    double length;
  };

public:
  /// Prepares buffers and the per-triangle geometry of `g`, with the graph's internal points.
  explicit Fast_marching(const TriangleMesh& g)
    : Fast_marching(g, get(CGAL::vertex_point, g)) {}

  /// Prepares buffers and the per-triangle geometry of `g` (edge lengths,
  /// triangle layouts, the unfolding of obtuse angles): O(#F) unless obtuse
  /// angles need long unfoldings. `g` and its points must not change while
  /// this object is used.
  ///
  /// \param g the mesh or patch
  /// \param vpm the points of the vertices of `g`
  /// \param options see `Fast_marching_options`
  Fast_marching(const TriangleMesh& g, VertexPointMap vpm, const Fast_marching_options& options = {})
    : graph_(g), vertex_index_(get(boost::vertex_index, g)), options_(options)
  {
    Tables& t = *tables_;
    const std::size_t n = num_vertices(g);
    t.vertices.resize(n);
    t.points.resize(n);
    for(vertex_descriptor v : boost::make_iterator_range(vertices(g))) {
      const Index i = index_of(v);
      t.vertices[i] = v;
      const auto& p = get(vpm, v);
      t.points[i] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    }
    build_neighbours();
    build_updates();
    // The points are needed only to build the tables.
    t.points.clear();
    t.points.shrink_to_fit();
    make_scratch();
  }

  /// Another engine over the same mesh that shares this one's tables, which
  /// no run changes, and has buffers of its own: the two may run at the same
  /// time on two threads (the four passes of one large patch), for the
  /// memory of one set of tables. Both must not outlive the mesh.
  Fast_marching twin() const { return Fast_marching(*this, Twin_tag()); }

  /// Fills `distance` with the approximate geodesic distance of every vertex
  /// to the nearest source. Vertices not reached from any source get `+infinity`.
  ///
  /// \tparam SourceRange a range of `vertex_descriptor`; duplicates are allowed
  /// \tparam DistanceMap a `WritablePropertyMap` from vertices to `double`
  /// \returns `empty_source_range` if `sources` is empty (every distance is then
  ///          `+infinity`), `not_triangle_mesh` if a face of `g` is not a
  ///          triangle (nothing is written), `ok` otherwise
  template <class SourceRange, class DistanceMap>
  Status run(const SourceRange& sources, DistanceMap distance)
  {
    if(!status_) return status_;
    constexpr double infinity = std::numeric_limits<double>::infinity();
    std::fill(distance_.begin(), distance_.end(), infinity);
    std::fill(state_.begin(), state_.end(), unseen);
    heap_.clear();

    bool any_source = false;
    for(vertex_descriptor s : sources) {
      any_source = true;
      const Index i = index_of(s);
      if(state_[i] == queued) continue; // listed twice
      distance_[i] = 0.;
      handles_[i] = heap_.push(Node{0., i});
      state_[i] = queued;
    }

    if(any_source) march();
    const Tables& t = *tables_;
    for(std::size_t i = 0; i < t.vertices.size(); ++i)
      put(distance, t.vertices[i], distance_[i]);
    return any_source ? Status() : Status(Status_code::empty_source_range);
  }

  const TriangleMesh& graph() const { return graph_; }

  /// The number of obtuse angles of `g`, and of those split by an unfolded vertex.
  std::size_t number_of_obtuse_angles() const { return obtuse_angles_; }
  std::size_t number_of_split_angles() const { return split_angles_; }

private:
  struct Twin_tag {};
  Fast_marching(const Fast_marching& other, Twin_tag)
    : graph_(other.graph_), vertex_index_(other.vertex_index_), options_(other.options_), status_(other.status_),
      obtuse_angles_(other.obtuse_angles_), split_angles_(other.split_angles_), tables_(other.tables_)
  {
    make_scratch();
  }

  void make_scratch()
  {
    const std::size_t n = tables_->vertices.size();
    handles_.resize(n);
    state_.assign(n, unseen);
    distance_.assign(n, std::numeric_limits<double>::infinity());
  }

  void march()
  {
    const Tables& t = *tables_;
    while(!heap_.empty()) {
      const Node top = heap_.top();
      heap_.pop();
      const Index a = top.vertex;
      const double da = top.distance;
      state_[a] = accepted;

      // Edge updates: Dijkstra's relaxation, the fallback and the upper bound.
      for(Index k = t.neighbour_begin[a]; k < t.neighbour_begin[a + 1]; ++k) {
        const Neighbour& nb = t.neighbours[k];
        if(state_[nb.vertex] != accepted) relax(nb.vertex, da + nb.length);
      }
      // Triangle updates through the (real or virtual) triangles where a and
      // the other known vertex are both accepted now.
      for(Index k = t.update_begin[a]; k < t.update_begin[a + 1]; ++k) {
        const Update& u = t.updates[t.update_ids[k]];
        if(state_[u.c] == accepted) continue;
        const Index b = (u.p == a) ? u.q : u.p;
        if(state_[b] != accepted) continue;
        const double through = internal::planar_wave_update(distance_[u.p], distance_[u.q], u.L, u.cx, u.cy);
        // d(b) <= d(a) (accepted earlier): through >= da keeps the acceptance
        // order monotone, which the upper bound by edge paths relies on.
        if(through >= da) relax(u.c, through);
      }
    }
  }

  void relax(Index c, double candidate)
  {
    if(!(candidate < distance_[c])) return;
    distance_[c] = candidate;
    if(state_[c] == queued) {
      heap_.increase(handles_[c], Node{candidate, c}); // higher priority = nearer
    } else {
      handles_[c] = heap_.push(Node{candidate, c});
      state_[c] = queued;
    }
  }

  Index index_of(vertex_descriptor v) const { return static_cast<Index>(get(vertex_index_, v)); }

  // Compressed rows of (neighbour, edge length), through the graph so that a
  // patch only lists its own edges.
  void build_neighbours()
  {
    Tables& t = *tables_;
    const std::size_t n = t.vertices.size();
    t.neighbour_begin.assign(n + 1, 0);
    t.neighbours.clear();
    // Each interior edge is listed from both ends, a border edge from both
    // too: 2E = 3F + B <= 3F + V on a manifold triangle mesh (elsewhere the
    // rows may still grow past it). Growing the rows by
    // doubling instead touched twice the memory (a third of this
    // constructor's time on a 1.1M-vertex disc was the kernel zeroing pages).
    t.neighbours.reserve(3 * static_cast<std::size_t>(num_faces(graph_)) + n);
    for(std::size_t i = 0; i < n; ++i) {
      t.neighbour_begin[i] = static_cast<Index>(t.neighbours.size());
      const vertex_descriptor v = t.vertices[i];
      if(halfedge(v, graph_) == boost::graph_traits<TriangleMesh>::null_halfedge()) continue; // isolated
      for(halfedge_descriptor h : CGAL::halfedges_around_target(v, graph_)) {
        const Index j = index_of(source(h, graph_));
        t.neighbours.push_back(Neighbour{j, internal::fmm_distance(t.points[i], t.points[j])});
      }
    }
    t.neighbour_begin[n] = static_cast<Index>(t.neighbours.size());
  }

  // The updates of every corner of every face, obtuse corners split by
  // unfolding when possible, then compressed rows of update ids per known
  // vertex (p and q of each update).
  void build_updates()
  {
    Tables& t = *tables_;
    t.updates.clear();
    // At most one obtuse corner per triangle, split into two more updates:
    // 5 per face is a bound, so the table is never copied while it grows.
    // Capacity never written is address space only, not memory.
    t.updates.reserve(5 * static_cast<std::size_t>(num_faces(graph_)));
    obtuse_angles_ = split_angles_ = 0;
    for(auto f : boost::make_iterator_range(faces(graph_))) {
      const halfedge_descriptor h0 = halfedge(f, graph_);
      if(next(next(next(h0, graph_), graph_), graph_) != h0) {
        status_ = Status(Status_code::not_triangle_mesh, "fast marching needs triangle faces");
        return;
      }
      halfedge_descriptor h = h0;
      for(int corner = 0; corner < 3; ++corner, h = next(h, graph_))
        add_corner(h);
    }

    const std::size_t n = t.vertices.size();
    t.update_begin.assign(n + 1, 0);
    for(const Update& u : t.updates) { ++t.update_begin[u.p + 1]; ++t.update_begin[u.q + 1]; }
    for(std::size_t i = 0; i < n; ++i) t.update_begin[i + 1] += t.update_begin[i];
    t.update_ids.resize(t.update_begin[n]);
    std::vector<Index> fill(t.update_begin.begin(), t.update_begin.end() - 1);
    for(Index k = 0; k < t.updates.size(); ++k) {
      t.update_ids[fill[t.updates[k].p]++] = k;
      t.update_ids[fill[t.updates[k].q]++] = k;
    }
  }

  // The corner at target(h) of the face of h: h goes q -> c, next(h) c -> p,
  // next(next(h)) p -> q (the opposite edge).
  void add_corner(halfedge_descriptor h)
  {
    const Tables& t = *tables_;
    const Index c = index_of(target(h, graph_));
    const Index q = index_of(source(h, graph_));
    const halfedge_descriptor opposite_edge = next(next(h, graph_), graph_);
    const Index p = index_of(source(opposite_edge, graph_));

    // Layout with c at the origin, p on the positive x-axis, q above it.
    const double lp = internal::fmm_distance(t.points[c], t.points[p]);
    const double lq = internal::fmm_distance(t.points[c], t.points[q]);
    const double lpq = internal::fmm_distance(t.points[p], t.points[q]);
    if(!(lp > 0.) || !(lq > 0.)) return; // degenerate: edge updates only
    const double cos_c = std::clamp((lp * lp + lq * lq - lpq * lpq) / (2. * lp * lq), -1., 1.);
    const Vec2 C{0., 0.}, P{lp, 0.}, Q{lq * cos_c, lq * std::sqrt(1. - cos_c * cos_c)};

    if(cos_c < -1e-12) { // obtuse; right angles (grids) need no split
      ++obtuse_angles_;
      Index d;
      Vec2 D;
      if(unfold(c, opposite_edge, P, Q, d, D)) {
        ++split_angles_;
        add_update(c, p, d, C, P, D);
        add_update(c, d, q, C, D, Q);
        // The obtuse triangle is kept too. Replacing it, as Kimmel and Sethian
        // do, made the mean error worse than no unfolding at all when the
        // front is curved (doc/design.md, "Distances"). More candidates only
        // lower the minimum, and fast marching errs mostly upwards.
      }
    }
    add_update(c, p, q, C, P, Q);
  }

  // Stores the update of c from p and q given their positions in one plane.
  void add_update(Index c, Index p, Index q, const Vec2& C, const Vec2& P, const Vec2& Q)
  {
    Tables& t = *tables_;
    const Vec2 pq = internal::fmm_minus(Q, P), pc = internal::fmm_minus(C, P);
    const double L = std::sqrt(internal::fmm_dot(pq, pq));
    if(!(L > 0.)) return;
    const double cx = internal::fmm_dot(pc, pq) / L;
    const double cy = std::abs(internal::fmm_cross(pq, pc)) / L;
    if(!(cy > 0.)) return; // c on the line pq: no triangle update
    t.updates.push_back(Update{c, p, q, L, cx, cy});
  }

  // Kimmel and Sethian's splitting of the obtuse angle of vertex c, at
  // C = (0,0) between P and Q (h goes p -> q, the edge opposite c): unfold
  // the faces beyond h into the plane of c's triangle until a vertex falls in
  // the section where both angles with CP and CQ are acute. Each step crosses
  // the edge that the section's axis crosses. Returns false at a border
  // (of the mesh or of the patch), at a face that is not a triangle, after
  // max_unfolding_steps, or when the strip wraps around back to c.
  bool unfold(Index c, halfedge_descriptor h, const Vec2& P, const Vec2& Q, Index& d, Vec2& D) const
  {
    const Tables& t = *tables_;
    // h goes p -> q; E1 and E2 are the positions of source(h) and target(h).
    Vec2 E1 = P, E2 = Q, behind{0., 0.}; // behind: the third vertex of the last face laid out
    const double nP = std::sqrt(internal::fmm_dot(P, P)), nQ = std::sqrt(internal::fmm_dot(Q, Q));
    const Vec2 axis{P[0] / nP + Q[0] / nQ, P[1] / nP + Q[1] / nQ}; // bisector of the angle at C

    for(unsigned step = 0; step < options_.max_unfolding_steps; ++step) {
      const halfedge_descriptor o = opposite(h, graph_);
      if(is_border(o, graph_)) return false; // mesh or patch border
      if(next(next(next(o, graph_), graph_), graph_) != o) return false;
      // o goes target(h) -> source(h); its face's third vertex is v.
      const halfedge_descriptor to_v = next(o, graph_);    // source(h) -> v
      const halfedge_descriptor from_v = next(to_v, graph_); // v -> target(h)
      const Index i1 = index_of(source(h, graph_)), i2 = index_of(target(h, graph_));
      const Index v = index_of(target(to_v, graph_));
      if(v == c) return false; // around a vertex of low valence: back to the start

      // Lay v out on the other side of E1E2 from `behind`, keeping its 3D
      // distances to the edge's endpoints.
      const Vec2 e = internal::fmm_minus(E2, E1);
      const double l = std::sqrt(internal::fmm_dot(e, e));
      if(!(l > 0.)) return false;
      const double r1 = internal::fmm_distance(t.points[v], t.points[i1]);
      const double r2 = internal::fmm_distance(t.points[v], t.points[i2]);
      const double along = (r1 * r1 - r2 * r2 + l * l) / (2. * l);
      const double across = std::sqrt(std::max(0., r1 * r1 - along * along));
      Vec2 normal{-e[1] / l, e[0] / l};
      if(internal::fmm_dot(normal, internal::fmm_minus(behind, E1)) > 0.) normal = {-normal[0], -normal[1]};
      const Vec2 V{E1[0] + along * e[0] / l + across * normal[0], E1[1] + along * e[1] / l + across * normal[1]};

      if(internal::fmm_dot(V, P) > 0. && internal::fmm_dot(V, Q) > 0.) { // inside the acute section
        d = v;
        D = V;
        return true;
      }
      // V is outside the section, so the section lies on one side of CV and
      // leaves the new face through one edge: the one its axis crosses,
      // (E1, V) if V is on E2's side of the axis, (V, E2) otherwise.
      if((internal::fmm_cross(axis, V) > 0.) == (internal::fmm_cross(axis, E2) > 0.)) {
        behind = E2;
        h = to_v;
        E2 = V;
      } else {
        behind = E1;
        h = from_v;
        E1 = V;
      }
    }
    return false;
  }

  const TriangleMesh& graph_;
  typename boost::property_map<TriangleMesh, boost::vertex_index_t>::const_type vertex_index_;
  Fast_marching_options options_;
  Status status_;
  std::size_t obtuse_angles_ = 0, split_angles_ = 0;

  // Per vertex, by vertex index, and per update: built once by the first
  // engine, then only read, so a twin() shares them.
  struct Tables {
    std::vector<vertex_descriptor> vertices;
    std::vector<Vec3> points;  // emptied once the rest is built
    std::vector<Index> neighbour_begin, update_begin;
    std::vector<Neighbour> neighbours;
    std::vector<Update> updates;
    std::vector<Index> update_ids;
  };
  std::shared_ptr<Tables> tables_ = std::make_shared<Tables>();

  // Scratch of a run.
  Heap heap_;
  std::vector<Handle> handles_;
  std::vector<std::uint8_t> state_;
  std::vector<double> distance_;
};

/// Computes, for every vertex of `g`, an approximation of its geodesic
/// distance on the surface to the nearest vertex of `sources` by first-order
/// fast marching (one-shot form of `Fast_marching`, which documents the
/// method and its accuracy).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph` with an
///         internal vertex index; triangle faces
/// \tparam VertexPointMap a `ReadablePropertyMap` from vertices to a CGAL `Point_3`
/// \tparam SourceRange a range of vertex descriptors of `g`
/// \tparam DistanceMap a `WritablePropertyMap` from vertices to `double`; unreachable vertices get +infinity
/// \tparam HeapTag `Fibonacci_heap_tag` (default) or another tag of heap_tags.h
/// \returns `empty_source_range`, `not_triangle_mesh` or `ok`
template <class TriangleMesh, class VertexPointMap, class SourceRange, class DistanceMap,
          class HeapTag = Fibonacci_heap_tag>
Status fast_marching_distances(const TriangleMesh& g, VertexPointMap vpm, const SourceRange& sources,
                               DistanceMap distance, HeapTag = HeapTag())
{
  Fast_marching<TriangleMesh, HeapTag, VertexPointMap> fmm(g, vpm);
  return fmm.run(sources, distance);
}

} // namespace diffuv

#endif // DIFFUV_GRAPH_FAST_MARCHING_H
