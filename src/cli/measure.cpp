// diffuv tool: `diffuv measure` — the distortion of an OBJ's texture charts,
// whoever made them (diffuv, Blender's Smart UV Project, xatlas ...).
#include "commands.h"

#include <diffuv/internal/message_text.h>

#include <diffuv/io/read_obj_charts.h>
#include <diffuv/metrics/distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace diffuv_cli {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Soup = CGAL::Surface_mesh<Kernel::Point_3>;
using diffuv::internal::count_text;

struct Measure_options {
  std::string obj;
  bool charts = false;
};

void run_measure(const Measure_options& options)
{
  const diffuv::Obj_charts obj = diffuv::read_obj_charts(options.obj);
  // Each chart as a soup of unwelded triangles: the measures need no
  // connectivity, and an atlas tool's charts need not be manifold.
  std::vector<std::vector<std::size_t>> triangles_of(obj.number_of_charts);
  for(std::size_t t = 0; t < obj.triangles.size(); ++t) triangles_of[obj.chart[t]].push_back(t);
  diffuv::Distortion_summary total;
  std::size_t not_injective = 0;
  if(options.charts)
    std::printf("%-6s %8s %7s %5s %8s %9s %9s %8s %9s %9s\n", "chart", "faces", "flipped", "degen", "overlaps",
                "angle_avg", "area_avg", "L2", "Linf", "injective");
  for(std::size_t c = 0; c < obj.number_of_charts; ++c) {
    Soup soup;
    std::vector<Kernel::Point_2> uv;
    std::vector<Soup::Face_index> faces;
    for(std::size_t t : triangles_of[c]) {
      std::array<Soup::Vertex_index, 3> v;
      for(int k = 0; k < 3; ++k) {
        const auto& p = obj.positions[obj.triangles[t][static_cast<std::size_t>(k)]];
        const auto& q = obj.texcoords[obj.triangle_uv[t][static_cast<std::size_t>(k)]];
        v[static_cast<std::size_t>(k)] = soup.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
        uv.emplace_back(q[0], q[1]);
      }
      faces.push_back(soup.add_face(v[0], v[1], v[2]));
    }
    const auto d = diffuv::measure_distortion(soup, soup.points(), faces,
                                              boost::make_iterator_property_map(uv.begin(), get(boost::vertex_index, soup)));
    if(!d.injective()) ++not_injective;
    if(options.charts)
      std::printf("%-6zu %8zu %7zu %5zu %8zu %9.4f %9.4f %8.4g %9.4g %9s\n", c, d.faces, d.flipped, d.degenerate,
                  d.overlapping_pairs, d.angle_mean, d.area_mean, d.stretch_l2, d.stretch_linf, d.injective() ? "yes" : "no");
    total = diffuv::combined(total, d);
  }
  std::cout << "diffuv measure " << options.obj << ": " << count_text(obj.positions.size(), "vertex", "vertices") << ", "
            << count_text(total.faces, "textured triangle") << " in " << count_text(obj.number_of_charts, "chart");
  if(obj.faces_without_uv > 0) std::cout << " (" << count_text(obj.faces_without_uv, "face") << " without vt)";
  std::cout << '\n';
  std::printf("%-8s %12s %7s %5s %8s %9s %9s %8s %9s\n", "charts", "not_1-to-1", "flipped", "degen", "overlaps",
              "angle_avg", "area_avg", "L2", "Linf");
  std::printf("%-8zu %12zu %7zu %5zu %8zu %9.4f %9.4f %8.4g %9.4g\n", obj.number_of_charts, not_injective, total.flipped,
              total.degenerate, total.overlapping_pairs, total.angle_mean, total.area_mean, total.stretch_l2,
              total.stretch_linf);
}

} // namespace

void add_measure_command(CLI::App& app)
{
  auto options = std::make_shared<Measure_options>();
  CLI::App* cmd = app.add_subcommand(
      "measure", "Measure the texture charts of an OBJ file (any tool's): flips, overlaps, angle, area and stretch "
                 "distortion, chart by chart, weighted by 3D area");
  cmd->add_option("obj", options->obj, "OBJ file with texture coordinates (f v/vt ...)")->required();
  cmd->add_flag("--charts", options->charts, "Also print one line per chart");
  cmd->footer("A chart is a set of faces joined across edges whose two corners share their vt (and their g/o group). "
              "Means are weighted by 3D area, each chart normalised by its own areas (1 = isometric up to scale); "
              "overlaps are counted within charts.\nExit codes: 0 ok, 1 bad input, 2 bad command line.");
  cmd->callback([options]() { run_measure(*options); });
}

} // namespace diffuv_cli
