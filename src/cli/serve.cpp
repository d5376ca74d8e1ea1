// diffuv tool: `diffuv serve`, the painter. A local web server (cpp-httplib)
// that serves one page (share/painter/, built into the tool) and a small JSON
// API over the library: the mesh, the layout of painted labels with its sides,
// corners and problems, the map with its distortion, and the label file and
// painted PLY to save (doc/painter.md).
#include "commands.h"
#include "inputs.h"
#include "pipeline.h"

#include <diffuv/correspondence/correspondence.h>
#include <diffuv/correspondence/labelled_atlas.h>
#include <diffuv/correspondence/labelled_atlas_pair.h>
#include <diffuv/correspondence/nearest_face_labels.h>
#include <diffuv/output/write_ply.h>
#include <diffuv/patches/patch_names.h>

#include <CGAL/Bbox_3.h>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <pthread.h>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace diffuv_cli {

// The page's files, built into the tool (painter_page.cpp, generated from share/painter/).
extern const char* const painter_index_html;
extern const char* const painter_js;
extern const char* const painter_css;

namespace {

using json = nlohmann::json;


struct Serve_options {
  std::string mesh;
  std::string labels;  // a label file for the mesh given
  std::string mesh_b;  // a second mesh, for correspondence
  std::string labels_b;
  int port = 8080;
  std::string host = "127.0.0.1";
  std::string three_dir = "/usr/share/javascript/three";  // Debian's libjs-three
  std::size_t threads = 0;
  std::size_t max_request_mb = 512;  // a mesh of a few million faces as ASCII
  bool strict_input = false;
};

// A request the server refuses: its status and message.
struct Bad_request {
  int status;
  std::string message;
};

// JSON text; bytes that are not UTF-8 (a file name, a parser's message
// quoting the request) are replaced rather than thrown on.
std::string as_text(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }


// Barycentric coordinates in the API's order (the face's vertices as GET
// /api/mesh lists them: from target(halfedge(f)) on) and in CGAL's
// Face_location order (from source(halfedge(f)) on).
std::array<double, 3> api_from_cgal(const std::array<double, 3>& b) { return {{b[1] + 0., b[2] + 0., b[0] + 0.}}; }
std::array<double, 3> cgal_from_api(const std::array<double, 3>& b) { return {{b[2], b[0], b[1]}}; }

json parsed_request(const std::string& body)
{
  json request;
  try {
    request = json::parse(body);
  } catch(const json::exception& e) {
    throw Bad_request{400, std::string("the request is not JSON: ") + e.what()};
  }
  return request;
}

// A number as JSON; NaN and infinity (which JSON lacks) as null.
json finite(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

double milliseconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// A library message about patch p may start with "patch p: "; the API gives the patch apart.
std::string without_patch_prefix(const std::string& message, std::size_t p)
{
  const std::string prefix = "patch " + std::to_string(p) + ": ";
  return message.compare(0, prefix.size(), prefix) == 0 ? message.substr(prefix.size()) : message;
}

// The state of one painter session: the mesh and what it came with.
class Painter {
public:
  // which: "a" (the mesh painted, A of a correspondence) or "b" (the second mesh)
  Painter(std::size_t threads, std::string which, bool strict_input)
    : threads_(threads), which_(std::move(which)), strict_input_(strict_input)
  {}

  void load(const std::string& path, const std::string& name, const std::string& labels = std::string())
  {
    Patch_cli_options o;
    o.labels = labels;
    o.strict_input = strict_input_;
    Input_mesh in = read_input(path, o);
    if(num_faces(in.mesh) == 0) throw Bad_request{400, name + ": the mesh has no faces"};
    // The page paints labels from 0 to 1,000,000 (and sends them back): a
    // file's larger ones would be refused at the first stroke.
    for(std::size_t f = 0; f < in.face_labels.size(); ++f)
      if(in.face_labels[f] < 0 || in.face_labels[f] > 1000000)
        throw diffuv::Input_error(in.labels_path.empty() ? path : in.labels_path, 0,
                                  "label " + std::to_string(in.face_labels[f]) + " (face " + std::to_string(f) +
                                      "): the painter takes labels from 0 to 1000000");
    in.path = name;
    mesh_ = std::make_unique<Input_mesh>(std::move(in));
    static std::atomic<std::uint64_t> loads{0};
    generation_ = ++loads;
  }

  // Which load this mesh came from: a mesh loaded later has another number.
  std::uint64_t generation() const { return generation_; }

  bool loaded() const { return mesh_ != nullptr; }

  json mesh_json() const
  {
    const Mesh& m = mesh().mesh;
    json vertices = json::array(), faces = json::array();
    CGAL::Bbox_3 box;
    for(auto v : m.vertices()) {
      const auto& p = m.point(v);
      box += p.bbox();
      vertices.push_back(p.x());
      vertices.push_back(p.y());
      vertices.push_back(p.z());
    }
    for(auto f : m.faces())
      for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) faces.push_back(static_cast<std::size_t>(v.idx()));
    json result = {{"name", mesh().path},
                   {"vertices", std::move(vertices)},
                   {"faces", std::move(faces)},
                   {"labels", mesh().face_labels.empty() ? json(nullptr) : json(mesh().face_labels)},
                   {"label_source", mesh().label_source},
                   {"read_repairs", repair_line(mesh())},
                   // the polygon of the file each triangle comes from (label files count polygons)
                   {"file_face", mesh().report.file_face.empty() ? json(nullptr) : json(mesh().report.file_face)},
                   {"diagonal", std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                          CGAL::square(box.zmax() - box.zmin()))}};
    return result;
  }

  // The labels of a request body: #F integers, -1 for a face not painted;
  // an empty array asks for automatic patches. Unpainted faces become one
  // more region (the largest label + 1), as a label file cannot say "none".
  std::vector<int> labels_of(const std::string& body) const
  {
    const json request = parsed_request(body);
    if(!request.is_object() || !request.contains("labels") || !request["labels"].is_array())
      throw Bad_request{400, "the request has no \"labels\" array"};
    return labels_from(request["labels"]);
  }

  // keep_unpainted: -1 stays -1 (the caller gives it a label).
  std::vector<int> labels_from(const json& labels, const std::string& which = std::string(), bool keep_unpainted = false) const
  {
    const std::size_t nf = num_faces(mesh().mesh);
    if(labels.empty()) return {};
    if(labels.size() != nf)
      throw Bad_request{400, count_text(labels.size(), "label") + which + " for a mesh of " + count_text(nf, "face")};
    std::vector<int> result(nf);
    int largest = -1;
    bool unpainted = false;
    for(std::size_t f = 0; f < nf; ++f) {
      const json& l = labels[f];
      if(!l.is_number_integer() || l.get<long long>() < -1 || l.get<long long>() > 1000000)
        throw Bad_request{400, "label " + std::to_string(f) + which + " is " + as_text(l) +
                                   ", not an integer from -1 to 1000000"};
      result[f] = l.get<int>();
      largest = std::max(largest, result[f]);
      unpainted = unpainted || result[f] < 0;
    }
    if(largest < 0) return {};  // nothing painted: automatic
    if(unpainted && !keep_unpainted)
      for(int& l : result)
        if(l < 0) l = largest + 1;
    return result;
  }

  json layout(const std::vector<int>& labels, bool map)
  {
    Input_mesh& in = *mesh_;
    // The pipeline reads the labels from the mesh; the file's own stay what
    // GET /api/mesh answers.
    struct Labels_swap {
      std::vector<int>& held;
      std::vector<int> kept;
      ~Labels_swap() { held.swap(kept); }
    } swap{in.face_labels, labels};
    in.face_labels.swap(swap.kept);
    Patch_cli_options o;
    o.threads = threads_;
    const auto start = std::chrono::steady_clock::now();
    Parameterization result;
    try {
      result = parameterize_by_patches(in, o, "fmm", diffuv::Repair_options(), threads_);
    } catch(const diffuv::Error& e) {
      throw Bad_request{422, e.what()};
    }
    const double ms = milliseconds_since(start);
    const Mesh& m = in.mesh;
    const auto& seg = result.seg;
    const std::size_t np = seg.number_of_patches();

    json face_patch(std::vector<int>(num_faces(m), -1)), patch_label = json::array(), corners = json::array(),
        sides = json::array(), problems = json::array();
    for(std::size_t p = 0; p < np; ++p) {
      for(auto f : seg.patch_faces[p]) face_patch[f.idx()] = static_cast<int>(p);
      patch_label.push_back(p < seg.patch_label.size() ? seg.patch_label[p] : static_cast<int>(p));
      const bool mapped = p < result.patches.size() && result.patches[p].status.ok();
      if(!mapped) {
        corners.push_back(nullptr);
        sides.push_back(nullptr);
        problems.push_back({{"kind", "not_mapped"},
                            {"patch", p},
                            {"message", p < result.patches.size() ? without_patch_prefix(result.patches[p].status.what(), p)
                                                                  : std::string("no result")}});
        continue;
      }
      const auto& s = result.patches[p].sides;
      json c = json::array();
      for(auto v : s.corners) c.push_back(static_cast<std::size_t>(v.idx()));
      corners.push_back(c);
      auto ids = [](const std::vector<Mesh::Vertex_index>& side) {
        json a = json::array();
        for(auto v : side) a.push_back(static_cast<std::size_t>(v.idx()));
        return a;
      };
      sides.push_back({{"v1", ids(s.v1)}, {"u2", ids(s.u2)}, {"v2", ids(s.v2)}, {"u1", ids(s.u1)}});
      const auto& repair = result.patches[p].repair;
      const std::size_t moved = repair.moved_vertices + repair.moved_border_vertices;
      if(moved > 0)
        problems.push_back({{"kind", "repaired"},
                            {"patch", p},
                            {"message", "the fold repair moved " + count_text(moved, "vertex", "vertices")}});
    }
    const auto& r = result.patching;
    for(std::size_t p : r.not_discs)
      problems.push_back({{"kind", "not_a_disc"}, {"patch", p}, {"message", "not a disc"}});
    auto note = [&](std::size_t n, const std::string& kind, const std::string& what) {
      if(n > 0) problems.push_back({{"kind", kind}, {"patch", -1}, {"message", what}});
    };
    note(r.merged, "merged", count_text(r.merged, "patch", "patches") + " with fewer than four boundary vertices merged into a neighbour");
    note(r.cut, "cut", count_text(r.cut, "region") + " that " + (r.cut == 1 ? "was" : "were") + " not a disc cut into discs");
    note(r.caps_split, "cap_split", count_text(r.caps_split, "cap") + " split");
    note(r.flat_triangles_handed, "flat_triangles",
         count_text(r.flat_triangles_handed, "face") + " flat on one side of " +
             (r.flat_triangles_handed == 1 ? "its patch" : "their patches") + " handed to a neighbour");
    if(!repair_line(in).empty()) problems.push_back({{"kind", "read_repairs"}, {"patch", -1}, {"message", repair_line(in)}});
    if(r.voronoi_instead)
      problems.push_back({{"kind", "voronoi_instead"},
                          {"patch", -1},
                          {"message", "the four-sided layout left a patch that is not a disc: Voronoi patches instead"}});

    json out = {{"patches", np},
                {"face_patch", std::move(face_patch)},
                {"patch_label", std::move(patch_label)},
                {"corners", std::move(corners)},
                {"sides", std::move(sides)},
                {"problems", std::move(problems)},
                {"report",
                 {{"automatic", r.automatic},
                  {"merged", r.merged},
                  {"cut", r.cut},
                  {"caps_split", r.caps_split},
                  {"flat_triangles_handed", r.flat_triangles_handed},
                  {"corners_chosen", r.corners_chosen},
                  {"voronoi_instead", r.voronoi_instead}}},
                {"milliseconds", ms}};
    if(!map) return out;

    // The map: per-corner (u,v) on each chart's unit square, per-face distortion.
    const Atlas& atlas = *result.atlas;
    const auto uv = atlas.corner_uv_map();
    json corner_uv = json::array(), face_chart = json::array();
    for(auto f : m.faces()) {
      const std::size_t c = atlas.chart_of(f);
      face_chart.push_back(c == Atlas::no_chart ? -1 : static_cast<long long>(c));
      // Corner by corner in the order of "faces": both walk from halfedge(f),
      // and a corner's (u,v) is that of its halfedge's target.
      for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
        const auto q = get(uv, h);
        const bool ok = c != Atlas::no_chart && std::isfinite(q.x()) && std::isfinite(q.y());
        corner_uv.push_back(ok ? json(q.x()) : json(nullptr));
        corner_uv.push_back(ok ? json(q.y()) : json(nullptr));
      }
    }
    const std::vector<Chart_measure> measures = measure_charts(in, result, false);
    std::vector<double> area(num_faces(m), 1.0), stretch(num_faces(m), 1.0);
    diffuv::Distortion_summary total;
    std::size_t moved = 0, charts = 0;
    for(std::size_t p = 0; p < measures.size(); ++p) {
      if(p >= result.patches.size() || !result.patches[p].status) continue;
      ++charts;
      moved += result.patches[p].repair.moved_vertices + result.patches[p].repair.moved_border_vertices;
      total = diffuv::combined(total, measures[p].summary);
      if(!measures[p].summary.injective())
        out["problems"].push_back({{"kind", "not_one_to_one"},
                                   {"patch", p},
                                   {"message", "not one-to-one: " + std::to_string(measures[p].summary.flipped) + " flipped, " +
                                                   std::to_string(measures[p].summary.degenerate) + " degenerate, " +
                                                   std::to_string(measures[p].summary.overlapping_pairs) +
                                                   " overlapping pairs of triangles"}});
      const auto& faces = atlas.chart(result.patches[p].chart).faces;
      for(std::size_t k = 0; k < faces.size() && k < measures[p].per_face.size(); ++k) {
        area[faces[k].idx()] = measures[p].per_face[k].area;
        stretch[faces[k].idx()] = measures[p].per_face[k].stretch_l2;
      }
    }
    json area_json = json::array(), stretch_json = json::array();
    for(std::size_t f = 0; f < area.size(); ++f) {
      area_json.push_back(finite(area[f]));
      stretch_json.push_back(finite(stretch[f]));
    }
    out["corner_uv"] = std::move(corner_uv);
    out["face_chart"] = std::move(face_chart);
    out["face_area_distortion"] = std::move(area_json);
    out["face_stretch"] = std::move(stretch_json);
    out["summary"] = {{"charts", charts},
                      {"l2", finite(total.stretch_l2)},
                      {"area", finite(total.area_mean)},
                      {"angle", finite(total.angle_mean)},
                      {"moved", moved},
                      {"injective", total.injective()}};
    return out;
  }

  // The labels as the mesh file's faces carry them (one per polygon of the
  // file, what `diffuv param MESH --labels FILE` reads).
  std::vector<int> file_labels(const std::vector<int>& labels) const
  {
    const Input_mesh& in = mesh();
    const auto& report = in.report;
    if(labels.empty()) throw Bad_request{400, "nothing is painted: there are no labels to save"};
    std::vector<int> by_polygon(report.faces_in_file, 0);
    std::size_t f = 0;
    for(auto face : in.mesh.faces()) {
      const std::size_t polygon = f < report.file_face.size() ? report.file_face[f] : f;
      if(polygon < by_polygon.size()) by_polygon[polygon] = labels[face.idx()];
      ++f;
    }
    return by_polygon;
  }

  std::string painted_ply(const std::vector<int>& labels) const
  {
    if(labels.empty()) throw Bad_request{400, "nothing is painted: there is no painted mesh to save"};
    std::ostringstream out;
    diffuv::write_labelled_ply(out, mesh().mesh, mesh().mesh.points(), labels);
    return out.str();
  }

  const Input_mesh& mesh() const
  {
    if(!mesh_)
      throw Bad_request{404, which_ == "a" ? "no mesh is loaded: open one in the page or POST it to /api/mesh"
                                           : "no second mesh (B) is loaded: open one in the page or POST it to "
                                             "/api/mesh?mesh=b"};
    return *mesh_;
  }

private:
  std::size_t threads_;
  std::string which_;
  bool strict_input_;
  std::unique_ptr<Input_mesh> mesh_;
  std::uint64_t generation_ = 0;
};

// The last correspondence built, kept while the meshes and the labels stay:
// the page asks again for every picked point.
struct Correspondence_cache {
  using Labelled = diffuv::Labelled_atlas<Mesh>;
  using Correspondence = diffuv::Atlas_correspondence<Mesh, Mesh>;
  std::uint64_t generation_a = 0, generation_b = 0;
  std::vector<int> labels_a, labels_b;
  bool transfer = false;
  std::unique_ptr<Labelled> atlas_a, atlas_b;       // destroyed after the correspondence (declared before it)
  std::unique_ptr<Correspondence> correspondence;
  json answer;  // all but the points

  void clear()
  {
    correspondence.reset();
    atlas_b.reset();
    atlas_a.reset();
    answer = json();
  }
  bool holds(std::uint64_t a, std::uint64_t b, const std::vector<int>& la, const std::vector<int>& lb, bool t) const
  {
    return correspondence && a == generation_a && b == generation_b && la == labels_a && lb == labels_b && t == transfer;
  }
};

// POST /api/correspond: every vertex of A (and any points asked for) mapped
// onto B through (region, u, v), as `diffuv correspond` maps them.
json correspond(const Painter& a, const Painter& b, const std::string& body, Correspondence_cache& cache)
{
  using Labelled = Correspondence_cache::Labelled;
  using Correspondence = Correspondence_cache::Correspondence;
  const json request = parsed_request(body);
  if(!request.is_object())
    throw Bad_request{400, "the request is not a JSON object like {\"labels_a\": [...], \"labels_b\": [...]}"};
  for(const char* key : {"labels_a", "labels_b"})
    if(request.contains(key) && !request[key].is_array())
      throw Bad_request{400, std::string("\"") + key + "\" is not an array of labels"};
  for(const char* key : {"transfer_labels", "only_points"})
    if(request.contains(key) && !request[key].is_boolean())
      throw Bad_request{400, std::string("\"") + key + "\" is not true or false"};
  const bool transfer = request.value("transfer_labels", false);
  const bool only_points = request.value("only_points", false);
  const Mesh& ma = a.mesh().mesh;
  const Mesh& mb = b.mesh().mesh;
  // Labels not sent: the ones the mesh came with (B's are ignored when they
  // are to be carried from A). Faces not painted (-1) on either mesh are one
  // region of the same label on both, so that they pair.
  std::vector<int> labels_a = request.contains("labels_a") ? a.labels_from(request["labels_a"], " of mesh A", true)
                                                           : a.mesh().face_labels;
  std::vector<int> labels_b = request.contains("labels_b") ? b.labels_from(request["labels_b"], " of mesh B", true)
                              : transfer                   ? std::vector<int>()
                                                           : b.mesh().face_labels;
  if(labels_a.empty())
    throw Bad_request{400, "mesh A has no regions: a correspondence pairs the same painted regions on both meshes"};
  if(labels_b.empty() && !transfer)
    throw Bad_request{400, "mesh B has no regions: paint the same regions on it (or ask for \"transfer_labels\" if B "
                           "lies on top of A)"};
  int largest = -1;
  for(const auto* labels : {&labels_a, &labels_b})
    for(int l : *labels) largest = std::max(largest, l);
  for(auto* labels : {&labels_a, &labels_b})
    for(int& l : *labels)
      if(l < 0) l = largest + 1;

  // The points of A asked for: [{"face": f, "barycentric": [w0, w1, w2]}].
  std::vector<std::pair<Mesh::Face_index, std::array<double, 3>>> points;
  if(request.contains("points")) {
    const json& ps = request["points"];
    if(!ps.is_array() || ps.size() > 100000) throw Bad_request{400, "\"points\" is not an array of at most 100000 points"};
    for(std::size_t i = 0; i < ps.size(); ++i) {
      const json& q = ps[i];
      const std::string which = "point " + std::to_string(i);
      if(!q.is_object() || !q.contains("face") || !q["face"].is_number_integer() || !q.contains("barycentric") ||
         !q["barycentric"].is_array() || q["barycentric"].size() != 3)
        throw Bad_request{400, which + " is not {\"face\": F, \"barycentric\": [w0, w1, w2]}"};
      const long long f = q["face"].get<long long>();
      if(f < 0 || f >= static_cast<long long>(num_faces(ma)))
        throw Bad_request{400, which + ": face " + std::to_string(f) + " is not a face of mesh A (" +
                                   count_text(num_faces(ma), "face") + ")"};
      std::array<double, 3> w{};
      for(int k = 0; k < 3; ++k) {
        const json& x = q["barycentric"][k];
        if(!x.is_number() || !std::isfinite(x.get<double>()) || x.get<double>() < 0.)
          throw Bad_request{400, which + ": its barycentric coordinates must be numbers ≥ 0"};
        w[k] = x.get<double>();
      }
      // Scaled by the largest first, so that huge weights do not overflow the sum.
      const double largest = std::max({w[0], w[1], w[2]});
      if(!(largest > 0.)) throw Bad_request{400, which + ": its barycentric coordinates sum to 0"};
      for(double& x : w) x /= largest;
      const double sum = w[0] + w[1] + w[2];
      for(double& x : w) x /= sum;
      points.emplace_back(Mesh::Face_index(static_cast<Mesh::size_type>(f)), cgal_from_api(w));
    }
  }

  const auto start = std::chrono::steady_clock::now();
  const bool cached = cache.holds(a.generation(), b.generation(), labels_a, labels_b, transfer);
  if(!cached) {
    cache.clear();
    const std::vector<int> sent_a = labels_a, sent_b = labels_b;
    if(labels_b.empty()) {
      diffuv::Nearest_face_report lying;
      labels_b = diffuv::nearest_face_labels(ma, labels_a, mb, &lying);
      if(!lying.lies_on_source())
        throw Bad_request{422, "mesh B does not lie on mesh A (the median distance from its faces to A is " +
                                   std::to_string(std::lround(100. * lying.median_fraction())) +
                                   " % of A's diagonal): \"transfer_labels\" needs a copy of A in A's place; paint B's regions"};
    }
    // As `diffuv correspond` builds them: regions B loses join their
    // neighbour on both meshes (by the longest border too when B's labels
    // were carried from A).
    diffuv::Labelled_atlas_pair_options pairing;
    pairing.join_labels_missing_in_b = sent_b.empty();
    diffuv::Labelled_atlas_pair<Mesh> both;
    try {
      both = diffuv::build_labelled_atlas_pair<diffuv::Fmm_distance_tag>(ma, ma.points(), labels_a, mb, mb.points(),
                                                                         labels_b, pairing);
    } catch(const diffuv::Error& e) {
      throw Bad_request{422, e.what()};
    }
    if(!both.status) throw Bad_request{422, both.status.what()};
    std::unique_ptr<Labelled> atlas_a = std::move(both.a), atlas_b = std::move(both.b);
    json joined = json::array();  // [label, the region it joined]
    for(const auto& [label, region] : both.joined) joined.push_back({label, region});
    auto correspondence = std::make_unique<Correspondence>(*atlas_a, *atlas_b);
    const diffuv::Region_match_report& match = correspondence->report();

    json vertex_face = json::array(), vertex_point = json::array();
    std::size_t mapped = 0, inside = 0;
    for(const auto& p : correspondence->map_vertices()) {
      vertex_face.push_back(p.mapped() ? static_cast<long long>(p.face.idx()) : -1LL);
      for(int k = 0; k < 3; ++k) vertex_point.push_back(p.mapped() ? finite(p.point[k]) : json(nullptr));
      mapped += p.mapped();
      inside += p.mapped() && p.inside;
    }
    // Paired charts share a number, so the page can colour them alike.
    auto face_charts = [](const Labelled& atlas) {
      json result = json::array();
      for(auto f : atlas.mesh().faces()) {
        const std::size_t c = atlas.atlas.chart_of(f);
        result.push_back(c == Atlas::no_chart ? -1LL : static_cast<long long>(c));
      }
      return result;
    };
    // Each chart's patch name (`correspond` prints them: label.part).
    const std::vector<std::string> names_a = diffuv::patch_names(atlas_a->segmentation),
                                   names_b = diffuv::patch_names(atlas_b->segmentation);
    auto chart_names = [](const Labelled& atlas, const std::vector<std::string>& names) {
      json result(std::vector<std::string>(atlas.atlas.number_of_charts()));
      for(std::size_t p = 0; p < atlas.patches.size() && p < names.size(); ++p)
        if(atlas.patches[p].status && atlas.patches[p].chart < result.size()) result[atlas.patches[p].chart] = names[p];
      return result;
    };
    json chart_pair = json::array();
    for(std::size_t c = 0; c < atlas_a->atlas.number_of_charts(); ++c) {
      const std::size_t cb = correspondence->chart_b(c);
      chart_pair.push_back(cb == Correspondence::no_chart ? -1LL : static_cast<long long>(cb));
    }
    auto names = [](const std::vector<diffuv::Patch_key>& keys) {
      json result = json::array();
      for(const auto& k : keys) result.push_back(diffuv::patch_name(k));
      return result;
    };
    json problems = json::array();
    for(const Labelled* atlas : {atlas_a.get(), atlas_b.get()}) {
      const std::vector<std::string>& patch = atlas == atlas_a.get() ? names_a : names_b;
      for(std::size_t p = 0; p < atlas->patches.size() && p < patch.size(); ++p)
        if(!atlas->patches[p].status)
          problems.push_back(std::string(atlas == atlas_a.get() ? "on A" : "on B") + ", patch " + patch[p] +
                             " could not be mapped: " + without_patch_prefix(atlas->patches[p].status.what(), p));
    }
    if(!match.unmatched_patches_a.empty())
      problems.push_back("patches of A without a counterpart on B: " + as_text(names(match.unmatched_patches_a)));
    if(!match.unmatched_patches_b.empty())
      problems.push_back("patches of B without a counterpart on A: " + as_text(names(match.unmatched_patches_b)));
    if(!joined.empty())
      problems.push_back("regions too small for B, joined to a neighbour on both meshes ([label, the region it joined]): " +
                         as_text(joined));
    if(!match.labels_with_different_pieces.empty())
      problems.push_back("labels cut into a different number of patches on A and B (their pieces pair by decreasing "
                         "area: check them): " + as_text(json(match.labels_with_different_pieces)));
    if(match.matched_patches == 0)
      throw Bad_request{422, "no patch of A pairs with a patch of B (labels of A: " + as_text(json(match.labels_only_in_a)) +
                                 " not on B; of B: " + as_text(json(match.labels_only_in_b)) + " not on A" +
                                 (problems.empty() ? std::string() : "; " + problems[0].get<std::string>()) + ")"};
    cache.answer = {{"vertex_face", std::move(vertex_face)},
                    {"vertex_point", std::move(vertex_point)},
                    {"face_chart_a", face_charts(*atlas_a)},
                    {"face_chart_b", face_charts(*atlas_b)},
                    {"chart_pair", std::move(chart_pair)},
                    {"chart_name_a", chart_names(*atlas_a, names_a)},
                    {"chart_name_b", chart_names(*atlas_b, names_b)},
                    {"labels_b", transfer && sent_b.empty() ? json(labels_b) : json(nullptr)},
                    {"report",
                     {{"matched_patches", match.matched_patches},
                      {"matched_labels", match.matched_labels},
                      {"labels_only_in_a", match.labels_only_in_a},
                      {"labels_only_in_b", match.labels_only_in_b},
                      {"unmatched_patches_a", names(match.unmatched_patches_a)},
                      {"unmatched_patches_b", names(match.unmatched_patches_b)},
                      {"labels_with_different_pieces", match.labels_with_different_pieces},
                      {"joined_labels", joined},
                      {"vertices", num_vertices(ma)},
                      {"mapped", mapped},
                      {"inside", inside}}},
                    {"problems", std::move(problems)}};
    cache.generation_a = a.generation();
    cache.generation_b = b.generation();
    cache.labels_a = sent_a;
    cache.labels_b = sent_b;
    cache.transfer = transfer;
    cache.atlas_a = std::move(atlas_a);
    cache.atlas_b = std::move(atlas_b);
    cache.correspondence = std::move(correspondence);
  }

  json asked = json::array();
  for(const auto& [f, w] : points) {
    const auto p = cache.correspondence->map_point(f, w);
    if(!p.mapped()) {
      asked.push_back(nullptr);
      continue;
    }
    const auto bary = api_from_cgal(p.barycentric);
    asked.push_back({{"face", static_cast<std::size_t>(p.face.idx())},
                     {"barycentric", {finite(bary[0]), finite(bary[1]), finite(bary[2])}},
                     {"point", {finite(p.point.x()), finite(p.point.y()), finite(p.point.z())}},
                     {"chart", p.chart},
                     {"inside", p.inside}});
  }
  json out = only_points ? json::object() : cache.answer;
  out["points"] = std::move(asked);
  out["cached"] = cached;
  out["milliseconds"] = milliseconds_since(start);
  return out;
}

void send_error(httplib::Response& res, int status, const std::string& message)
{
  res.status = status;
  res.set_content(as_text(json{{"error", message}}), "application/json");
}

// The mesh's file name as sent by the page: a plain name with a known extension.
std::string checked_mesh_name(const std::string& name)
{
  const std::string plain = std::filesystem::path(name).filename().string();
  std::string ext = std::filesystem::path(plain).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const bool control = std::any_of(name.begin(), name.end(), [](unsigned char c) { return c < 32 || c == 127; });
  if(control || plain.empty() || plain != name || (ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl"))
    throw Bad_request{400, "the mesh name '" + (control ? std::string("(with control characters)") : name) +
                               "' is not a file name ending in .off, .obj, .ply or .stl"};
  if(name.size() > 200) throw Bad_request{400, "the mesh name is longer than 200 characters"};
  return plain;
}

void run_server(const Serve_options& options)
{
  // SIGINT and SIGTERM are waited for by one thread (below), which stops the
  // server; blocked here, before any other thread starts, so no other thread
  // takes them.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  Painter painter_a(options.threads, "a", options.strict_input), painter_b(options.threads, "b", options.strict_input);
  if(!options.mesh.empty())
    painter_a.load(options.mesh, std::filesystem::path(options.mesh).filename().string(), options.labels);
  if(!options.mesh_b.empty())
    painter_b.load(options.mesh_b, std::filesystem::path(options.mesh_b).filename().string(), options.labels_b);
  Correspondence_cache correspondence_cache;  // cleared before a mesh it refers to goes
  // ?mesh=a (the default) or ?mesh=b: which mesh a request is about.
  auto slot = [&](const httplib::Request& req) -> Painter& {
    const std::string which = req.has_param("mesh") ? req.get_param_value("mesh") : "a";
    if(which == "a") return painter_a;
    if(which == "b") return painter_b;
    throw Bad_request{400, "?mesh= takes a or b (the second mesh), not '" + which + "'"};
  };
  std::mutex working;  // one request at a time touches the mesh (CGAL adds property maps even to a const mesh)

  // A temporary folder of this server's own (mkdtemp: a fresh name, mode
  // 0700, never an existing folder or link), for meshes sent by the page.
  std::string uploads_template = (std::filesystem::temp_directory_path() / "diffuv-serve-XXXXXX").string();
  if(!::mkdtemp(uploads_template.data()))
    throw diffuv::Output_error(uploads_template, "cannot make a temporary folder for the meshes sent by the page");
  const std::filesystem::path uploads = uploads_template;
  struct Removed_at_exit {  // also when the server cannot start (a port in use)
    std::filesystem::path folder;
    ~Removed_at_exit()
    {
      std::error_code ignored;
      std::filesystem::remove_all(folder, ignored);
    }
  } remove_uploads{uploads};

  httplib::Server server;
  // httplib's default also sets SO_REUSEPORT, with which a second server on
  // the same port would start and share it silently: address reuse only.
  server.set_socket_options([](socket_t sock) {
    int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  const std::size_t max_request_mb = options.max_request_mb;
  server.set_payload_max_length(max_request_mb << 20);
  server.set_read_timeout(10, 0);      // a stalled client holds a worker (and the shutdown) this long at most
  server.set_keep_alive_timeout(1);    // an open page's idle connection does not delay Ctrl-C
  server.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr e) {
    try {
      if(e) std::rethrow_exception(e);
    } catch(const std::exception& x) {
      send_error(res, 500, std::string("internal error: ") + x.what());
      return;
    } catch(...) {
    }
    send_error(res, 500, "internal error");
  });
  server.set_error_handler([max_request_mb](const httplib::Request& req, httplib::Response& res) {
    if(!res.body.empty()) return;
    if(res.status == 404) send_error(res, 404, "no such page: " + req.path);
    else if(res.status == 413) send_error(res, 413, "the request is larger than " + std::to_string(max_request_mb) + " MB");
    else if(res.status == 414) send_error(res, 414, "the address is too long");
    else if(res.status == 400)
      send_error(res, 400, "the request could not be read (a body needs a Content-Length, and is dropped if it "
                           "stalls for 10 s)");
    else send_error(res, res.status, "bad request");
  });

  // Every API call: the mesh locked, a refusal turned into its status.
  auto api = [&](auto handler) {
    return [&, handler](const httplib::Request& req, httplib::Response& res) {
      std::lock_guard<std::mutex> lock(working);
      try {
        handler(req, res);
      } catch(const Bad_request& e) {
        send_error(res, e.status, e.message);
      } catch(const diffuv::Input_error& e) {
        send_error(res, 400, e.what());
      } catch(const diffuv::Error& e) {
        send_error(res, 422, e.what());
      } catch(const json::exception& e) {  // a value of the wrong type that a check above missed
        send_error(res, 400, std::string("the request does not say what it should: ") + e.what());
      }
    };
  };

  const char* page_dir = std::getenv("DIFFUV_PAINTER_DIR");  // development: the page's files from disk
  if(page_dir && !std::filesystem::exists(std::filesystem::path(page_dir) / "index.html"))
    std::cerr << "diffuv: warning: DIFFUV_PAINTER_DIR=" << page_dir << " has no index.html: the page will be empty\n";
  auto page_file = [page_dir](const char* name, const char* built_in, const char* type) {
    return [=](const httplib::Request&, httplib::Response& res) {
      if(page_dir) {
        std::ifstream file(std::filesystem::path(page_dir) / name, std::ios::binary);
        std::stringstream text;
        text << file.rdbuf();
        res.set_content(text.str(), type);
      } else {
        res.set_content(built_in, type);
      }
      res.set_header("Cache-Control", "no-store");
    };
  };
  server.Get("/", page_file("index.html", painter_index_html, "text/html; charset=utf-8"));
  server.Get("/index.html", page_file("index.html", painter_index_html, "text/html; charset=utf-8"));
  server.Get("/painter.js", page_file("painter.js", painter_js, "text/javascript; charset=utf-8"));
  server.Get("/painter.css", page_file("painter.css", painter_css, "text/css; charset=utf-8"));
  if(!server.set_mount_point("/three", options.three_dir))
    std::cerr << "diffuv: warning: " << options.three_dir
              << " is not there: the page needs three.js (Debian package libjs-three)\n";

  server.Get("/api/mesh", api([&](const httplib::Request& req, httplib::Response& res) {
    res.set_content(as_text(slot(req).mesh_json()), "application/json");
  }));
  server.Post("/api/mesh", api([&](const httplib::Request& req, httplib::Response& res) {
    Painter& painter = slot(req);
    if(!req.has_param("name")) throw Bad_request{400, "POST /api/mesh needs ?name=FILE.off (or .obj, .ply, .stl)"};
    const std::string name = checked_mesh_name(req.get_param_value("name"));
    if(req.body.empty()) throw Bad_request{400, name + ": the request has no file in its body"};
    const std::filesystem::path file = uploads / name;
    {
      std::ofstream out(file, std::ios::binary);
      out.write(req.body.data(), static_cast<std::streamsize>(req.body.size()));
      if(!out) throw Bad_request{500, "cannot keep the mesh in " + uploads.string()};
    }
    Painter next(options.threads, req.has_param("mesh") ? req.get_param_value("mesh") : "a", options.strict_input);  // the mesh in use stays if the new one cannot be read
    try {
      next.load(file.string(), name);
    } catch(const diffuv::Error& e) {
      std::filesystem::remove(file);
      std::string what = e.what();
      const std::string path = file.string();
      for(std::size_t at = what.find(path); at != std::string::npos; at = what.find(path)) what.replace(at, path.size(), name);
      throw Bad_request{400, what};
    }
    std::filesystem::remove(file);
    correspondence_cache.clear();  // its atlases refer to the mesh replaced
    painter = std::move(next);
    res.set_content(as_text(painter.mesh_json()), "application/json");
  }));
  server.Post("/api/layout", api([&](const httplib::Request& req, httplib::Response& res) {
    Painter& painter = slot(req);
    res.set_content(as_text(painter.layout(painter.labels_of(req.body), false)), "application/json");
  }));
  server.Post("/api/param", api([&](const httplib::Request& req, httplib::Response& res) {
    Painter& painter = slot(req);
    res.set_content(as_text(painter.layout(painter.labels_of(req.body), true)), "application/json");
  }));
  server.Post("/api/labels.txt", api([&](const httplib::Request& req, httplib::Response& res) {
    const Painter& painter = slot(req);
    const std::vector<int> labels = painter.file_labels(painter.labels_of(req.body));
    std::string text = "# diffuv labels: one region per face of " + painter.mesh().path + ", in the file's order\n";
    for(int l : labels) text += std::to_string(l) + '\n';
    res.set_content(text, "text/plain; charset=utf-8");
    res.set_header("Content-Disposition", "attachment; filename=\"labels.txt\"");
  }));
  server.Post("/api/painted.ply", api([&](const httplib::Request& req, httplib::Response& res) {
    const Painter& painter = slot(req);
    res.set_content(painter.painted_ply(painter.labels_of(req.body)), "application/octet-stream");
    res.set_header("Content-Disposition", "attachment; filename=\"painted.ply\"");
  }));

  server.Post("/api/correspond", api([&](const httplib::Request& req, httplib::Response& res) {
    res.set_content(as_text(correspond(painter_a, painter_b, req.body, correspondence_cache)), "application/json");
  }));
  // The routes that take a body answer other methods with 405, not "no such page".
  for(const char* route : {"/api/layout", "/api/param", "/api/labels.txt", "/api/painted.ply", "/api/correspond"}) {
    const auto not_allowed = [route](const httplib::Request&, httplib::Response& res) {
      send_error(res, 405, std::string(route) + " takes a POST with a JSON body (doc/painter.md)");
      res.set_header("Allow", "POST");
    };
    server.Get(route, not_allowed).Put(route, not_allowed).Patch(route, not_allowed).Delete(route, not_allowed);
    server.Options(route, not_allowed);
  }
  const auto mesh_not_allowed = [](const httplib::Request&, httplib::Response& res) {
    send_error(res, 405, "/api/mesh takes a GET, or a POST with a mesh file (doc/painter.md)");
    res.set_header("Allow", "GET, POST");
  };
  server.Put("/api/mesh", mesh_not_allowed).Patch("/api/mesh", mesh_not_allowed).Delete("/api/mesh", mesh_not_allowed);
  server.Options("/api/mesh", mesh_not_allowed);

  int port = options.port;
  if(port == 0) {
    port = server.bind_to_any_port(options.host);
    if(port < 0) throw diffuv::Input_error(options.host, 0, "cannot listen on any port of this address");
  } else if(!server.bind_to_port(options.host, port)) {
    throw diffuv::Input_error(options.host + ":" + std::to_string(port), 0,
                              "cannot listen there (in use? try --port 0 for any free port)");
  }
  const bool loopback = options.host == "127.0.0.1" || options.host == "localhost" || options.host == "::1";
  const bool any_address = options.host == "0.0.0.0" || options.host == "::";
  const std::string shown_host =
      any_address ? "127.0.0.1" : options.host.find(':') != std::string::npos ? "[" + options.host + "]" : options.host;
  if(!loopback)
    std::cerr << "diffuv: warning: listening on " << options.host
              << ": anyone who can reach it can load meshes into this server" << std::endl;
  std::cout << "diffuv: serving http://" << shown_host << ':' << port << "/"
            << (any_address ? " (on every address of this machine)" : "")
            << (options.mesh.empty() ? "" : " (" + options.mesh + (options.mesh_b.empty() ? "" : " and " + options.mesh_b) + ")")
            << "; Ctrl-C stops it" << std::endl;

  // Before a body is read: refuse what would slip past the size limit
  // (chunked or compressed bodies), form-encoded bodies (httplib caps them at
  // 8 KB), and, on this machine's loopback, requests for another host name or
  // from another site's page (DNS rebinding, cross-site posts).
  const std::string port_text = std::to_string(port);
  const std::vector<std::string> own_hosts = {"127.0.0.1:" + port_text, "localhost:" + port_text, "[::1]:" + port_text};
  server.set_pre_routing_handler([loopback, own_hosts, port_text](const httplib::Request& req, httplib::Response& res) {
    auto refuse = [&](int status, const std::string& message) {
      send_error(res, status, message);
      return httplib::Server::HandlerResponse::Handled;
    };
    if(req.path.find('\0') != std::string::npos) return refuse(400, "the path has a NUL byte");
    const std::string host = req.get_header_value("Host");
    if(loopback && std::find(own_hosts.begin(), own_hosts.end(), host) == own_hosts.end())
      return refuse(403, "this server answers requests for 127.0.0.1:" + port_text + " only, not for '" + host + "'");
    if(req.has_header("Origin")) {
      const std::string origin = req.get_header_value("Origin");
      const bool own = loopback ? std::any_of(own_hosts.begin(), own_hosts.end(),
                                              [&](const std::string& h) { return origin == "http://" + h; })
                                : origin == "http://" + host;
      if(!own) return refuse(403, "requests from the page of another site (" + origin + ") are refused");
    }
    if(req.get_header_value("Transfer-Encoding").find("chunked") != std::string::npos)
      return refuse(411, "send the body with a Content-Length, not in chunks");
    const std::string encoding = req.get_header_value("Content-Encoding");
    if(!encoding.empty() && encoding != "identity")
      return refuse(415, "send the body uncompressed (Content-Encoding: " + encoding + ")");
    if(req.get_header_value("Content-Type").find("application/x-www-form-urlencoded") != std::string::npos)
      return refuse(415, "send the body as application/json, or as application/octet-stream for a mesh "
                         "(curl: -H 'Content-Type: application/json')");
    return httplib::Server::HandlerResponse::Unhandled;
  });

  std::atomic<bool> stopping{false};
  std::thread stopper([&] {
    int signal = 0;
    sigwait(&stop_signals, &signal);
    stopping = true;
    server.stop();
  });
  server.listen_after_bind();
  if(!stopping) {  // listen ended by itself: wake the stopper so it can be joined
    stopping = true;
    pthread_kill(stopper.native_handle(), SIGTERM);
  }
  stopper.join();
  std::cout << "diffuv: stopped" << std::endl;
}

} // namespace

void add_serve_command(CLI::App& app)
{
  auto options = std::make_shared<Serve_options>();
  CLI::App* cmd = app.add_subcommand(
      "serve", "Paint regions on a mesh in the browser and see the patches and the map (a local web server; "
             "open the address it prints; ?view=patches, isolines, distortion or correspond opens that view, "
             "&pick=FACE picks A's face FACE in the correspondence view, &colors=gradient colours it by position on "
             "B; guide and HTTP API: doc/painter.md)");
  cmd->add_option("mesh", options->mesh, "The mesh to open (OFF, OBJ, PLY, STL; painted colours or labels are read); "
                                         "default: none, open one in the page")
      ->check(CLI::ExistingFile);
  cmd->add_option("mesh_b", options->mesh_b,
                  "A second mesh, to paint the same regions on and see the correspondence (as `diffuv correspond "
                  "MESH MESH_B`); default: none, open one in the page")
      ->check(CLI::ExistingFile);
  cmd->add_option("--labels", options->labels, "A label file for the mesh (one region per polygon of the file, as param --labels reads), to go on painting")
      ->check(CLI::ExistingFile);
  cmd->add_option("--labels-b", options->labels_b, "A label file for the second mesh")->check(CLI::ExistingFile);
  cmd->add_option("--port", options->port, "The port to listen on (0: any free port, printed)")
      ->check(number_in(0, 65535))
      ->capture_default_str();
  cmd->add_option("--host", options->host, "The address to listen on (default: this machine only)")->capture_default_str();
  cmd->add_option("--three", options->three_dir, "Where three.js is (Debian's libjs-three)")->capture_default_str();
  cmd->add_option("--threads", options->threads, "Threads that map the patches (0: all)")
      ->check(number_in(0, 1024))
      ->capture_default_str();
  add_strict_input_option(cmd, options->strict_input);
  cmd->add_option("--max-request-mb", options->max_request_mb, "The largest request accepted, in MB (a mesh sent by the page)")
      ->check(number_in(1, 4096))
      ->capture_default_str();
  cmd->callback([options] {
    if(!options->labels.empty() && options->mesh.empty())
      throw CLI::ValidationError("--labels", "needs a mesh to go with (diffuv serve MESH --labels FILE)");
    if(!options->labels_b.empty() && options->mesh_b.empty())
      throw CLI::ValidationError("--labels-b", "needs a second mesh to go with (diffuv serve MESH MESH_B --labels-b FILE)");
    run_server(*options);
  });
}

} // namespace diffuv_cli
