// diffuv tool: what `param` and `segment` share — reading a mesh and its
// regions, and cutting it into disc patches.
#ifndef DIFFUV_CLI_INPUTS_H
#define DIFFUV_CLI_INPUTS_H

#include "command_line.h"

#include <diffuv/core/error.h>
#include <diffuv/graph/distance_tags.h>
#include <diffuv/core/color.h>
#include <diffuv/io/paint_look.h>
#include <diffuv/io/internal/number_tokens.h>
#include <diffuv/io/painted_labels.h>
#include <diffuv/io/read_labels.h>
#include <diffuv/io/read_mesh.h>
#include <diffuv/io/selection_file.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/parameterization/diffusion_patches.h>
#include <diffuv/layout/disc_patches.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace diffuv_cli {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using diffuv::internal::count_text;

/// A mesh as read, with its regions if it has any.
struct Input_mesh {
  std::string path;
  Mesh mesh;
  diffuv::Mesh_read_report report;
  std::vector<int> face_labels;  ///< #F entries, or empty: no regions
  std::string label_source;      ///< where the labels came from, for the summary
  std::string labels_path;       ///< the label file, if one was given
};

/// Options that shape the patches, shared by `param` and `segment`.
struct Patch_cli_options {
  std::string labels;
  std::string layout = "quads";  // quads | voronoi
  std::size_t patches = 0;       // 0: the layout's own density (voronoi: 12 seeds)
  bool no_split_caps = false;
  bool keep_flat_triangles = false;
  bool strict = false;
  bool strict_input = false;     // refuse a mesh file that needs a repair instead of repairing it
  std::string regions_from = "auto"; // auto | labels | colors | none: what in the mesh file names regions
  std::size_t threads = 0;       // threads that map the patches while the layout is refined
};

/// One of CGAL's meshes, for a command given none: from $DIFFUV_DATA_DIR, else
/// as installed with the tool (DIFFUV_INSTALLED_DATA_DIR, relative to the
/// folder of the executable), else from the build tree (DIFFUV_DEFAULT_DATA_DIR).
inline std::string default_mesh(const std::string& name)
{
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::filesystem::path installed =
      error ? std::filesystem::path() : executable.parent_path() / DIFFUV_INSTALLED_DATA_DIR;
  return data_folder(name, std::getenv("DIFFUV_DATA_DIR"), installed, DIFFUV_DEFAULT_DATA_DIR) + "/meshes/" + name;
}

/// Checks a number option's text before it is converted: a value that is not
/// a number, or out of [low, high], is a usage error that says which.
inline CLI::Validator number_in(double low, double high, bool whole = true)
{
  std::ostringstream name;
  name << (whole ? "INT in [" : "NUMBER in [") << low << " - " << high << "]";
  return CLI::Validator([=](const std::string& s) { return range_problem(s, low, high, whole); }, name.str());
}

inline void add_strict_input_option(CLI::App* cmd, bool& strict_input)
{
  cmd->add_flag("--strict-input", strict_input,
                "Refuse a mesh file that is not a manifold, consistently oriented mesh, naming the problem, instead of "
                "repairing it (by default borders that coincide are stitched, faces that use a point twice or repeat "
                "another are dropped, faces are oriented consistently and non-manifold vertices are split; no point "
                "moves and the file's points keep their numbers)");
}

inline void add_regions_from_option(CLI::App* cmd, std::string& regions_from)
{
  cmd->add_option("--regions-from", regions_from,
                  "What in the mesh file names regions when no --labels file is given: auto (face colours and integer "
                  "label properties; vertex colours only when they look painted: at most 256 colours in at most 2 "
                  "connected areas per colour + 16, else they are ignored with a warning), labels (label properties only, colours "
                  "ignored), colors (also vertex colours that do not look painted), none (automatic patches)")
      ->check(CLI::IsMember({"auto", "labels", "colors", "none"}))
      ->capture_default_str();
}

inline void add_patch_options(CLI::App* cmd, Patch_cli_options& o)
{
  cmd->add_option("--labels", o.labels,
                  "Region label file: one integer per face of the mesh file (file order). The regions keep their borders "
                  "(with --layout quads, but for faces that jut out of a region by two edges, flat in any map onto the "
                  "square: they join the region they jut into, unless --keep-flat-triangles): "
                  "with --layout quads each is split into four-sided patches (a label file that is a layout already, "
                  "as segment writes, is kept as it is; a region that is a whole disc follows the rule for discs), with "
                  "voronoi each connected region is a patch. Default: the colours or integer face property "
                  "painted in a PLY/OFF mesh, else automatic patches (a disc whose map as one patch is good stays one patch)");
  cmd->add_option("--layout", o.layout,
                  "How patches are made where no labels say: quads (four-sided patches, conforming, refined until each "
                  "patch's raw map is good; labelled regions are split into them too) or voronoi (Voronoi cells whose "
                  "runs of neighbours are merged into four sides: the patches of diffuv 0.1)")
      ->check(CLI::IsMember({"quads", "voronoi"}))
      ->capture_default_str();
  cmd->add_option("--patches", o.patches,
                  "quads: seeds for about N patches to start from (default: one cell per 900 faces, about five "
                  "patches each); the cell-complex rules and the refinement then add cells where the surface needs "
                  "them, so below a few hundred they decide the count (cow: 297 patches for N = 1 to 6, 291 by "
                  "default, 338 for 100, 358 for 300); voronoi: N seeds to start from (default 12; more are added until every "
                  "patch is a disc). A disc whose map as one patch is good stays one patch unless N is given; with voronoi a "
                  "disc is always one patch, and on a mesh of discs the option has no effect (a warning says so)")
      ->check(number_in(1, 100000));
  cmd->add_flag("--no-split-caps", o.no_split_caps,
                "voronoi layout: keep caps (patches with one neighbour all around, like a hand or an ear) whole "
                "instead of splitting them in two");
  cmd->add_flag("--keep-flat-triangles", o.keep_flat_triangles,
                "Keep every face in its region even when its three vertices end up on one side of the patch (flat in "
                "any map onto the square) instead of handing it to a neighbouring patch, and every face in its "
                "labelled region even when it juts out of it by two edges");
  cmd->add_flag("--strict", o.strict, "Report a region that is not a disc instead of cutting it into discs");
  add_strict_input_option(cmd, o.strict_input);
  add_regions_from_option(cmd, o.regions_from);
}

/// Refuses option combinations that would be silently ignored.
/// \throws CLI::ValidationError (a usage error)
inline void check_patch_options(const Patch_cli_options& o)
{
  if(o.no_split_caps && o.layout != "voronoi")
    throw CLI::ValidationError("--no-split-caps", "applies to --layout voronoi only (the quads layout splits caps its own way)");
}

/// Runs `f` with the distance tag named by --distance (graph, exact, else fmm).
template <class F>
auto with_distance(const std::string& name, F f)
{
  if(name == "graph") return f(diffuv::Graph_distance_tag());
  if(name == "exact") return f(diffuv::Exact_distance_tag());
  return f(diffuv::Fmm_distance_tag());
}

/// Checks an output folder option: an empty name is a usage error.
inline CLI::Validator output_folder_check()
{
  return CLI::Validator([](const std::string& s) { return s.empty() ? "the output folder name is empty" : ""; }, "DIR");
}

/// How `read_input()` reads painted regions.
struct Paint_reading {
  bool read = true;            ///< false: ignore paint (the labels come from elsewhere)
  /// A colour's label is its value (r * 65536 + g * 256 + b) rather than its
  /// rank among the file's colours: two meshes painted with different sets of
  /// colours still give one colour the same label (correspondence).
  bool color_values = false;
  /// Warn of vertex colours that do not look painted (ignored as regions); `bake` takes them as data.
  bool warn_unpainted = true;
};

/// Reads the mesh and its regions: `--labels` first, else painted colours or
/// integer face properties of the mesh file.
inline Input_mesh read_input(const std::string& path, const Patch_cli_options& o, Paint_reading paint = {})
{
  Input_mesh in;
  in.path = path;
  diffuv::Mesh_read_options reading;
  reading.repair = !o.strict_input;
  in.report = diffuv::read_triangle_mesh(path, in.mesh, reading);
  if(in.report.coinciding_border_points > 0)
    std::cerr << "diffuv: warning: " << path << ": "
              << count_text(in.report.coinciding_border_points, "border point")
              << (in.report.coinciding_border_points == 1 ? " lies" : " lie")
              << " where another border point lies: the mesh may need welding (reading stitches such borders "
                 "unless --strict-input)\n";
  std::vector<int> polygon_labels;
  if(!o.labels.empty()) {
    polygon_labels = diffuv::read_face_labels(o.labels, in.report.faces_in_file);
    in.label_source = "labels from " + o.labels;
    in.labels_path = o.labels;
  } else if(paint.read && o.regions_from != "none" && in.report.may_hold_regions) {
    diffuv::Painted_labels painted = diffuv::read_painted_labels(path, std::string(), o.regions_from != "labels");
    if(painted.source == diffuv::Label_source::vertex_colors && o.regions_from == "auto") {
      // A coloured scan or a transferred field is data, not regions.
      // Faces take the colour most of their vertices have: the look counts the colours they take.
      const diffuv::Paint_look look =
          diffuv::look_of_paint(in.mesh, diffuv::face_labels_of_mesh(painted.polygon_labels, in.report));
      if(!look.painted) {
        if(paint.warn_unpainted)
          std::cerr << "diffuv: warning: " << path << ": "
                    << count_text(painted.colors.size(), "distinct vertex colour", "distinct vertex colours")
                    << ", taken by the faces as " << count_text(look.colors, "colour") << " in "
                    << count_text(look.areas, "area") << ": not taken as regions (--regions-from colors takes them)\n";
        painted = diffuv::Painted_labels();
      }
    }
    if(painted.source != diffuv::Label_source::none) {
      polygon_labels = std::move(painted.polygon_labels);
      in.label_source = "regions painted in the mesh file (" + painted.property + ")";
      if(paint.color_values && !painted.colors.empty()) {
        // Colours of diffuv's palette (what `diffuv segment` paints) read back
        // as their label number; any other painting labels a colour by its value.
        std::map<diffuv::Color, int> palette;
        for(int k = 0; k < 4096; ++k) palette.emplace(diffuv::label_color(k), k);
        bool all_in_palette = true;
        for(const diffuv::Color& c : painted.colors) all_in_palette = all_in_palette && palette.count(c) > 0;
        for(int& label : polygon_labels) {
          const diffuv::Color& c = painted.colors[static_cast<std::size_t>(label)];
          label = all_in_palette ? palette[c] : (c.r << 16) | (c.g << 8) | c.b;
        }
        in.label_source += all_in_palette ? ", diffuv's palette" : ", a colour's label is its value";
      }
    }
  }
  if(!polygon_labels.empty()) {
    in.face_labels = diffuv::face_labels_of_mesh(polygon_labels, in.report);
    // Thousands of regions take a while to lay out (seconds per ten thousand): say so first.
    std::vector<int> distinct = in.face_labels;
    std::sort(distinct.begin(), distinct.end());
    const std::size_t regions = static_cast<std::size_t>(std::unique(distinct.begin(), distinct.end()) - distinct.begin());
    if(regions > 2000)
      std::cerr << "diffuv: " << path << ": " << regions << " regions (" << in.label_source
                << "); laying them out may take a while" << std::endl;
  }
  return in;
}

/// Per-vertex rows of numbers, one row per vertex, all rows as long as the
/// first (`#` starts a comment): what `correspond --values` transfers and
/// `bake --values` bakes. `mesh` names the mesh in the message for a wrong count.
/// \throws diffuv::Input_error naming the file and line
inline std::vector<std::vector<double>> read_value_rows(const std::string& path, std::size_t expected_rows,
                                                       const std::string& mesh)
{
  std::ifstream in(path);
  if(!in) throw diffuv::Input_error(path, 0, "cannot open file");
  std::vector<std::vector<double>> rows;
  std::string line;
  std::size_t line_number = 0, columns = 0;
  while(std::getline(in, line)) {
    ++line_number;
    const auto hash = line.find('#');
    if(hash != std::string::npos) line.erase(hash);
    std::istringstream fields(line);
    std::vector<double> row;
    std::string token;
    while(fields >> token) {
      double value = 0;
      if(!diffuv::internal::parse_number(token, value) || !std::isfinite(value))
        throw diffuv::Input_error(path, line_number, "\"" + token + "\" is not a finite number (separate values by spaces)");
      row.push_back(value);
    }
    if(row.empty()) continue;
    if(rows.empty()) columns = row.size();
    if(row.size() != columns)
      throw diffuv::Input_error(path, line_number, "this row has " + count_text(row.size(), "value") +
                                                       ", the first row has " + std::to_string(columns));
    rows.push_back(std::move(row));
  }
  if(rows.size() != expected_rows)
    throw diffuv::Input_error(path, 0, "the file has " + count_text(rows.size(), "row") + ", " + mesh + " has " +
                                           count_text(expected_rows, "vertex", "vertices") + " (one row per vertex)");
  return rows;
}

/// What reading repaired, for the summary ("repaired: 12 faces reoriented, 1
/// non-manifold vertex split"), or an empty string.
inline std::string repair_line(const Input_mesh& in)
{
  const diffuv::Mesh_repair_report& r = in.report.repair;
  std::vector<std::string> parts;
  if(r.points_merged) parts.push_back(count_text(r.points_merged, "coinciding point") + " merged (borders stitched; a merged point has no (u,v) of its own)");
  if(r.degenerate_faces) parts.push_back(count_text(r.degenerate_faces, "face") + " using a point twice dropped");
  if(r.duplicate_faces) parts.push_back(count_text(r.duplicate_faces, "duplicate face") + " dropped");
  if(r.faces_reoriented) parts.push_back(count_text(r.faces_reoriented, "face") + " reoriented");
  if(r.non_manifold_edges) parts.push_back(count_text(r.non_manifold_edges, "non-manifold edge") + " cut");
  if(r.vertices_split)
    parts.push_back(count_text(r.vertices_split, "non-manifold vertex", "non-manifold vertices") + " split (" +
                    count_text(r.vertex_copies, "copy", "copies") + " added)");
  if(parts.empty()) return std::string();
  std::string line = "repaired:";
  for(std::size_t k = 0; k < parts.size(); ++k) line += (k ? ", " : " ") + parts[k];
  return line + " (--strict-input turns repairs off)";
}

/// The vertices named by a selection file (corners, sources): indices of the
/// mesh file's points, each the vertex that stands for it after the repair.
inline std::vector<Mesh::Vertex_index> selected_vertices(const Input_mesh& in, const std::string& selection_path)
{
  std::vector<std::size_t> indices = diffuv::read_selection_file(selection_path);
  for(std::size_t& i : indices)
    if(i < in.report.vertices) i = in.report.vertex_of(i);
  return diffuv::selection_vertices(in.mesh, indices, selection_path);
}

/// Warns on stderr of the input's faces of zero area (their (u,v) triangles
/// may be flat); `note` ends the line, e.g. " (column degen)".
inline void warn_of_zero_area_faces(const Input_mesh& in, const std::string& note = std::string())
{
  if(in.report.degenerate_faces == 0) return;
  std::cerr << "diffuv: warning: " << in.path << ": "
            << count_text(in.report.degenerate_faces, "face has zero area; its (u,v) triangle",
                          "faces have zero area; their (u,v) triangles")
            << " may be flat" << note << "\n";
}

/// What the summary lines say of `Patching_report::flat_triangles_handed`: nothing for none.
inline std::string flat_triangles_handed_clause(std::size_t handed)
{
  if(handed == 0) return std::string();
  return count_text(handed, "flat triangle") + " handed to a neighbour";
}

/// Cuts the mesh into disc patches (see `diffuv::disc_patches()`). With
/// `known`, the maps of the discs kept whole are left there for the mapping
/// to take (`diffuv::Known_charts`).
/// \throws diffuv::Input_error with `--strict` if a region is not a disc
inline diffuv::Segmentation<Mesh> make_patches(const Input_mesh& in, const Patch_cli_options& o,
                                               diffuv::Patching_report& report,
                                               std::shared_ptr<diffuv::Known_charts> known = nullptr)
{
  diffuv::Patching_options options;
  options.layout = o.layout == "voronoi" ? diffuv::Patch_layout::voronoi : diffuv::Patch_layout::quads;
  options.split_caps = !o.no_split_caps;
  options.hand_off_flat_triangles = !o.keep_flat_triangles;
  options.strict = o.strict;
  options.automatic.patches = o.patches > 0 ? o.patches : 12;
  options.quads.target_patches = o.patches;
  // A number of patches asked for a disc: lay it out rather than keep it whole.
  if(o.patches > 0) options.discs = diffuv::Disc_components::laid_out;
  diffuv::Raw_map_judge_options judging;
  judging.threads = o.threads;
  judging.known_charts = std::move(known);
  diffuv::Segmentation<Mesh> seg;
  const diffuv::Status status =
      diffuv::diffusion_patches(in.mesh, in.mesh.points(), in.face_labels, seg, options, &report, judging);
  if(!status && o.strict)
    throw diffuv::Input_error(in.labels_path.empty() ? in.path : in.labels_path, 0, status.what());
  // With the Voronoi layout a disc is one patch whatever the seed count: say
  // so rather than ignore it.
  if(o.patches > 0 && in.face_labels.empty() && !report.automatic)
    std::cerr << "diffuv: warning: --patches " << o.patches << " has no effect on " << in.path << ": "
              << (report.components <= 1 ? "the mesh is a disc, and a disc is one patch"
                                         : "every component is a disc, and a disc is one patch")
              << "\n";
  return seg;
}

/// What the summary says of the patches made: the layout's counts, or the
/// Voronoi steps ("0 merged, 1 cut into discs, 2 caps split").
inline std::string patching_clause(const diffuv::Patching_report& r, const Patch_cli_options& o)
{
  std::string s;
  if(o.layout == "voronoi" || r.voronoi_instead) {
    s = std::to_string(r.merged) + " merged, " + std::to_string(r.cut) + " cut into discs, " +
        count_text(r.caps_split, "cap") + " split";
    if(r.voronoi_instead) s = "the four-sided layout left a patch that is not a disc: Voronoi patches instead; " + s;
  } else {
    const auto& l = r.layout;
    if(l.cells == 0 && l.kept_regions == 0)
      return r.flat_triangles_handed ? flat_triangles_handed_clause(r.flat_triangles_handed)
                                     : r.components > 1 ? "each disc kept whole: its map as one patch is good"
                                                        : "kept whole: its map as one patch is good";
    s = "four-sided layout: " + count_text(l.quads, "quad");
    if(l.kept_regions > 0) {
      s += " (the regions, kept whole)";
    } else {
      s += " from " + count_text(l.cells, "cell");
      if(l.refined_cells > 0) s += ", " + std::to_string(l.refined_cells) + " refined";
    }
    if(l.fallback_patches > 0) s += ", " + count_text(l.fallback_patches, "other patch", "other patches");
    // The search serves quads and regions kept whole too, not only the other patches.
    if(r.corners_chosen > 0)
      s += ", " + count_text(r.corners_chosen, "patch", "patches") +
           (r.corners_chosen == 1 ? " with corners chosen by its map" : " with corners chosen by their maps");
    if(r.merged > 0) s += ", " + std::to_string(r.merged) + " merged (fewer than four border vertices)";
    if(r.cut > 0) s += ", " + count_text(r.cut, "region not a disc", "regions not discs") + " (cut into cells)";
    if(l.region_ears_moved > 0)
      s += ", " + count_text(l.region_ears_moved, "face") +
           (l.region_ears_moved == 1 ? " jutting out of its region moved into the next"
                                     : " jutting out of their regions moved into the next");
    if(r.discs_laid_out > 0)
      s += ", " + count_text(r.discs_laid_out, "disc") + " laid out (" +
           (o.patches > 0 ? std::string("--patches given") : std::string("as one patch its map would fold or stretch")) + ")";
    if(r.whole_components > 0)
      s += ", " + count_text(r.whole_components, "disc") + " kept whole (good as one patch)";
  }
  if(r.flat_triangles_handed) s += ", " + flat_triangles_handed_clause(r.flat_triangles_handed);
  return s;
}

/// Writes the patch of each face of the mesh file, one per line (a label file
/// for --labels); a polygon that was triangulated gets its first triangle's patch.
inline void write_polygon_patches(std::ostream& out, const Input_mesh& in, const diffuv::Segmentation<Mesh>& seg)
{
  std::vector<std::size_t> patch_of_polygon(in.report.faces_in_file, diffuv::Segmentation<Mesh>::no_patch);
  for(auto f : faces(in.mesh)) {
    std::size_t& p = patch_of_polygon[in.report.file_face[f.idx()]];
    if(p == diffuv::Segmentation<Mesh>::no_patch) p = seg.face_patch[f.idx()];
  }
  for(std::size_t p : patch_of_polygon) out << p << '\n';
}

} // namespace diffuv_cli

#endif
