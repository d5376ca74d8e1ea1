// diffuv tool: `diffuv correspond` — every vertex of mesh A mapped onto mesh B
// through (region, u, v), and B's colours (or any per-vertex values) carried to A.
#include "commands.h"
#include "inputs.h"

#include <diffuv/correspondence/correspondence.h>
#include <diffuv/correspondence/labelled_atlas.h>
#include <diffuv/correspondence/labelled_atlas_pair.h>
#include <diffuv/correspondence/nearest_face_labels.h>
#include <diffuv/correspondence/transfer.h>
#include <diffuv/core/color.h>
#include <diffuv/io/atomic_file.h>
#include <diffuv/internal/number_format.h>
#include <diffuv/io/internal/number_tokens.h>
#include <diffuv/io/read_vertex_colors.h>
#include <diffuv/output/write_ply.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace diffuv_cli {
namespace {

using Clock = std::chrono::steady_clock;
using Atlas = diffuv::Labelled_atlas<Mesh>;
using Correspondence = diffuv::Atlas_correspondence<Mesh, Mesh>;
using Image = Correspondence::Point;

struct Correspond_options {
  std::string mesh_a, mesh_b;
  std::string labels_a, labels_b;
  std::string values;
  std::string output = "diffuv-out";
  std::string distance = "fmm";
  bool transfer_labels = false;
  bool repair = false;
  bool no_clean = false;
  bool no_split_caps = false;
  bool strict_input = false;
  std::string regions_from = "auto";
};

double ms_since(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::string no_labels_message(const std::string& option, bool other_has_labels)
{
  std::string m = "the mesh has no region labels, and a correspondence needs the same regions on both meshes. "
                  "Give " + option + " FILE (one integer per face, in file order), or paint the regions as face "
                  "colours in a PLY/OFF file";
  if(option == "--labels-b" && other_has_labels)
    m += ", or pass --transfer-labels to give B the label of A's nearest face (when B lies on top of A)";
  else
    m += "; `diffuv segment A` writes a label file to start from (then paint B the same, or use "
         "--transfer-labels when B lies on top of A)";
  return m;
}


// A smooth colour field on B: its position in its bounding box, as red, green, blue.
std::vector<diffuv::Color> position_colors(const Mesh& mesh)
{
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  std::vector<diffuv::Color> colors;
  for(auto v : vertices(mesh)) {
    const auto& p = mesh.point(v);
    unsigned char rgb[3];
    for(int k = 0; k < 3; ++k) {
      const double extent = box.max(k) - box.min(k);
      const double t = extent > 0 ? (p[k] - box.min(k)) / extent : 0.5;
      rgb[k] = static_cast<unsigned char>(std::lround(30 + 210 * std::clamp(t, 0., 1.)));
    }
    colors.push_back(diffuv::Color{rgb[0], rgb[1], rgb[2]});
  }
  return colors;
}

std::string label_list(const std::vector<int>& labels)
{
  std::string s;
  for(std::size_t i = 0; i < labels.size() && i < 12; ++i) s += (i ? ", " : "") + std::to_string(labels[i]);
  if(labels.size() > 12) s += ", ... (" + std::to_string(labels.size()) + " in all)";
  return s;
}

// The faces relabelled, and by which rule: "12 faces relabelled (7 in 3
// islands, 5 by border smoothing, 0 at 1 pinch)". Where a face was relabelled
// more than once, the rules' counts are relabellings and add up to more.
std::string cleaning_text(const diffuv::Label_cleaning_report& r, bool cleaned)
{
  if(!cleaned) return "labels not cleaned (--no-clean)";
  if(r.empty()) return "labels clean";
  const std::size_t relabellings = r.island_faces + r.smoothed_faces + r.pinch_faces;
  return count_text(r.changed_faces(), "face") + " relabelled (" +
         (relabellings == r.changed_faces() ? std::string() : count_text(relabellings, "relabelling") + ": ") +
         std::to_string(r.island_faces) + " in " + count_text(r.islands, "island") + ", " +
         std::to_string(r.smoothed_faces) + " by border smoothing, " + std::to_string(r.pinch_faces) + " at " +
         count_text(r.pinches, "pinch", "pinches") + ")";
}

// Why patches have no chart: how many, and the first reason.
std::string unmapped_text(const Atlas& atlas)
{
  std::size_t failed = 0;
  std::string first;
  for(std::size_t p = 0; p < atlas.patches.size(); ++p)
    if(!atlas.patches[p].status) {
      if(failed++ == 0) first = atlas.patches[p].status.what();
    }
  return failed == 0 ? std::string() : count_text(failed, "patch", "patches") + " could not be mapped (" + first + ")";
}

void run_correspond(const Correspond_options& o)
{
  const auto start = Clock::now();
  Patch_cli_options pa, pb;
  pa.labels = o.labels_a;
  pb.labels = o.labels_b;
  pa.strict_input = pb.strict_input = o.strict_input;
  pa.regions_from = pb.regions_from = o.regions_from;
  // Colours are region names on both meshes: compare them by value. With
  // --transfer-labels, B's colours are data to carry, not regions.
  Paint_reading paint_a, paint_b;
  paint_a.color_values = paint_b.color_values = true;
  paint_b.read = !o.transfer_labels;
  const Input_mesh a = read_input(o.mesh_a, pa, paint_a);
  Input_mesh b = read_input(o.mesh_b, pb, paint_b);
  if(a.face_labels.empty())
    throw diffuv::Input_error(a.path, 0, no_labels_message("--labels-a", !b.face_labels.empty()));
  double transfer_ms = 0;
  if(b.face_labels.empty()) {
    if(!o.transfer_labels) throw diffuv::Input_error(b.path, 0, no_labels_message("--labels-b", true));
    const auto t0 = Clock::now();
    diffuv::Nearest_face_report lying;
    b.face_labels = diffuv::nearest_face_labels(a.mesh, a.face_labels, b.mesh, &lying);
    if(!lying.lies_on_source()) {
      std::ostringstream what;
      what.precision(2);
      what << std::fixed << "does not lie on " << a.path << " (the median distance from its faces to A is "
           << 100. * lying.median_fraction() << " % of A's bounding-box diagonal, more than 1 %): --transfer-labels "
           << "carries labels to a copy of A in A's place (remeshed, repaired, re-exported); give B's own regions "
           << "with --labels-b or paint them";
      throw diffuv::Input_error(b.path, 0, what.str());
    }
    transfer_ms = ms_since(t0);
    b.label_source = "labels of A's nearest faces (--transfer-labels)";
  }
  std::vector<diffuv::Color> b_colors = diffuv::read_vertex_colors(b.path);
  std::vector<std::vector<double>> value_rows;
  if(!o.values.empty()) value_rows = read_value_rows(o.values, num_vertices(b.mesh), "mesh B");
  const double read_ms = ms_since(start) - transfer_ms;

  diffuv::Labelled_atlas_pair_options options;
  options.atlas.clean = !o.no_clean;
  options.atlas.repair.enabled = o.repair;
  options.atlas.patching.split_caps = !o.no_split_caps;
  // B's labels carried from A: a lost region joins where most of its faces
  // of B went, and a label no face of B got (a region too thin for B's faces)
  // joins its neighbour across the longest border. B's own labels: only a
  // region touching it on A can take it in, and a label B leaves out is B's
  // choice, reported below.
  options.join_labels_missing_in_b = o.transfer_labels;
  // B splits the regions A split, along the same runs, and takes its corners
  // at the same junctions of regions as A (by name); regions B is too coarse
  // to keep join their neighbour on both meshes.
  auto t = Clock::now();
  diffuv::Labelled_atlas_pair<Mesh> both = with_distance(o.distance, [&](auto tag) {
    return diffuv::build_labelled_atlas_pair<decltype(tag)>(a.mesh, a.mesh.points(), a.face_labels, b.mesh,
                                                            b.mesh.points(), b.face_labels, options);
  });
  const double param_ms = ms_since(t);
  if(!both.status)  // only no labels; both meshes have them here
    throw diffuv::Input_error(a.path, 0, "the atlases could not be built: " + both.status.what());
  const Atlas& atlas_a = *both.a;
  const Atlas& atlas_b = *both.b;

  t = Clock::now();
  const Correspondence correspondence(atlas_a, atlas_b);
  const std::vector<Image> images = correspondence.map_vertices();
  const double map_ms = ms_since(t);
  const diffuv::Region_match_report& match = correspondence.report();
  if(match.matched_patches == 0) {
    std::string why;
    const std::string failed_a = unmapped_text(atlas_a), failed_b = unmapped_text(atlas_b);
    if(!failed_a.empty()) why += "; on A, " + failed_a;
    if(!failed_b.empty()) why += "; on B, " + failed_b;
    throw diffuv::Input_error(b.labels_path.empty() ? b.path : b.labels_path, 0,
                              "no patch of A pairs with a patch of B (labels of A: " +
                                  label_list(atlas_a.segmentation.patch_label) + "; of B: " +
                                  label_list(atlas_b.segmentation.patch_label) + why + ")");
  }

  // Outputs: all or nothing.
  t = Clock::now();
  const bool b_painted = !b_colors.empty();
  if(!b_painted) b_colors = position_colors(b.mesh);
  const std::vector<diffuv::Color> a_colors = diffuv::transfer_vertex_values(
      b.mesh, images, boost::make_iterator_property_map(b_colors.begin(), get(boost::vertex_index, b.mesh)),
      diffuv::Color{128, 128, 128});

  std::vector<std::string> inputs = {a.path, b.path, o.labels_a, o.labels_b, o.values};
  diffuv::Output_folder out(o.output, inputs);
  std::ostream& csv = out.open("correspondence.csv");
  csv << "vertex,face,b0,b1,b2,x,y,z\n";
  std::size_t mapped = 0, inside = 0;
  for(auto v : vertices(a.mesh)) {
    const Image& p = images[v.idx()];
    csv << v.idx() << ',';
    if(!p.mapped()) {
      csv << "-1,,,,,,\n";
      continue;
    }
    ++mapped;
    if(p.inside) ++inside;
    // The file lists a triangle's vertices from target(halfedge(f)) on (checked by a test).
    const double w[3] = {p.barycentric[1] + 0., p.barycentric[2] + 0., p.barycentric[0] + 0.}; // + 0.: no "-0"
    csv << b.report.file_face[p.face.idx()];
    for(double x : w) {
      csv << ',';
      diffuv::internal::write_shortest(csv, x);
    }
    for(int k = 0; k < 3; ++k) {
      csv << ',';
      diffuv::internal::write_shortest(csv, p.point[k]);
    }
    csv << '\n';
  }
  std::ostream& transfer = out.open("transfer.ply");
  diffuv::write_vertex_colored_ply(transfer, a.mesh, a.mesh.points(), a_colors, out.paths().back());
  std::ostream& reference = out.open("reference.ply");
  diffuv::write_vertex_colored_ply(reference, b.mesh, b.mesh.points(), b_colors, out.paths().back());
  if(!value_rows.empty()) {
    std::ostream& values = out.open("values.txt");
    values << "# one row per vertex of A: B's rows from " << o.values << " interpolated; nan: not mapped\n";
    for(const Image& p : images) {
      const std::size_t columns = value_rows.front().size();
      for(std::size_t c = 0; c < columns; ++c) {
        if(c) values << ' ';
        if(!p.mapped()) {
          values << "nan";
          continue;
        }
        const auto column = boost::make_function_property_map<Mesh::Vertex_index>(
            [&](Mesh::Vertex_index v) { return value_rows[v.idx()][c]; });
        diffuv::internal::write_shortest(values, diffuv::interpolate_at(b.mesh, p, column));
      }
      values << '\n';
    }
  }
  out.commit();
  const double write_ms = ms_since(t);

  const std::size_t na = num_vertices(a.mesh);
  std::cout << "diffuv correspond " << a.path << " -> " << b.path << "\n"
            << "A: " << count_text(na, "vertex", "vertices") << ", "
            << count_text(atlas_a.segmentation.number_of_patches(), "patch", "patches") << " (" << a.label_source << "; "
            << cleaning_text(atlas_a.cleaning, !o.no_clean) << ")\n"
            << "B: " << count_text(num_vertices(b.mesh), "vertex", "vertices") << ", "
            << count_text(atlas_b.segmentation.number_of_patches(), "patch", "patches") << " (" << b.label_source << "; "
            << cleaning_text(atlas_b.cleaning, !o.no_clean) << ")\n"
            ;
  if(const std::string repaired = repair_line(a); !repaired.empty()) std::cout << "A " << repaired << '\n';
  if(const std::string repaired = repair_line(b); !repaired.empty()) std::cout << "B " << repaired << '\n';
  warn_of_zero_area_faces(a);
  warn_of_zero_area_faces(b);
  std::cout << "regions matched: " << count_text(match.matched_labels.size(), "label") << ", "
            << count_text(match.matched_patches, "patch", "patches") << "\n";
  if(!both.joined.empty()) {
    // All of them, each with the region it ended in, so that a user can
    // check them; the patch counts above are after these joins.
    std::cout << "regions too small for B, joined to a neighbour on both meshes (the patches above are counted after "
                 "the joins; label -> the region it joined): ";
    const char* comma = "";
    for(const auto& [label, region] : both.joined) {
      std::cout << comma << label << " -> " << region;
      comma = ", ";
    }
    std::cout << '\n';
  }
  if(!match.labels_only_in_a.empty())
    std::cout << "labels only in A (not mapped): " << label_list(match.labels_only_in_a) << '\n';
  if(!match.labels_only_in_b.empty())
    std::cout << "labels only in B (nothing maps there): " << label_list(match.labels_only_in_b) << '\n';
  // Patches by name, as param's table names them.
  auto pieces = [](const std::vector<diffuv::Patch_key>& v) {
    std::string s;
    for(std::size_t i = 0; i < v.size() && i < 8; ++i) s += (i ? ", " : "") + diffuv::patch_name(v[i]);
    if(v.size() > 8) s += ", ... (" + std::to_string(v.size()) + " in all)";
    return s;
  };
  if(!match.labels_with_different_pieces.empty())
    std::cout << "warning: these labels are cut into a different number of patches on A and B, whose pieces pair by "
                 "decreasing area (check them, or give each piece its own label): "
              << label_list(match.labels_with_different_pieces) << '\n';
  for(const auto& [name, atlas] : {std::make_pair("A", &atlas_a), std::make_pair("B", &atlas_b)}) {
    const std::string failed = unmapped_text(*atlas);
    if(!failed.empty()) std::cout << "on " << name << ", " << failed << '\n';
  }
  if(!match.unmatched_patches_a.empty())
    std::cout << "patches of A without a counterpart: " << pieces(match.unmatched_patches_a) << '\n';
  if(!match.unmatched_patches_b.empty())
    std::cout << "patches of B without a counterpart: " << pieces(match.unmatched_patches_b) << '\n';
  std::cout << "vertices mapped: " << mapped << " of " << na << " (" << inside << " inside a triangle of B's chart, "
            << mapped - inside << " onto its nearest point)\n"
            << "colours: " << (b_painted ? "B's vertex colours" : "B's position in its bounding box (B has no vertex colours)")
            << (value_rows.empty() ? "" : "; values from " + o.values) << "\n"
            << "time: read " << std::lround(read_ms) << " ms, "
            << (o.transfer_labels && transfer_ms > 0 ? "transfer labels " + std::to_string(std::lround(transfer_ms)) + " ms, " : "")
            << "parameterize A and B " << std::lround(param_ms)
            << (both.rounds > 1 ? " ms (" + std::to_string(both.rounds) + " builds)" : std::string(" ms")) << ", map " << std::lround(map_ms) << " ms, write "
            << std::lround(write_ms) << " ms\n" << wrote_line(out.paths()) << '\n';
}

} // namespace

void add_correspond_command(CLI::App& app)
{
  auto options = std::make_shared<Correspond_options>();
  CLI::App* cmd = app.add_subcommand(
      "correspond", "Map every vertex of mesh A onto mesh B through matching region labels and (u,v), and carry "
                    "B's colours to A");
  cmd->add_option("mesh_a", options->mesh_a, "Mesh A (OFF, OBJ, PLY, STL): its vertices are mapped")->required();
  cmd->add_option("mesh_b", options->mesh_b, "Mesh B: where they land")->required();
  cmd->add_option("--labels-a", options->labels_a,
                  "Region label file of A: one integer per face (file order). Default: regions painted in A's "
                  "PLY/OFF file (face colours or a label property)");
  CLI::Option* labels_b =
      cmd->add_option("--labels-b", options->labels_b, "Region label file of B (the same labels name the same regions)");
  cmd->add_flag("--transfer-labels", options->transfer_labels,
                "Give each face of B the label of A's nearest face, instead of --labels-b or regions painted in B "
                "(only meaningful when B lies on top of A, e.g. a remeshed copy; B's colours are then data to carry). "
                "A region of A that B is too coarse to keep (its cleaning or its merging of small patches gives it "
                "away, or no face of B is nearest to it) then joins its neighbour on both meshes, both atlases are "
                "built again (the time line counts the builds), and the joined labels are listed. Without it, only "
                "regions that B's cleaning or merging gives away are joined; a label B's own labels leave out is "
                "reported as only in A")
      ->excludes(labels_b);
  cmd->add_option("--values", options->values,
                  "Text file with one row of numbers per vertex of B (scalars, colours, texture coordinates...): "
                  "written for A's vertices, interpolated, to OUTPUT/values.txt");
  cmd->add_option("-o,--output", options->output, "Output folder (created if needed)")
      ->check(output_folder_check())
      ->capture_default_str();
  cmd->add_option("--distance", options->distance, "Distances diffused in each patch: fmm, graph or exact")
      ->check(CLI::IsMember({"graph", "fmm", "exact"}))
      ->capture_default_str();
  cmd->add_flag("--repair", options->repair,
                "Repair the folds of each patch map before mapping (default: the raw diffusion coordinates, which "
                "measured closer to the truth for correspondence; see doc/correspondence.md)");
  cmd->add_flag("--no-clean", options->no_clean,
                "Use the labels as they are (default: islands absorbed, jagged borders smoothed, pinches undone; "
                "see doc/correspondence.md)");
  cmd->add_flag("--no-split-caps", options->no_split_caps, "Keep caps whole (on both meshes)");
  add_strict_input_option(cmd, options->strict_input);
  add_regions_from_option(cmd, options->regions_from);
  cmd->footer("Writes OUTPUT/correspondence.csv (vertex,face,b0,b1,b2,x,y,z: one row per vertex of A in file order, "
              "then one per vertex copy the input repair added to A (splitting a non-manifold vertex or edge); "
              "face indexes B's faces in file order, b0..b2 weight that face's vertices in the order the file lists "
              "them, x,y,z is the point on B; face -1: not mapped), OUTPUT/transfer.ply (A with B's vertex colours, "
              "or with B's position colours if B has none) and OUTPUT/reference.ply (B with those colours).\n"
              "The two meshes may differ in tessellation, vertex order, position, scale and pose: only the labels "
              "and each surface's own shape are used.\nExit codes: 0 ok, 1 bad input, 2 bad command line, "
              "3 cannot write, 4 internal error.");
  cmd->callback([options]() { run_correspond(*options); });
}

} // namespace diffuv_cli
