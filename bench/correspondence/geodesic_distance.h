// diffuv correspondence bench: the exact geodesic distance between two
// points of a mesh, computed on a local piece of it.
#ifndef DIFFUV_BENCH_CORRESPONDENCE_GEODESIC_DISTANCE_H
#define DIFFUV_BENCH_CORRESPONDENCE_GEODESIC_DISTANCE_H

#include "correspondence/correspondence_bench.h"

#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace diffuv_bench {

// Exact geodesic distance between two points of a mesh, on a local piece.
//
// A path of length at most L from p to q stays in the ellipsoid
// {x : |x - p| + |x - q| <= L}, so it only meets faces T with
// d(p, T) + d(q, T) <= L. Those faces, grown from p's face across edges, form
// a piece of the mesh holding every such path (a path through a vertex v of
// the ellipsoid finds v's whole fan in the piece: the fan's faces all pass the
// test, since d(p, T) + d(q, T) <= |p - v| + |v - q|, and are joined across
// edges). CGAL's Surface_mesh_shortest_path on that piece gives a distance
// d >= the true geodesic g (a path on the piece is a path on the mesh), and
// d = g when g <= L. Hence: if d <= L, d is exact; if d > L, d bounds g, so
// the piece for L = d holds a shortest path and the next run is exact; if q
// is not reached, L grows by half. L starts at 1.2 |pq|. The piece may pinch
// at a vertex outside the ellipsoid (two runs of its fan taken); such a vertex
// is duplicated, one copy per run, which removes only paths through it, all
// longer than L. A piece that is the whole mesh is not copied.
//
// Two points on one face (a point on an edge or at a vertex is on each face
// around it) are joined by the straight segment: exact without any run. This
// also avoids a failure of Surface_mesh_shortest_path 5.5: a source at a
// vertex and a target at (or within 1e-16 of) the same vertex, located in
// another face, gives 0.03-0.07 x sqrt(area) or no path at all (found on the
// shuffled cow).
class Geodesic_distance {
public:
  struct Statistics {
    std::size_t queries = 0, same_face = 0, piece_runs = 0, retries = 0, whole_mesh_runs = 0, pinched_vertices = 0;
    std::size_t no_path = 0;   // Surface_mesh_shortest_path found no path from p, retried from q
    std::size_t piece_faces = 0; // summed over runs
  };

  explicit Geodesic_distance(const Mesh& m)
    : mesh_(m), diagonal_(bounding_diagonal(m)), slot_(m.number_of_faces(), unvisited)
  {
    // Surface_mesh_shortest_path needs contiguous indices.
    if(m.has_garbage()) throw std::invalid_argument("Geodesic_distance: collect the mesh's garbage first");
  }

  /// The exact geodesic distance between `p` and `q`.
  double operator()(const Location& p, const Location& q)
  {
    ++stats_.queries;
    const Point_3 P = point_at(p, mesh_), Q = point_at(q, mesh_);
    const double euclidean = std::sqrt(CGAL::squared_distance(P, Q));
    if(share_a_face(p, q)) {
      ++stats_.same_face;
      return euclidean;
    }
    double bound = 1.2 * euclidean + 1e-9 * diagonal_;
    for(int attempt = 0; attempt < 100; ++attempt) {
      const double d = on_piece(P, Q, bound, p, q);
      if(d >= 0. && (d <= bound || whole_mesh_used_)) return d;
      ++stats_.retries;
      bound = d > bound ? d * (1. + 1e-9) : 1.5 * bound;
    }
    return whole_mesh(p, q);
  }

  /// Surface_mesh_shortest_path on the whole mesh (the reference); if no path
  /// is found (see above), from q to p; infinity if neither finds one.
  double whole_mesh(const Location& p, const Location& q)
  {
    ++stats_.whole_mesh_runs;
    whole_mesh_used_ = true;
    double d = shortest_path(mesh_, p, q);
    if(d < 0.) {
      ++stats_.no_path;
      d = shortest_path(mesh_, q, p);
    }
    return d < 0. ? infinity : d;
  }

  /// The distance on the piece for the bound `bound` only (for the
  /// self-check): -1 if q is not reached.
  double piece_only(const Location& p, const Location& q, double bound)
  {
    return on_piece(point_at(p, mesh_), point_at(q, mesh_), bound, p, q);
  }

  const Statistics& statistics() const { return stats_; }

  /// Checks, on every piece built, that the located points of the piece are
  /// the original points (the corner rotation of the copied faces is right).
  bool verify_points = false;
  double worst_point_mismatch = 0.;

private:
  using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, Mesh>;
  using Shortest_path = CGAL::Surface_mesh_shortest_path<Traits>;
  static constexpr int unvisited = -2, rejected = -1;

  static double shortest_path(const Mesh& m, const Location& source, const Location& target)
  {
    Shortest_path sp(m);
    sp.add_source_point(source.first, {{source.second[0], source.second[1], source.second[2]}});
    return sp.shortest_distance_to_source_points(target.first, {{target.second[0], target.second[1], target.second[2]}})
        .first;
  }

  // The vertices whose barycentric coordinate in `loc` is not negligible.
  std::vector<vertex_descriptor> support(const Location& loc) const
  {
    const auto c = corners(loc.first, mesh_);
    std::vector<vertex_descriptor> s;
    for(int k = 0; k < 3; ++k)
      if(loc.second[k] > 1e-12) s.push_back(c[k]);
    return s;
  }

  // True if some face holds both points (a point at a vertex lies on all the
  // faces around it, a point on an edge on both faces of the edge).
  bool share_a_face(const Location& p, const Location& q) const
  {
    if(p.first == q.first) return true;
    const std::vector<vertex_descriptor> sp = support(p), sq = support(q);
    std::vector<face_descriptor> candidates{p.first};
    if(sp.size() == 1) {
      for(face_descriptor f : CGAL::faces_around_target(mesh_.halfedge(sp[0]), mesh_))
        if(f != Mesh::null_face()) candidates.push_back(f);
    } else if(sp.size() == 2) {
      const auto h = CGAL::halfedge(sp[0], sp[1], mesh_);
      if(h.second && !mesh_.is_border(mesh_.opposite(h.first))) candidates.push_back(mesh_.face(mesh_.opposite(h.first)));
      if(h.second && !mesh_.is_border(h.first)) candidates.push_back(mesh_.face(h.first));
    }
    for(face_descriptor f : candidates) {
      const auto c = corners(f, mesh_);
      bool all = true;
      for(vertex_descriptor v : sq) all = all && (v == c[0] || v == c[1] || v == c[2]);
      if(all) return true;
    }
    return false;
  }

  // The faces T with d(P, T) + d(Q, T) <= bound, grown from `start` across
  // edges, into `selected_` (slot_[f] = position; rejected faces -1).
  void select(const Point_3& P, const Point_3& Q, double bound, face_descriptor start)
  {
    for(face_descriptor f : visited_) slot_[f.idx()] = unvisited;
    visited_.clear();
    selected_.clear();
    slot_[start.idx()] = 0;
    visited_.push_back(start);
    selected_.push_back(start);
    for(std::size_t i = 0; i < selected_.size(); ++i) {
      for(halfedge_descriptor h : CGAL::halfedges_around_face(mesh_.halfedge(selected_[i]), mesh_)) {
        const halfedge_descriptor o = mesh_.opposite(h);
        if(mesh_.is_border(o)) continue;
        const face_descriptor g = mesh_.face(o);
        if(slot_[g.idx()] != unvisited) continue;
        visited_.push_back(g);
        const auto c = corners(g, mesh_);
        const Kernel::Triangle_3 t(mesh_.point(c[0]), mesh_.point(c[1]), mesh_.point(c[2]));
        if(std::sqrt(CGAL::squared_distance(P, t)) + std::sqrt(CGAL::squared_distance(Q, t)) <= bound) {
          slot_[g.idx()] = static_cast<int>(selected_.size());
          selected_.push_back(g);
        } else {
          slot_[g.idx()] = rejected;
        }
      }
    }
  }

  bool in_piece(face_descriptor f) const { return slot_[f.idx()] >= 0; }

  // The corner (0, 1, 2 in Face_location order) of face f at vertex v.
  int corner_of(face_descriptor f, vertex_descriptor v) const
  {
    const auto c = corners(f, mesh_);
    return c[0] == v ? 0 : c[1] == v ? 1 : 2;
  }

  // The distance on the piece for `bound`; -1 if q is not in it.
  double on_piece(const Point_3& P, const Point_3& Q, double bound, const Location& p, const Location& q)
  {
    whole_mesh_used_ = false; // set by whole_mesh(): the answer is then exact whatever the bound
    select(P, Q, bound, p.first);
    if(!in_piece(q.first)) return -1.;
    if(selected_.size() == mesh_.number_of_faces()) return whole_mesh(p, q);
    ++stats_.piece_runs;
    stats_.piece_faces += selected_.size();

    // A vertex of the piece per run of consecutive selected faces around each
    // original vertex (one per vertex unless the piece pinches there).
    std::vector<std::array<int, 3>> corner_vertex(selected_.size(), {{-1, -1, -1}});
    std::vector<Point_3> points;
    for(std::size_t i = 0; i < selected_.size(); ++i) {
      const face_descriptor f = selected_[i];
      const auto c = corners(f, mesh_);
      for(int k = 0; k < 3; ++k) {
        if(corner_vertex[i][k] >= 0) continue;
        const vertex_descriptor v = c[k];
        const int id = static_cast<int>(points.size());
        points.push_back(mesh_.point(v));
        corner_vertex[i][k] = id;
        // The halfedge of f whose target is v, then turn around v both ways.
        halfedge_descriptor h = mesh_.halfedge(f);
        while(mesh_.target(h) != v) h = mesh_.next(h);
        bool full_turn = false;
        for(halfedge_descriptor g = h;;) {
          const halfedge_descriptor o = mesh_.opposite(mesh_.next(g)); // target v, in the next face
          if(o == h) { full_turn = true; break; }
          if(mesh_.is_border(o) || !in_piece(mesh_.face(o))) break;
          corner_vertex[slot_[mesh_.face(o).idx()]][corner_of(mesh_.face(o), v)] = id;
          g = o;
        }
        if(full_turn) continue;
        for(halfedge_descriptor g = h;;) {
          const halfedge_descriptor o = mesh_.opposite(g); // source v, in the previous face
          if(mesh_.is_border(o) || !in_piece(mesh_.face(o))) break;
          const halfedge_descriptor into = mesh_.prev(o);
          corner_vertex[slot_[mesh_.face(o).idx()]][corner_of(mesh_.face(o), v)] = id;
          g = into;
        }
      }
    }
    std::size_t distinct_vertices = 0;
    {
      std::vector<vertex_descriptor> originals;
      for(const face_descriptor f : selected_)
        for(vertex_descriptor v : corners(f, mesh_)) originals.push_back(v);
      std::sort(originals.begin(), originals.end());
      distinct_vertices = static_cast<std::size_t>(std::unique(originals.begin(), originals.end()) - originals.begin());
    }
    stats_.pinched_vertices += points.size() - distinct_vertices;

    Mesh piece;
    piece.reserve(static_cast<Mesh::size_type>(points.size()), static_cast<Mesh::size_type>(3 * selected_.size()),
                  static_cast<Mesh::size_type>(selected_.size()));
    for(const Point_3& x : points) piece.add_vertex(x);
    std::vector<face_descriptor> piece_face(selected_.size());
    for(std::size_t i = 0; i < selected_.size(); ++i) {
      piece_face[i] = piece.add_face(vertex_descriptor(corner_vertex[i][0]), vertex_descriptor(corner_vertex[i][1]),
                                     vertex_descriptor(corner_vertex[i][2]));
      if(piece_face[i] == Mesh::null_face()) return whole_mesh(p, q); // not expected: fans are runs
    }

    // The locations on the piece: the same corners, perhaps rotated.
    auto on_piece_location = [&](const Location& loc) {
      const int i = slot_[loc.first.idx()];
      const face_descriptor nf = piece_face[i];
      const vertex_descriptor first = piece.source(piece.halfedge(nf));
      int r = 0;
      while(vertex_descriptor(corner_vertex[i][r]) != first) ++r;
      Location out;
      out.first = nf;
      for(int k = 0; k < 3; ++k) out.second[k] = loc.second[(r + k) % 3];
      if(verify_points)
        worst_point_mismatch = std::max(worst_point_mismatch,
                                        std::sqrt(CGAL::squared_distance(point_at(out, piece), point_at(loc, mesh_))));
      return out;
    };
    const Location lp = on_piece_location(p), lq = on_piece_location(q);
    double d = shortest_path(piece, lp, lq);
    if(d < 0.) {
      ++stats_.no_path;
      d = shortest_path(piece, lq, lp);
    }
    return d < 0. ? whole_mesh(p, q) : d;
  }

  const Mesh& mesh_;
  double diagonal_;
  std::vector<int> slot_;                 // by face: position in selected_, rejected, or unvisited
  std::vector<face_descriptor> visited_;  // faces whose slot_ was set
  std::vector<face_descriptor> selected_;
  bool whole_mesh_used_ = false;
  Statistics stats_;
};

} // namespace diffuv_bench

#endif // DIFFUV_BENCH_CORRESPONDENCE_GEODESIC_DISTANCE_H
