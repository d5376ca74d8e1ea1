// diffuv tool: the values of the command line as text — picture sizes, lists
// of names, the names of output files. No CGAL: the tests include it as is.
#ifndef DIFFUV_CLI_COMMAND_LINE_H
#define DIFFUV_CLI_COMMAND_LINE_H

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace diffuv_cli {

/// The smallest and largest width or height of a picture (`--size`).
constexpr int smallest_picture_side = 16;
constexpr int largest_picture_side = 8192;

/// What is wrong with `text` as a number from `low` to `high` (a whole number
/// if `whole`), or an empty string: "expects a whole number from 1 to 100000,
/// not 'abc'". The whole text must be the number (no spaces, no unit).
inline std::string range_problem(const std::string& text, double low, double high, bool whole)
{
  auto bound = [](double x) {
    std::ostringstream out;
    out << x;
    return out.str();
  };
  const std::string expected = std::string("expects ") + (whole ? "a whole number" : "a number") + " from " + bound(low) +
                               " to " + bound(high) + ", not '" + text + "'";
  if(text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return expected;
  char* end = nullptr;
  errno = 0;
  const double value = whole ? static_cast<double>(std::strtoll(text.c_str(), &end, 10)) : std::strtod(text.c_str(), &end);
  if(end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(value)) return expected;
  if(value < low || value > high) return expected;
  return std::string();
}

/// `--size WxH`: two whole numbers of pixels joined by an `x`, each from
/// `smallest_picture_side` to `largest_picture_side`, nothing before, between
/// or after ("800x600"); anything else (`800x600x3`, `800x`, ` 800x600`,
/// `+800x600`) gives nothing.
inline std::optional<std::pair<int, int>> parse_size(const std::string& text)
{
  const auto x = text.find('x');
  if(x == std::string::npos) return std::nullopt;
  auto side = [](const std::string& digits) -> std::optional<int> {
    if(digits.empty() || digits.size() > 5) return std::nullopt;
    int value = 0;
    for(char c : digits) {
      if(c < '0' || c > '9') return std::nullopt;
      value = 10 * value + (c - '0');
    }
    if(value < smallest_picture_side || value > largest_picture_side) return std::nullopt;
    return value;
  };
  const auto width = side(text.substr(0, x)), height = side(text.substr(x + 1));
  if(!width || !height) return std::nullopt;
  return std::make_pair(*width, *height);
}

/// The items of a comma-separated list, each without the spaces and tabs
/// around it ("tutte, lscm" is tutte and lscm). An empty item stays (as an
/// empty string) for the caller to refuse; an empty list has no items.
inline std::vector<std::string> split_list(const std::string& text)
{
  std::vector<std::string> items;
  std::stringstream list(text);
  std::string item;
  while(std::getline(list, item, ',')) {
    const auto first = item.find_first_not_of(" \t");
    const auto last = item.find_last_not_of(" \t");
    items.push_back(first == std::string::npos ? std::string() : item.substr(first, last - first + 1));
  }
  return items;
}

/// The line every command ends with: "wrote" and the files written.
inline std::string wrote_line(const std::vector<std::string>& paths)
{
  std::string line = "wrote";
  for(const std::string& p : paths) line += ' ' + p;
  return line;
}

/// The name of an output file: the mesh file's stem and an ending, with the
/// part of the ending that the stem already ends with written once. The
/// ending's parts are split at its dots: cow.off and `.patches.txt` give
/// cow.patches.txt, and so does cow.patches.ply (what `diffuv segment`
/// writes), where the plain join would give cow.patches.patches.txt.
inline std::string output_name(const std::string& mesh_path, const std::string& ending)
{
  const std::string stem = std::filesystem::path(mesh_path).stem().string();
  // The longest leading part of the ending, ending before one of its dots or
  // at its end, that the stem ends with (leaving something of the stem).
  std::size_t overlap = 0;
  for(std::size_t end = 1; end <= ending.size(); ++end) {
    if(end < ending.size() && ending[end] != '.') continue;
    if(ending[0] == '.' && end < stem.size() && stem.compare(stem.size() - end, end, ending, 0, end) == 0) overlap = end;
  }
  return stem + ending.substr(overlap);
}

/// The folder of the meshes a command maps when it is given none (its
/// `meshes/` holds cow.off, nefertiti.off): the first of `from_environment`
/// ($DIFFUV_DATA_DIR) if set, `installed` (the data installed with the tool,
/// found from the tool's own path) if it holds `mesh_name`, and `built` (the
/// build tree's data, where the tool was built).
inline std::string data_folder(const std::string& mesh_name, const char* from_environment,
                               const std::filesystem::path& installed, const std::string& built)
{
  if(from_environment) return from_environment;
  const std::filesystem::path folder = installed.lexically_normal();  // bin/../share/diffuv: share/diffuv
  std::error_code error;
  if(!folder.empty() && std::filesystem::is_regular_file(folder / "meshes" / mesh_name, error)) return folder.string();
  return built;
}

} // namespace diffuv_cli

#endif // DIFFUV_CLI_COMMAND_LINE_H
