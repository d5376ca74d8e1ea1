// diffuv correspondence bench, --self-check: the local exact geodesics
// (Geodesic_distance) against CGAL's Surface_mesh_shortest_path on the whole
// mesh, on random pairs of points and on every vertex located in two faces.
#include "correspondence/correspondence_bench.h"

#include "correspondence/geodesic_distance.h"

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <iostream>
#include <random>

namespace diffuv_bench {

bool self_check(const std::string& path)
{
  Mesh m;
  read_named_mesh(path, m);
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
      local_ms += ms_since(t0);
      t0 = Clock::now();
      const double whole = geodesic.whole_mesh(p, q);
      whole_ms += ms_since(t0);
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

} // namespace diffuv_bench
