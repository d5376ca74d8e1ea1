// diffuv: the OFF scanner, shared by every reader of OFF files: the header's
// keyword, lines read with their numbers (comments and blank lines skipped
// as CGAL skips them), numbers read as CGAL reads them. `scan_off()` checks a
// file for what CGAL's OFF reader takes on trust, before it reads the mesh;
// `read_off_paint()` (read_paint.h) reads the colours of the same lines.
#ifndef DIFFUV_IO_INTERNAL_OFF_SCANNER_H
#define DIFFUV_IO_INTERNAL_OFF_SCANNER_H

#include <diffuv/internal/message_text.h>
#include <diffuv/io/internal/mesh_scan.h>
#include <diffuv/io/internal/number_tokens.h>

#include <CGAL/IO/io.h>

#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace diffuv {
namespace internal {

/// The keyword of an OFF header: [ST][C][N][4][n]OFF, and what it announces.
struct Off_keyword {
  bool texture = false;       ///< "ST": texture coordinates after the coordinates (and normal)
  bool colors = false;        ///< "C": a colour on every vertex
  bool normals = false;       ///< "N": a normal after the coordinates
  bool homogeneous = false;   ///< "4": a fourth, homogeneous coordinate
  bool n_dimensional = false; ///< "n": the dimension comes before the counts
  bool in_order = false;      ///< each prefix at most once and in that order: what CGAL reads
  bool ends_with_off = false; ///< "OFF" after any letters
};

/// What `keyword` announces. The flags say which prefixes it holds, in any
/// order; `in_order` says whether CGAL reads it.
inline Off_keyword off_keyword(const std::string& keyword)
{
  Off_keyword k;
  const std::size_t off = keyword.size() >= 3 ? keyword.size() - 3 : 0;
  k.ends_with_off = keyword.compare(off, std::string::npos, "OFF") == 0;
  const std::string prefix = keyword.substr(0, off);
  k.texture = prefix.find("ST") != std::string::npos;
  k.colors = prefix.find('C') != std::string::npos;
  k.normals = prefix.find('N') != std::string::npos;
  k.homogeneous = prefix.find('4') != std::string::npos;
  k.n_dimensional = prefix.find('n') != std::string::npos;
  // [ST][C][N][4][n]OFF, as CGAL accepts it
  std::size_t i = 0;
  if(keyword.compare(i, 2, "ST") == 0) i += 2;
  for(const char c : {'C', 'N', '4', 'n'})
    if(i < keyword.size() && keyword[i] == c) ++i;
  k.in_order = keyword.substr(i) == "OFF";
  return k;
}

/// A file's text, read whole, walked with the line counted: one read of the
/// file and views into it instead of a stream read character by character.
class Line_counting_reader {
public:
  explicit Line_counting_reader(std::string_view text) : text_(text) {}

  std::size_t line() const { return line_; }

  /// The lines begun so far: at the end of the input, the number of lines of
  /// the file (the last one may have no end of line).
  std::size_t lines_begun() const { return at_line_start_ ? line_ - 1 : line_; }

  int peek() const { return at_ < text_.size() ? static_cast<unsigned char>(text_[at_]) : std::char_traits<char>::eof(); }

  int get()
  {
    if(at_ == text_.size())
      return std::char_traits<char>::eof();
    const char c = text_[at_++];
    if(c == '\n')
      ++line_;
    at_line_start_ = c == '\n';
    return static_cast<unsigned char>(c);
  }

  /// Skips white space and `#` comments, as CGAL's `skip_comment_OFF`.
  /// Returns false at the end of the input.
  bool skip_space_and_comments()
  {
    for(;;) {
      const int c = peek();
      if(c == std::char_traits<char>::eof())
        return false;
      if(c == '#')
        rest_of_line();
      else if(is_blank(static_cast<char>(c)))
        get();
      else
        return true;
    }
  }

  /// The characters up to white space or `#`.
  std::string_view token()
  {
    const std::size_t first = at_;
    while(at_ < text_.size() && text_[at_] != '#' && !is_blank(text_[at_]))
      ++at_;
    if(at_ > first)
      at_line_start_ = false;
    return text_.substr(first, at_ - first);
  }

  /// The characters up to the end of the line, which is consumed.
  std::string_view rest_of_line()
  {
    const std::size_t first = at_;
    const std::size_t end = text_.find('\n', at_);
    if(end != std::string_view::npos) {
      at_ = end + 1;
      ++line_; // the end of line was read
      at_line_start_ = true;
      return text_.substr(first, end - first);
    }
    at_ = text_.size();
    if(at_ > first)
      at_line_start_ = false;
    return text_.substr(first);
  }

  /// The next line that holds more than white space and comments, from its
  /// first character on, and its number. Returns false at the end of the input.
  bool next_line(std::string_view& text, std::size_t& line)
  {
    if(!skip_space_and_comments())
      return false;
    line = line_;
    text = rest_of_line();
    return true;
  }

  /// The bytes not read yet (binary data after a header).
  std::string_view rest() const { return text_.substr(at_); }

private:
  std::string_view text_;
  std::size_t at_ = 0;
  std::size_t line_ = 1;
  bool at_line_start_ = true;
};

/// The numbers of an OFF line as CGAL's `File_scanner_OFF` reads them: up to
/// a `#` comment, with `CGAL::IO::iformat()` (whose syntax differs from
/// `operator>>`: "1e999" is infinite, "1-2" is one number).
inline std::vector<double> cgal_off_numbers(std::string_view line)
{
  std::istringstream in(before_comment(std::string(line)));
  std::vector<double> numbers;
  double d;
  while(in >> CGAL::IO::iformat(d))
    numbers.push_back(d);
  return numbers;
}

/// The numbers of an OFF line made of plain decimal numbers only (up to a `#`
/// comment), on which `leading_numbers()` and `cgal_off_numbers()` agree,
/// without their string streams (`std::from_chars`, correctly rounded like
/// them); false if the line has anything else, a sign `+` or a number that
/// is not finite, which are left to them.
inline bool plain_numbers(std::string_view line, std::vector<double>& numbers)
{
  numbers.clear();
  const char* p = line.data();
  const char* const end = p + line.size();
  for(;;) {
    while(p < end && is_blank(*p))
      ++p;
    if(p == end || *p == '#')
      return true;
    const char* const start = p;
    for(; p < end && !is_blank(*p); ++p)
      if(!((*p >= '0' && *p <= '9') || *p == '.' || *p == '-' || *p == 'e' || *p == 'E'))
        return false;
    double d = 0;
    const auto [stop, ec] = std::from_chars(start, p, d);
    if(ec != std::errc() || stop != p || !std::isfinite(d))
      return false;
    numbers.push_back(d);
  }
}

/// True if CGAL's OFF header reader can double `edges` (an int) without overflow.
inline bool edge_count_fits(long long edges)
{
  return edges >= std::numeric_limits<int>::min() / 2 && edges <= std::numeric_limits<int>::max() / 2;
}

/// Reads and checks an OFF file like CGAL's `File_scanner_OFF`: header, then
/// one vertex per line, then one face per line, giving the lines of the
/// elements and the first problem. With `soup`, also gives the points and
/// polygons as CGAL's `read_OFF()` reads them (homogeneous coordinates
/// divided through), so that this one pass is the OFF reader. With
/// `header_only`, stops after the header, whose counts are checked against
/// the size of the file: CGAL resizes its arrays to the announced counts
/// before reading them, so a corrupt header would otherwise allocate gigabytes.
/// Binary OFF has no lines: its data is read as CGAL reads it (no colours).
inline Text_mesh_scan scan_off(std::string_view text, bool header_only, Polygon_soup* soup = nullptr)
{
  Text_mesh_scan scan;
  const std::uintmax_t file_size = text.size();
  Line_counting_reader in(text);
  auto fail = [&](std::size_t line, const std::string& what) {
    scan.error_line = line;
    scan.error = "not a valid OFF file (" + what + ")";
    return scan;
  };
  if(soup)
    *soup = Polygon_soup();

  if(!in.skip_space_and_comments())
    return fail(0, "the file has no OFF header");
  const std::size_t header_line = in.line();
  const std::string keyword(in.token());
  const Off_keyword announced = off_keyword(keyword);
  if(!announced.in_order)
    return fail(header_line, "the file does not start with an OFF header");
  const bool texture = announced.texture, colors = announced.colors, normals = announced.normals;
  const bool homogeneous = announced.homogeneous, n_dimensional = announced.n_dimensional;

  long long nv = 0, nf = 0, ne = 0;
  in.skip_space_and_comments();
  std::size_t counts_line = in.line();
  std::string_view token = in.token();
  if(token == "BINARY") {
    // Three big-endian 32-bit counts after the end of the line (after the
    // dimension for nOFF, which CGAL's reader does not use: it reads three
    // coordinates per vertex whatever the dimension).
    in.rest_of_line();
    std::string_view data = in.rest();
    auto read32 = [&](std::uint32_t& u) {
      if(data.size() < 4)
        return false;
      const unsigned char* b = reinterpret_cast<const unsigned char*>(data.data());
      u = (std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) | (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]);
      data.remove_prefix(4);
      return true;
    };
    auto signed32 = [](std::uint32_t u) { return static_cast<long long>(static_cast<std::int32_t>(u)); };
    std::uint32_t counts[3];
    if(n_dimensional && !read32(counts[0]))
      return fail(counts_line, "cannot read the dimension");
    if(!read32(counts[0]) || !read32(counts[1]) || !read32(counts[2]))
      return fail(counts_line, "cannot read the numbers of vertices, faces and edges");
    nv = signed32(counts[0]);
    nf = signed32(counts[1]);
    ne = signed32(counts[2]);
    if(nv < 0 || nf < 0)
      return fail(counts_line, "negative number of vertices or faces");
    if(!edge_count_fits(ne))
      return fail(counts_line, "the number of edges " + std::to_string(ne) + " is out of range");
    // At least three 4-byte floats per vertex, one 4-byte count per face.
    if(static_cast<std::uintmax_t>(nv) * 12 + static_cast<std::uintmax_t>(nf) * 4 > file_size)
      return fail(counts_line, "the header announces " + count_text(static_cast<std::size_t>(nv), "vertex", "vertices") +
                                   " and " + count_text(static_cast<std::size_t>(nf), "face") + ", more than the " + std::to_string(file_size) +
                                   " bytes of the file can hold");
    if(header_only)
      return scan;
    // Binary data has no lines to find; read it as CGAL reads it, checking
    // the face sizes, which CGAL allocates before reading the indices.
    const std::size_t h = homogeneous ? 1 : 0;
    const std::size_t floats = 3 + h + (normals ? 3 + h : 0) + (texture ? 2 + h : 0);
    // CGAL's read_OFF() reads no colour in binary files (nor their counts).
    if(data.size() / 4 / floats < static_cast<std::uintmax_t>(nv))
      return scan; // CGAL stops in the vertices too: the soup is not complete
    if(soup) {
      soup->points.resize(static_cast<std::size_t>(nv));
      for(auto& point : soup->points) {
        float xyzw[4] = {0, 0, 0, 1};
        for(std::size_t c = 0; c < 3 + h; ++c) {
          std::uint32_t u = 0;
          read32(u);
          std::memcpy(&xyzw[c], &u, 4);
        }
        data.remove_prefix(4 * (floats - 3 - h));
        for(int c = 0; c < 3; ++c) point[c] = double(xyzw[c]) / double(xyzw[3]);
      }
    } else {
      data.remove_prefix(4 * floats * static_cast<std::size_t>(nv));
    }
    std::uint32_t count = 0;
    bool truncated = false;
    for(long long j = 0; j < nf; ++j) {
      if(!read32(count)) // CGAL would allocate the face with the unread (uninitialised) size
        return fail(0, "the file ends before face " + std::to_string(j) + " of " + std::to_string(nf));
      const long long size = signed32(count);
      if(size < 0 || static_cast<std::uintmax_t>(size) * 4 > file_size)
        return fail(0, "face " + std::to_string(j) + " has " + std::to_string(size) + " vertices, " +
                           (size < 0 ? "a negative number" : "more than the file can hold"));
      if(data.size() / 4 < static_cast<std::uintmax_t>(size)) {
        // CGAL reads to the end; the next face, if any, finds nothing.
        data = std::string_view();
        truncated = true;
        continue;
      }
      if(soup) {
        std::vector<std::size_t> polygon(static_cast<std::size_t>(size));
        for(auto& index : polygon) { // as CGAL converts it: a negative index becomes a huge one
          std::uint32_t u = 0;
          read32(u);
          index = static_cast<std::size_t>(signed32(u));
        }
        soup->polygons.push_back(std::move(polygon));
      } else {
        data.remove_prefix(4 * static_cast<std::size_t>(size));
      }
    }
    if(soup)
      soup->complete = !truncated;
    return scan;
  }

  if(n_dimensional) { // the dimension, then the counts
    long long dimension = 0;
    if(!parse_count(token, dimension))
      return fail(counts_line, "cannot read the dimension");
    in.skip_space_and_comments();
    counts_line = in.line();
    token = in.token();
  }
  if(!parse_count(token, nv))
    return fail(counts_line, "cannot read the numbers of vertices, faces and edges");
  in.skip_space_and_comments();
  counts_line = in.line();
  if(!parse_count(in.token(), nf))
    return fail(counts_line, "cannot read the numbers of vertices, faces and edges");
  in.skip_space_and_comments();
  counts_line = in.line();
  if(!parse_count(in.token(), ne))
    return fail(counts_line, "cannot read the numbers of vertices, faces and edges");
  if(nv < 0 || nf < 0)
    return fail(counts_line, "negative number of vertices or faces");
  if(!edge_count_fits(ne))
    return fail(counts_line, "the number of edges " + std::to_string(ne) + " is out of range");
  // Each vertex line holds at least "x y z" and an end of line, each face
  // line at least its size and an end of line; the last line may have no end.
  const std::uintmax_t needed = static_cast<std::uintmax_t>(nv) * 6 + static_cast<std::uintmax_t>(nf) * 2;
  if(needed > file_size + 1)
    return fail(counts_line, "the header announces " + count_text(static_cast<std::size_t>(nv), "vertex", "vertices") +
                                 " and " + count_text(static_cast<std::size_t>(nf), "face") + ", more than the " + std::to_string(file_size) +
                                 " bytes of the file can hold");
  if(header_only)
    return scan;

  // What CGAL's File_scanner_OFF (CGAL 5.5) takes on trust, checked on the
  // numbers as it reads them (cgal_off_numbers()): a vertex line long enough
  // for its normal, texture coordinates and colour; colours of 1 (an index in
  // CGAL's colour map), 3 or 4 components in range, on every vertex (face)
  // after a coloured one; face sizes and indices it can convert. Else it
  // reads past the end of its vector or converts out-of-range values. It
  // reads texture coordinates at an uninitialised position unless the
  // vertices are coloured too (STCOFF).
  if(texture && !colors)
    return fail(header_line, "texture coordinates without colours (STOFF) cannot be read");
  const std::size_t h = homogeneous ? 1 : 0;
  const std::size_t vertex_numbers = 3 + h + (normals ? 3 + h : 0) + (texture ? 2 + h : 0);
  // The `n` colour components at `first` in `entries` (before texture
  // coordinates, as Geomview writes them); "" if they are fine.
  auto color_problem = [](const std::vector<double>& entries, std::size_t first, std::size_t n,
                          bool& colored) -> std::string {
    colored = colored || n > 0;
    if(!colored)
      return std::string();
    if(n == 0)
      return "has no colour, but an earlier one has";
    if(n != 1 && n != 3 && n != 4)
      return "has " + count_text(n, "colour component") + "; expected 3 or 4";
    if(n == 1)
      return entries[first] >= 0 && entries[first] < 149
               ? std::string()
               : "has colour-map index " + number_text(entries[first]) + ", outside [0, 148]";
    bool integers = true;
    for(std::size_t c = first; c < first + 3; ++c)
      integers = integers && std::floor(entries[c]) == entries[c];
    for(std::size_t c = first; c < first + 3; ++c)
      if(!(entries[c] >= 0 && entries[c] <= (integers ? 255 : 1)))
        return "has colour component " + number_text(entries[c]) + ", outside " +
               (integers ? "[0, 255] (integers)" : "[0, 1]");
    return std::string();
  };
  bool vertex_colored = false, face_colored = false;

  const std::size_t needed_coordinates = homogeneous ? 4 : 3;
  std::string stop;
  std::vector<double> numbers, entries;
  // The numbers of `text` read as the messages below describe them
  // (operator>>), and as CGAL reads them.
  auto read_numbers = [&](std::string_view text) {
    if(plain_numbers(text, numbers)) {
      entries = numbers;
      stop.clear();
    } else {
      numbers = leading_numbers(std::string(text), stop);
      entries = cgal_off_numbers(text);
    }
  };
  if(soup) {
    soup->points.reserve(static_cast<std::size_t>(nv));
    soup->polygons.reserve(static_cast<std::size_t>(nf));
  }
  scan.vertex_line.reserve(static_cast<std::size_t>(nv));
  scan.face_line.reserve(static_cast<std::size_t>(nf));
  for(long long i = 0; i < nv; ++i) {
    std::string_view text;
    std::size_t line = 0;
    if(!in.next_line(text, line))
      return fail(0, "the file ends before vertex " + std::to_string(i) + " of " + std::to_string(nv));
    scan.vertex_line.push_back(line);
    read_numbers(text);
    if(numbers.size() < needed_coordinates) {
      if(is_non_finite_number(stop)) {
        scan.error_line = line;
        scan.error = non_finite_message(static_cast<std::size_t>(i));
        return scan;
      }
      return fail(line, "vertex " + std::to_string(i) + " does not have " + std::to_string(needed_coordinates) +
                            " coordinates");
    }
    if(entries.size() < needed_coordinates)
      return fail(line, "vertex " + std::to_string(i) + " does not have " + std::to_string(needed_coordinates) +
                            " coordinates");
    if(homogeneous && entries[3] == 0) { // a point at infinity
      scan.error_line = line;
      scan.error = non_finite_message(static_cast<std::size_t>(i));
      return scan;
    }
    if(entries.size() < vertex_numbers && (colors || normals))
      return fail(line, "vertex " + std::to_string(i) + " has " + count_text(entries.size(), "number") + "; " +
                            keyword + " needs " + std::to_string(vertex_numbers));
    if(colors) {
      const std::string problem = color_problem(entries, vertex_numbers - (texture ? 2 + h : 0),
                                                entries.size() - vertex_numbers, vertex_colored);
      if(!problem.empty())
        return fail(line, "vertex " + std::to_string(i) + " " + problem);
    }
    if(soup) {
      const double w = homogeneous ? entries[3] : 1.0;
      soup->points.push_back({entries[0] / w, entries[1] / w, entries[2] / w});
    }
  }

  for(long long j = 0; j < nf; ++j) {
    std::string_view text;
    std::size_t line = 0;
    if(!in.next_line(text, line))
      return fail(0, "the file ends before face " + std::to_string(j) + " of " + std::to_string(nf));
    scan.face_line.push_back(line);
    read_numbers(text);
    if(numbers.empty() || numbers[0] < 0 || numbers[0] != std::floor(numbers[0]))
      return fail(line, "face " + std::to_string(j) + " does not start with its number of vertices");
    if(static_cast<double>(numbers.size()) <= numbers[0])
      return fail(line, "face " + std::to_string(j) + " lists fewer than its " + number_text(numbers[0]) +
                            " vertex indices");
    const std::size_t size = static_cast<std::size_t>(numbers[0]);
    for(std::size_t c = 1; c <= size; ++c) {
      const double index = numbers[c];
      if(index < 0 || index >= static_cast<double>(nv) || index != std::floor(index)) {
        scan.error_line = line;
        scan.error = out_of_range_message(static_cast<std::size_t>(j), number_text(index),
                                          static_cast<std::size_t>(nv));
        return scan;
      }
    }
    if(entries.empty() || !(entries[0] >= 0) || static_cast<double>(entries.size()) <= entries[0])
      return fail(line, "face " + std::to_string(j) + " does not start with its number of vertices, then as many indices");
    const std::size_t cgal_size = static_cast<std::size_t>(entries[0]);
    for(std::size_t c = 1; c <= cgal_size; ++c)
      if(!(entries[c] >= 0 && entries[c] < static_cast<double>(nv))) {
        scan.error_line = line;
        scan.error = out_of_range_message(static_cast<std::size_t>(j), number_text(entries[c]),
                                          static_cast<std::size_t>(nv));
        return scan;
      }
    if(colors) {
      const std::string problem = color_problem(entries, cgal_size + 1, entries.size() - cgal_size - 1, face_colored);
      if(!problem.empty())
        return fail(line, "face " + std::to_string(j) + " " + problem);
    } else if(numbers.size() > size + 1 || entries.size() > cgal_size + 1) {
      face_colored = true;  // numbers after the indices: colours to read_off_paint() (MeshLab writes them under "OFF")
    }
    if(soup) {
      std::vector<std::size_t> polygon(cgal_size);
      for(std::size_t c = 0; c < cgal_size; ++c)
        polygon[c] = static_cast<std::size_t>(entries[c + 1]);
      soup->polygons.push_back(std::move(polygon));
    }
  }
  if(soup)
    soup->complete = true;
  scan.colors = colors || vertex_colored || face_colored;
  return scan;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_OFF_SCANNER_H
