// diffuv: one error vocabulary for the whole library.
//
// Algorithms return a Status (an enum plus a detail string naming the patch,
// vertex or side) and never print. Readers and writers throw Input_error /
// Output_error (both diffuv::Error), which carry the file, the line and the
// reason. A call that breaks a documented precondition (arrays of the wrong
// size, an option out of its range) throws std::invalid_argument, or
// std::out_of_range for an index past the end (a chart that does not exist),
// as the standard library does. Nothing else leaves the library. Only a
// program's main() writes to the terminal.
#ifndef DIFFUV_CORE_ERROR_H
#define DIFFUV_CORE_ERROR_H

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

namespace diffuv {

/// What an algorithm of the library reports.
enum class Status_code {
  ok,
  empty_source_range,     ///< a distance computation was given no source vertex
  negative_weight,        ///< an edge weight is negative or not a number
  empty_side,             ///< one of the four sides of a patch has no vertex
  not_triangle_mesh,      ///< a face is not a triangle
  empty_mesh,             ///< the mesh has no face
  disconnected_mesh,      ///< the mesh has several connected components
  no_border,              ///< a closed mesh, where a disc was expected
  several_borders,        ///< more than one boundary loop, where a disc was expected
  not_a_disc,             ///< one boundary loop, but Euler characteristic is not 1 (handles)
  non_manifold,           ///< a vertex whose faces do not form a single fan
  corner_count,           ///< not exactly four corner vertices
  corner_out_of_range,    ///< a corner index is not a vertex of the mesh
  corner_not_on_border,   ///< a corner vertex is not on the boundary loop
  corner_duplicated,      ///< the same vertex is given twice as a corner
  border_too_short,       ///< fewer than four vertices on the boundary loop
  unreachable_vertices,   ///< some vertices are not reached from a side
  not_injective,          ///< the (u,v) map still folds after the repair
  no_labels               ///< a mesh has no region labels where they are needed (correspondence)
};

/// Returns the fixed English sentence for `code`.
/// A switch with no default: the compiler flags a code without a message.
inline const char* message(Status_code code)
{
  switch(code) {
    case Status_code::ok: return "ok";
    case Status_code::empty_source_range: return "no source vertex was given";
    case Status_code::negative_weight: return "an edge weight is negative or not a number";
    case Status_code::empty_side: return "a side of the patch has no vertex";
    case Status_code::not_triangle_mesh: return "the mesh has a face that is not a triangle";
    case Status_code::empty_mesh: return "the mesh has no face";
    case Status_code::disconnected_mesh: return "the mesh is not connected";
    case Status_code::no_border: return "the mesh is closed (no boundary), not a topological disc";
    case Status_code::several_borders: return "the mesh has several boundary loops, not a topological disc";
    case Status_code::not_a_disc: return "the mesh is not a topological disc (it has handles)";
    case Status_code::non_manifold: return "the mesh has a non-manifold vertex";
    case Status_code::corner_count: return "exactly four corner vertices are needed";
    case Status_code::corner_out_of_range: return "a corner index is not a vertex of the mesh";
    case Status_code::corner_not_on_border: return "a corner vertex is not on the boundary of the mesh";
    case Status_code::corner_duplicated: return "a corner vertex is given twice";
    case Status_code::border_too_short: return "the boundary has fewer than four vertices";
    case Status_code::not_injective: return "the (u,v) map still folds after the repair";
    case Status_code::unreachable_vertices: return "some vertices are not reached from every side";
    case Status_code::no_labels: return "the mesh has no region labels";
  }
  return "unknown status"; // unreachable for valid enum values
}

/// The outcome of an algorithm: a code, a detail naming what is concerned,
/// and the part of the input the message is about when it is not the whole
/// mesh (e.g. "patch 3 (label 1)").
struct Status {
  Status_code code = Status_code::ok;
  std::string detail;
  std::string subject;  ///< empty: the message is about the mesh

  Status() = default;
  Status(Status_code c, std::string d = {}, std::string about = {})
    : code(c), detail(std::move(d)), subject(std::move(about)) {}

  bool ok() const { return code == Status_code::ok; }
  explicit operator bool() const { return ok(); }

  /// The message about the subject, followed by the detail when there is one:
  /// "patch 3 (label 1) has several boundary loops, not a topological disc (2 boundary loops)".
  std::string what() const
  {
    std::string s = message(code);
    const std::string mesh = "the mesh ";
    if(!subject.empty()) s = s.compare(0, mesh.size(), mesh) == 0 ? subject + ' ' + s.substr(mesh.size()) : subject + ": " + s;
    if(!detail.empty()) s += " (" + detail + ")";
    return s;
  }
};

/// Base of every exception thrown by diffuv.
class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// A file that cannot be read or does not parse. `line` is 0 when the problem
/// is not tied to one line.
class Input_error : public Error {
public:
  Input_error(std::string file, std::size_t line, std::string reason)
    : Error(format(file, line, reason)), file_(std::move(file)), line_(line), reason_(std::move(reason)) {}

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  const std::string& reason() const { return reason_; }

private:
  static std::string format(const std::string& file, std::size_t line, const std::string& reason)
  {
    return file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + reason;
  }
  std::string file_;
  std::size_t line_;
  std::string reason_;
};

/// A file or folder that cannot be written.
class Output_error : public Error {
public:
  Output_error(std::string path, std::string reason)
    : Error(path + ": " + reason), path_(std::move(path)) {}
  const std::string& path() const { return path_; }

private:
  std::string path_;
};

namespace internal {

/// `text` as it can be quoted in a one-line message: bytes that are not
/// printable ASCII (a NUL, a control character, binary junk) become \xHH, and
/// a long text is cut at 40 characters.
inline std::string printable(const std::string& text)
{
  static const char* const hex = "0123456789abcdef";
  std::string out;
  for(std::size_t i = 0; i < text.size() && i < 40; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if(c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if(text.size() > 40) out += "...";
  return out;
}

/// Removes a UTF-8 byte-order mark from the start of `line` (editors on
/// Windows write one; it is invisible in a message).
inline void drop_byte_order_mark(std::string& line)
{
  if(line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
}

} // namespace internal

} // namespace diffuv

#endif // DIFFUV_CORE_ERROR_H
