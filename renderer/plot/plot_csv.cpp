#include "renderer/plot/plot_csv.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace glossy::plot {

namespace {

// A column name as a CSV field: quoted when it holds a comma, quote or line break.
std::string field(const std::string& name) {
  if (name.find_first_of(",\"\n\r") == std::string::npos) return name;
  std::string q = "\"";
  for (char c : name) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' || c == '\r' ? ' ' : c);
  return q + "\"";
}

}  // namespace

CsvTable::CsvTable(std::vector<std::string> columns) : columns_(columns.size()) {
  for (size_t i = 0; i < columns.size(); ++i) {
    if (i) text_ += ',';
    text_ += field(columns[i]);
  }
  text_ += '\n';
}

void CsvTable::add(const std::vector<double>& row) {
  if (row.size() != columns_) throw std::logic_error("CsvTable: row of " + std::to_string(row.size()) + " values for " +
                                                     std::to_string(columns_) + " columns");
  for (size_t i = 0; i < row.size(); ++i) {
    if (i) text_ += ',';
    if (!std::isfinite(row[i])) continue;
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, row[i]);
    text_.append(buf, end);
  }
  text_ += '\n';
  ++rows_;
}

}  // namespace glossy::plot
