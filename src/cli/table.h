// diffuv tool: the tables it prints, in columns as wide as their widest
// entry, so that a large value never pushes a row out of line.
#ifndef DIFFUV_CLI_TABLE_H
#define DIFFUV_CLI_TABLE_H

#include <algorithm>
#include <cstdarg>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace diffuv_cli {

/// `std::printf()` into a string.
#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
inline std::string formatted(const char* format, ...)
{
  std::va_list args;
  va_start(args, format);
  std::va_list again;
  va_copy(again, args);
  const int size = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::string text(size > 0 ? static_cast<std::size_t>(size) : 0, '\0');
  if(size > 0) std::vsnprintf(&text[0], text.size() + 1, format, again);
  va_end(again);
  return text;
}

/// A table: a title per column, then rows; printed with one space between
/// columns, each column as wide as its widest entry or its given width.
class Table {
public:
  enum Align { left, right };
  struct Column {
    std::string title;
    std::size_t width;  ///< the least width
    Align align;
  };

  explicit Table(std::vector<Column> columns) : columns_(std::move(columns)) {}

  /// A row of at most one cell per column (the first ones), and text written
  /// right after the last cell.
  void add_row(std::vector<std::string> cells, std::string tail = {})
  {
    rows_.push_back(Row{std::move(cells), std::move(tail)});
  }

  /// The titles and the rows, a line each.
  std::string text() const
  {
    std::vector<std::size_t> width;
    for(const Column& c : columns_) width.push_back((std::max)(c.width, c.title.size()));
    for(const Row& row : rows_)
      for(std::size_t k = 0; k < row.cells.size() && k < width.size(); ++k)
        width[k] = (std::max)(width[k], row.cells[k].size());
    std::vector<std::string> titles;
    for(const Column& c : columns_) titles.push_back(c.title);
    std::string text = line(titles, width) + '\n';
    for(const Row& row : rows_) text += line(row.cells, width) + row.tail + '\n';
    return text;
  }

private:
  struct Row {
    std::vector<std::string> cells;
    std::string tail;
  };

  std::string line(const std::vector<std::string>& cells, const std::vector<std::size_t>& width) const
  {
    std::string text;
    for(std::size_t k = 0; k < cells.size() && k < width.size(); ++k) {
      const std::string padding(width[k] - (std::min)(width[k], cells[k].size()), ' ');
      if(k > 0) text += ' ';
      text += columns_[k].align == left ? cells[k] + padding : padding + cells[k];
    }
    return text;
  }

  std::vector<Column> columns_;
  std::vector<Row> rows_;
};

} // namespace diffuv_cli

#endif // DIFFUV_CLI_TABLE_H
