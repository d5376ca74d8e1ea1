// diffuv: make a patch's (u,v) map one-to-one while keeping the diffusion
// coordinates wherever they are already valid.
//
// The paper's distance ratio folds where distance isolines bend around
// singularities or follow the tessellation (issue #5, doc/quality.md). Repair:
//  1. each side of the border must run monotonically along its edge of the
//     square; a side that does not is re-spaced by arc length (CGAL's
//     Square_border_arc_length_parameterizer_3 does the same for every side);
//  2. the interior vertices of every folded triangle (flipped or degenerate,
//     or around a vertex the map winds around twice), grown by rings, are re-solved as a
//     convex-combination map (mean value weights, Floater 2003) with every
//     other vertex fixed; the region grows until no fold remains;
//  3. as a last resort every interior vertex is re-solved: with the border on
//     the convex square and positive weights, Tutte/Floater's theorem makes
//     that map an embedding. Triangles whose three vertices lie on one side
//     are flat in any map onto the square, and so are the triangles around a
//     group of interior vertices whose border neighbours all lie on one side;
//     they are "forced" and reported.
// Then the near-folds: a triangle that the map bends far more than any
// shape needs (sigma_max / sigma_min of its Jacobian on the chart's rectangle
// above `max_angle_distortion`) is one step from a fold: a vertex almost on
// the line of its opposite edge, or two border vertices squeezed together
// on a side. Squeezed sides are re-spaced by arc length and the interior
// around the bent triangles is re-solved the same way, each round kept only
// if it folds nothing and bends the triangles it changed less. On bear, one
// 17-face quad had L2 stretch 51 from one such triangle (doc/layout.md).
#ifndef DIFFUV_PARAMETERIZATION_REPAIR_FOLDS_H
#define DIFFUV_PARAMETERIZATION_REPAIR_FOLDS_H

#include <diffuv/core/error.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/core/four_sides.h>
#include <diffuv/internal/uv_triangle.h>
#include <diffuv/parameterization/chart_rectangle.h>

#include <CGAL/boost/graph/iterator.h>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace diffuv {

/// How `repair_folds()` works.
struct Repair_options {
  bool enabled = true;            ///< false keeps the raw diffusion coordinates (the paper's method)
  std::size_t initial_rings = 1;  ///< rings of vertices added around the first folds
  std::size_t max_local_rounds = 6;  ///< local re-solves (rings doubling) before the whole patch is re-solved
  /// A triangle bent by more than this (sigma_max / sigma_min of the map on the
  /// chart's rectangle, 1 = shape kept) is re-solved like a fold if that helps
  /// (doc/quality.md); 0 turns the near-fold pass off.
  double max_angle_distortion = 20;
  std::size_t max_thin_rounds = 3;  ///< near-fold re-solves (rings doubling)
};

/// What `repair_folds()` did to one patch (all zero when the repair is off).
struct Repair_report {
  std::size_t folded_faces = 0;        ///< faces flipped or degenerate, or around a vertex the map winds around twice, before the repair (forced ones excluded)
  std::size_t flat_triangles = 0;   ///< faces with all three vertices on one side, or around interior vertices whose border neighbours all are: flat in any map onto the square
  std::size_t moved_vertices = 0;      ///< interior vertices whose (u,v) changed
  std::size_t moved_border_vertices = 0;  ///< border vertices re-spaced because their side was not monotone, or was squeezed at a near-fold
  std::size_t rounds = 0;              ///< linear solves
  bool whole_patch = false;            ///< whether the last resort (every interior vertex re-solved) was needed
  std::size_t remaining_folded_faces = 0;  ///< folds left (0 unless the last resort met a numerical limit)
  std::size_t thin_faces = 0;          ///< faces bent beyond `max_angle_distortion` once the folds were repaired (forced ones excluded)
  std::size_t remaining_thin_faces = 0;  ///< of those, the ones the near-fold pass left bent beyond it
};

namespace internal {

/// The vertices of a patch by index, their sides, and the patch's triangles.
template <class TriangleMesh>
struct Repair_patch {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  std::vector<vertex_descriptor> vertex;       // by index
  std::vector<std::uint8_t> side_mask;         // bit s set: on side s (in the order of `Side`)
  std::vector<std::array<std::size_t, 3>> triangle;
  std::vector<bool> forced;                    // all three vertices on one side
  std::vector<std::vector<std::size_t>> ring;  // neighbours of each vertex
};

/// Whether triangle t of (u, v) is counter-clockwise and not degenerate (area
/// above 1e-14 of `total`, the threshold of measure_distortion).
inline bool positive_triangle(const std::array<std::size_t, 3>& t, const std::vector<double>& u,
                              const std::vector<double>& v, double total)
{
  const Uv_triangle uv_t = {Uv_point(u[t[0]], v[t[0]]), Uv_point(u[t[1]], v[t[1]]), Uv_point(u[t[2]], v[t[2]])};
  const double a = signed_area(uv_t);
  return !is_degenerate_area(a, total) && a > 0 && CGAL::orientation(uv_t[0], uv_t[1], uv_t[2]) == CGAL::LEFT_TURN;
}

} // namespace internal

/// Repairs the folds of a disc patch's (u,v) map in place.
///
/// \tparam TriangleMesh a model of `FaceListGraph` with an internal vertex index
///         (`CGAL::Surface_mesh`, a `CGAL::Face_filtered_graph` patch, ...)
/// \param tm the patch (a disc), \param vpm its 3D points (for the weights and arc lengths)
/// \param sides the four sides used for `uv`; border vertices are fixed on them
/// \param uv read-write map from vertices to 2D points, initially the diffusion coordinates
/// \returns `ok`, or `not_injective` (detail: how many folds remain) if folds
///          survive even the last resort (only with numerically degenerate input)
template <class TriangleMesh, class VertexPointMap, class UvMap>
Status repair_folds(const TriangleMesh& tm, VertexPointMap vpm,
                    const Four_sides<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& sides, UvMap uv,
                    const Repair_options& options = Repair_options(), Repair_report* report = nullptr)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point_2 = typename boost::property_traits<UvMap>::value_type;
  using Point_3 = typename boost::property_traits<VertexPointMap>::value_type;
  Repair_report local;
  Repair_report& r = report ? *report : local;
  r = Repair_report();
  if(!options.enabled) return Status();  // the raw method: nothing to check or count

  auto index = get(boost::vertex_index, tm);
  const std::size_t n = num_vertices(tm);
  internal::Repair_patch<TriangleMesh> p;
  p.vertex.resize(n);
  p.side_mask.assign(n, 0);
  std::vector<Point_3> xyz(n);
  std::vector<double> u(n), v(n);
  for(vertex_descriptor vd : vertices(tm)) {
    const std::size_t i = get(index, vd);
    p.vertex[i] = vd;
    xyz[i] = get(vpm, vd);
    const auto q = get(uv, vd);
    u[i] = CGAL::to_double(q.x());
    v[i] = CGAL::to_double(q.y());
  }
  for(Side s : all_sides)
    for(vertex_descriptor vd : sides[s]) p.side_mask[get(index, vd)] |= static_cast<std::uint8_t>(1u << static_cast<int>(s));

  std::vector<std::vector<std::size_t>> faces_of(n);
  for(auto f : faces(tm)) {
    std::array<std::size_t, 3> t{};
    std::size_t k = 0;
    for(vertex_descriptor vd : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      if(k < 3) t[k] = get(index, vd);
      ++k;
    }
    if(k != 3) return Status(Status_code::not_triangle_mesh, "a face of the patch has " + std::to_string(k) + " vertices");
    for(std::size_t i : t) faces_of[i].push_back(p.triangle.size());
    p.forced.push_back((p.side_mask[t[0]] & p.side_mask[t[1]] & p.side_mask[t[2]]) != 0);
    p.triangle.push_back(t);
  }
  // So are the faces around a connected group of interior vertices whose
  // border neighbours all lie on one side: a convex combination of points on
  // a line stays on it (components across interior edges).
  {
    std::vector<std::size_t> component(n, n);
    std::vector<std::size_t> members;
    for(std::size_t seed = 0; seed < n; ++seed) {
      if(p.side_mask[seed] || component[seed] < n || faces_of[seed].empty()) continue;
      members.assign(1, seed);
      component[seed] = seed;
      std::uint8_t common = 0xF;
      for(std::size_t k = 0; k < members.size(); ++k)
        for(std::size_t f : faces_of[members[k]])
          for(std::size_t j : p.triangle[f]) {
            if(p.side_mask[j]) common &= p.side_mask[j];
            else if(component[j] == n) {
              component[j] = seed;
              members.push_back(j);
            }
          }
      if(common)
        for(std::size_t i : members)
          for(std::size_t f : faces_of[i]) p.forced[f] = true;
    }
  }
  r.flat_triangles = static_cast<std::size_t>(std::count(p.forced.begin(), p.forced.end(), true));
  const std::vector<double> u0 = u, v0 = v;

  auto write_back = [&]() {
    std::size_t moved = 0, moved_border = 0;
    for(std::size_t i = 0; i < n; ++i) {
      if(u[i] == u0[i] && v[i] == v0[i]) continue;
      (p.side_mask[i] ? moved_border : moved) += 1;
      put(uv, p.vertex[i], Point_2(u[i], v[i]));
    }
    r.moved_vertices = moved;
    r.moved_border_vertices = moved_border;
  };

  // Local defects: a triangle that is not counter-clockwise (or degenerate),
  // or a vertex around which the triangles turn by more than once: 2 pi for
  // an interior vertex, less than 2 pi for a border one (pi on a side, pi/2 at
  // a corner). Theorem: a map of a disc without local defects whose border
  // runs once around the square (monotone sides) is a local homeomorphism that
  // is one-to-one on the border, hence one-to-one. So no overlap test is
  // needed, before or after the repair (the tests check overlaps independently).
  const double total_area = 1.;  // the unit square
  std::vector<bool> bad_face(p.triangle.size()), bad_vertex(n);
  auto find_defects = [&]() {
    std::size_t count = 0;
    for(std::size_t f = 0; f < p.triangle.size(); ++f) {
      bad_face[f] = !p.forced[f] && !internal::positive_triangle(p.triangle[f], u, v, total_area);
      count += bad_face[f];
    }
    for(std::size_t i = 0; i < n; ++i) {
      // Interior vertex: the winding number of its link around it, counted
      // as signed crossings of the ray from the vertex along +u (no
      // trigonometry; the link's edges are the faces' far edges). Border
      // vertex: the total angle of its open fan, which must stay below 2 pi.
      double turn = 0;
      int winding = 0;
      for(std::size_t f : faces_of[i]) {
        const auto& t = p.triangle[f];
        const int k = t[0] == i ? 0 : (t[1] == i ? 1 : 2);
        const std::size_t a = t[(k + 1) % 3], b = t[(k + 2) % 3];
        const double ax = u[a] - u[i], ay = v[a] - v[i], bx = u[b] - u[i], by = v[b] - v[i];
        if(p.side_mask[i]) {
          turn += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
        } else if((ay < 0) != (by < 0)) {
          const double x = ax + ay / (ay - by) * (bx - ax);  // where edge ab meets v = v_i
          if(x > 0) winding += ay < 0 ? 1 : -1;
        }
      }
      bad_vertex[i] = p.side_mask[i] ? !(turn < 2 * CGAL_PI - 1e-6) : winding != 1;
      if(bad_vertex[i])
        for(std::size_t f : faces_of[i]) count += !bad_face[f];
    }
    return count;
  };

  // Walking counter-clockwise, v1 has u increasing, u2 v increasing, v2 u
  // decreasing, u1 v decreasing: each side runs once along its edge of the square.
  struct Walk { const std::vector<vertex_descriptor>* side; bool along_u; bool increasing; std::uint8_t bit; };
  auto bit = [](Side s) { return static_cast<std::uint8_t>(1u << static_cast<int>(s)); };
  const std::array<Walk, 4> walks = {Walk{&sides.v1, true, true, bit(Side::v1)}, Walk{&sides.u2, false, true, bit(Side::u2)},
                                     Walk{&sides.v2, true, false, bit(Side::v2)}, Walk{&sides.u1, false, false, bit(Side::u1)}};
  auto side_arc_lengths = [&](const Walk& w) {
    const auto& side = *w.side;
    std::vector<double> arc(side.size(), 0.);
    for(std::size_t k = 1; k < side.size(); ++k)
      arc[k] = arc[k - 1] + std::sqrt(CGAL::to_double(CGAL::squared_distance(xyz[get(index, side[k - 1])],
                                                                              xyz[get(index, side[k])])));
    return arc;
  };
  auto monotone = [&](const Walk& w) {
    const std::vector<double>& c = w.along_u ? u : v;
    for(std::size_t k = 1; k < w.side->size(); ++k) {
      const double a = c[get(index, (*w.side)[k - 1])], b = c[get(index, (*w.side)[k])];
      if(!(w.increasing ? a < b : a > b)) return false;
    }
    return true;
  };

  // The common case costs two linear passes: no local defect and monotone
  // sides prove the map one-to-one, no overlap test needed.
  const bool border_ok = std::all_of(walks.begin(), walks.end(), monotone);
  // How much the map bends each triangle's shape on the chart's rectangle
  // (sigma_max / sigma_min of its Jacobian; 0 for a triangle degenerate in 3D).
  const std::array<double, 2> rectangle = side_length_rectangle(sides, vpm);
  auto bend = [&](const std::array<std::size_t, 3>& t) {
    const auto e1 = xyz[t[1]] - xyz[t[0]], e2 = xyz[t[2]] - xyz[t[0]];
    const double l1 = std::sqrt(CGAL::to_double(e1 * e1));
    const double x2 = l1 > 0 ? CGAL::to_double(e1 * e2) / l1 : 0.;
    const double y2_squared = CGAL::to_double(e2 * e2) - x2 * x2;
    if(!(l1 > 0 && y2_squared > 0)) return 0.;
    const double y2 = std::sqrt(y2_squared);
    // The triangle in a frame of its plane is [[l1, x2], [0, y2]]; J maps it onto its (u,v) edges.
    const double du1 = (u[t[1]] - u[t[0]]) * rectangle[0], du2 = (u[t[2]] - u[t[0]]) * rectangle[0];
    const double dv1 = (v[t[1]] - v[t[0]]) * rectangle[1], dv2 = (v[t[2]] - v[t[0]]) * rectangle[1];
    const auto [s_max, s_min] =
        internal::singular_values_2x2(du1 / l1, (du2 - du1 * x2 / l1) / y2, dv1 / l1, (dv2 - dv1 * x2 / l1) / y2);
    return s_min > 0 ? s_max / s_min : std::numeric_limits<double>::infinity();
  };
  // The triangles bent beyond the threshold (forced ones aside: flat in any
  // map), and the worst bend.
  std::vector<bool> thin(p.triangle.size());
  auto find_thin = [&]() {
    std::size_t count = 0;
    double worst = 0;
    for(std::size_t f = 0; f < p.triangle.size(); ++f) {
      const auto& t = p.triangle[f];
      thin[f] = false;
      if(p.forced[f]) continue;
      const double b = bend(t);
      worst = std::max(worst, b);
      thin[f] = b > options.max_angle_distortion;
      count += thin[f];
    }
    return std::make_pair(count, worst);
  };
  const bool near_folds = options.max_angle_distortion > 0;

  r.folded_faces = find_defects();
  if(r.folded_faces == 0 && border_ok && !(near_folds && find_thin().first > 0)) return Status();

  // 1. A side that does not run monotonically is re-spaced by arc length.
  auto respace = [&](const Walk& w) {
    const auto& side = *w.side;
    std::vector<double>& c = w.along_u ? u : v;
    const std::vector<double> arc = side_arc_lengths(w);
    const double total = arc.back();
    for(std::size_t k = 1; k + 1 < side.size(); ++k) {
      const double t = total > 0 ? arc[k] / total : double(k) / double(side.size() - 1);
      c[get(index, side[k])] = w.increasing ? t : 1. - t;
    }
  };
  for(const Walk& w : walks)
    if(!monotone(w)) respace(w);

  // Vertex adjacency for growing regions.
  p.ring.resize(n);
  for(const auto& t : p.triangle)
    for(int k = 0; k < 3; ++k) {
      p.ring[t[k]].push_back(t[(k + 1) % 3]);
      p.ring[t[k]].push_back(t[(k + 2) % 3]);
    }
  for(auto& nb : p.ring) {
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  }

  // The weights of a re-solved vertex: mean value weights (Floater 2003),
  // w_ij = (tan(a/2) + tan(b/2)) / |x_i - x_j| with a and b the 3D angles at
  // x_i next to edge ij. They follow the surface's shape (better angles than
  // Tutte's uniform weights) and are positive, which is all Floater's
  // embedding theorem needs. Uniform weights where an angle is undefined
  // (a zero-length edge). (Symmetrised mean value weights would allow a
  // Cholesky solve but measured worse angles: doc/quality.md.)
  std::vector<std::pair<std::size_t, double>> row;
  auto weights_of = [&](std::size_t i) {
    row.clear();
    for(std::size_t f : faces_of[i]) {
      const auto& t = p.triangle[f];
      const int k = t[0] == i ? 0 : (t[1] == i ? 1 : 2);
      const std::size_t a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      const auto ea = xyz[a] - xyz[i], eb = xyz[b] - xyz[i];
      const double la = std::sqrt(CGAL::to_double(ea * ea)), lb = std::sqrt(CGAL::to_double(eb * eb));
      const double half_tan =
          la > 0 && lb > 0 ? std::tan(std::acos(std::clamp(CGAL::to_double(ea * eb) / (la * lb), -1., 1.)) / 2) : 0.;
      if(!(half_tan > 0) || !std::isfinite(half_tan)) {
        row.clear();
        for(std::size_t g : faces_of[i])
          for(std::size_t j : p.triangle[g])
            if(j != i) row.emplace_back(j, 1.);
        return;
      }
      row.emplace_back(a, half_tan / la);
      row.emplace_back(b, half_tan / lb);
    }
  };

  // Re-solves the vertices flagged in `free_vertex` with every other vertex fixed.
  auto solve = [&](const std::vector<bool>& free_vertex) -> bool {
    std::vector<std::size_t> local_of(n, n);
    std::vector<std::size_t> unknowns;
    for(std::size_t i = 0; i < n; ++i)
      if(free_vertex[i]) {
        local_of[i] = unknowns.size();
        unknowns.push_back(i);
      }
    if(unknowns.empty()) return true;
    ++r.rounds;
    const auto m = static_cast<Eigen::Index>(unknowns.size());
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(m, 2);
    for(std::size_t li = 0; li < unknowns.size(); ++li) {
      const std::size_t i = unknowns[li];
      const auto row_index = static_cast<Eigen::Index>(li);
      weights_of(i);
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
  };

  // Marks in `into` the interior vertices within `steps` edges of `seeds`
  // (a border seed reaches out through its neighbours, other border vertices
  // stop the search) and returns how many `into` holds. A new search each
  // time, so that a region whose defects lie inside it still grows.
  auto grow = [&](const std::vector<std::size_t>& seeds, std::size_t steps, std::vector<bool>& into) {
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
        for(std::size_t j : p.ring[i])
          if(!reached[j]) {
            reached[j] = true;
            if(!p.side_mask[j]) next.push_back(j);
          }
      front.swap(next);
    }
    std::size_t size = 0;
    for(std::size_t i = 0; i < n; ++i) {
      if(reached[i] && !p.side_mask[i]) into[i] = true;
      size += into[i];
    }
    return size;
  };

  // 2. Local re-solves around the defects, rings doubling; the region only
  //    grows, and stops growing locally at a third of the patch.
  std::vector<bool> region(n, false);
  std::size_t rings = std::max<std::size_t>(options.initial_rings, 1);
  std::size_t defects = find_defects();
  // Folds over a tenth of the patch are not local: go straight to step 3.
  const std::size_t local_rounds = 10 * defects > p.triangle.size() ? 0 : options.max_local_rounds;
  for(std::size_t round = 0; defects > 0 && round < local_rounds; ++round, rings *= 2) {
    std::vector<std::size_t> seeds;
    for(std::size_t i = 0; i < n; ++i)
      if(bad_vertex[i]) seeds.push_back(i);
    for(std::size_t f = 0; f < p.triangle.size(); ++f)
      if(bad_face[f]) seeds.insert(seeds.end(), p.triangle[f].begin(), p.triangle[f].end());
    // The defects' own ring, then `rings` more.
    const std::size_t region_size = grow(seeds, rings + 1, region);
    if(3 * region_size > n || !solve(region)) break;
    defects = find_defects();
  }

  // 3. Last resort: every interior vertex.
  if(defects > 0) {
    r.whole_patch = true;
    std::vector<bool> interior(n);
    for(std::size_t i = 0; i < n; ++i) interior[i] = p.side_mask[i] == 0;
    if(solve(interior)) defects = find_defects();
  }
  r.remaining_folded_faces = defects;

  // 4. Near-folds, once the map is one-to-one. A side along which a bent
  //    triangle's edge is squeezed to under a quarter of its share of the
  //    side's arc length (the distance to the next side grows slowly along a
  //    side that meets it at a flat corner: cow's small quads) is re-spaced
  //    by arc length; the interior vertices around the bent triangles and
  //    next to re-spaced sides, 1, 2, 4 rings deep, are re-solved. A round is
  //    kept only if it folds nothing, keeps the sides monotone, and lowers
  //    the worst bend among the triangles it may change by over 0.1 %.
  if(defects == 0 && near_folds) {
    std::size_t count = find_thin().first;
    r.thin_faces = count;
    std::vector<bool> near(n, false);
    std::array<bool, 4> respaced{};
    std::size_t near_rings = 1;
    for(std::size_t round = 0; count > 0 && round < options.max_thin_rounds; ++round, near_rings *= 2) {
      std::vector<double> u_kept = u, v_kept = v;
      const std::vector<bool> near_kept = near;
      const std::array<bool, 4> respaced_kept = respaced;
      std::vector<std::size_t> seeds;
      for(std::size_t k = 0; k < 4; ++k) {
        const Walk& w = walks[k];
        if(respaced[k]) continue;
        const std::vector<double>& c = w.along_u ? u : v;
        const double length = side_arc_lengths(w).back();
        bool squeezed = false;
        for(std::size_t f = 0; f < p.triangle.size() && !squeezed; ++f) {
          if(!thin[f]) continue;
          const auto& t = p.triangle[f];
          for(int e = 0; e < 3 && !squeezed; ++e) {
            const std::size_t a = t[e], b = t[(e + 1) % 3];
            if(!(p.side_mask[a] & p.side_mask[b] & w.bit)) continue;
            const double along = std::sqrt(CGAL::to_double(CGAL::squared_distance(xyz[a], xyz[b])));
            squeezed = length > 0 && std::abs(c[a] - c[b]) < 0.25 * along / length;
          }
        }
        if(!squeezed) continue;
        respace(w);
        respaced[k] = true;
        for(vertex_descriptor vd : *w.side) seeds.push_back(get(index, vd));
      }
      for(std::size_t f = 0; f < p.triangle.size(); ++f)
        if(thin[f]) seeds.insert(seeds.end(), p.triangle[f].begin(), p.triangle[f].end());
      grow(seeds, near_rings, near);
      bool better = solve(near) && find_defects() == 0 && std::all_of(walks.begin(), walks.end(), monotone);
      if(better) {
        // The triangles this round may change (a re-solved vertex or one on a
        // re-spaced side: decided by the region, not by rounding), before and after.
        std::vector<bool> may_change(n);
        for(std::size_t i = 0; i < n; ++i) may_change[i] = near[i];
        for(std::size_t k = 0; k < 4; ++k)
          if(respaced[k])
            for(vertex_descriptor vd : *walks[k].side) may_change[get(index, vd)] = true;
        std::vector<std::size_t> changed;
        for(std::size_t f = 0; f < p.triangle.size(); ++f) {
          const auto& t = p.triangle[f];
          if(!p.forced[f] && std::any_of(t.begin(), t.end(), [&](std::size_t i) { return may_change[i]; }))
            changed.push_back(f);
        }
        auto worst_changed = [&]() {
          double b = 0;
          for(std::size_t f : changed) b = std::max(b, bend(p.triangle[f]));
          return b;
        };
        const double after = worst_changed();
        std::swap(u, u_kept);
        std::swap(v, v_kept);
        const double before = worst_changed();
        std::swap(u, u_kept);
        std::swap(v, v_kept);
        better = after < 0.999 * before;
        if(better) count = find_thin().first;
      }
      if(!better) {
        u = u_kept;
        v = v_kept;
        near = near_kept;
        respaced = respaced_kept;
        break;
      }
    }
    r.remaining_thin_faces = count;
  }
  write_back();
  if(r.remaining_folded_faces > 0)
    return Status(Status_code::not_injective, internal::count_text(r.remaining_folded_faces, "folded face remains", "folded faces remain"));
  return Status();
}

} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_REPAIR_FOLDS_H
