// Tests of `diffuv serve` (src/cli/serve.cpp) through its HTTP API, as the
// page uses it: the tool started on a free port, an httplib client, JSON
// answers checked against the mesh file and against `diffuv param` run on the
// same labels; bad requests get a 4xx status and a message, and the server
// goes on; Ctrl-C (SIGINT) stops it cleanly.
#include "test_cli_tool.h"

#include <httplib.h>
#include <nlohmann/json.hpp>

#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <set>
#include <thread>
#include <unistd.h>

namespace {

using namespace diffuv_cli_test;
using json = nlohmann::json;

// `diffuv serve ARGS --port 0` in the background; its stdout read until the
// line that names the address.
class Server_process {
public:
  Server_process(const std::string& args, const fs::path& log)
  {
    int pipe_fds[2];
    if(::pipe(pipe_fds) != 0) return;
    pid_ = ::fork();
    if(pid_ == 0) {
      ::dup2(pipe_fds[1], 1);
      const int err = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(err, 2);
      ::close(pipe_fds[0]);
      const std::string cmd = std::string("exec ") + DIFFUV_TOOL_PATH + " serve " + args + " --port 0";
      ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(pipe_fds[1]);
    out_ = ::fdopen(pipe_fds[0], "r");
    char line[512];
    if(out_ && std::fgets(line, sizeof line, out_)) {
      first_line_ = line;
      const auto colon = first_line_.find("127.0.0.1:");
      if(colon != std::string::npos) port_ = std::atoi(first_line_.c_str() + colon + 10);
    }
  }
  ~Server_process()
  {
    // Stopped as a user would (so it removes its temporary folder), killed if it does not stop.
    if(pid_ > 0 && !waited_ && stop(SIGTERM, 5) == -1 && !waited_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    if(out_) std::fclose(out_);
  }
  int port() const { return port_; }
  const std::string& first_line() const { return first_line_; }

  // Sends `signal` and waits up to `seconds` for the exit: the exit code, or -1.
  int stop(int signal, int seconds)
  {
    ::kill(pid_, signal);
    for(int i = 0; i < seconds * 20; ++i) {
      int status = 0;
      if(::waitpid(pid_, &status, WNOHANG) == pid_) {
        waited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return -1;
  }
  // The rest of stdout (after stop()).
  std::string rest()
  {
    std::string text;
    char line[512];
    while(out_ && std::fgets(line, sizeof line, out_)) text += line;
    return text;
  }

private:
  pid_t pid_ = -1;
  FILE* out_ = nullptr;
  std::string first_line_;
  int port_ = 0;
  bool waited_ = false;
};

class Serve : public Tool {
protected:
  json post_json(httplib::Client& client, const std::string& path, const json& body, int expected_status = 200)
  {
    auto res = client.Post(path.c_str(), body.dump(), "application/json");
    EXPECT_TRUE(res) << path;
    if(!res) return json();
    EXPECT_EQ(res->status, expected_status) << path << ": " << res->body.substr(0, 300);
    return json::parse(res->body, nullptr, false);
  }
};

// Labels by height: cow cut into `bands` bands of equal height (y).
std::vector<int> height_bands(const diffuv_test::Mesh& m, int bands)
{
  double lo = 1e300, hi = -1e300;
  for(auto v : vertices(m)) {
    lo = std::min(lo, m.point(v).y());
    hi = std::max(hi, m.point(v).y());
  }
  std::vector<int> labels;
  for(auto f : faces(m)) {
    double y = 0;
    for(auto v : vertices_around_face(m.halfedge(f), m)) y += m.point(v).y() / 3;
    labels.push_back(std::min(bands - 1, static_cast<int>(bands * (y - lo) / (hi - lo))));
  }
  return labels;
}

TEST_F(Serve, MeshLayoutAndMapAsThePageGetsThem)
{
  const std::string cow_path = data_path("meshes/cow.off");
  Server_process server(cow_path, dir_ / "server.err");
  ASSERT_GT(server.port(), 0) << server.first_line() << slurp(dir_ / "server.err");
  EXPECT_NE(server.first_line().find("http://127.0.0.1:"), std::string::npos);
  httplib::Client client("127.0.0.1", server.port());
  client.set_read_timeout(120, 0);

  const diffuv_test::Mesh& cow = diffuv_test::cgal_mesh("cow.off");
  auto res = client.Get("/api/mesh");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200);
  const json mesh = json::parse(res->body);
  EXPECT_EQ(mesh["name"], "cow.off");
  ASSERT_EQ(mesh["vertices"].size(), 3 * num_vertices(cow));
  ASSERT_EQ(mesh["faces"].size(), 3 * num_faces(cow));
  EXPECT_TRUE(mesh["labels"].is_null());
  for(std::size_t i = 0; i < 30; ++i) {  // the file's points, in the file's order
    const auto& p = cow.point(diffuv_test::Mesh::Vertex_index(static_cast<unsigned>(i)));
    EXPECT_DOUBLE_EQ(mesh["vertices"][3 * i + 1].get<double>(), p.y());
  }

  // Automatic layout: every face in a patch, each mapped patch's four sides
  // run corner to corner around it.
  const json layout = post_json(client, "/api/layout", {{"labels", json::array()}});
  ASSERT_TRUE(layout.is_object());
  const std::size_t np = layout["patches"].get<std::size_t>();
  EXPECT_GT(np, 50u);
  ASSERT_EQ(layout["face_patch"].size(), num_faces(cow));
  std::vector<std::size_t> faces_of(np, 0);
  for(const auto& p : layout["face_patch"]) {
    ASSERT_GE(p.get<int>(), 0);
    ASSERT_LT(p.get<std::size_t>(), np);
    ++faces_of[p.get<std::size_t>()];
  }
  for(std::size_t p = 0; p < np; ++p) EXPECT_GT(faces_of[p], 0u) << "patch " << p;
  std::size_t drawn = 0;
  for(std::size_t p = 0; p < np; ++p) {
    const json& sides = layout["sides"][p];
    const json& corners = layout["corners"][p];
    if(sides.is_null()) continue;
    ++drawn;
    ASSERT_EQ(corners.size(), 4u);
    EXPECT_EQ(std::set<int>(corners.begin(), corners.end()).size(), 4u) << "patch " << p;
    const char* order[4] = {"v1", "u2", "v2", "u1"};
    for(int s = 0; s < 4; ++s) {
      const json& side = sides[order[s]];
      ASSERT_GE(side.size(), 2u) << "patch " << p << " side " << order[s];
      EXPECT_EQ(side.front(), corners[s]) << "patch " << p << " side " << order[s];
      EXPECT_EQ(side.back(), corners[(s + 1) % 4]) << "patch " << p << " side " << order[s];
    }
  }
  EXPECT_EQ(drawn, np);
  EXPECT_TRUE(layout["problems"].is_array());

  // Painted labels: the map, then the saved label file, which `diffuv param
  // --labels` reads into the very same patches.
  const std::vector<int> bands = height_bands(cow, 4);
  const json mapped = post_json(client, "/api/param", {{"labels", bands}});
  ASSERT_TRUE(mapped.is_object());
  ASSERT_EQ(mapped["corner_uv"].size(), 6 * num_faces(cow));
  for(const auto& x : mapped["corner_uv"]) {
    ASSERT_TRUE(x.is_number()) << "a face without (u,v)";
    EXPECT_GE(x.get<double>(), -1e-9);
    EXPECT_LE(x.get<double>(), 1 + 1e-9);
  }
  EXPECT_TRUE(mapped["summary"]["injective"].get<bool>());
  EXPECT_EQ(mapped["summary"]["charts"], mapped["patches"]);
  EXPECT_LT(mapped["summary"]["l2"].get<double>(), 5.0);
  ASSERT_EQ(mapped["face_area_distortion"].size(), num_faces(cow));
  // A patch of a band lies in the band (but for the faces jutting out of a
  // band's jagged border, which the layout gives to the next band).
  std::size_t kept = 0;
  for(std::size_t f = 0; f < num_faces(cow); ++f)
    kept += mapped["patch_label"][mapped["face_patch"][f].get<std::size_t>()].get<int>() == bands[f];
  EXPECT_GE(kept, num_faces(cow) * 97 / 100);

  // The mesh's own labels (none) are still what it answers.
  auto again = client.Get("/api/mesh");
  ASSERT_TRUE(again);
  EXPECT_TRUE(json::parse(again->body)["labels"].is_null());

  auto saved = client.Post("/api/labels.txt", json{{"labels", bands}}.dump(), "application/json");
  ASSERT_TRUE(saved);
  ASSERT_EQ(saved->status, 200);
  std::ofstream(dir_ / "bands.txt") << saved->body;
  const Tool_run param = run("param " + cow_path + " --labels " + (dir_ / "bands.txt").string() + " -o " + out_dir().string() + " -q");
  ASSERT_EQ(param.code, 0) << param.err;
  std::ifstream patches_file(out_dir() / "cow.patches.txt");
  std::string line;
  std::size_t f = 0;
  while(std::getline(patches_file, line)) {
    if(line.empty() || line[0] == '#') continue;
    ASSERT_LT(f, num_faces(cow));
    EXPECT_EQ(std::stoi(line), mapped["face_patch"][f].get<int>()) << "face " << f;
    ++f;
  }
  EXPECT_EQ(f, num_faces(cow));

  // Unpainted faces (-1) are one more region; the painted PLY carries the labels.
  std::vector<int> partly(num_faces(cow), -1);
  for(std::size_t k = 0; k < partly.size(); ++k) if(bands[k] == 0) partly[k] = 3;
  auto ply = client.Post("/api/painted.ply", json{{"labels", partly}}.dump(), "application/json");
  ASSERT_TRUE(ply);
  ASSERT_EQ(ply->status, 200);
  EXPECT_EQ(ply->body.rfind("ply\n", 0), 0u);
  EXPECT_NE(ply->body.find("element face " + std::to_string(num_faces(cow))), std::string::npos);

  EXPECT_EQ(server.stop(SIGINT, 10), 0) << "Ctrl-C must stop the server cleanly";
  EXPECT_NE(server.rest().find("stopped"), std::string::npos);
}

TEST_F(Serve, BadRequestsGetAClearRefusalAndTheServerGoesOn)
{
  Server_process server(data_path("meshes/cow.off") + " --max-request-mb 1", dir_ / "server.err");
  ASSERT_GT(server.port(), 0) << server.first_line() << slurp(dir_ / "server.err");
  httplib::Client client("127.0.0.1", server.port());
  client.set_read_timeout(60, 0);
  const std::size_t nf = num_faces(diffuv_test::cgal_mesh("cow.off"));

  auto expect_refused = [&](httplib::Result res, int status, const std::string& says, const std::string& what) {
    ASSERT_TRUE(res) << what << ": no answer (crashed?)";
    EXPECT_EQ(res->status, status) << what << ": " << res->body.substr(0, 200);
    const json body = json::parse(res->body, nullptr, false);
    ASSERT_TRUE(body.is_object() && body.contains("error")) << what << ": " << res->body.substr(0, 200);
    EXPECT_NE(body["error"].get<std::string>().find(says), std::string::npos) << what << ": " << body["error"];
  };
  expect_refused(client.Post("/api/layout", "{\"labels\": [1, 2", "application/json"), 400, "not JSON", "malformed JSON");
  expect_refused(client.Post("/api/layout", "[]", "application/json"), 400, "no \"labels\"", "no labels");
  expect_refused(client.Post("/api/param", json{{"labels", std::vector<int>(nf - 1, 0)}}.dump(), "application/json"), 400,
                 std::to_string(nf - 1) + " labels for a mesh of " + std::to_string(nf) + " faces", "labels too few");
  json wrong = json{{"labels", std::vector<int>(nf, 0)}};
  wrong["labels"][7] = "leg";
  expect_refused(client.Post("/api/layout", wrong.dump(), "application/json"), 400, "label 7 is \"leg\"", "a string label");
  wrong["labels"][7] = -5;
  expect_refused(client.Post("/api/layout", wrong.dump(), "application/json"), 400, "label 7 is -5", "a label below -1");
  expect_refused(client.Post("/api/labels.txt", json{{"labels", std::vector<int>(nf, -1)}}.dump(), "application/json"), 400,
                 "nothing is painted", "saving nothing");
  expect_refused(client.Post("/api/mesh", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "text/plain"), 400, "?name=",
                 "a mesh without a name");
  expect_refused(client.Post("/api/mesh?name=..%2Fcow.off", "OFF\n", "text/plain"), 400, "not a file name", "a path as name");
  expect_refused(client.Post("/api/mesh?name=cow.exe", "OFF\n", "text/plain"), 400, "not a file name", "an unknown format");
  expect_refused(client.Post("/api/mesh?name=broken.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n", "text/plain"), 400, "broken.off",
                 "a truncated mesh");
  expect_refused(client.Get("/api/nothing"), 404, "no such page", "an unknown path");
  expect_refused(client.Post("/api/layout", std::string(2u << 20, ' '), "application/json"), 413, "larger than",
                 "a request over the limit");
  expect_refused(client.Post("/api/layout", "{\"labels\": \"\xff\xfe\"}", "application/json"), 400, "not JSON",
                 "invalid UTF-8");
  expect_refused(client.Post(("/api/mesh?name=" + std::string(250, 'a') + ".off").c_str(), grid_off, "text/plain"), 400,
                 "longer than 200", "a very long name");
  expect_refused(client.Post("/api/layout", "labels=1", "application/x-www-form-urlencoded"), 415, "application/json",
                 "a form-encoded body (curl -d)");
  {
    httplib::Headers gzip = {{"Content-Encoding", "gzip"}};
    expect_refused(client.Post("/api/layout", gzip, std::string(20, 'x'), "application/json"), 415, "uncompressed",
                   "a compressed body");
    httplib::Headers foreign = {{"Origin", "http://evil.example"}};
    expect_refused(client.Post("/api/mesh?name=grid.off", foreign, grid_off, "text/plain"), 403, "another site",
                   "a post from another site's page");
    httplib::Headers own = {{"Origin", "http://127.0.0.1:" + std::to_string(server.port())}};
    auto same_site = client.Get("/api/mesh", own);
    ASSERT_TRUE(same_site);
    EXPECT_EQ(same_site->status, 200);
    httplib::Headers rebound = {{"Host", "evil.example"}};
    expect_refused(client.Get("/api/mesh", rebound), 403, "127.0.0.1:", "a request for another host name");
  }
  // Files outside the page and three.js are not served.
  auto escape = client.Get("/three/../../../../etc/passwd");
  ASSERT_TRUE(escape);
  EXPECT_GE(escape->status, 400);
  EXPECT_EQ(escape->body.find("root:"), std::string::npos);

  // Still the cow, still serving.
  auto res = client.Get("/api/mesh");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200);
  EXPECT_EQ(json::parse(res->body)["faces"].size(), 3 * nf);
  auto page = client.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("painter.js"), std::string::npos);
  EXPECT_EQ(server.stop(SIGTERM, 10), 0);
}

TEST_F(Serve, WithoutAMeshTheFirstIsSentByThePage)
{
  Server_process server("", dir_ / "server.err");
  ASSERT_GT(server.port(), 0) << server.first_line() << slurp(dir_ / "server.err");
  httplib::Client client("127.0.0.1", server.port());
  auto none = client.Get("/api/mesh");
  ASSERT_TRUE(none);
  EXPECT_EQ(none->status, 404);
  EXPECT_NE(none->body.find("no mesh is loaded"), std::string::npos);
  auto sent = client.Post("/api/mesh?name=grid.off", grid_off, "application/octet-stream");
  ASSERT_TRUE(sent);
  ASSERT_EQ(sent->status, 200) << sent->body;
  const json mesh = json::parse(sent->body);
  EXPECT_EQ(mesh["name"], "grid.off");
  EXPECT_EQ(mesh["faces"].size(), 24u);
  EXPECT_DOUBLE_EQ(mesh["diagonal"].get<double>(), std::sqrt(8.0));
  const json mapped = post_json(client, "/api/param", {{"labels", json::array()}});
  EXPECT_EQ(mapped["patches"], 1);
  EXPECT_TRUE(mapped["summary"]["injective"].get<bool>());
  EXPECT_EQ(server.stop(SIGINT, 10), 0);
}

// Two meshes: cow (A) and a copy turned, scaled and moved, with each face
// listed from another corner (B). The same painted regions on both: every
// vertex of A lands on its copy, asked points and their barycentric
// coordinates come back in each mesh's own face order, and the answer is
// what `diffuv correspond` writes for the same labels.
TEST_F(Serve, SecondMeshAndCorrespondenceAsDiffuvCorrespondGivesThem)
{
  const diffuv_test::Mesh& cow = diffuv_test::cgal_mesh("cow.off");
  auto moved = [](const diffuv_test::Mesh::Point& p) {
    return std::array<double, 3>{{-2. * p.y() + 5., 2. * p.x(), 2. * p.z() - 3.}};
  };
  std::ostringstream b;
  b.precision(17);
  b << "OFF\n" << num_vertices(cow) << ' ' << num_faces(cow) << " 0\n";
  for(auto v : vertices(cow)) {
    const auto q = moved(cow.point(v));
    b << q[0] << ' ' << q[1] << ' ' << q[2] << '\n';
  }
  for(auto f : faces(cow)) {
    std::vector<std::size_t> t;
    for(auto v : CGAL::vertices_around_face(cow.halfedge(f), cow)) t.push_back(v.idx());
    b << "3 " << t[1] << ' ' << t[2] << ' ' << t[0] << '\n';
  }
  const std::string b_path = write("b.off", b.str());
  const std::string cow_path = data_path("meshes/cow.off");
  const std::vector<int> bands = height_bands(cow, 4);

  Server_process server(cow_path + " " + b_path, dir_ / "server.err");
  ASSERT_GT(server.port(), 0) << server.first_line() << slurp(dir_ / "server.err");
  EXPECT_NE(server.first_line().find("b.off"), std::string::npos) << server.first_line();
  httplib::Client client("127.0.0.1", server.port());
  client.set_read_timeout(120, 0);

  auto got_b = client.Get("/api/mesh?mesh=b");
  ASSERT_TRUE(got_b);
  ASSERT_EQ(got_b->status, 200);
  const json mesh_b = json::parse(got_b->body);
  EXPECT_EQ(mesh_b["name"], "b.off");
  ASSERT_EQ(mesh_b["faces"].size(), 3 * num_faces(cow));
  const json mesh_a = json::parse(client.Get("/api/mesh")->body);
  // B's layout is asked for as A's is.
  const json layout_b = post_json(client, "/api/layout?mesh=b", {{"labels", bands}});
  ASSERT_TRUE(layout_b.is_object());
  EXPECT_EQ(layout_b["face_patch"].size(), num_faces(cow));

  // A point inside face 100 of A, and a vertex of face 7 (all weight on one corner).
  const std::array<double, 3> w = {{0.2, 0.3, 0.5}};
  const json asked = json::array({{{"face", 100}, {"barycentric", w}}, {{"face", 7}, {"barycentric", {0, 1, 0}}}});
  const json c = post_json(client, "/api/correspond", {{"labels_a", bands}, {"labels_b", bands}, {"points", asked}});
  ASSERT_TRUE(c.is_object()) << c;
  const std::size_t nv = num_vertices(cow);
  EXPECT_EQ(c["report"]["mapped"], nv);
  EXPECT_EQ(c["report"]["matched_labels"], json({0, 1, 2, 3}));
  EXPECT_TRUE(c["report"]["labels_only_in_a"].empty());
  EXPECT_EQ(c["report"]["joined_labels"], json::array());  // B is A moved: it loses no region
  ASSERT_EQ(c["vertex_point"].size(), 3 * nv);
  ASSERT_EQ(c["vertex_face"].size(), nv);
  // Diagonal of B: twice A's.
  const double tolerance = 1e-6 * mesh_b["diagonal"].get<double>();
  for(auto v : vertices(cow)) {
    const auto q = moved(cow.point(v));
    for(int k = 0; k < 3; ++k)
      ASSERT_NEAR(c["vertex_point"][3 * v.idx() + k].get<double>(), q[k], tolerance) << "vertex " << v.idx();
  }
  auto point_of = [](const json& mesh, std::size_t f, const json& weights) {
    std::array<double, 3> p{{0., 0., 0.}};
    for(int k = 0; k < 3; ++k) {
      const std::size_t v = mesh["faces"][3 * f + k].get<std::size_t>();
      for(int d = 0; d < 3; ++d) p[d] += weights[k].get<double>() * mesh["vertices"][3 * v + d].get<double>();
    }
    return p;
  };
  ASSERT_EQ(c["points"].size(), 2u);
  for(std::size_t i = 0; i < 2; ++i) {
    const json& image = c["points"][i];
    ASSERT_TRUE(image.is_object()) << "point " << i << " not mapped";
    // The asked point of A, moved, is the image; and the image's face and
    // barycentric coordinates (B's face order) give back that point.
    const auto on_a = point_of(mesh_a, asked[i]["face"].get<std::size_t>(), asked[i]["barycentric"]);
    const auto expected = moved(diffuv_test::Mesh::Point(on_a[0], on_a[1], on_a[2]));
    const auto from_b = point_of(mesh_b, image["face"].get<std::size_t>(), image["barycentric"]);
    for(int d = 0; d < 3; ++d) {
      EXPECT_NEAR(image["point"][d].get<double>(), expected[d], tolerance) << "point " << i;
      EXPECT_NEAR(from_b[d], expected[d], tolerance) << "point " << i;
    }
  }
  // Paired charts: as many as A has, each paired with one of B's.
  std::set<int> charts_a(c["face_chart_a"].begin(), c["face_chart_a"].end());
  EXPECT_EQ(charts_a.size(), c["chart_pair"].size());
  EXPECT_EQ(c["report"]["matched_patches"], c["chart_pair"].size());
  for(const auto& pair : c["chart_pair"]) EXPECT_GE(pair.get<int>(), 0);

  // Asked again with the same labels (a picked point): the correspondence
  // is kept, and only the points come back; faces left unpainted on both
  // meshes are one region of the same label on both.
  const json again = post_json(client, "/api/correspond",
                               {{"labels_a", bands}, {"labels_b", bands}, {"points", asked}, {"only_points", true}});
  EXPECT_TRUE(again["cached"].get<bool>());
  EXPECT_FALSE(again.contains("vertex_point"));
  EXPECT_EQ(again["points"], c["points"]);
  std::vector<int> top_unpainted = bands;
  for(int& l : top_unpainted)
    if(l == 3) l = -1;
  const json unpainted = post_json(client, "/api/correspond", {{"labels_a", top_unpainted}, {"labels_b", top_unpainted}});
  EXPECT_TRUE(unpainted["cached"].get<bool>()) << "the unpainted faces are label 3 on both: the regions asked before";
  EXPECT_EQ(unpainted["report"]["matched_labels"], json({0, 1, 2, 3}));
  EXPECT_EQ(unpainted["vertex_point"], c["vertex_point"]);

  // The same labels through `diffuv correspond`: the same points on B.
  std::ostringstream labels;
  for(int l : bands) labels << l << '\n';
  const std::string labels_path = write("bands.txt", labels.str());
  const Tool_run cli = run("correspond " + cow_path + " " + b_path + " --labels-a " + labels_path + " --labels-b " +
                           labels_path + " -o " + out_dir().string());
  ASSERT_EQ(cli.code, 0) << cli.err;
  std::ifstream csv(out_dir() / "correspondence.csv");
  std::string row;
  std::getline(csv, row);  // header
  std::size_t rows = 0;
  while(std::getline(csv, row)) {
    std::vector<std::string> cell;
    std::stringstream fields(row);
    for(std::string x; std::getline(fields, x, ',');) cell.push_back(x);
    ASSERT_EQ(cell.size(), 8u) << row;
    const std::size_t v = std::stoul(cell[0]);
    EXPECT_EQ(std::stol(cell[1]), c["vertex_face"][v].get<long>()) << "vertex " << v;
    for(int k = 0; k < 3; ++k)
      EXPECT_NEAR(std::stod(cell[5 + k]), c["vertex_point"][3 * v + k].get<double>(), 1e-12) << "vertex " << v;
    ++rows;
  }
  EXPECT_EQ(rows, nv);

  // B paints band 3 on one face only, inside band 2: B's patching gives that
  // face to band 2, so band 3 joins band 2 on A too, and B being A moved,
  // the vertices land on their own copies (B's face order is A's), but for a
  // few on the folds of the joined region's raw map, where rounding picks the
  // sheet (doc/correspondence.md, "Rounding on folds").
  std::vector<int> one_face_of_3 = bands;
  std::size_t kept = num_faces(cow);
  for(auto h : halfedges(cow))
    if(!cow.is_border(h) && !cow.is_border(cow.opposite(h)) && bands[cow.face(h).idx()] == 3 &&
       bands[cow.face(cow.opposite(h)).idx()] == 2) {
      kept = cow.face(h).idx();
      break;
    }
  ASSERT_LT(kept, num_faces(cow));
  for(std::size_t f = 0; f < one_face_of_3.size(); ++f)
    if(one_face_of_3[f] == 3 && f != kept) one_face_of_3[f] = 2;
  const json joined = post_json(client, "/api/correspond", {{"labels_a", bands}, {"labels_b", one_face_of_3}});
  ASSERT_TRUE(joined.is_object()) << joined;
  EXPECT_EQ(joined["report"]["joined_labels"], json::array({json::array({3, 2})}));
  EXPECT_EQ(joined["report"]["mapped"], nv);
  EXPECT_EQ(joined["report"]["matched_labels"], json({0, 1, 2}));
  std::size_t on_copy = 0;
  for(auto v : vertices(cow)) {
    const auto q = moved(cow.point(v));
    bool same = true;
    for(int k = 0; k < 3; ++k) same = same && std::abs(joined["vertex_point"][3 * v.idx() + k].get<double>() - q[k]) <= tolerance;
    on_copy += same ? 1 : 0;
  }
  EXPECT_GE(on_copy * 100, nv * 99);  // measured: 2,902 of 2,904

  // B's labels carried from A's nearest faces: B does not lie on A (moved).
  auto transfer = client.Post("/api/correspond", json{{"labels_a", bands}, {"transfer_labels", true}}.dump(), "application/json");
  ASSERT_TRUE(transfer);
  EXPECT_EQ(transfer->status, 422) << transfer->body.substr(0, 300);
  EXPECT_NE(transfer->body.find("does not lie on mesh A"), std::string::npos) << transfer->body.substr(0, 300);

  // Refusals.
  auto refused = [&](httplib::Result res, int status, const std::string& says, const std::string& what) {
    ASSERT_TRUE(res) << what << ": no answer";
    EXPECT_EQ(res->status, status) << what << ": " << res->body.substr(0, 300);
    EXPECT_NE(res->body.find(says), std::string::npos) << what << ": " << res->body.substr(0, 300);
  };
  const std::string json_type = "application/json";
  refused(client.Post("/api/correspond", json{{"labels_a", bands}, {"labels_b", json::array()}}.dump(), json_type), 400,
          "mesh B has no regions", "B not painted");
  refused(client.Post("/api/correspond", json{{"labels_a", json::array()}, {"labels_b", bands}}.dump(), json_type), 400,
          "mesh A has no regions", "A not painted");
  refused(client.Post("/api/correspond", json{{"labels_a", bands}, {"labels_b", std::vector<int>(3, 0)}}.dump(), json_type),
          400, "3 labels of mesh B for a mesh of", "B's labels too few");
  refused(client.Post("/api/correspond", json{{"labels_a", bands}, {"labels_b", std::vector<int>(bands.size(), 9)}}.dump(),
                      json_type),
          422, "no patch of A pairs", "no common region");
  refused(client.Post("/api/correspond",
                      json{{"labels_a", bands}, {"labels_b", bands}, {"points", {{{"face", 999999}, {"barycentric", w}}}}}.dump(),
                      json_type),
          400, "face 999999 is not a face of mesh A", "a point off the mesh");
  refused(client.Post("/api/correspond",
                      json{{"labels_a", bands}, {"labels_b", bands}, {"points", {{{"face", 1}, {"barycentric", {1, -1, 0}}}}}}.dump(),
                      json_type),
          400, "numbers ≥ 0", "a negative weight");
  refused(client.Get("/api/correspond"), 405, "takes a POST", "GET on a POST route");
  refused(client.Put("/api/layout", "{}", json_type), 405, "takes a POST", "PUT on a POST route");
  refused(client.Delete("/api/mesh"), 405, "takes a GET", "DELETE on the mesh");
  // Huge weights are the same point as equal ones (no overflow to infinity).
  const json equal = post_json(client, "/api/correspond",
                               {{"labels_a", bands}, {"labels_b", bands}, {"only_points", true},
                                {"points", {{{"face", 100}, {"barycentric", {1e308, 1e308, 1e308}}},
                                            {{"face", 100}, {"barycentric", {1, 1, 1}}}}}});
  ASSERT_EQ(equal["points"].size(), 2u);
  EXPECT_EQ(equal["points"][0]["face"], equal["points"][1]["face"]);
  for(int d = 0; d < 3; ++d)
    EXPECT_NEAR(equal["points"][0]["point"][d].get<double>(), equal["points"][1]["point"][d].get<double>(), 1e-12);
  refused(client.Get("/api/mesh?mesh=c"), 400, "takes a or b", "a third mesh");
  EXPECT_EQ(server.stop(SIGTERM, 10), 0);
}

TEST_F(Serve, WithoutASecondMeshCorrespondenceSaysSo)
{
  Server_process server(data_path("meshes/cow.off"), dir_ / "server.err");
  ASSERT_GT(server.port(), 0) << server.first_line() << slurp(dir_ / "server.err");
  httplib::Client client("127.0.0.1", server.port());
  auto none = client.Get("/api/mesh?mesh=b");
  ASSERT_TRUE(none);
  EXPECT_EQ(none->status, 404);
  EXPECT_NE(none->body.find("no second mesh (B) is loaded"), std::string::npos) << none->body;
  const std::size_t nf = num_faces(diffuv_test::cgal_mesh("cow.off"));
  auto c = client.Post("/api/correspond", json{{"labels_a", std::vector<int>(nf, 0)}}.dump(), "application/json");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->status, 404);
  // The second mesh, sent by the page, then answers as the first does.
  auto sent = client.Post("/api/mesh?mesh=b&name=grid.off", grid_off, "application/octet-stream");
  ASSERT_TRUE(sent);
  ASSERT_EQ(sent->status, 200) << sent->body;
  EXPECT_EQ(json::parse(client.Get("/api/mesh?mesh=b")->body)["name"], "grid.off");
  EXPECT_EQ(json::parse(client.Get("/api/mesh")->body)["name"], "cow.off");
  const Tool_run lone = run("serve --labels-b " + write("l.txt", "0\n"));
  EXPECT_EQ(lone.code, 2);
  EXPECT_NE(lone.err.find("--labels-b"), std::string::npos) << lone.err;
  EXPECT_EQ(server.stop(SIGTERM, 10), 0);
}

TEST_F(Serve, RefusesAPortInUseAndAMissingMesh)
{
  Server_process first("", dir_ / "first.err");
  ASSERT_GT(first.port(), 0);
  const Tool_run taken = run("serve --port " + std::to_string(first.port()));
  EXPECT_EQ(taken.code, 1);
  EXPECT_NE(taken.err.find("cannot listen there"), std::string::npos) << taken.err;
  const Tool_run threads = run("serve --threads 99999");
  EXPECT_EQ(threads.code, 2);
  EXPECT_NE(threads.err.find("--threads"), std::string::npos) << threads.err;
  // A label the page could not send back is refused at start.
  std::string big_labels;
  for(std::size_t f = 0; f < num_faces(diffuv_test::cgal_mesh("cow.off")); ++f) big_labels += f == 7 ? "5000000\n" : "1\n";
  const Tool_run big = run("serve " + data_path("meshes/cow.off") + " --labels " + write("big.txt", big_labels) + " --port 0");
  EXPECT_EQ(big.code, 1);
  EXPECT_NE(big.err.find("label 5000000 (face 7): the painter takes labels from 0 to 1000000"), std::string::npos) << big.err;
  // A mesh that needs a repair: refused with --strict-input, naming the problem.
  const std::string twice = write("twice.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 0 1 2\n");
  const Tool_run strict = run("serve " + twice + " --strict-input --port 0");
  EXPECT_EQ(strict.code, 1);
  EXPECT_NE(strict.err.find("twice.off"), std::string::npos) << strict.err;
  const Tool_run missing = run("serve " + (dir_ / "nothing.off").string());
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("nothing.off"), std::string::npos) << missing.err;
}

} // namespace
