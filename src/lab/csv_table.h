#pragma once
// CsvTable: the experiments' source of truth, a header row and data rows of text cells,
// written as RFC 4180 CSV (cells holding a comma, a quote or a line break are quoted). Numbers
// are formatted by the caller (csvNumber) so files are stable and diffable.
// Plain value type; not thread-safe.

#include <string>
#include <vector>

namespace prt {

class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> columns);

  // One cell per column (a CHECK).
  void addRow(std::vector<std::string> cells);

  const std::vector<std::string>& columns() const { return columns_; }
  const std::vector<std::vector<std::string>>& rows() const { return rows_; }
  // Index of the named column (a CHECK that it exists).
  size_t column(const std::string& name) const;

  std::string text() const;
  // Writes text() to `path` atomically (image/atomic_file.h).
  void write(const std::string& path) const;

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;
};

// A number as CSV text: up to `significant` significant digits, no trailing zeros; NaN and
// infinities as the empty cell (missing).
std::string csvNumber(double value, int significant = 6);

}  // namespace prt
