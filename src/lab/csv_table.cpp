#include "lab/csv_table.h"

#include <cmath>
#include <cstdio>

#include "core/check.h"
#include "image/atomic_file.h"

namespace prt {
namespace {

std::string csvField(const std::string& cell) {
  if (cell.find_first_of(",\"\r\n") == std::string::npos) return cell;
  std::string out = "\"";
  for (char c : cell) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

void appendLine(std::string& out, const std::vector<std::string>& cells) {
  for (size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) out += ',';
    out += csvField(cells[i]);
  }
  out += '\n';
}

}  // namespace

CsvTable::CsvTable(std::vector<std::string> columns) : columns_(std::move(columns)) {
  PRT_CHECK(!columns_.empty());
}

void CsvTable::addRow(std::vector<std::string> cells) {
  PRT_CHECK(cells.size() == columns_.size());
  rows_.push_back(std::move(cells));
}

size_t CsvTable::column(const std::string& name) const {
  for (size_t i = 0; i < columns_.size(); ++i) {
    if (columns_[i] == name) return i;
  }
  PRT_CHECK(false && "no such column");
  return 0;
}

std::string CsvTable::text() const {
  std::string out;
  appendLine(out, columns_);
  for (const auto& row : rows_) appendLine(out, row);
  return out;
}

void CsvTable::write(const std::string& path) const {
  const std::string contents = text();
  writeFileAtomically(path, contents);
}

std::string csvNumber(double value, int significant) {
  if (!std::isfinite(value)) return "";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
  return buffer;
}

}  // namespace prt
