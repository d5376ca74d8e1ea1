// diffuv: the OBJ reader. One pass over the file's bytes reads the points and
// polygons exactly as CGAL's `read_OBJ()` (CGAL 5.5) reads them, and says
// where and why a file is bad, so that CGAL's reader is not called (issue #20).
#ifndef DIFFUV_IO_INTERNAL_OBJ_SCANNER_H
#define DIFFUV_IO_INTERNAL_OBJ_SCANNER_H

#include <diffuv/core/error.h>
#include <diffuv/io/internal/mesh_scan.h>
#include <diffuv/io/internal/number_tokens.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace diffuv {
namespace internal {

/// The first word of an OBJ line, as `std::istringstream >> std::string`
/// reads it; moves `at` past it. Empty if the line holds only white space.
inline std::string_view obj_keyword(const char*& at, const char* end)
{
  while(at < end && is_blank(*at))
    ++at;
  const char* const first = at;
  while(at < end && !is_blank(*at))
    ++at;
  return std::string_view(first, static_cast<std::size_t>(at - first));
}

/// True if CGAL's OBJ reader skips lines of `keyword` without an error:
/// comments, texture coordinates, normals, and statements it does not read.
inline bool obj_keyword_ignored(std::string_view keyword)
{
  static const char* const ignored[] = {
    "vt", "vn", "vp", "bevel", "lod", "ctech", "c_interp", "usemap", "usemtl", "stech", "d_interp", "mtllib",
    "shadow_obj", "trace_obj", "o", "g", "s", "p", "cstype", "deg", "step", "bmat", "con", "curv", "curv2",
    "surf", "parm", "trim", "hole", "scrv", "sp", "end", "surf_1", "q0_1", "q1_1", "curv2d_1", "surf_2",
    "q0_2", "q1_2", "curv2d_2", "bsp", "bzp", "cdc", "cdp", "res"};
  return keyword.front() == '#' ||
         std::find(std::begin(ignored), std::end(ignored), keyword) != std::end(ignored);
}

/// The vertex indices of a face line after its "f", as written, read as
/// CGAL reads them: `>> int` then `ignore(256, ' ')`, which keeps the v of
/// "v/vt/vn" and stops at the first word that does not start with an integer.
inline void obj_written_indices(const char* at, const char* end, std::vector<int>& written)
{
  written.clear();
  int index = 0;
  while(extract_int(at, end, index)) {
    written.push_back(index);
    ignore_to_space(at, end);
  }
}

/// The index that corner `corner` of the face on line `line` is written with.
inline int obj_index_as_written(std::string_view text, std::size_t line, std::size_t corner)
{
  std::size_t at = 0;
  for(std::size_t l = 1; l < line; ++l)
    at = text.find('\n', at) + 1;
  const std::size_t end = std::min(text.find('\n', at), text.size());
  const char* p = text.data() + at;
  obj_keyword(p, text.data() + end); // "f"
  std::vector<int> written;
  obj_written_indices(p, text.data() + end, written);
  return written.at(corner);
}

/// Reads the OBJ file `text` in one pass, as CGAL's `read_OBJ()` reads it
/// with `std::getline` and `std::istringstream`: a line per element, a
/// vertex as three numbers read with `>> double` (more are ignored), a face
/// as the integers `>> int` reads (1 is the first vertex, 0 and below count
/// back from the last vertex read so far), the keywords in
/// `obj_keyword_ignored()` skipped and any other refused. Fills `soup` with
/// what CGAL would give; `soup.complete` is whether CGAL would accept the
/// file. The scan gives the line of each element and the first problem: a
/// vertex or keyword CGAL stops at, else the first index out of range (quoted
/// as written), else a file without faces.
inline Text_mesh_scan scan_obj(std::string_view text, Polygon_soup& soup)
{
  Text_mesh_scan scan;
  soup = Polygon_soup();
  auto fail = [&](std::size_t line, const std::string& what) {
    scan.error_line = line;
    scan.error = "not a valid OBJ file (" + what + ")";
    return scan;
  };

  int smallest_written = 1, largest_positive = -1; // the bounds CGAL checks at the end
  long long smallest_resolved = 0, largest_resolved = -1; // whether any index is out of range
  std::vector<int> written;
  std::size_t line_number = 0;
  const char* const text_end = text.data() + text.size();

  // Room for an element on every line, so that the arrays never grow: growing
  // copies them into fresh memory, whose pages are what a large read costs
  // (the pages reserved and never written cost nothing).
  std::size_t lines = 1;
  for(const char* p = text.data(); (p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(text_end - p))));
      ++p)
    ++lines;
  soup.points.reserve(lines);
  soup.polygons.reserve(lines);
  scan.vertex_line.reserve(lines);
  scan.face_line.reserve(lines);
  for(const char* next = text.data(); next < text_end;) {
    const char* at = next;
    const char* line_end = static_cast<const char*>(std::memchr(at, '\n', static_cast<std::size_t>(text_end - at)));
    if(!line_end)
      line_end = text_end;
    next = line_end + 1;
    ++line_number;

    const std::string_view keyword = obj_keyword(at, line_end);
    if(keyword.empty())
      continue;
    if(keyword == "v") {
      scan.vertex_line.push_back(line_number);
      std::array<double, 3> point;
      if(!extract_double(at, line_end, point[0]) || !extract_double(at, line_end, point[1]) ||
         !extract_double(at, line_end, point[2])) {
        // The numbers as the messages describe them: a number too large
        // or "inf" is a value to name, not a syntax error.
        const std::string line(keyword.data(), static_cast<std::size_t>(line_end - keyword.data()));
        std::string stop;
        leading_numbers(line.substr(1), stop);
        if(is_non_finite_number(stop)) {
          scan.error_line = line_number;
          scan.error = non_finite_message(scan.vertex_line.size() - 1);
          return scan;
        }
        return fail(line_number, "cannot read the coordinates of vertex " + std::to_string(scan.vertex_line.size() - 1));
      }
      soup.points.push_back(point);
    } else if(keyword == "f") {
      scan.face_line.push_back(line_number);
      obj_written_indices(at, line_end, written);
      const int vertices_before = static_cast<int>(soup.points.size());
      std::vector<std::size_t> polygon(written.size());
      for(std::size_t c = 0; c < written.size(); ++c) {
        const int i = written[c];
        // As CGAL stores it: an int, converted (a negative one to a huge index).
        const int resolved = i < 1 ? vertices_before + i : i - 1;
        polygon[c] = static_cast<std::size_t>(resolved);
        if(i < 1)
          smallest_written = std::min(smallest_written, i);
        else
          largest_positive = std::max(largest_positive, resolved);
        smallest_resolved = std::min<long long>(smallest_resolved, resolved);
        largest_resolved = std::max<long long>(largest_resolved, resolved);
      }
      soup.polygons.push_back(std::move(polygon));
    } else if(!obj_keyword_ignored(keyword)) {
      return fail(line_number, "unknown keyword \"" + printable(std::string(keyword)) + "\"");  // binary junk escaped
    }
  }

  // CGAL refuses a file without points or faces, and indices beyond its
  // bounds; these let through the index one past the last vertex, and a
  // relative index that points before the first vertex read so far.
  const int nv = static_cast<int>(soup.points.size());
  soup.complete = nv > 0 && !soup.polygons.empty() && largest_positive <= nv && smallest_written >= -nv;

  const bool out_of_range = smallest_resolved < 0 || largest_resolved >= nv;
  for(std::size_t j = 0; out_of_range && j < soup.polygons.size() && scan.error.empty(); ++j) {
    const std::vector<std::size_t>& polygon = soup.polygons[j];
    for(std::size_t c = 0; c < polygon.size(); ++c)
      if(polygon[c] >= soup.points.size()) {
        scan.error_line = scan.face_line[j];
        scan.error = out_of_range_message(j, std::to_string(obj_index_as_written(text, scan.error_line, c)),
                                          soup.points.size());
        break;
      }
  }
  if(soup.polygons.empty())
    scan.error = "the file has no face";
  return scan;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_OBJ_SCANNER_H
