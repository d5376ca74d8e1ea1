// diffuv tool: `diffuv measure` — the distortion of an OBJ's texture charts,
// whoever made them (diffuv, Blender's Smart UV Project, xatlas ...).
#include "commands.h"
#include "inputs.h"
#include "table.h"

#include <diffuv/internal/message_text.h>

#include <diffuv/io/read_obj_charts.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/metrics/texture_use.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <cmath>
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
  int texture_size = 1024;
};

void run_measure(const Measure_options& options)
{
  std::string extension = std::filesystem::path(options.obj).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if(extension != ".obj")
    throw diffuv::Input_error(options.obj, 0,
                              "diffuv measure reads OBJ files with texture coordinates (f v/vt ...), not " +
                                  (extension.empty() ? std::string("a file without extension")
                                                     : "\"" + extension + "\" files"));
  const diffuv::Obj_charts obj = diffuv::read_obj_charts(options.obj);
  // Each chart as a soup of unwelded triangles: the measures need no
  // connectivity, and an atlas tool's charts need not be manifold.
  std::vector<std::vector<std::size_t>> triangles_of(obj.number_of_charts);
  for(std::size_t t = 0; t < obj.triangles.size(); ++t) triangles_of[obj.chart[t]].push_back(t);
  diffuv::Distortion_summary total;
  std::size_t not_injective = 0;
  Table charts({{"chart", 6, Table::left},     {"faces", 8, Table::right},    {"flipped", 7, Table::right},
                {"degen", 5, Table::right},    {"overlaps", 8, Table::right}, {"angle_avg", 9, Table::right},
                {"area_avg", 9, Table::right}, {"L2", 8, Table::right},       {"Linf", 9, Table::right},
                {"injective", 9, Table::right}});
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
    charts.add_row({std::to_string(c), std::to_string(d.faces), std::to_string(d.flipped), std::to_string(d.degenerate),
                    std::to_string(d.overlapping_pairs), formatted("%.4f", d.angle_mean), formatted("%.4f", d.area_mean),
                    formatted("%.4g", d.stretch_l2), formatted("%.4g", d.stretch_linf), d.injective() ? "yes" : "no"});
    total = diffuv::combined(total, d);
  }
  if(options.charts) std::cout << charts.text();
  // How the atlas uses a texture of --texture-size texels.
  std::vector<diffuv::Uv_triangle_in_chart> in_texture(obj.triangles.size());
  for(std::size_t t = 0; t < obj.triangles.size(); ++t) {
    std::array<Kernel::Point_3, 3> p;
    for(std::size_t k = 0; k < 3; ++k) {
      const auto& x = obj.positions[obj.triangles[t][k]];
      p[k] = Kernel::Point_3(x[0], x[1], x[2]);
      in_texture[t].uv[k] = obj.texcoords[obj.triangle_uv[t][k]];
    }
    in_texture[t].area_3d = std::sqrt(CGAL::to_double(CGAL::squared_area(p[0], p[1], p[2])));
    in_texture[t].chart = obj.chart[t];
  }
  const diffuv::Texture_use use = diffuv::measure_texture_use(in_texture, options.texture_size);
  std::size_t outside = 0;
  for(const auto& q : obj.texcoords) outside += !(q[0] >= 0 && q[0] <= 1 && q[1] >= 0 && q[1] <= 1);
  if(outside > 0)
    std::cerr << "warning: " << count_text(outside, "texture coordinate") << " of " << obj.texcoords.size()
              << " lie outside [0,1]: texels% and shared% count only what lies in the texture's square\n";
  std::cout << "diffuv measure " << options.obj << ": " << count_text(obj.positions.size(), "vertex", "vertices") << ", "
            << count_text(total.faces, "textured triangle") << " in " << count_text(obj.number_of_charts, "chart");
  if(obj.faces_without_uv > 0) std::cout << " (" << count_text(obj.faces_without_uv, "face") << " without vt)";
  std::cout << '\n';
  Table summary({{"charts", 8, Table::left},     {"not_1-to-1", 12, Table::right}, {"flipped", 7, Table::right},
                 {"degen", 5, Table::right},     {"overlaps", 8, Table::right},    {"angle_avg", 9, Table::right},
                 {"area_avg", 9, Table::right},  {"L2", 8, Table::right},          {"Linf", 9, Table::right},
                 {"texels%", 8, Table::right},   {"shared%", 8, Table::right},     {"density_10%", 11, Table::right}});
  summary.add_row({std::to_string(obj.number_of_charts), std::to_string(not_injective), std::to_string(total.flipped),
                   std::to_string(total.degenerate), std::to_string(total.overlapping_pairs),
                   formatted("%.4f", total.angle_mean), formatted("%.4f", total.area_mean),
                   formatted("%.4g", total.stretch_l2), formatted("%.4g", total.stretch_linf),
                   formatted("%.2f", 100. * use.covered), formatted("%.2f", 100. * use.shared),
                   formatted("%.2f", 100. * use.within_10_percent)});
  std::cout << summary.text();
  std::cout << "texture " << use.resolution << " x " << use.resolution << ": "
            << formatted("%.1f", 100. * use.covered) << " % of the texels in a chart, "
            << formatted("%.2f", 100. * use.shared) << " % in two charts or more; texel density "
            << formatted("%.4g", use.density_median) << " texels per unit of length (median by area), "
            << formatted("%.1f", 100. * use.within_10_percent) << " % of the area within 10 % of it, charts from "
            << formatted("%.3g", use.lowest) << " to " << formatted("%.3g", use.highest) << " times it\n";
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
  cmd->add_option("--texture-size", options->texture_size,
                  "Texels per side of the texture the atlas is measured on (texels%, shared%: texels whose centre "
                  "lies in a chart, in two charts; 4 bytes of memory per texel)")
      ->check(number_in(16, 8192))
      ->capture_default_str();
  cmd->footer("A chart is a set of faces joined across edges whose two corners share their vt (and their g/o group). "
              "Means are weighted by 3D area, each chart normalised by its own areas (1 = isometric up to scale); "
              "overlaps are counted within charts. texels%: the share of the texture's texels whose centre lies in a chart; "
              "shared%: in two charts or more; density_10%: the share of the 3D area in charts whose texel density "
              "(sqrt of texels over 3D area) is within 10 % of the median.\nExit codes: 0 ok, 1 bad input, 2 bad command line.");
  cmd->callback([options]() { run_measure(*options); });
}

} // namespace diffuv_cli
