// diffuv tool: `diffuv compare` — diffuv and CGAL's parameterizers on the same
// patches with the same corners, measured by the same metrics.
#include "commands.h"
#include "inputs.h"
#include "table.h"

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/cgal/Diffusion_parameterizer_3.h>
#include "compare/cgal_parameterizers.h"
#include <diffuv/io/atomic_file.h>
#include <diffuv/io/selection_file.h>
#include <diffuv/output/write_obj.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/diffusion_coordinates.h>
#include <diffuv/parameterization/repair_folds.h>
#include <diffuv/patches/disc_topology.h>
#include <diffuv/patches/region_sides.h>

#include <CGAL/boost/graph/Face_filtered_graph.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace diffuv_cli {
namespace {

using vertex_descriptor = Mesh::Vertex_index;
using face_descriptor = Mesh::Face_index;
using Point_2 = Kernel::Point_2;
using Patch = CGAL::Face_filtered_graph<Mesh>;

struct Compare_options {
  std::string mesh;
  std::string corners;
  std::string methods = "diffuv,tutte,mean_value,authalic,conformal,lscm,arap";
  std::string output;
  std::string distance = "fmm";
  bool no_repair = false;
  int runs = 5;
  Patch_cli_options patches;
};

// One method of the table: diffuv with a distance and repair on or off, or one of CGAL's.
struct Method {
  std::string name;
  bool is_diffuv = false;
  std::string distance;  // diffuv: graph, fmm or exact
  bool repair = true;    // diffuv
  diffuv::Cgal_method cgal = diffuv::Cgal_method::tutte;
};

// diffuv           the defaults of --distance and --no-repair
// diffuv-D         distance D (graph, fmm, exact), repaired
// diffuv-D-raw     distance D, not repaired (diffuv-graph-raw: the paper's method)
// tutte, mean_value, authalic, conformal, lscm, arap: CGAL's
std::vector<Method> parse_methods(const Compare_options& o)
{
  std::vector<Method> methods;
  for(const std::string& name : split_list(o.methods)) {
    Method m;
    m.name = name;
    if(name == "diffuv") {
      m.is_diffuv = true;
      m.distance = o.distance;
      m.repair = !o.no_repair;
    } else if(name.rfind("diffuv-", 0) == 0) {
      std::string rest = name.substr(7);
      m.is_diffuv = true;
      if(rest.size() > 4 && rest.compare(rest.size() - 4, 4, "-raw") == 0) {
        m.repair = false;
        rest.resize(rest.size() - 4);
      }
      if(rest != "graph" && rest != "fmm" && rest != "exact")
        throw CLI::ValidationError("--methods", "unknown diffuv distance in '" + name + "' (graph, fmm or exact)");
      m.distance = rest;
    } else if(const auto cgal = diffuv::cgal_method_from_name(name)) {
      m.cgal = *cgal;
    } else {
      throw CLI::ValidationError("--methods", "unknown method '" + name +
                                                  "' (diffuv, diffuv-graph|fmm|exact[-raw], tutte, mean_value, "
                                                  "authalic, conformal, lscm, arap)");
    }
    if(std::any_of(methods.begin(), methods.end(), [&](const Method& other) { return other.name == name; }))
      throw CLI::ValidationError("--methods", "'" + name + "' is listed twice");
    methods.push_back(m);
  }
  if(methods.empty()) throw CLI::ValidationError("--methods", "no method given");
  return methods;
}

// What one method did on every patch.
struct Method_result {
  std::unique_ptr<diffuv::Uv_atlas<Mesh>> atlas;
  double milliseconds = 0;  // sum over patches of the median over runs
  std::size_t failed = 0;   // patches without a map
  std::string first_failure;
  diffuv::Distortion_summary total;
  std::size_t moved = 0;    // diffuv: vertices moved by the repair
};

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// diffuv on one patch, timed like CGAL's parameterize(): the four distance
// runs, the ratios and the repair (the corners are given to both).
template <class Tag>
std::optional<std::vector<Point_2>> diffuv_patch(const Mesh& mesh, const Patch& patch,
                                                 const diffuv::Four_sides<vertex_descriptor>& sides, bool repair,
                                                 int runs, double& ms, diffuv::Repair_report& report, std::string& why)
{
  const auto lengths = diffuv::edge_length_map(mesh);
  auto pindex = get(boost::vertex_index, patch);
  std::vector<Point_2> uv(num_vertices(patch));
  std::vector<double> times;
  diffuv::Repair_options options;
  options.enabled = repair;
  for(int run = 0; run < runs; ++run) {
    const auto start = std::chrono::steady_clock::now();
    diffuv::Diffusion_coordinates<Patch, Tag> coordinates(patch);
    diffuv::Status status = coordinates.compute(sides, lengths, boost::make_iterator_property_map(uv.begin(), pindex));
    if(status)
      diffuv::repair_folds(patch, mesh.points(), sides, boost::make_iterator_property_map(uv.begin(), pindex), options,
                           &report);
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    if(!status) {
      why = status.what();
      return std::nullopt;
    }
  }
  ms = median(times);
  return uv;
}

void run_compare(const Compare_options& options)
{
  const std::vector<Method> methods = parse_methods(options);
  check_patch_options(options.patches);
  if(!options.corners.empty() && !options.patches.labels.empty())
    throw CLI::ValidationError("--corners", "applies to a disc mesh without --labels");
  if(!options.corners.empty() && options.patches.patches > 0)
    throw CLI::ValidationError("--corners", "maps the disc as one patch: --patches does not apply");
  const std::string mesh_path = options.mesh.empty() ? default_mesh("nefertiti.off") : options.mesh;
  const Input_mesh in = read_input(mesh_path, options.patches);
  const Mesh& mesh = in.mesh;

  // The patches and their sides: one patch with the given corners, or the
  // patches and canonical sides that `diffuv param` uses.
  diffuv::Segmentation<Mesh> seg;
  std::vector<diffuv::Four_sides<vertex_descriptor>> sides;
  std::vector<diffuv::Status> patch_status;
  std::size_t flat_triangles_handed = 0;  // faces flat on one side of their patch, handed to a neighbour
  if(!options.corners.empty()) {
    const auto corners =
        selected_vertices(in, options.corners);
    diffuv::Status status = diffuv::check_disc(mesh);
    if(!status) throw diffuv::Input_error(in.path, 0, status.what());
    const auto loop = diffuv::counterclockwise_boundary(mesh, diffuv::boundary_loops(mesh).front());
    sides.emplace_back();
    status = diffuv::sides_from_corners(loop, corners, sides.back());
    if(!status) throw diffuv::Input_error(options.corners, 1, status.what());
    seg.face_patch.assign(num_faces(mesh), 0);
    seg.patch_label = {0};
    seg.patch_part = {0};
    seg.patch_faces = {std::vector<face_descriptor>(faces(mesh).begin(), faces(mesh).end())};
    patch_status.push_back(status);
  } else {
    diffuv::Patching_report report;
    seg = make_patches(in, options.patches, report);
    flat_triangles_handed = report.flat_triangles_handed;
    sides.resize(seg.number_of_patches());
    for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
      diffuv::Status status = diffuv::check_patch_disc(mesh, seg, p);
      if(status) status = diffuv::region_sides(mesh, mesh.points(), seg, p, sides[p]);
      patch_status.push_back(status);
    }
  }

  std::vector<Method_result> results(methods.size());
  std::vector<Point_2> uv_of(num_vertices(mesh));  // by mesh vertex, reused patch after patch
  auto uv_map = boost::make_iterator_property_map(uv_of.begin(), get(boost::vertex_index, mesh));
  for(std::size_t k = 0; k < methods.size(); ++k) {
    const Method& method = methods[k];
    Method_result& r = results[k];
    r.atlas = std::make_unique<diffuv::Uv_atlas<Mesh>>(mesh);
    for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
      std::vector<vertex_descriptor> chart_vertices;
      std::vector<Point_2> chart_uv;
      double ms = 0;
      std::string why;
      if(!patch_status[p]) {
        why = patch_status[p].what();
      } else if(method.is_diffuv) {
        const Patch patch(mesh, seg.patch_faces[p]);
        diffuv::Repair_report report;
        std::optional<std::vector<Point_2>> uv;
        auto run = [&](auto tag) {
          return diffuv_patch<decltype(tag)>(mesh, patch, sides[p], method.repair, options.runs, ms, report, why);
        };
        if(method.distance == "graph") uv = run(diffuv::Graph_distance_tag());
        else if(method.distance == "exact") uv = run(diffuv::Exact_distance_tag());
        else uv = run(diffuv::Fmm_distance_tag());
        if(uv) {
          chart_vertices.resize(num_vertices(patch));
          const auto pindex = get(boost::vertex_index, patch);  // the patch's own 0..n-1 indices
          for(vertex_descriptor v : vertices(patch)) chart_vertices[get(pindex, v)] = v;
          chart_uv = std::move(*uv);
          r.moved += report.moved_vertices + report.moved_border_vertices;
        }
      } else {
        const auto& s = sides[p];
        std::vector<double> times;
        for(int run = 0; run < options.runs; ++run) {
          const auto map = diffuv::cgal_parameterize_patch(mesh, seg.patch_faces[p], mesh.points(), s.corners,
                                                           method.cgal, uv_map);
          if(!map.ok()) {
            why = std::string("CGAL: ") + diffuv::cgal_error_message(map.error);
            break;
          }
          times.push_back(map.milliseconds);
          if(run + 1 == options.runs) {
            chart_vertices = map.vertices;
            chart_uv = map.uv;
          }
        }
        if(why.empty()) ms = median(times);
      }
      if(chart_vertices.empty()) {
        if(r.failed++ == 0) r.first_failure = why.rfind("patch ", 0) == 0 ? why : "patch " + std::to_string(p) + ": " + why;
        continue;
      }
      r.milliseconds += ms;
      for(std::size_t i = 0; i < chart_vertices.size(); ++i) uv_of[chart_vertices[i].idx()] = chart_uv[i];
      r.total = diffuv::combined(r.total, diffuv::measure_distortion(mesh, mesh.points(), seg.patch_faces[p], uv_map));
      r.atlas->add_chart(seg.patch_faces[p], std::move(chart_vertices), std::move(chart_uv));
    }
  }

  // Nothing mapped at all: an error, as for diffuv param (and nothing is written).
  if(std::all_of(results.begin(), results.end(), [&](const Method_result& r) { return r.failed == seg.number_of_patches(); }))
    throw diffuv::Input_error(in.labels_path.empty() ? in.path : in.labels_path, 0,
                              "no method could map any patch; the first reason: " + results.front().first_failure);

  // Everything is computed before anything is written: all files or none.
  if(!options.output.empty()) {
    diffuv::Output_folder out(options.output, {in.path, options.corners, options.patches.labels});
    for(std::size_t k = 0; k < methods.size(); ++k)
      diffuv::write_obj(out.open(output_name(in.path, "." + methods[k].name + ".obj")), mesh, mesh.points(),
                        results[k].atlas->corner_uv_map());
    out.commit();
  }

  std::cout << "diffuv compare " << in.path << ": " << count_text(num_vertices(mesh), "vertex", "vertices") << ", "
            << count_text(num_faces(mesh), "face") << ", " << count_text(seg.number_of_patches(), "patch", "patches")
            << (options.corners.empty() ? "" : " (corners from " + options.corners + ")") << "; median of "
            << count_text(static_cast<std::size_t>(options.runs), "run") << ", times summed over patches";
  if(flat_triangles_handed) std::cout << "; " << flat_triangles_handed_clause(flat_triangles_handed);
  std::cout << "\n";
  if(const std::string repaired = repair_line(in); !repaired.empty()) std::cout << repaired << '\n';
  Table table({{"method", 18, Table::left},    {"time_ms", 10, Table::right},  {"failed", 7, Table::right},
               {"flipped", 7, Table::right},    {"degen", 5, Table::right},     {"overlaps", 8, Table::right},
               {"angle_avg", 9, Table::right},  {"angle_max", 9, Table::right}, {"area_avg", 9, Table::right},
               {"area_max", 9, Table::right},   {"L2", 8, Table::right},        {"moved", 9, Table::right},
               {"1-to-1", 7, Table::right}});
  for(std::size_t k = 0; k < methods.size(); ++k) {
    const Method_result& r = results[k];
    const diffuv::Distortion_summary& d = r.total;
    const bool one_to_one = r.failed == 0 && d.injective();
    table.add_row({methods[k].name, formatted("%.3f", r.milliseconds), std::to_string(r.failed),
                   std::to_string(d.flipped), std::to_string(d.degenerate), std::to_string(d.overlapping_pairs),
                   formatted("%.4f", d.angle_mean), formatted("%.4g", d.angle_max), formatted("%.4f", d.area_mean),
                   formatted("%.4g", d.area_max), formatted("%.4g", d.stretch_l2),
                   methods[k].is_diffuv ? std::to_string(r.moved) : "-", one_to_one ? "yes" : "no"});
  }
  std::cout << table.text();
  for(std::size_t k = 0; k < methods.size(); ++k)
    if(results[k].failed > 0)
      std::cerr << "diffuv: warning: " << methods[k].name << " could not map " << results[k].failed << " of "
                << count_text(seg.number_of_patches(), "patch", "patches") << "; the first: " << results[k].first_failure
                << '\n';
}

} // namespace

void add_compare_command(CLI::App& app)
{
  auto options = std::make_shared<Compare_options>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "Run diffuv and CGAL's parameterizers on the same patches with the same four corners and print one "
                 "table of time and distortion");
  cmd->add_option("mesh", options->mesh, "Triangle mesh (OFF, OBJ, PLY, STL). Default: CGAL's nefertiti.off");
  cmd->add_option("--corners", options->corners,
                  "Disc mesh only, mapped as one patch: CGAL *.selection.txt with four boundary vertex indices (the first goes to (0,0), "
                  "the others follow counter-clockwise). Default: the corners diffuv param chooses");
  add_patch_options(cmd, options->patches);
  cmd->add_option("--methods", options->methods,
                  "Comma-separated: diffuv (with --distance/--no-repair), diffuv-graph, diffuv-fmm, diffuv-exact "
                  "(repaired) and the same with -raw (not repaired; diffuv-graph-raw is the paper's method); CGAL's "
                  "tutte, mean_value, authalic, conformal (square border by arc length, same corners), lscm, arap "
                  "(free border)")
      ->capture_default_str();
  cmd->add_option("--distance", options->distance, "Distance of the 'diffuv' method: fmm, graph or exact")
      ->check(CLI::IsMember({"graph", "fmm", "exact"}))
      ->capture_default_str();
  cmd->add_flag("--no-repair", options->no_repair, "The 'diffuv' method keeps its folds (see diffuv param --help)");
  cmd->add_option("--runs", options->runs, "Runs of each method on each patch; the median time is reported")
      ->check(number_in(1, 1000))
      ->capture_default_str();
  cmd->add_option("-o,--output", options->output, "Also write each method's map as OUTPUT/<mesh>.<method>.obj")
      ->check(output_folder_check());
  cmd->footer("Times: diffuv's four distance runs, ratios and repair; CGAL's parameterize() call. Neither includes "
              "reading, patching, choosing corners or copying the patch. Metrics: the same measure_distortion() for "
              "every method (doc/quality.md).\nExit codes: 0 ok, 1 bad input, 2 bad command line, 3 cannot write, "
              "4 internal error.");
  cmd->callback([options]() { run_compare(*options); });
}

} // namespace diffuv_cli
