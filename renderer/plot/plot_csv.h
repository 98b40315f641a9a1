// The numbers behind a figure, as CSV beside it: a header of column names, then one row per point, each
// number in full double precision (the shortest text that reads back to the same double, as `glossy eval`
// prints), an empty field where there is no value (an unmeasured bin of the table). Never NaN or Inf.
#pragma once

#include <string>
#include <vector>

namespace glossy::plot {

class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> columns);
  // One value per column; a non-finite value is written as an empty field.
  void add(const std::vector<double>& row);
  size_t rows() const { return rows_; }
  const std::string& str() const { return text_; }

 private:
  size_t columns_, rows_ = 0;
  std::string text_;
};

}  // namespace glossy::plot
