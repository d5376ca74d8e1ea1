// diffuv: what the fold repair (parameterization/repair_folds.h) works on: a
// patch's vertices by index with their (u,v), sides and triangles, and the
// operations of the repair: finding local defects and bent triangles,
// re-solving a set of vertices as a mean value map, growing a region by rings,
// walking and re-spacing the sides.
#ifndef DIFFUV_PARAMETERIZATION_INTERNAL_REPAIR_PATCH_H
#define DIFFUV_PARAMETERIZATION_INTERNAL_REPAIR_PATCH_H

#include <diffuv/core/four_sides.h>
#include <diffuv/internal/uv_triangle.h>

#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace diffuv {
namespace internal {

/// Whether triangle t of (u, v) is counter-clockwise and not degenerate (area
/// above 1e-14 of `total`, the threshold of measure_distortion).
inline bool positive_triangle(const std::array<std::size_t, 3>& t, const std::vector<double>& u,
                              const std::vector<double>& v, double total)
{
  const Uv_triangle uv_t = {Uv_point(u[t[0]], v[t[0]]), Uv_point(u[t[1]], v[t[1]]), Uv_point(u[t[2]], v[t[2]])};
  const double a = signed_area(uv_t);
  return !is_degenerate_area(a, total) && a > 0 && CGAL::orientation(uv_t[0], uv_t[1], uv_t[2]) == CGAL::LEFT_TURN;
}

/// Lists of indices, one per vertex, in one array (compressed rows): on a
/// 1.1M-vertex patch a vector per vertex cost a million allocations, for the
/// triangles around the vertices and again for their neighbours.
struct Index_lists {
  std::vector<std::size_t> offsets{0};  // list i is items[offsets[i], offsets[i + 1])
  std::vector<std::size_t> items;

  struct List {
    const std::size_t* first;
    const std::size_t* last;
    const std::size_t* begin() const { return first; }
    const std::size_t* end() const { return last; }
    bool empty() const { return first == last; }
    std::size_t size() const { return static_cast<std::size_t>(last - first); }
  };
  List operator[](std::size_t i) const { return {items.data() + offsets[i], items.data() + offsets[i + 1]}; }
  std::size_t size() const { return offsets.size() - 1; }

  /// Lists of `n` items made of the pairs (list, value) that `each_pair(add)`
  /// gives to `add`, twice in the same order: values in that order within a list.
  template <class EachPair>
  void assign(std::size_t n, EachPair each_pair)
  {
    offsets.assign(n + 1, 0);
    each_pair([&](std::size_t list, std::size_t) { ++offsets[list + 1]; });
    for(std::size_t i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
    items.resize(offsets[n]);
    std::vector<std::size_t> next(offsets.begin(), offsets.end() - 1);
    each_pair([&](std::size_t list, std::size_t value) { items[next[list]++] = value; });
  }
};

/// The vertices of a patch by index, their sides, the patch's triangles, and
/// the map being repaired.
template <class TriangleMesh, class Point_3>
struct Repair_patch {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Triangle = std::array<std::size_t, 3>;

  std::vector<vertex_descriptor> vertex;          // by index
  std::vector<Point_3> xyz;                       // by index
  std::vector<double> u, v;                       // by index: the map
  std::vector<std::uint8_t> side_mask;            // bit s set: on side s (in the order of `Side`)
  std::vector<Triangle> triangle;
  Index_lists faces_of;                           // triangles around each vertex, in increasing order (`find_faces_of()`)
  std::vector<bool> flat;                         // flat in any map onto the square
  Index_lists ring;                               // neighbours of each vertex, in increasing order (`find_rings()`)
  std::vector<bool> bad_face, bad_vertex;         // local defects (`find_defects()`)
  std::vector<bool> thin;                         // bent triangles (`find_thin()`)
  std::array<double, 2> rectangle{{1., 1.}};      // the chart's rectangle, for the bends
  std::size_t solves = 0;                         // linear solves made

  std::size_t size() const { return vertex.size(); }

  /// Marks as flat the faces around a connected group of interior vertices
  /// whose border neighbours all lie on one side: a convex combination of
  /// points on a line stays on it (groups joined across interior edges, by
  /// union-find over the triangles: no list of faces around each vertex is
  /// needed until the map has a defect to repair).
  void mark_flat_interior_groups()
  {
    const std::size_t n = size();
    std::vector<std::size_t> parent(n);
    for(std::size_t i = 0; i < n; ++i) parent[i] = i;
    auto root = [&](std::size_t i) {
      while(parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    for(const Triangle& t : triangle)
      for(int e = 0; e < 3; ++e) {
        const std::size_t a = t[e], b = t[(e + 1) % 3];
        if(side_mask[a] || side_mask[b]) continue;
        const std::size_t ra = root(a), rb = root(b);
        if(ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
      }
    // The sides every border neighbour of each group lies on.
    std::vector<std::uint8_t> common(n, 0xF);
    for(const Triangle& t : triangle)
      for(std::size_t i : t)
        if(!side_mask[i])
          for(std::size_t j : t)
            if(side_mask[j]) common[root(i)] &= side_mask[j];
    for(std::size_t f = 0; f < triangle.size(); ++f)
      for(std::size_t i : triangle[f])
        if(!side_mask[i] && common[root(i)]) flat[f] = true;
  }

  /// Local defects: a triangle that is not counter-clockwise (or degenerate),
  /// or a vertex around which the triangles turn by more than once: 2 pi for
  /// an interior vertex, less than 2 pi for a border one (pi on a side, pi/2 at
  /// a corner). Theorem: a map of a disc without local defects whose border
  /// runs once around the square (monotone sides) is a local homeomorphism
  /// that is one-to-one on the border, hence one-to-one. So no overlap test is
  /// needed, before or after the repair (the tests check overlaps independently).
  /// Returns the number of faces that are or touch a defect (a face counted
  /// once for each defective vertex of it that is not itself a defect).
  /// One pass over the triangles: each corner adds its share to its vertex, in
  /// the triangles' order, so no list of faces around each vertex is needed.
  std::size_t find_defects()
  {
    const double total_area = 1.;  // the unit square
    const std::size_t n = size();
    bad_face.assign(triangle.size(), false);
    bad_vertex.assign(n, false);
    std::vector<double> turn(n, 0.);  // each border vertex's fan angle
    std::vector<int> winding(n, 0);   // each interior vertex's winding number
    std::size_t count = 0;
    for(std::size_t f = 0; f < triangle.size(); ++f) {
      const Triangle& t = triangle[f];
      bad_face[f] = !flat[f] && !positive_triangle(t, u, v, total_area);
      count += bad_face[f];
      // Interior vertex: the winding number of its link around it, counted
      // as signed crossings of the ray from the vertex along +u (no
      // trigonometry; the link's edges are the faces' far edges). Border
      // vertex: the total angle of its open fan, which must stay below 2 pi.
      for(int k = 0; k < 3; ++k) {
        const std::size_t i = t[k], a = t[(k + 1) % 3], b = t[(k + 2) % 3];
        const double ax = u[a] - u[i], ay = v[a] - v[i], bx = u[b] - u[i], by = v[b] - v[i];
        if(side_mask[i]) {
          turn[i] += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
        } else if((ay < 0) != (by < 0)) {
          const double x = ax + ay / (ay - by) * (bx - ax);  // where edge ab meets v = v_i
          if(x > 0) winding[i] += ay < 0 ? 1 : -1;
        }
      }
    }
    bool any_bad_vertex = false;
    for(std::size_t i = 0; i < n; ++i) {
      bad_vertex[i] = side_mask[i] ? !(turn[i] < 2 * CGAL_PI - 1e-6) : winding[i] != 1;
      any_bad_vertex = any_bad_vertex || bad_vertex[i];
    }
    if(any_bad_vertex)
      for(std::size_t f = 0; f < triangle.size(); ++f)
        if(!bad_face[f])
          for(std::size_t i : triangle[f]) count += bad_vertex[i];
    return count;
  }

  /// How much the map bends a triangle's shape on the chart's rectangle
  /// (sigma_max / sigma_min of its Jacobian; 0 for a triangle degenerate in 3D).
  double bend(const Triangle& t) const
  {
    const auto e1 = xyz[t[1]] - xyz[t[0]], e2 = xyz[t[2]] - xyz[t[0]];
    const double l1 = std::sqrt(CGAL::to_double(e1 * e1));
    const double x2 = l1 > 0 ? CGAL::to_double(e1 * e2) / l1 : 0.;
    const double y2_squared = CGAL::to_double(e2 * e2) - x2 * x2;
    if(!(l1 > 0 && y2_squared > 0)) return 0.;
    const double y2 = std::sqrt(y2_squared);
    // The triangle in a frame of its plane is [[l1, x2], [0, y2]]; J maps it onto its (u,v) edges.
    const double du1 = (u[t[1]] - u[t[0]]) * rectangle[0], du2 = (u[t[2]] - u[t[0]]) * rectangle[0];
    const double dv1 = (v[t[1]] - v[t[0]]) * rectangle[1], dv2 = (v[t[2]] - v[t[0]]) * rectangle[1];
    const auto [s_max, s_min] = singular_values_2x2(du1 / l1, (du2 - du1 * x2 / l1) / y2, dv1 / l1, (dv2 - dv1 * x2 / l1) / y2);
    return s_min > 0 ? s_max / s_min : std::numeric_limits<double>::infinity();
  }

  /// Marks the triangles bent beyond `limit` (flat ones aside: flat in any
  /// map); returns how many, and the worst bend.
  std::pair<std::size_t, double> find_thin(double limit)
  {
    thin.assign(triangle.size(), false);
    std::size_t count = 0;
    double worst = 0;
    for(std::size_t f = 0; f < triangle.size(); ++f) {
      if(flat[f]) continue;
      const double b = bend(triangle[f]);
      worst = std::max(worst, b);
      thin[f] = b > limit;
      count += thin[f];
    }
    return std::make_pair(count, worst);
  }

  /// Fills `faces_of` from `triangle`.
  void find_faces_of()
  {
    faces_of.assign(size(), [&](auto add) {
      for(std::size_t f = 0; f < triangle.size(); ++f)
        for(std::size_t i : triangle[f]) add(i, f);
    });
  }

  /// Fills `ring`: the neighbours of each vertex, for growing regions.
  void find_rings()
  {
    ring.assign(size(), [&](auto add) {
      for(const auto& t : triangle)
        for(int k = 0; k < 3; ++k) {
          add(t[k], t[(k + 1) % 3]);
          add(t[k], t[(k + 2) % 3]);
        }
    });
    // Each list sorted, repeats dropped, and the lists packed again.
    std::size_t kept = 0;
    for(std::size_t i = 0; i < size(); ++i) {
      const auto first = ring.items.begin() + static_cast<std::ptrdiff_t>(ring.offsets[i]);
      const auto last = ring.items.begin() + static_cast<std::ptrdiff_t>(ring.offsets[i + 1]);
      std::sort(first, last);
      const auto unique_end = std::unique(first, last);
      ring.offsets[i] = kept;
      for(auto j = first; j != unique_end; ++j) ring.items[kept++] = *j;  // kept <= offsets[i]: moves down
    }
    ring.offsets[size()] = kept;
    ring.items.resize(kept);
  }

  /// The kernel of interior vertex i's link: the points of the unit square
  /// from which every triangle around i is counter-clockwise (each triangle
  /// (i, a, b) asks i to lie left of a -> b), clipped from the square one
  /// half-plane at a time. Empty if there is none.
  std::vector<std::array<double, 2>> link_kernel(std::size_t i) const
  {
    using P = std::array<double, 2>;
    std::vector<P> poly = {P{{0., 0.}}, P{{1., 0.}}, P{{1., 1.}}, P{{0., 1.}}}, next;
    for(std::size_t f : faces_of[i]) {
      const auto& t = triangle[f];
      const int k = t[0] == i ? 0 : (t[1] == i ? 1 : 2);
      const std::size_t a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      // side(q) > 0: q left of a -> b (linear in q).
      auto side = [&](const P& q) { return (u[a] - q[0]) * (v[b] - q[1]) - (v[a] - q[1]) * (u[b] - q[0]); };
      next.clear();
      for(std::size_t j = 0; j < poly.size(); ++j) {
        const P& c = poly[j];
        const P& d = poly[(j + 1) % poly.size()];
        const double sc = side(c), sd = side(d);
        if(sc > 0) next.push_back(c);
        if((sc > 0) != (sd > 0) && sc != sd) {
          const double t_cut = sc / (sc - sd);
          next.push_back(P{{c[0] + t_cut * (d[0] - c[0]), c[1] + t_cut * (d[1] - c[1])}});
        }
      }
      poly.swap(next);
      if(poly.size() < 3) return {};
    }
    return poly;
  }

  /// Whether interior vertex i, put at `q`, would have every triangle around
  /// it counter-clockwise and not degenerate, turning once around it, and
  /// bent by no more than `max_bend` (`bend()`; 0: any bend).
  bool fits_at(std::size_t i, const std::array<double, 2>& q, double max_bend)
  {
    const double keep_u = u[i], keep_v = v[i];
    u[i] = q[0];
    v[i] = q[1];
    bool ok = true;
    double turn = 0;
    for(std::size_t f : faces_of[i]) {
      const auto& t = triangle[f];
      if(!positive_triangle(t, u, v, 1.) || (max_bend > 0 && !(bend(t) <= max_bend))) { ok = false; break; }
      const int k = t[0] == i ? 0 : (t[1] == i ? 1 : 2);
      const std::size_t a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      const double ax = u[a] - q[0], ay = v[a] - q[1], bx = u[b] - q[0], by = v[b] - q[1];
      turn += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
    }
    u[i] = keep_u;
    v[i] = keep_v;
    return ok && std::abs(turn - 2 * CGAL_PI) < 1e-6;
  }

  /// Moves interior vertices of the local defects into the kernels of their
  /// links, at the kernel's centroid, so that every triangle around each is
  /// counter-clockwise again: only the defects' own vertices leave the
  /// diffusion map, where a re-solve moves their whole ring. Each sweep finds
  /// every candidate's place first, then moves them in order (the one around
  /// more defective faces first, ties by the smaller 3D point), each unless
  /// a neighbour moved already in this sweep or ties with it, so the result
  /// depends on neither the vertex order nor an order of visits. A kernel
  /// must cover more than `min_area` of the square, and its centroid must
  /// give the vertex a single turn and triangles that `fits_at()` accepts
  /// with `max_bend` (a fold mended into a near-fold is left to the
  /// re-solve). Returns the vertices moved.
  std::size_t move_into_kernels(std::size_t sweeps, double min_area, double max_bend)
  {
    const std::size_t n = size();
    std::vector<char> moved(n, 0);
    std::size_t count = 0;
    for(std::size_t sweep = 0; sweep < sweeps; ++sweep) {
      if(find_defects() == 0) break;
      std::vector<std::size_t> badness(n, 0);
      for(std::size_t f = 0; f < triangle.size(); ++f)
        if(bad_face[f])
          for(std::size_t i : triangle[f]) ++badness[i];
      for(std::size_t i = 0; i < n; ++i) badness[i] += bad_vertex[i] ? 1 : 0;
      auto first = [&](std::size_t a, std::size_t b) {
        if(badness[a] != badness[b]) return badness[a] > badness[b];
        return xyz[a] < xyz[b];
      };
      std::vector<char> candidate(n, 0);
      std::vector<std::pair<std::size_t, std::array<double, 2>>> places;
      for(std::size_t i = 0; i < n; ++i) {
        if(badness[i] == 0 || side_mask[i] || faces_of[i].empty()) continue;
        candidate[i] = 1;
        const auto kernel = link_kernel(i);
        if(kernel.size() < 3) continue;
        double area = 0, cx = 0, cy = 0;
        for(std::size_t j = 0; j < kernel.size(); ++j) {
          const auto& c = kernel[j];
          const auto& d = kernel[(j + 1) % kernel.size()];
          const double w = c[0] * d[1] - d[0] * c[1];
          area += w;
          cx += (c[0] + d[0]) * w;
          cy += (c[1] + d[1]) * w;
        }
        if(!(area / 2 > min_area)) continue;
        const std::array<double, 2> q = {{cx / (3 * area), cy / (3 * area)}};
        if(fits_at(i, q, max_bend)) places.push_back({i, q});
      }
      std::sort(places.begin(), places.end(), [&](const auto& a, const auto& b) { return first(a.first, b.first); });
      std::vector<char> accepted(n, 0);
      std::size_t this_sweep = 0;
      for(const auto& [i, q] : places) {
        bool blocked = false;
        for(std::size_t j : ring[i])
          blocked |= accepted[j] || (candidate[j] && !first(i, j) && !first(j, i));
        if(blocked) continue;
        accepted[i] = 1;
        u[i] = q[0];
        v[i] = q[1];
        count += !moved[i];
        moved[i] = 1;
        ++this_sweep;
      }
      if(this_sweep == 0) break;
    }
    find_defects();
    return count;
  }

  /// The weights of a re-solved vertex: mean value weights (Floater 2003),
  /// w_ij = (tan(a/2) + tan(b/2)) / |x_i - x_j| with a and b the 3D angles at
  /// x_i next to edge ij. They follow the surface's shape (better angles than
  /// Tutte's uniform weights) and are positive, which is all Floater's
  /// embedding theorem needs. Uniform weights where an angle is undefined
  /// (a zero-length edge). (Symmetrised mean value weights would allow a
  /// Cholesky solve but measured worse angles: doc/quality.md.)
  void weights_of(std::size_t i, std::vector<std::pair<std::size_t, double>>& row) const
  {
    row.clear();
    for(std::size_t f : faces_of[i]) {
      const auto& t = triangle[f];
      const int k = t[0] == i ? 0 : (t[1] == i ? 1 : 2);
      const std::size_t a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      const auto ea = xyz[a] - xyz[i], eb = xyz[b] - xyz[i];
      const double la = std::sqrt(CGAL::to_double(ea * ea)), lb = std::sqrt(CGAL::to_double(eb * eb));
      const double half_tan =
          la > 0 && lb > 0 ? std::tan(std::acos(std::clamp(CGAL::to_double(ea * eb) / (la * lb), -1., 1.)) / 2) : 0.;
      if(!(half_tan > 0) || !std::isfinite(half_tan)) {
        row.clear();
        for(std::size_t g : faces_of[i])
          for(std::size_t j : triangle[g])
            if(j != i) row.emplace_back(j, 1.);
        return;
      }
      row.emplace_back(a, half_tan / la);
      row.emplace_back(b, half_tan / lb);
    }
  }

  /// Re-solves the vertices flagged in `free_vertex` with every other vertex fixed.
  bool solve(const std::vector<bool>& free_vertex)
  {
    const std::size_t n = size();
    std::vector<std::size_t> local_of(n, n);
    std::vector<std::size_t> unknowns;
    for(std::size_t i = 0; i < n; ++i)
      if(free_vertex[i]) {
        local_of[i] = unknowns.size();
        unknowns.push_back(i);
      }
    if(unknowns.empty()) return true;
    ++solves;
    const auto m = static_cast<Eigen::Index>(unknowns.size());
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(m, 2);
    std::vector<std::pair<std::size_t, double>> row;
    for(std::size_t li = 0; li < unknowns.size(); ++li) {
      const std::size_t i = unknowns[li];
      const auto row_index = static_cast<Eigen::Index>(li);
      weights_of(i, row);
      double diagonal = 0;
      for(const auto& [j, w] : row) {
        diagonal += w;
        if(local_of[j] < n) {
          entries.emplace_back(row_index, static_cast<Eigen::Index>(local_of[j]), -w);
        } else {
          rhs(row_index, 0) += w * u[j];
          rhs(row_index, 1) += w * v[j];
        }
      }
      entries.emplace_back(row_index, row_index, diagonal);
    }
    Eigen::SparseMatrix<double> a(m, m);
    a.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(a);
    if(lu.info() != Eigen::Success) return false;
    const Eigen::MatrixXd x = lu.solve(rhs);
    if(lu.info() != Eigen::Success || !x.allFinite()) return false;
    // Convex combinations of points of the unit square stay in it up to a
    // rounding step: clamp that step, (u,v) are documented to be in [0,1].
    for(std::size_t li = 0; li < unknowns.size(); ++li) {
      u[unknowns[li]] = std::clamp(x(static_cast<Eigen::Index>(li), 0), 0., 1.);
      v[unknowns[li]] = std::clamp(x(static_cast<Eigen::Index>(li), 1), 0., 1.);
    }
    return true;
  }

  /// Marks in `into` the interior vertices within `steps` edges of `seeds`
  /// (a border seed reaches out through its neighbours, other border vertices
  /// stop the search) and returns how many `into` holds. A new search each
  /// time, so that a region whose defects lie inside it still grows.
  std::size_t grow(const std::vector<std::size_t>& seeds, std::size_t steps, std::vector<bool>& into) const
  {
    const std::size_t n = size();
    std::vector<bool> reached(n, false);
    std::vector<std::size_t> front;
    for(std::size_t i : seeds)
      if(!reached[i]) {
        reached[i] = true;
        front.push_back(i);
      }
    for(std::size_t step = 0; step < steps && !front.empty(); ++step) {
      std::vector<std::size_t> next;
      for(std::size_t i : front)
        for(std::size_t j : ring[i])
          if(!reached[j]) {
            reached[j] = true;
            if(!side_mask[j]) next.push_back(j);
          }
      front.swap(next);
    }
    std::size_t count = 0;
    for(std::size_t i = 0; i < n; ++i) {
      if(reached[i] && !side_mask[i]) into[i] = true;
      count += into[i];
    }
    return count;
  }
};

/// One side walked counter-clockwise: v1 has u increasing, u2 v increasing,
/// v2 u decreasing, u1 v decreasing, so each side runs once along its edge of
/// the square.
struct Side_walk {
  std::vector<std::size_t> vertices;  // vertex indices, in the side's order
  bool along_u = true;
  bool increasing = true;
  std::uint8_t bit = 0;               // the side's bit in `Repair_patch::side_mask`

  template <class Patch>
  std::vector<double> arc_lengths(const Patch& p) const
  {
    std::vector<double> arc(vertices.size(), 0.);
    for(std::size_t k = 1; k < vertices.size(); ++k)
      arc[k] = arc[k - 1] + std::sqrt(CGAL::to_double(CGAL::squared_distance(p.xyz[vertices[k - 1]], p.xyz[vertices[k]])));
    return arc;
  }

  template <class Patch>
  bool monotone(const Patch& p) const
  {
    const std::vector<double>& c = along_u ? p.u : p.v;
    for(std::size_t k = 1; k < vertices.size(); ++k) {
      const double a = c[vertices[k - 1]], b = c[vertices[k]];
      if(!(increasing ? a < b : a > b)) return false;
    }
    return true;
  }

  /// Re-spaces the side's inner vertices by arc length.
  template <class Patch>
  void respace(Patch& p) const
  {
    std::vector<double>& c = along_u ? p.u : p.v;
    const std::vector<double> arc = arc_lengths(p);
    const double total = arc.back();
    for(std::size_t k = 1; k + 1 < vertices.size(); ++k) {
      const double t = total > 0 ? arc[k] / total : double(k) / double(vertices.size() - 1);
      c[vertices[k]] = increasing ? t : 1. - t;
    }
  }
};

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_INTERNAL_REPAIR_PATCH_H
