// diffuv: the OBJ scanner. CGAL's OBJ reader answers true or false; this
// pass reads the file line by line as it does, to say where and why.
#ifndef DIFFUV_IO_INTERNAL_OBJ_SCANNER_H
#define DIFFUV_IO_INTERNAL_OBJ_SCANNER_H

#include <diffuv/io/internal/mesh_scan.h>
#include <diffuv/io/internal/number_tokens.h>

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace diffuv {
namespace internal {

/// Scans an OBJ file line by line like CGAL's OBJ reader.
inline Text_mesh_scan scan_obj(const std::string& path)
{
  Text_mesh_scan scan;
  std::ifstream file(path);
  auto fail = [&](std::size_t line, const std::string& what) {
    scan.error_line = line;
    scan.error = "not a valid OBJ file (" + what + ")";
    return scan;
  };

  // The keywords CGAL's reader skips without an error.
  static const char* const ignored[] = {
    "vt", "vn", "vp", "bevel", "lod", "ctech", "c_interp", "usemap", "usemtl", "stech", "d_interp", "mtllib",
    "shadow_obj", "trace_obj", "o", "g", "s", "p", "cstype", "deg", "step", "bmat", "con", "curv", "curv2",
    "surf", "parm", "trim", "hole", "scrv", "sp", "end", "surf_1", "q0_1", "q1_1", "curv2d_1", "surf_2",
    "q0_2", "q1_2", "curv2d_2", "bsp", "bzp", "cdc", "cdp", "res"};

  struct Written_face { std::size_t line, vertices_before; std::vector<int> indices; };
  std::vector<Written_face> written;

  std::string line;
  std::size_t number = 0;
  while(std::getline(file, line)) {
    ++number;
    std::istringstream in(line);
    std::string keyword;
    if(!(in >> keyword))
      continue;
    if(keyword == "v") {
      scan.vertex_line.push_back(number);
      double x, y, z;
      if(!(in >> x >> y >> z)) {
        std::string stop;
        leading_numbers(line.substr(line.find('v') + 1), stop);
        if(is_non_finite_number(stop)) {
          scan.error_line = number;
          scan.error = non_finite_message(scan.vertex_line.size() - 1);
          return scan;
        }
        return fail(number, "cannot read the coordinates of vertex " + std::to_string(scan.vertex_line.size() - 1));
      }
    } else if(keyword == "f") {
      scan.face_line.push_back(number);
      Written_face face{number, scan.vertex_line.size(), {}};
      int i;
      while(in >> i) {
        face.indices.push_back(i);
        in.ignore(256, ' '); // "v/vt/vn": CGAL keeps v and skips to the next space
      }
      written.push_back(std::move(face));
    } else if(keyword.front() == '#' ||
              std::find(std::begin(ignored), std::end(ignored), keyword) != std::end(ignored)) {
      continue;
    } else {
      return fail(number, "unknown keyword \"" + keyword + "\"");
    }
  }

  // Positive indices count from 1, negative ones back from the last vertex
  // read so far.
  const long long nv = static_cast<long long>(scan.vertex_line.size());
  for(std::size_t j = 0; j < written.size(); ++j) {
    for(int i : written[j].indices) {
      const long long resolved = i < 1 ? static_cast<long long>(written[j].vertices_before) + i : i - 1LL;
      if(resolved < 0 || resolved >= nv) {
        scan.error_line = written[j].line;
        scan.error = out_of_range_message(j, std::to_string(i), scan.vertex_line.size());
        return scan;
      }
    }
  }
  if(written.empty()) {
    scan.error = "the file has no face";
    return scan;
  }
  return scan;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_OBJ_SCANNER_H
