// diffuv benchmark: accuracy of the (region, u, v) correspondence where the
// truth is known.
//
// Mesh A is one of CGAL's closed meshes, cut into disc patches automatically
// (what `diffuv segment` does); mesh B is the same surface tessellated another
// way:
//   fine      isotropic remeshing at 0.7 x A's mean edge length (3 iterations)
//   coarse    the same at 1.6 x
//   shuffled  vertices and faces in a random order (and each face's first corner
//             rotated); labels carried exactly
//   loop      one Loop subdivision step
//   noise     every vertex moved by 5 % of the mean edge length in a random direction
// B's labels come from A's by nearest face (except for `shuffled`), so they
// carry the imperfections the label cleaning has to absorb.
//
// The true image of a vertex of A is its closest point on B (for `shuffled`:
// the vertex itself). The error is the exact geodesic distance on B
// (CGAL::Surface_mesh_shortest_path, on a local piece of B that provably holds
// the shortest path; see `Geodesic_distance`) from the mapped point to the
// true point, over sqrt(area of B). Also measured: the round trip A -> B -> A,
// the seam continuity (a vertex on a patch border mapped from each of its
// charts), and the time of the mapping apart from the two parameterizations.
// B's atlas follows A's sub-patches and corners (`atlas_to_follow()`, as the `correspond`
// tool does) unless --no-follow is given.
//
// Usage: diffuv_correspondence_bench [--meshes cow,man,elephant,hand]
//          [--pairs fine,coarse,shuffled,loop,noise] [--runs 3] [--output DIR]
//          [--distance fmm|graph|exact] [--no-follow] [--sub-patches]
//          [--labels quads|voronoi] [--self-check]
// Writes DIR/table.md, DIR/curves.csv, DIR/correspondence_<mesh>.png and
// DIR/diagnostics.md (where the errors are); prints the table on stdout and
// progress on stderr. Exit code: 0 if every pair meets the targets,
// 1 if one does not (or the self-check fails), 4 on an error.
#include "plot_png.h"

#include <diffuv/correspondence/correspondence.h>
#include <diffuv/correspondence/nearest_face_labels.h>
#include <diffuv/correspondence/labelled_atlas.h>
#include <diffuv/core/error.h>
#include <diffuv/graph/distance_tags.h>
#include <diffuv/io/read_mesh.h>
#include <diffuv/layout/disc_patches.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/bounding_box.h>
#include <CGAL/subdivision_method_3.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#ifndef DIFFUV_DEFAULT_DATA_DIR
#define DIFFUV_DEFAULT_DATA_DIR "data"
#endif

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
using halfedge_descriptor = Mesh::Halfedge_index;
using face_descriptor = Mesh::Face_index;
using Location = PMP::Face_location<Mesh, double>;  // (face, barycentric coordinates)
using Aabb_tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
using Labelled = diffuv::Labelled_atlas<Mesh>;
using Correspondence = diffuv::Atlas_correspondence<Mesh, Mesh>;
using Image = Correspondence::Point;
using Clock = std::chrono::steady_clock;

constexpr double infinity = std::numeric_limits<double>::infinity();

double milliseconds_since(Clock::time_point t0)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

double median(std::vector<double> v)
{
  if(v.empty()) return 0.;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// ---------------------------------------------------------------------------
// Mesh helpers

std::array<vertex_descriptor, 3> corners(face_descriptor f, const Mesh& m)
{
  const halfedge_descriptor h = m.halfedge(f);
  return {{m.source(h), m.target(h), m.target(m.next(h))}};
}

double mean_edge_length(const Mesh& m)
{
  double sum = 0.;
  for(auto e : m.edges()) sum += std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
  return m.number_of_edges() ? sum / static_cast<double>(m.number_of_edges()) : 0.;
}

double bounding_diagonal(const Mesh& m)
{
  const auto box = CGAL::bounding_box(m.points().begin(), m.points().end());
  return std::sqrt(CGAL::squared_distance(box.min(), box.max()));
}

Point_3 point_at(const Location& loc, const Mesh& m) { return PMP::construct_point(loc, m); }

// ---------------------------------------------------------------------------
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

// ---------------------------------------------------------------------------
// The second meshes (B) and their labels.

struct Variant {
  std::string name;
  Mesh mesh;
  std::vector<int> labels;        // #F(B) entries
  std::vector<Location> truth;    // #V(A) entries: the true image of each vertex of A on B
  std::string how;                // how the labels and the truth were made
};

void collect(Mesh& m)
{
  m.collect_garbage();
  if(!CGAL::is_triangle_mesh(m)) throw std::runtime_error("a variant is not a triangle mesh");
}

Mesh remeshed(const Mesh& a, double target)
{
  Mesh b = a; // A stays untouched
  auto constrained = b.add_property_map<Mesh::Edge_index, bool>("e:bench_border", false).first;
  for(auto e : b.edges())
    if(b.is_border(e)) constrained[e] = true; // keep a border where it is (the default meshes are closed)
  PMP::isotropic_remeshing(b.faces(), target, b,
                           CGAL::parameters::number_of_iterations(3).edge_is_constrained_map(constrained));
  b.remove_property_map(constrained);
  collect(b);
  return b;
}

Mesh loop_subdivided(const Mesh& a)
{
  Mesh b = a;
  CGAL::Subdivision_method_3::Loop_subdivision(b, CGAL::parameters::number_of_iterations(1));
  collect(b);
  return b;
}

Mesh noisy(const Mesh& a, double amplitude, unsigned seed)
{
  Mesh b = a;
  std::mt19937 random(seed);
  std::normal_distribution<double> normal(0., 1.);
  for(auto v : b.vertices()) {
    double x, y, z, n;
    do {
      x = normal(random);
      y = normal(random);
      z = normal(random);
      n = std::sqrt(x * x + y * y + z * z);
    } while(n < 1e-12);
    const double s = amplitude / n;
    b.point(v) = Point_3(b.point(v).x() + s * x, b.point(v).y() + s * y, b.point(v).z() + s * z);
  }
  return b;
}

// A copy with vertices and faces in a random order and each face starting at a
// random corner; `new_vertex[v]` is the copy of vertex v of `a`, `new_face[f]`
// the copy of face f.
Mesh shuffled(const Mesh& a, unsigned seed, std::vector<vertex_descriptor>& new_vertex,
              std::vector<face_descriptor>& new_face)
{
  std::mt19937 random(seed);
  std::vector<std::size_t> vorder(a.number_of_vertices()), forder(a.number_of_faces());
  std::iota(vorder.begin(), vorder.end(), std::size_t(0));
  std::iota(forder.begin(), forder.end(), std::size_t(0));
  std::shuffle(vorder.begin(), vorder.end(), random);
  std::shuffle(forder.begin(), forder.end(), random);
  Mesh b;
  new_vertex.assign(a.number_of_vertices(), Mesh::null_vertex());
  new_face.assign(a.number_of_faces(), Mesh::null_face());
  for(std::size_t old : vorder) new_vertex[old] = b.add_vertex(a.point(vertex_descriptor(static_cast<Mesh::size_type>(old))));
  std::uniform_int_distribution<int> rotation(0, 2);
  for(std::size_t old : forder) {
    const auto c = corners(face_descriptor(static_cast<Mesh::size_type>(old)), a);
    const int r = rotation(random);
    new_face[old] = b.add_face(new_vertex[c[r].idx()], new_vertex[c[(r + 1) % 3].idx()], new_vertex[c[(r + 2) % 3].idx()]);
    if(new_face[old] == Mesh::null_face()) throw std::runtime_error("shuffled copy: add_face failed");
  }
  return b;
}

// The closest point on B of every vertex of A.
std::vector<Location> closest_points(const Mesh& a, const Mesh& b)
{
  Aabb_tree tree;
  PMP::build_AABB_tree(b, tree);
  std::vector<Location> truth(a.number_of_vertices());
  for(auto v : a.vertices()) truth[v.idx()] = PMP::locate_with_AABB_tree(a.point(v), tree, b);
  return truth;
}

Variant make_variant(const std::string& name, const Mesh& a, const std::vector<int>& labels_a, double mean_edge)
{
  Variant out;
  out.name = name;
  if(name == "shuffled") {
    std::vector<vertex_descriptor> new_vertex;
    std::vector<face_descriptor> new_face;
    out.mesh = shuffled(a, 20240601u, new_vertex, new_face);
    out.labels.assign(a.number_of_faces(), 0);
    for(auto f : a.faces()) out.labels[new_face[f.idx()].idx()] = labels_a[f.idx()];
    out.truth.resize(a.number_of_vertices());
    for(auto v : a.vertices()) out.truth[v.idx()] = PMP::locate_vertex<double>(new_vertex[v.idx()], out.mesh);
    out.how = "vertices and faces permuted, labels carried exactly, truth = the vertex itself";
    return out;
  }
  if(name == "fine") {
    out.mesh = remeshed(a, 0.7 * mean_edge);
    out.how = "isotropic remeshing, target 0.7 x mean edge, 3 iterations";
  } else if(name == "coarse") {
    out.mesh = remeshed(a, 1.6 * mean_edge);
    out.how = "isotropic remeshing, target 1.6 x mean edge, 3 iterations";
  } else if(name == "loop") {
    out.mesh = loop_subdivided(a);
    out.how = "1 Loop subdivision step";
  } else if(name == "noise") {
    out.mesh = noisy(a, 0.05 * mean_edge, 20240602u);
    out.how = "vertices moved by 0.05 x mean edge in random directions";
  } else {
    throw std::invalid_argument("unknown pair '" + name + "' (fine, coarse, shuffled, loop, noise)");
  }
  out.labels = diffuv::nearest_face_labels(a, labels_a, out.mesh);
  out.truth = closest_points(a, out.mesh);
  out.how += "; labels by nearest face of A, truth = closest point on B";
  return out;
}

// ---------------------------------------------------------------------------
// Statistics

struct Summary {
  double mean = 0., p95 = 0., max = 0.;
  std::size_t count = 0, infinite = 0;
};

// Mean and max over the finite values, p95 (nearest rank) over all of them
// (an infinite value is a failure: it sorts last).
Summary summarize(std::vector<double> values)
{
  Summary s;
  s.count = values.size();
  if(values.empty()) return s;
  std::sort(values.begin(), values.end());
  double sum = 0.;
  std::size_t finite = 0;
  for(double x : values)
    if(std::isfinite(x)) {
      sum += x;
      ++finite;
      s.max = x;
    }
  s.infinite = values.size() - finite;
  s.mean = finite ? sum / static_cast<double>(finite) : infinity;
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(values.size())));
  s.p95 = values[std::max<std::size_t>(rank, 1) - 1];
  return s;
}

double percent_within(const std::vector<double>& values, double r)
{
  if(values.empty()) return 0.;
  const auto n = std::count_if(values.begin(), values.end(), [r](double x) { return x <= r; });
  return 100. * static_cast<double>(n) / static_cast<double>(values.size());
}

std::string format(const char* f, double x)
{
  if(std::isinf(x)) return "inf";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, f, x);
  return buffer;
}

// ---------------------------------------------------------------------------
// Atlases, with the distance chosen on the command line.

enum class Distance { fmm, graph, exact };


// --repair / --no-repair: -1 keeps the library's default (Labelled_atlas_options).
int repair_choice = -1;
// --sub-patches: regions with 3 or 5..9 runs are split into four-sided sectors (split_regions_into_quads()).
bool sub_patches_choice = false;

// `follow`: the sub-patches and corners of another atlas to follow (atlas_to_follow()), or null.
diffuv::Status build_atlas(const Mesh& m, const std::vector<int>& labels, Labelled& out, Distance distance,
                           const diffuv::Atlas_to_follow* follow)
{
  diffuv::Labelled_atlas_options options;
  if(repair_choice >= 0) options.repair.enabled = repair_choice == 1;
  options.sub_patches = sub_patches_choice;
  auto build = [&](auto tag) {
    using Tag = decltype(tag);
    return follow ? diffuv::build_labelled_atlas<Tag>(m, m.points(), labels, *follow, out, options)
                  : diffuv::build_labelled_atlas<Tag>(m, m.points(), labels, out, options);
  };
  switch(distance) {
  case Distance::fmm: return build(diffuv::Fmm_distance_tag());
  case Distance::graph: return build(diffuv::Graph_distance_tag());
  case Distance::exact: return build(diffuv::Exact_distance_tag());
  }
  return diffuv::Status();
}

// Builds the labelled atlas `runs` times; returns the last one and the median time.
std::unique_ptr<Labelled> timed_atlas(const Mesh& m, const std::vector<int>& labels, Distance distance, int runs,
                                      double& median_ms, const diffuv::Atlas_to_follow* follow = nullptr)
{
  std::vector<double> times;
  std::unique_ptr<Labelled> la;
  for(int run = 0; run < runs; ++run) {
    la = std::make_unique<Labelled>(m);
    const auto t0 = Clock::now();
    const diffuv::Status status = build_atlas(m, labels, *la, distance, follow);
    times.push_back(milliseconds_since(t0));
    if(!status.ok()) throw std::runtime_error("build_labelled_atlas failed: " + status.what());
  }
  median_ms = median(times);
  return la;
}

// ---------------------------------------------------------------------------
// One mesh A and its pairs.

struct Mesh_case {
  std::string name, path;
  Mesh mesh;
  std::vector<int> labels;           // automatic patches (what `diffuv segment` writes)
  std::size_t automatic_patches = 0;
  double area = 0., mean_edge = 0.;
  std::unique_ptr<Labelled> atlas;
  double param_ms = 0.;
  std::vector<int> ring;             // per vertex: edges to the nearest vertex in two or more charts
};

struct Pair_result {
  std::string mesh, pair, how;
  std::size_t vertices_a = 0, vertices_b = 0, faces_b = 0;
  std::size_t charts_a = 0, charts_b = 0, patches_a = 0, patches_b = 0, matched = 0;
  std::size_t cleaned_a = 0, cleaned_b = 0;
  std::size_t followed = 0;          // patches of B whose corners followed A's names
  diffuv::Region_match_report match;
  std::size_t unmapped = 0;
  std::vector<double> error;         // #V(A): geodesic on B / sqrt(area B), inf if unmapped
  std::vector<double> round_trip;    // #V(A): geodesic on A / sqrt(area A), inf if unmapped
  std::vector<double> seam;          // per vertex of A in two or more charts
  std::size_t seam_unmapped = 0;
  double param_a_ms = 0., param_b_ms = 0., map_ms = 0.;
  std::string diagnostics;           // markdown
  bool passed = false;
  std::string verdict;
};

// Edges from each vertex to the nearest vertex in two or more charts.
std::vector<int> seam_rings(const Mesh& m, const Labelled& la)
{
  std::vector<int> ring(m.number_of_vertices(), std::numeric_limits<int>::max());
  std::vector<vertex_descriptor> queue;
  for(auto v : m.vertices()) {
    const auto e = la.atlas.entries(v);
    if(e.second - e.first >= 2) {
      ring[v.idx()] = 0;
      queue.push_back(v);
    }
  }
  for(std::size_t i = 0; i < queue.size(); ++i)
    for(auto w : CGAL::vertices_around_target(m.halfedge(queue[i]), m))
      if(ring[w.idx()] == std::numeric_limits<int>::max()) {
        ring[w.idx()] = ring[queue[i].idx()] + 1;
        queue.push_back(w);
      }
  return ring;
}

std::string key_text(const Correspondence::Key& k)
{
  return "(" + std::to_string(std::get<0>(k)) + "," + std::to_string(std::get<1>(k)) + "," +
         std::to_string(std::get<2>(k)) + ")";
}

template <class Range>
std::string list_text(const Range& r)
{
  std::ostringstream s;
  bool first = true;
  for(const auto& x : r) {
    s << (first ? "" : " ") << x;
    first = false;
  }
  return first ? "-" : s.str();
}

std::string patch_names_text(const std::vector<diffuv::Patch_key>& r)
{
  std::ostringstream s;
  bool first = true;
  for(const auto& x : r) {
    s << (first ? "" : " ") << diffuv::patch_name(x);
    first = false;
  }
  return first ? "-" : s.str();
}

// Where the errors of one pair come from (markdown).
std::string diagnose(const Mesh_case& a, const Variant& b, const Labelled& atlas_b, const Correspondence& ab,
                     const Correspondence& ba, const std::vector<Image>& images, const Pair_result& r)
{
  std::ostringstream out;
  const Mesh& ma = a.mesh;
  out << "### " << r.mesh << " / " << r.pair << "\n\n" << r.how << ".\n\n";
  out << "- patches: A " << a.atlas->segmentation.number_of_patches() << " (" << r.charts_a << " charts), B "
      << atlas_b.segmentation.number_of_patches() << " (" << r.charts_b << " charts); matched " << r.matched
      << "; labels only in A: " << list_text(r.match.labels_only_in_a) << "; only in B: "
      << list_text(r.match.labels_only_in_b) << "; unmatched patches of A: " << patch_names_text(r.match.unmatched_patches_a)
      << ", of B: " << patch_names_text(r.match.unmatched_patches_b) << "\n";
  out << "- label cleaning changed " << r.cleaned_a << " faces of A, " << r.cleaned_b << " of B; patching of B: "
      << atlas_b.patching.merged << " merged, " << atlas_b.patching.cut << " cut, " << atlas_b.patching.caps_split
      << " caps split (A: " << a.atlas->patching.merged << ", " << a.atlas->patching.cut << ", "
      << a.atlas->patching.caps_split << "); " << r.followed << " of B's " << atlas_b.patches.size()
      << " patches took their corners from A's names\n";

  // Faces of B whose cleaned label differs from the label of A's face nearest to them.
  {
    const std::vector<int> expected = diffuv::nearest_face_labels(ma, a.atlas->face_labels, b.mesh);
    std::size_t differ = 0;
    double differ_area = 0., total_area = 0.;
    for(auto f : b.mesh.faces()) {
      const double fa = PMP::face_area(f, b.mesh);
      total_area += fa;
      if(expected[f.idx()] != atlas_b.face_labels[f.idx()]) {
        ++differ;
        differ_area += fa;
      }
    }
    out << "- after cleaning, " << differ << " faces of B (" << format("%.2f", 100. * differ_area / total_area)
        << " % of the area) have another label than A's cleaned label at their centroid\n";
  }

  // Errors by distance (in edges) from the patch borders of A.
  struct Bucket {
    std::size_t n = 0, bad = 0, unmapped = 0;
    double sum = 0.;
  };
  const char* bucket_names[] = {"on a seam (2+ charts)", "1 edge from a seam", "2-3 edges", "4+ edges"};
  Bucket buckets[4];
  std::size_t truth_elsewhere = 0, truth_elsewhere_bad = 0;
  double truth_elsewhere_sum = 0.;
  std::map<std::size_t, Bucket> per_chart;
  for(auto v : ma.vertices()) {
    const int ring = a.ring[v.idx()];
    Bucket& bk = buckets[ring == 0 ? 0 : ring == 1 ? 1 : ring <= 3 ? 2 : 3];
    const double e = r.error[v.idx()];
    ++bk.n;
    if(!std::isfinite(e)) {
      ++bk.unmapped;
      continue;
    }
    bk.sum += e;
    if(e > 0.05) ++bk.bad;
    // The chart of B holding the true point, against the charts of v in A.
    const std::size_t truth_chart = atlas_b.atlas.chart_of(b.truth[v.idx()].first);
    bool same = false;
    const auto entries = a.atlas->atlas.entries(v);
    for(auto it = entries.first; it != entries.second; ++it)
      if(ab.chart_b(it->chart) == truth_chart) same = true;
    if(!same) {
      ++truth_elsewhere;
      truth_elsewhere_sum += e;
      if(e > 0.05) ++truth_elsewhere_bad;
    }
    Bucket& pc = per_chart[images[v.idx()].chart];
    ++pc.n;
    pc.sum += e;
    if(e > 0.05) ++pc.bad;
  }
  out << "\n| vertices of A | count | mean error | > 0.05 | unmapped |\n|---|---:|---:|---:|---:|\n";
  for(int k = 0; k < 4; ++k) {
    const Bucket& bk = buckets[k];
    const std::size_t finite = bk.n - bk.unmapped;
    out << "| " << bucket_names[k] << " | " << bk.n << " | " << format("%.4f", finite ? bk.sum / finite : 0.) << " | "
        << bk.bad << " | " << bk.unmapped << " |\n";
  }
  out << "\n- " << truth_elsewhere << " mapped vertices have their true point in a chart of B that is not the "
      << "counterpart of any of their charts (mean error " << format("%.4f", truth_elsewhere ? truth_elsewhere_sum / truth_elsewhere : 0.)
      << ", " << truth_elsewhere_bad << " above 0.05)\n";

  // Per chart: do the patches of A and B agree (corners, runs), was the map
  // re-solved by the fold repair, and how large are the errors.
  std::map<std::size_t, std::size_t> patch_of_chart_a, patch_of_chart_b;
  for(std::size_t p = 0; p < a.atlas->patches.size(); ++p) patch_of_chart_a[a.atlas->patches[p].chart] = p;
  for(std::size_t p = 0; p < atlas_b.patches.size(); ++p) patch_of_chart_b[atlas_b.patches[p].chart] = p;
  const double scale_b = 1. / std::sqrt(PMP::area(b.mesh));
  out << "\n| chart (label,part,rank) | faces A/B | neighbour runs A/B | corners moved (max, / sqrt area) | "
         "folded faces A/B | whole patch re-solved A/B | vertices | mean error | > 0.05 |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(std::size_t c = 0; c < r.charts_a; ++c) {
    const auto& pa = a.atlas->patches[patch_of_chart_a[c]];
    const std::size_t cb = ab.chart_b(c);
    out << "| " << key_text(ab.key_a(c)) << " | " << a.atlas->segmentation.patch_faces[patch_of_chart_a[c]].size();
    if(cb == diffuv::Uv_atlas<Mesh>::no_chart) {
      out << "/- | " << pa.side_report.runs << "/- | - | " << pa.repair.folded_faces << "/- | "
          << (pa.repair.whole_patch ? "yes" : "no") << "/- | ";
    } else {
      const auto& pb = atlas_b.patches[patch_of_chart_b[cb]];
      double moved = 0.;
      for(int k = 0; k < 4; ++k)
        moved = std::max(moved, std::sqrt(CGAL::squared_distance(ma.point(pa.sides.corners[k]),
                                                                 b.mesh.point(pb.sides.corners[k]))) * scale_b);
      out << "/" << atlas_b.segmentation.patch_faces[patch_of_chart_b[cb]].size() << " | " << pa.side_report.runs << "/"
          << pb.side_report.runs << " | " << format("%.3f", moved) << " | " << pa.repair.folded_faces << "/"
          << pb.repair.folded_faces << " | " << (pa.repair.whole_patch ? "yes" : "no") << "/"
          << (pb.repair.whole_patch ? "yes" : "no") << " | ";
    }
    const auto it = per_chart.find(cb);
    if(cb == diffuv::Uv_atlas<Mesh>::no_chart || it == per_chart.end()) out << "- | - | - |\n";
    else out << it->second.n << " | " << format("%.4f", it->second.sum / it->second.n) << " | " << it->second.bad << " |\n";
  }
  out << "\nWorst vertices:\n\n| vertex of A | error | charts of A | edges to seam | image chart key | truth chart key | inside | uv distance | round trip |\n|---:|---:|---|---:|---|---|---|---:|---:|\n";
  std::vector<std::size_t> order(ma.number_of_vertices());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return r.error[i] > r.error[j]; });
  for(std::size_t k = 0; k < std::min<std::size_t>(8, order.size()); ++k) {
    const vertex_descriptor v(static_cast<Mesh::size_type>(order[k]));
    const Image& img = images[v.idx()];
    std::string charts;
    const auto entries = a.atlas->atlas.entries(v);
    for(auto it = entries.first; it != entries.second; ++it)
      charts += (charts.empty() ? "" : " ") + key_text(ab.key_a(it->chart));
    const std::size_t truth_chart = atlas_b.atlas.chart_of(b.truth[v.idx()].first);
    out << "| " << v.idx() << " | " << format("%.4f", r.error[v.idx()]) << " | " << charts << " | " << a.ring[v.idx()]
        << " | " << (img.mapped() ? key_text(ba.key_a(img.chart)) : std::string("unmapped")) << " | "
        << (truth_chart == diffuv::Uv_atlas<Mesh>::no_chart ? std::string("none") : key_text(ba.key_a(truth_chart)))
        << " | " << (img.inside ? "yes" : "no") << " | " << format("%.3g", img.uv_distance) << " | "
        << format("%.4f", r.round_trip[v.idx()]) << " |\n";
  }
  out << "\n";
  return out.str();
}

Pair_result run_pair(Mesh_case& a, const std::string& pair, Distance distance, int runs,
                     bool follow, Geodesic_distance& geodesic_a)
{
  Pair_result r;
  r.mesh = a.name;
  r.pair = pair;
  const auto t_variant = Clock::now();
  const Variant b = make_variant(pair, a.mesh, a.labels, a.mean_edge);
  r.how = b.how;
  r.vertices_a = a.mesh.number_of_vertices();
  r.vertices_b = b.mesh.number_of_vertices();
  r.faces_b = b.mesh.number_of_faces();
  std::cerr << "[" << a.name << "/" << pair << "] B: " << r.vertices_b << " vertices, " << r.faces_b << " faces ("
            << format("%.0f", milliseconds_since(t_variant)) << " ms to make)\n";

  // B follows A's corners (as the `correspond` tool and the example do) unless told not to.
  const diffuv::Atlas_to_follow follow_a = diffuv::atlas_to_follow(*a.atlas);
  std::unique_ptr<Labelled> atlas_b =
      timed_atlas(b.mesh, b.labels, distance, runs, r.param_b_ms, follow ? &follow_a : nullptr);
  for(const auto& patch : atlas_b->patches) r.followed += patch.side_report.named ? 1 : 0;
  r.param_a_ms = a.param_ms;

  // The mapping of every vertex: construction of the correspondence + map_vertices().
  std::vector<double> times;
  std::vector<Image> images;
  for(int run = 0; run < runs; ++run) {
    const auto t0 = Clock::now();
    const Correspondence c(*a.atlas, *atlas_b);
    images = c.map_vertices();
    times.push_back(milliseconds_since(t0));
  }
  r.map_ms = median(times);
  const Correspondence ab(*a.atlas, *atlas_b);
  const Correspondence ba(*atlas_b, *a.atlas);
  r.match = ab.report();
  r.matched = r.match.matched_patches;
  r.charts_a = a.atlas->atlas.number_of_charts();
  r.charts_b = atlas_b->atlas.number_of_charts();
  r.patches_a = a.atlas->segmentation.number_of_patches();
  r.patches_b = atlas_b->segmentation.number_of_patches();
  r.cleaned_a = a.atlas->cleaning.changed_faces();
  r.cleaned_b = atlas_b->cleaning.changed_faces();
  std::cerr << "[" << a.name << "/" << pair << "] param B " << format("%.1f", r.param_b_ms) << " ms, map "
            << format("%.1f", r.map_ms) << " ms; " << r.matched << "/" << r.charts_a << " charts matched ("
            << r.charts_b << " in B); measuring errors\n";

  // Errors against the truth, and the round trip.
  const auto t_errors = Clock::now();
  Geodesic_distance geodesic_b(b.mesh);
  const double scale_b = 1. / std::sqrt(PMP::area(b.mesh)), scale_a = 1. / std::sqrt(a.area);
  r.error.assign(r.vertices_a, infinity);
  r.round_trip.assign(r.vertices_a, infinity);
  for(auto v : a.mesh.vertices()) {
    const Image& img = images[v.idx()];
    if(!img.mapped()) {
      ++r.unmapped;
      continue;
    }
    const Location mapped(img.face, img.barycentric);
    r.error[v.idx()] = geodesic_b(b.truth[v.idx()], mapped) * scale_b;
    const Image back = ba.map_point(img.face, img.barycentric);
    if(back.mapped())
      r.round_trip[v.idx()] = geodesic_a(PMP::locate_vertex<double>(v, a.mesh), Location(back.face, back.barycentric)) * scale_a;
  }

  // Seams: the images of a vertex taken from each of its charts.
  for(auto v : a.mesh.vertices()) {
    const auto entries = a.atlas->atlas.entries(v);
    if(entries.second - entries.first < 2) continue;
    std::vector<Location> points;
    bool all = true;
    for(auto it = entries.first; it != entries.second; ++it) {
      const Image img = ab.map_vertex(v, it->chart);
      if(!img.mapped()) all = false;
      else points.emplace_back(img.face, img.barycentric);
    }
    if(!all) {
      ++r.seam_unmapped;
      continue;
    }
    double worst = 0.;
    for(std::size_t i = 0; i < points.size(); ++i)
      for(std::size_t j = i + 1; j < points.size(); ++j) worst = std::max(worst, geodesic_b(points[i], points[j]));
    r.seam.push_back(worst * scale_b);
  }
  const auto& gs = geodesic_b.statistics();
  std::cerr << "[" << a.name << "/" << pair << "] errors measured in " << format("%.1f", milliseconds_since(t_errors) / 1000.)
            << " s (" << gs.queries << " geodesics on B: " << gs.same_face << " in one face, " << gs.piece_runs
            << " runs on pieces of " << format("%.0f", gs.piece_runs ? double(gs.piece_faces) / gs.piece_runs : 0.)
            << " faces on average, " << gs.retries << " retries, " << gs.whole_mesh_runs << " on the whole mesh, "
            << gs.no_path << " without a path from p, retried from q)\n";

  // Verdict against the targets.
  const Summary e = summarize(r.error);
  std::vector<std::string> failures;
  if(pair == "shuffled") {
    if(r.unmapped > 0 || e.max > 1e-9) failures.push_back("max > 1e-9");
  } else {
    if(percent_within(r.error, 0.05) < 95.) failures.push_back("< 95 % within 0.05");
    if(e.mean > 0.01) failures.push_back("mean > 0.01");
  }
  if(a.name == "man" && (pair == "fine" || pair == "coarse") && r.map_ms > 50.) failures.push_back("t_map > 50 ms");
  r.passed = failures.empty();
  r.verdict = r.passed ? "ok" : "FAIL";
  for(std::size_t k = 0; k < failures.size(); ++k) r.verdict += (k ? ", " : " (") + failures[k] + (k + 1 == failures.size() ? ")" : "");
  r.diagnostics = diagnose(a, b, *atlas_b, ab, ba, images, r);
  return r;
}

// ---------------------------------------------------------------------------
// The self-check of the local geodesics against Surface_mesh_shortest_path on
// the whole mesh.

bool self_check(const std::string& path)
{
  Mesh m;
  diffuv::read_triangle_mesh(path, m);
  Geodesic_distance geodesic(m);
  geodesic.verify_points = true;
  std::mt19937 random(7u);
  std::uniform_int_distribution<std::size_t> any_face(0, m.number_of_faces() - 1);
  std::uniform_real_distribution<double> unit(0., 1.);
  auto random_location = [&](face_descriptor f) {
    double x = unit(random), y = unit(random);
    if(x + y > 1.) {
      x = 1. - x;
      y = 1. - y;
    }
    return Location(f, {{1. - x - y, x, y}});
  };
  // A face some steps away across edges.
  auto nearby_face = [&](face_descriptor f, int steps) {
    for(int s = 0; s < steps; ++s) {
      halfedge_descriptor h = m.halfedge(f);
      for(int k = static_cast<int>(unit(random) * 3); k > 0; --k) h = m.next(h);
      if(!m.is_border(m.opposite(h))) f = m.face(m.opposite(h));
    }
    return f;
  };
  struct Case {
    const char* kind;
    int count;
    int min_steps, max_steps; // faces apart; -1: anywhere
    bool vertex_source;
  };
  const Case cases[] = {{"in one face", 5, 0, 0, false},
                        {"1-6 faces apart", 12, 1, 6, false},
                        {"5-20 faces apart", 12, 5, 20, false},
                        {"anywhere", 11, -1, -1, false},
                        {"from a vertex, 1-10 faces apart", 10, 1, 10, true}};
  double worst = 0., worst_tight = 0., local_ms = 0., whole_ms = 0.;
  int n = 0, tight_runs = 0;
  std::cout << "Self-check of the local exact geodesics on " << path << " (" << m.number_of_vertices()
            << " vertices), against Surface_mesh_shortest_path on the whole mesh:\n";
  for(const Case& c : cases) {
    double case_worst = 0.;
    const std::size_t whole_before = geodesic.statistics().whole_mesh_runs;
    for(int i = 0; i < c.count; ++i) {
      const face_descriptor f(static_cast<Mesh::size_type>(any_face(random)));
      face_descriptor g = f;
      if(c.min_steps < 0) g = face_descriptor(static_cast<Mesh::size_type>(any_face(random)));
      else if(c.max_steps > 0) g = nearby_face(f, c.min_steps + static_cast<int>(unit(random) * (c.max_steps - c.min_steps + 1)));
      Location p = random_location(f);
      if(c.vertex_source) p = PMP::locate_vertex<double>(corners(f, m)[i % 3], m);
      const Location q = random_location(g);
      auto t0 = Clock::now();
      const double local = geodesic(p, q);
      local_ms += milliseconds_since(t0);
      t0 = Clock::now();
      const double whole = geodesic.whole_mesh(p, q);
      whole_ms += milliseconds_since(t0);
      case_worst = std::max(case_worst, std::fabs(local - whole) / std::max(whole, 1e-300));
      // The tightest pieces: a bound just above the geodesic, where the
      // ellipsoid cuts the surface close to the path (pinched vertices, long
      // piece borders).
      if(f != g) {
        const double tight = geodesic.piece_only(p, q, 1.000001 * whole);
        if(tight >= 0.) {
          ++tight_runs;
          worst_tight = std::max(worst_tight, std::fabs(tight - whole) / std::max(whole, 1e-300));
        }
      }
      ++n;
    }
    const std::size_t on_whole = (geodesic.statistics().whole_mesh_runs - whole_before) - static_cast<std::size_t>(c.count);
    std::cout << "  " << c.count << " pairs " << c.kind << ": largest relative difference " << format("%.3g", case_worst)
              << " (" << c.count - static_cast<int>(on_whole) << " local, " << on_whole << " on the whole mesh)\n";
    worst = std::max(worst, case_worst);
  }
  std::cout << "  " << tight_runs << " of these pairs on the tightest piece (bound = 1.000001 x geodesic): largest "
            << "relative difference " << format("%.3g", worst_tight) << "\n";
  worst = std::max(worst, worst_tight);

  // Every vertex located in two different faces, one of them 1e-16 off the
  // vertex as a point location in the uv plane gives it: the distance is 0.
  // Surface_mesh_shortest_path (here on the vertex's neighbourhood) gets this
  // wrong at some vertices; the local method answers from the common face.
  double worst_coincident = 0., worst_smsp_coincident = 0.;
  std::size_t smsp_wrong = 0;
  const double tiny = 1e-12 * bounding_diagonal(m), edge = mean_edge_length(m);
  for(vertex_descriptor v : m.vertices()) {
    std::vector<Location> at_v;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(m.halfedge(v), m)) {
      if(m.is_border(h)) continue;
      const auto c = corners(m.face(h), m);
      at_v.emplace_back(m.face(h), std::array<double, 3>{{c[0] == v ? 1. : 0., c[1] == v ? 1. : 0., c[2] == v ? 1. : 0.}});
    }
    const Location& p = at_v.front();
    Location q = at_v[at_v.size() / 2];
    for(double& b : q.second) b = b == 0. ? 1e-16 : 1. - 2e-16;
    worst_coincident = std::max(worst_coincident, geodesic(p, q));
    const double smsp = geodesic.piece_only(p, q, edge);
    const double smsp_value = smsp < 0. ? infinity : smsp;
    worst_smsp_coincident = std::max(worst_smsp_coincident, smsp_value);
    if(smsp_value > tiny) ++smsp_wrong;
  }
  const double scale = std::sqrt(PMP::area(m));
  std::cout << "  " << m.number_of_vertices() << " pairs (each vertex located in two of its faces): local distance at most "
            << format("%.3g", worst_coincident / scale) << " x sqrt(area) (must be 0); plain "
            << "Surface_mesh_shortest_path from the one to the other: " << smsp_wrong << " wrong, up to "
            << format("%.3g", worst_smsp_coincident / scale) << " x sqrt(area)\n";

  const auto& s = geodesic.statistics();
  const bool ok = worst <= 1e-9 && worst_coincident <= tiny &&
                  geodesic.worst_point_mismatch <= 1e-9 * bounding_diagonal(m);
  std::cout << "  " << n << " pairs: largest relative difference " << format("%.3g", worst) << " (must be <= 1e-9); "
            << "points copied onto the pieces off by at most " << format("%.3g", geodesic.worst_point_mismatch) << "\n"
            << "  local: " << format("%.2f", local_ms / n) << " ms per pair (" << s.piece_runs << " piece runs, "
            << s.retries << " retries, " << s.pinched_vertices << " pinched vertices duplicated, " << s.no_path
            << " without a path from p, retried from q); whole mesh: "
            << format("%.2f", whole_ms / n) << " ms per pair\n"
            << "  self-check " << (ok ? "passed" : "FAILED") << "\n";
  return ok;
}

// ---------------------------------------------------------------------------
// Output

std::string mesh_path(const std::string& name)
{
  if(name.find('/') != std::string::npos || name.find('.') != std::string::npos) return name;
  return std::string(DIFFUV_DEFAULT_DATA_DIR) + "/meshes/" + name + ".off";
}

std::string mesh_name(const std::string& path)
{
  return std::filesystem::path(path).stem().string();
}

std::string table(const std::vector<Pair_result>& results, const std::string& distance, int runs, bool follow,
                  const std::string& labels)
{
  std::ostringstream out;
  out << "Correspondence accuracy (errors: geodesic distance on B / sqrt(area B); round trip on A / sqrt(area A)); "
      << distance << " distances; "
      << (follow ? "B's atlas follows A's sub-patches and corners (atlas_to_follow)" : "B's atlas built on its own (--no-follow)")
      << "; A's regions: " << (labels == "voronoi" ? "diffuv 0.1's Voronoi patches" : "the four-sided layout's patches")
      << "; sub-patches " << (sub_patches_choice ? "on (--sub-patches)" : "off")
      << "; times in ms, median of " << runs << " run" << (runs > 1 ? "s" : "") << ".\n\n";
  out << "| mesh | pair | A verts | B verts | charts matched | cleaned faces A/B | unmapped | mean | p95 | max | "
         "% <= 0.01 | % <= 0.05 | round trip mean | round trip p95 | seam mean | seam p95 | seam max | t_param A | t_param B | "
         "t_map | target |\n";
  out << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for(const Pair_result& r : results) {
    const Summary e = summarize(r.error), rt = summarize(r.round_trip), s = summarize(r.seam);
    std::string charts = std::to_string(r.matched) + "/" + std::to_string(r.charts_a);
    if(r.charts_b != r.charts_a) charts += " (B " + std::to_string(r.charts_b) + ")";
    out << "| " << r.mesh << " | " << r.pair << " | " << r.vertices_a << " | " << r.vertices_b << " | " << charts << " | "
        << r.cleaned_a << "/" << r.cleaned_b << " | " << r.unmapped << " | " << format("%.3g", e.mean) << " | "
        << format("%.3g", e.p95) << " | " << format("%.3g", e.max) << " | "
        << format("%.1f", percent_within(r.error, 0.01)) << " | " << format("%.1f", percent_within(r.error, 0.05))
        << " | " << format("%.3g", rt.mean) << " | " << format("%.3g", rt.p95) << " | " << format("%.3g", s.mean)
        << (r.seam_unmapped ? " (" + std::to_string(r.seam_unmapped) + " unmapped)" : std::string()) << " | "
        << format("%.3g", s.p95) << " | " << format("%.3g", s.max) << " | " << format("%.1f", r.param_a_ms) << " | " << format("%.1f", r.param_b_ms)
        << " | " << format("%.1f", r.map_ms) << " | " << r.verdict << " |\n";
  }
  out << "\nTargets: shuffled: every vertex maps to itself (max <= 1e-9); other pairs: >= 95 % within 0.05 and mean <= "
         "0.01; man fine/coarse: t_map <= 50 ms. Mean and max are over mapped vertices; p95 and the percentages count "
         "unmapped vertices as failures. Round-trip mean/p95 likewise. Seam: for each vertex of A in two or more charts, "
         "the largest geodesic distance on B between its images from each chart (vertices with an unmapped image "
         "left out and counted). Charts matched: charts of A with a counterpart in B / charts of A (B's count if it "
         "differs). Cleaned faces: faces whose label the cleaning changed.\n";
  return out.str();
}

struct Options {
  std::vector<std::string> meshes{"cow", "man", "elephant", "hand"};
  std::vector<std::string> pairs{"fine", "coarse", "shuffled", "loop", "noise"};
  int runs = 3;
  std::string output = "bench-out/correspondence";
  std::string distance = "fmm";
  bool self_check = false;
  bool follow = true;
  std::string labels = "quads";
};

int run(const Options& o)
{
  const Distance distance = o.distance == "graph" ? Distance::graph : o.distance == "exact" ? Distance::exact : Distance::fmm;
  const auto t_start = Clock::now();
  std::filesystem::create_directories(o.output);
  std::vector<Pair_result> results;
  // r in [0, 0.25], 101 samples
  std::vector<double> radii;
  for(int i = 0; i <= 100; ++i) radii.push_back(0.0025 * i);

  for(const std::string& name : o.meshes) {
    Mesh_case a;
    a.path = mesh_path(name);
    a.name = mesh_name(a.path);
    diffuv::read_triangle_mesh(a.path, a.mesh);
    a.area = PMP::area(a.mesh);
    a.mean_edge = mean_edge_length(a.mesh);

    // A's labels: automatic disc patches, as `diffuv segment` makes them
    // (--labels quads), or the Voronoi patches of diffuv 0.1 (--labels
    // voronoi: regions of three to eight runs, like painted ones).
    const auto t0 = Clock::now();
    diffuv::Segmentation<Mesh> seg;
    diffuv::Patching_report report;
    diffuv::Patching_options patching;
    if(o.labels == "voronoi") patching.layout = diffuv::Patch_layout::voronoi;
    diffuv::disc_patches(a.mesh, a.mesh.points(), std::vector<int>{}, seg, patching, &report);
    a.labels.assign(a.mesh.number_of_faces(), 0);
    for(auto f : a.mesh.faces()) a.labels[f.idx()] = static_cast<int>(seg.face_patch[f.idx()]);
    a.automatic_patches = seg.number_of_patches();
    std::cerr << "[" << a.name << "] " << a.mesh.number_of_vertices() << " vertices, " << a.automatic_patches
              << " automatic patches (" << format("%.0f", milliseconds_since(t0)) << " ms)\n";

    a.atlas = timed_atlas(a.mesh, a.labels, distance, o.runs, a.param_ms);
    a.ring = seam_rings(a.mesh, *a.atlas);
    std::cerr << "[" << a.name << "] param A " << format("%.1f", a.param_ms) << " ms: "
              << a.atlas->segmentation.number_of_patches() << " patches, " << a.atlas->atlas.number_of_charts()
              << " charts, " << a.atlas->cleaning.changed_faces() << " faces relabelled by the cleaning\n";

    Geodesic_distance geodesic_a(a.mesh);
    diffuv_bench::Line_plot plot;
    plot.x_min = 0.;
    plot.x_max = 0.25;
    plot.y_min = 0.;
    plot.y_max = 100.;
    plot.x_step = 0.05;
    plot.y_step = 20.;
    plot.title = a.name + ": vertices with error <= r";
    plot.x_label = "r = geodesic error / sqrt(area)";
    plot.y_label = "% of vertices";
    for(const std::string& pair : o.pairs) {
      results.push_back(run_pair(a, pair, distance, o.runs, o.follow, geodesic_a));
      const Pair_result& r = results.back();
      const Summary e = summarize(r.error);
      std::cerr << "[" << a.name << "/" << pair << "] mean " << format("%.4f", e.mean) << ", p95 "
                << format("%.4f", e.p95) << ", max " << format("%.4f", e.max) << ", "
                << format("%.1f", percent_within(r.error, 0.05)) << " % within 0.05, " << r.unmapped
                << " unmapped: " << r.verdict << "\n";
      diffuv_bench::Plot_series series;
      series.name = pair;
      series.color = diffuv_bench::series_color(plot.series.size());
      for(double x : radii) series.points.emplace_back(x, percent_within(r.error, x));
      plot.series.push_back(std::move(series));
    }
    const std::string png = o.output + "/correspondence_" + a.name + ".png";
    diffuv_bench::write_plot_png(png, plot);
    std::cerr << "[" << a.name << "] wrote " << png << "\n";
  }

  const std::string md = table(results, o.distance, o.runs, o.follow, o.labels);
  std::cout << md;
  {
    std::ofstream f(o.output + "/table.md");
    f << md;
  }
  {
    std::ofstream f(o.output + "/curves.csv");
    f << "r";
    for(const Pair_result& r : results) f << "," << r.mesh << "/" << r.pair;
    f << "\n";
    for(double x : radii) {
      f << format("%.4f", x);
      for(const Pair_result& r : results) f << "," << format("%.3f", percent_within(r.error, x));
      f << "\n";
    }
  }
  {
    std::ofstream f(o.output + "/diagnostics.md");
    f << "# Where the errors come from\n\nChart keys are (label, part, rank). Edges to seam: edges from the vertex to "
         "the nearest vertex of A in two or more charts.\n\n";
    for(const Pair_result& r : results) f << r.diagnostics;
  }
  std::cerr << "wrote " << o.output << "/table.md, curves.csv, diagnostics.md and " << o.meshes.size()
            << " PNG files; total " << format("%.1f", milliseconds_since(t_start) / 1000.) << " s\n";
  for(const Pair_result& r : results)
    if(!r.passed) return 1;
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  CLI::App app{"diffuv correspondence benchmark: pairs of one surface with different tessellations, where the true "
               "image of a vertex is its closest point"};
  app.add_option("--meshes", o.meshes, "Meshes A: names in CGAL's data set (cow = <data>/meshes/cow.off) or paths")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--pairs", o.pairs, "Meshes B: fine, coarse, shuffled, loop, noise")
      ->delimiter(',')
      ->check(CLI::IsMember({"fine", "coarse", "shuffled", "loop", "noise"}))
      ->capture_default_str();
  app.add_option("--runs", o.runs, "Runs to take the median time of")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("-o,--output", o.output, "Output folder")->capture_default_str();
  app.add_option("--distance", o.distance, "Distances of the parameterizations")
      ->check(CLI::IsMember({"fmm", "graph", "exact"}))
      ->capture_default_str();
  app.add_flag("!--no-follow", o.follow,
               "Build B's atlas on its own, without following A's sub-patches and corners (atlas_to_follow())");
  bool repair = false, no_repair = false;
  auto* repair_flag = app.add_flag("--repair", repair, "Repair the folds of each chart (default: the library's default)");
  app.add_flag("--no-repair", no_repair, "Keep the raw diffusion coordinates")->excludes(repair_flag);
  app.add_option("--labels", o.labels, "A's regions: the four-sided layout's patches, or diffuv 0.1's Voronoi patches")
      ->check(CLI::IsMember({"quads", "voronoi"}))
      ->capture_default_str();
  app.add_flag("--sub-patches", sub_patches_choice,
               "Split regions with three or five to nine runs of neighbours into four-sided sectors (split_regions_into_quads())");
  app.add_flag("--self-check", o.self_check,
               "Only check the local exact geodesics against Surface_mesh_shortest_path on the whole of cow.off");
  app.footer("Exit codes: 0 every target met, 1 a target missed (or the self-check failed), 4 error.");
  CLI11_PARSE(app, argc, argv);
  if(repair) repair_choice = 1;
  if(no_repair) repair_choice = 0;
  try {
    if(o.self_check) return self_check(mesh_path("cow")) ? 0 : 1;
    return run(o);
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 4;
  }
}
