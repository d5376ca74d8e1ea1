// diffuv: make a patch's (u,v) map one-to-one while keeping the diffusion
// coordinates wherever they are already valid.
//
// The paper's distance ratio folds where distance isolines bend around
// singularities or follow the tessellation (doc/quality.md). Repair:
//  1. each side of the border must run monotonically along its edge of the
//     square; a side that does not is re-spaced by arc length (CGAL's
//     Square_border_arc_length_parameterizer_3 does the same for every side);
//  2. an interior vertex of a folded triangle (flipped or degenerate, or
//     around a vertex the map winds around twice) that has a place from which
//     all its triangles turn counter-clockwise (its link's kernel) moves to
//     that place's centroid, alone, unless that bends a triangle beyond the
//     near-fold limit below; the interior vertices of the folds that
//     are left, grown by rings, are re-solved as a
//     convex-combination map (mean value weights, Floater 2003) with every
//     other vertex fixed; the region grows until no fold remains;
//  3. as a last resort every interior vertex is re-solved: with the border on
//     the convex square and positive weights, Tutte/Floater's theorem makes
//     that map an embedding. Triangles whose three vertices lie on one side
//     are flat in any map onto the square, and so are the triangles around a
//     group of interior vertices whose border neighbours all lie on one side;
//     they are the flat triangles, reported.
// Then the near-folds: a triangle that the map bends far more than any
// shape needs (sigma_max / sigma_min of its Jacobian on the chart's rectangle
// above `max_angle_distortion`) is one step from a fold: a vertex almost on
// the line of its opposite edge, or two border vertices squeezed together
// on a side. Squeezed sides are re-spaced by arc length and the interior
// around the bent triangles is re-solved the same way, each round kept only
// if it folds nothing and bends the triangles it changed less (a single such
// triangle can dominate a chart's stretch: doc/layout.md).
#ifndef DIFFUV_PARAMETERIZATION_REPAIR_FOLDS_H
#define DIFFUV_PARAMETERIZATION_REPAIR_FOLDS_H

#include <diffuv/core/error.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/core/four_sides.h>
#include <diffuv/parameterization/chart_rectangle.h>
#include <diffuv/parameterization/internal/repair_patch.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace diffuv {

/// How `repair_folds()` works. (A new field must join `operator==` below:
/// `Known_charts` takes a map only for equal options.)
struct Repair_options {
  bool enabled = true;            ///< false keeps the raw diffusion coordinates (the paper's method)
  /// Rings of vertices added around the first folds' own ring (0: the folds'
  /// vertices and their neighbours only; then 1, 2, 4, ... rings).
  std::size_t initial_rings = 0;
  std::size_t max_local_rounds = 7;  ///< local re-solves (rings doubling) before the whole patch is re-solved
  /// A patch of more faces whose folds cover over a tenth of it is re-solved
  /// whole at once: local re-solves fail there and cost 4-8x the one solve
  /// (lion-head, doc/quality.md). A smaller patch tries local re-solves first.
  std::size_t whole_patch_faces = 2000;
  /// A triangle bent by more than this (sigma_max / sigma_min of the map on the
  /// chart's rectangle, 1 = shape kept) is re-solved like a fold if that helps
  /// (doc/quality.md); 0 turns the near-fold pass off.
  double max_angle_distortion = 20;
  std::size_t max_thin_rounds = 3;  ///< near-fold re-solves (rings doubling)
  /// Sweeps moving the folds' own vertices into the kernels of their links
  /// before any re-solve, so that fewer vertices leave the diffusion map
  /// (same layouts: cow 10.2 -> 8.3 % moved, bull 11.9 -> 8.5 %, L2 within
  /// 0.01: doc/layout.md); 0: none.
  std::size_t kernel_sweeps = 4;
};

/// Whether two sets of options repair alike (every field; keep in step with them).
inline bool operator==(const Repair_options& a, const Repair_options& b)
{
  return a.enabled == b.enabled && a.initial_rings == b.initial_rings && a.max_local_rounds == b.max_local_rounds &&
         a.whole_patch_faces == b.whole_patch_faces && a.max_angle_distortion == b.max_angle_distortion &&
         a.max_thin_rounds == b.max_thin_rounds && a.kernel_sweeps == b.kernel_sweeps;
}
inline bool operator!=(const Repair_options& a, const Repair_options& b) { return !(a == b); }

/// What `repair_folds()` did to one patch (all zero when the repair is off).
struct Repair_report {
  std::size_t folded_faces = 0;        ///< faces flipped or degenerate, or around a vertex the map winds around twice, before the repair (flat ones excluded)
  std::size_t flat_triangles = 0;   ///< faces with all three vertices on one side, or around interior vertices whose border neighbours all are: flat in any map onto the square
  std::size_t moved_vertices = 0;      ///< interior vertices whose (u,v) changed
  std::size_t moved_border_vertices = 0;  ///< border vertices re-spaced because their side was not monotone, or was squeezed at a near-fold
  std::size_t rounds = 0;              ///< linear solves
  bool whole_patch = false;            ///< whether the last resort (every interior vertex re-solved) was needed
  std::size_t remaining_folded_faces = 0;  ///< folds left (0 unless the last resort met a numerical limit)
  std::size_t thin_faces = 0;          ///< faces bent beyond `max_angle_distortion` once the folds were repaired (flat ones excluded)
  std::size_t remaining_thin_faces = 0;  ///< of those, the ones the near-fold pass left bent beyond it
};

/// Repairs the folds of a disc patch's (u,v) map in place.
///
/// \tparam TriangleMesh a model of `FaceListGraph` with an internal vertex index
///         (`CGAL::Surface_mesh`, a `CGAL::Face_filtered_graph` patch, ...)
/// \param tm the patch (a disc), \param vpm its 3D points (for the weights and arc lengths)
/// \param sides the four sides used for `uv`; border vertices are fixed on them
/// \param uv read-write map from vertices to 2D points, initially the diffusion coordinates
/// \returns `ok`, or `not_injective` (detail: how many folds remain) if folds
///          survive even the last resort (only with numerically degenerate input)
/// \throws std::out_of_range, when the repair is enabled, if a side vertex's
///         index is not below `num_vertices(tm)` (not a vertex of the patch);
///         `uv` is then unchanged
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
  internal::check_side_vertices(sides, index, n, "repair_folds");
  internal::Repair_patch<TriangleMesh, Point_3> p;
  p.vertex.resize(n);
  p.xyz.resize(n);
  p.u.resize(n);
  p.v.resize(n);
  p.side_mask.assign(n, 0);
  for(vertex_descriptor vd : vertices(tm)) {
    const std::size_t i = get(index, vd);
    p.vertex[i] = vd;
    p.xyz[i] = get(vpm, vd);
    const auto q = get(uv, vd);
    p.u[i] = CGAL::to_double(q.x());
    p.v[i] = CGAL::to_double(q.y());
  }
  for(Side s : all_sides)
    for(vertex_descriptor vd : sides[s]) p.side_mask[get(index, vd)] |= static_cast<std::uint8_t>(1u << static_cast<int>(s));
  p.triangle.reserve(num_faces(tm));
  p.flat.reserve(num_faces(tm));
  for(auto f : faces(tm)) {
    std::array<std::size_t, 3> t{};
    std::size_t k = 0;
    for(vertex_descriptor vd : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      if(k < 3) t[k] = get(index, vd);
      ++k;
    }
    if(k != 3) return Status(Status_code::not_triangle_mesh, "a face of the patch has " + std::to_string(k) + " vertices");
    p.flat.push_back((p.side_mask[t[0]] & p.side_mask[t[1]] & p.side_mask[t[2]]) != 0);
    p.triangle.push_back(t);
  }
  p.mark_flat_interior_groups();
  r.flat_triangles = static_cast<std::size_t>(std::count(p.flat.begin(), p.flat.end(), true));

  std::array<internal::Side_walk, 4> walks;
  const std::array<Side, 4> walk_order = {Side::v1, Side::u2, Side::v2, Side::u1};
  for(std::size_t k = 0; k < 4; ++k) {
    const Side s = walk_order[k];
    for(vertex_descriptor vd : sides[s]) walks[k].vertices.push_back(get(index, vd));
    walks[k].along_u = s == Side::v1 || s == Side::v2;
    walks[k].increasing = s == Side::v1 || s == Side::u2;
    walks[k].bit = static_cast<std::uint8_t>(1u << static_cast<int>(s));
  }
  auto sides_monotone = [&] { return std::all_of(walks.begin(), walks.end(), [&](const auto& w) { return w.monotone(p); }); };

  // The common case costs two linear passes: no local defect and monotone
  // sides prove the map one-to-one, no overlap test needed.
  const bool border_ok = sides_monotone();
  p.rectangle = side_length_rectangle(sides, vpm);
  const bool near_folds = options.max_angle_distortion > 0;
  r.folded_faces = p.find_defects();
  if(r.folded_faces == 0 && border_ok && !(near_folds && p.find_thin(options.max_angle_distortion).first > 0)) return Status();

  // There is something to repair: the faces around each vertex, which the
  // kernel moves and the region growth walk.
  p.find_faces_of();
  // Nothing has moved yet: the map as it came, to count what the repair moves.
  const std::vector<double> u0 = p.u, v0 = p.v;
  auto write_back = [&]() {
    std::size_t moved = 0, moved_border = 0;
    for(std::size_t i = 0; i < n; ++i) {
      if(p.u[i] == u0[i] && p.v[i] == v0[i]) continue;
      (p.side_mask[i] ? moved_border : moved) += 1;
      put(uv, p.vertex[i], Point_2(p.u[i], p.v[i]));
    }
    r.moved_vertices = moved;
    r.moved_border_vertices = moved_border;
    r.rounds = p.solves;
  };

  // 1. A side that does not run monotonically is re-spaced by arc length.
  for(const auto& w : walks)
    if(!w.monotone(p)) w.respace(p);
  p.find_rings();

  // 2. Local re-solves around the defects, rings doubling; the region only
  //    grows, and stops growing locally at a third of the patch.
  std::vector<bool> region(n, false);
  std::size_t rings = options.initial_rings;
  std::size_t defects = p.find_defects();
  if(defects > 0 && options.kernel_sweeps > 0) {
    p.move_into_kernels(options.kernel_sweeps, 1e-12, options.max_angle_distortion);
    defects = p.find_defects();
  }
  // Folds over a tenth of a large patch are not local: go straight to step 3.
  // On small patches (the layout's) local rounds still move fewer vertices.
  const bool not_local = p.triangle.size() > options.whole_patch_faces && 10 * defects > p.triangle.size();
  const std::size_t local_rounds = not_local ? 0 : options.max_local_rounds;
  for(std::size_t round = 0; defects > 0 && round < local_rounds; ++round, rings = std::max<std::size_t>(1, 2 * rings)) {
    std::vector<std::size_t> seeds;
    for(std::size_t i = 0; i < n; ++i)
      if(p.bad_vertex[i]) seeds.push_back(i);
    for(std::size_t f = 0; f < p.triangle.size(); ++f)
      if(p.bad_face[f]) seeds.insert(seeds.end(), p.triangle[f].begin(), p.triangle[f].end());
    // The defects' own ring, then `rings` more.
    const std::size_t region_size = p.grow(seeds, rings + 1, region);
    if(3 * region_size > n || !p.solve(region)) break;
    defects = p.find_defects();
  }

  // 3. Last resort: every interior vertex.
  if(defects > 0) {
    r.whole_patch = true;
    std::vector<bool> interior(n);
    for(std::size_t i = 0; i < n; ++i) interior[i] = p.side_mask[i] == 0;
    if(p.solve(interior)) defects = p.find_defects();
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
    std::size_t count = p.find_thin(options.max_angle_distortion).first;
    r.thin_faces = count;
    std::vector<bool> near(n, false);
    std::array<bool, 4> respaced{};
    std::size_t near_rings = 1;
    for(std::size_t round = 0; count > 0 && round < options.max_thin_rounds; ++round, near_rings *= 2) {
      std::vector<double> u_kept = p.u, v_kept = p.v;
      const std::vector<bool> near_kept = near;
      const std::array<bool, 4> respaced_kept = respaced;
      std::vector<std::size_t> seeds;
      for(std::size_t k = 0; k < 4; ++k) {
        const auto& w = walks[k];
        if(respaced[k]) continue;
        const std::vector<double>& c = w.along_u ? p.u : p.v;
        const double length = w.arc_lengths(p).back();
        bool squeezed = false;
        for(std::size_t f = 0; f < p.triangle.size() && !squeezed; ++f) {
          if(!p.thin[f]) continue;
          const auto& t = p.triangle[f];
          for(int e = 0; e < 3 && !squeezed; ++e) {
            const std::size_t a = t[e], b = t[(e + 1) % 3];
            if(!(p.side_mask[a] & p.side_mask[b] & w.bit)) continue;
            const double along = std::sqrt(CGAL::to_double(CGAL::squared_distance(p.xyz[a], p.xyz[b])));
            squeezed = length > 0 && std::abs(c[a] - c[b]) < 0.25 * along / length;
          }
        }
        if(!squeezed) continue;
        w.respace(p);
        respaced[k] = true;
        seeds.insert(seeds.end(), w.vertices.begin(), w.vertices.end());
      }
      for(std::size_t f = 0; f < p.triangle.size(); ++f)
        if(p.thin[f]) seeds.insert(seeds.end(), p.triangle[f].begin(), p.triangle[f].end());
      p.grow(seeds, near_rings, near);
      bool better = p.solve(near) && p.find_defects() == 0 && sides_monotone();
      if(better) {
        // The triangles this round may change (a re-solved vertex or one on a
        // re-spaced side: decided by the region, not by rounding), before and after.
        std::vector<bool> may_change(n);
        for(std::size_t i = 0; i < n; ++i) may_change[i] = near[i];
        for(std::size_t k = 0; k < 4; ++k)
          if(respaced[k])
            for(std::size_t i : walks[k].vertices) may_change[i] = true;
        std::vector<std::size_t> changed;
        for(std::size_t f = 0; f < p.triangle.size(); ++f) {
          const auto& t = p.triangle[f];
          if(!p.flat[f] && std::any_of(t.begin(), t.end(), [&](std::size_t i) { return may_change[i]; }))
            changed.push_back(f);
        }
        auto worst_changed = [&]() {
          double b = 0;
          for(std::size_t f : changed) b = std::max(b, p.bend(p.triangle[f]));
          return b;
        };
        const double after = worst_changed();
        std::swap(p.u, u_kept);
        std::swap(p.v, v_kept);
        const double before = worst_changed();
        std::swap(p.u, u_kept);
        std::swap(p.v, v_kept);
        better = after < 0.999 * before;
        if(better) count = p.find_thin(options.max_angle_distortion).first;
      }
      if(!better) {
        p.u = u_kept;
        p.v = v_kept;
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
