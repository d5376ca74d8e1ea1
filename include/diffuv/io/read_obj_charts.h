// diffuv: the texture charts of an OBJ file (its `vt` per face corner).
//
// CGAL's OBJ reader ignores `vt`, and a chart is not a property of the mesh
// but of its texture coordinates: two faces are in one chart when they share
// an edge whose two corners carry the same `vt` on both faces (and, where the
// file groups faces with `g` or `o`, the same group). This is how any atlas
// (diffuv's, Blender's Smart UV Project, xatlas) can be measured by
// `measure_distortion()`, chart by chart.
#ifndef DIFFUV_IO_READ_OBJ_CHARTS_H
#define DIFFUV_IO_READ_OBJ_CHARTS_H

#include <diffuv/core/error.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace diffuv {

/// A triangle soup with texture coordinates, cut into charts.
struct Obj_charts {
  std::vector<std::array<double, 3>> positions;     ///< `v` lines, in file order
  std::vector<std::array<double, 2>> texcoords;     ///< `vt` lines, in file order
  std::vector<std::array<std::size_t, 3>> triangles;   ///< positions of each triangle (polygons are fanned)
  std::vector<std::array<std::size_t, 3>> triangle_uv; ///< texture coordinates of each triangle's corners
  std::vector<std::size_t> chart;                   ///< #triangles entries: the chart of each triangle
  std::size_t number_of_charts = 0;
  std::size_t faces_without_uv = 0;                 ///< faces of the file with a corner without `vt` (in no chart)
};

namespace internal {

// One index of an `f` corner ("7", "7/3", "7/3/2", "7//2", negative = relative).
inline bool parse_obj_index(const std::string& text, std::size_t count, std::size_t& index)
{
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if(ec != std::errc() || end != text.data() + text.size() || value == 0) return false;
  const long long resolved = value > 0 ? value - 1 : static_cast<long long>(count) + value;
  if(resolved < 0 || resolved >= static_cast<long long>(count)) return false;
  index = static_cast<std::size_t>(resolved);
  return true;
}

inline bool parse_obj_number(const std::string& text, double& value)
{
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}

} // namespace internal

/// Reads the positions, texture coordinates and faces of an OBJ file and
/// groups its triangles into charts (see the top of this header).
///
/// \throws Input_error naming the file and line: a file that cannot be opened,
///         a number that does not parse, an index out of range, a face of
///         fewer than three corners, or no face with texture coordinates
inline Obj_charts read_obj_charts(const std::string& path)
{
  std::error_code error;
  if(std::filesystem::is_directory(path, error)) throw Input_error(path, 0, "is a directory, not an OBJ file");
  std::ifstream in(path);
  if(!in) throw Input_error(path, 0, "cannot open file");
  Obj_charts obj;
  std::vector<std::size_t> group_of_triangle;
  std::size_t group = 0, line_number = 0;
  std::map<std::string, std::size_t> groups;
  std::string line;
  std::vector<std::string> tokens;
  while(std::getline(in, line)) {
    ++line_number;
    if(line_number == 1 && line.size() >= 3 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
    tokens.clear();
    for(std::size_t i = 0; i < line.size();) {
      while(i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      if(i >= line.size() || line[i] == '#') break;
      const std::size_t start = i;
      while(i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
      tokens.push_back(line.substr(start, i - start));
    }
    if(tokens.empty()) continue;
    const std::string& tag = tokens.front();
    auto fail = [&](const std::string& why) { throw Input_error(path, line_number, why); };
    if(tag == "v") {
      if(tokens.size() < 4) fail("a vertex needs three coordinates");
      std::array<double, 3> p{};
      for(int k = 0; k < 3; ++k)
        if(!internal::parse_obj_number(tokens[static_cast<std::size_t>(k) + 1], p[static_cast<std::size_t>(k)]))
          fail("vertex coordinate '" + tokens[static_cast<std::size_t>(k) + 1] + "' is not a finite number");
      obj.positions.push_back(p);
    } else if(tag == "vt") {
      if(tokens.size() < 3) fail("a texture coordinate needs two numbers");
      std::array<double, 2> t{};
      for(int k = 0; k < 2; ++k)
        if(!internal::parse_obj_number(tokens[static_cast<std::size_t>(k) + 1], t[static_cast<std::size_t>(k)]))
          fail("texture coordinate '" + tokens[static_cast<std::size_t>(k) + 1] + "' is not a finite number");
      obj.texcoords.push_back(t);
    } else if(tag == "g" || tag == "o") {
      const std::string name = tokens.size() > 1 ? tokens[1] : std::string();
      group = groups.emplace(name, groups.size() + 1).first->second;
    } else if(tag == "f") {
      if(tokens.size() < 4) fail("a face needs three corners or more");
      std::vector<std::size_t> position, uv;
      bool textured = true;
      for(std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string& corner = tokens[k];
        const std::size_t slash = corner.find('/');
        std::size_t p = 0;
        if(!internal::parse_obj_index(corner.substr(0, slash), obj.positions.size(), p))
          fail("face corner '" + corner + "': no vertex with that index");
        position.push_back(p);
        std::size_t t = 0;
        const std::size_t second = slash == std::string::npos ? std::string::npos : corner.find('/', slash + 1);
        const std::string uv_text =
            slash == std::string::npos ? std::string() : corner.substr(slash + 1, second == std::string::npos ? std::string::npos : second - slash - 1);
        if(uv_text.empty()) {
          textured = false;
        } else if(!internal::parse_obj_index(uv_text, obj.texcoords.size(), t)) {
          fail("face corner '" + corner + "': no texture coordinate with that index");
        }
        uv.push_back(t);
      }
      if(!textured) {
        ++obj.faces_without_uv;
        continue;
      }
      for(std::size_t k = 1; k + 1 < position.size(); ++k) {
        obj.triangles.push_back({position[0], position[k], position[k + 1]});
        obj.triangle_uv.push_back({uv[0], uv[k], uv[k + 1]});
        group_of_triangle.push_back(group);
      }
    }
  }
  if(obj.triangles.empty()) throw Input_error(path, 0, "no face with texture coordinates (f v/vt ...)");

  // Charts: triangles joined across an edge with the same vt at both ends, in one group.
  const std::size_t n = obj.triangles.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::size_t x) {
    while(parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> first_triangle;  // (vt, vt) edge -> triangle
  for(std::size_t t = 0; t < n; ++t)
    for(int k = 0; k < 3; ++k) {
      const std::size_t a = obj.triangle_uv[t][static_cast<std::size_t>(k)], b = obj.triangle_uv[t][static_cast<std::size_t>((k + 1) % 3)];
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = first_triangle.find(key);
      if(it == first_triangle.end()) first_triangle.emplace(key, t);
      else if(group_of_triangle[it->second] == group_of_triangle[t]) parent[find(t)] = find(it->second);
    }
  obj.chart.assign(n, 0);
  std::map<std::size_t, std::size_t> number;
  for(std::size_t t = 0; t < n; ++t) obj.chart[t] = number.emplace(find(t), number.size()).first->second;
  obj.number_of_charts = number.size();
  return obj;
}

} // namespace diffuv

#endif // DIFFUV_IO_READ_OBJ_CHARTS_H
