#include "renderer/lights/nested_grid.h"

#include "renderer/lights/compact_cdf.h"

#include <cmath>
#include <stdexcept>

namespace glossy {

namespace {

// n items split into `parts` runs as evenly as integers allow: the runs' starts and the end.
std::vector<std::size_t> splits(std::size_t n, std::size_t parts) {
  std::vector<std::size_t> start(parts + 1);
  for (std::size_t p = 0; p <= parts; ++p) start[p] = p * n / parts;
  return start;
}

std::vector<std::size_t> owners(const std::vector<std::size_t>& start) {
  std::vector<std::size_t> owner(start.back());
  for (std::size_t p = 0; p + 1 < start.size(); ++p)
    for (std::size_t i = start[p]; i < start[p + 1]; ++i) owner[i] = p;
  return owner;
}

}  // namespace

NestedGrid::NestedGrid(std::size_t width, std::size_t height, std::size_t cellColumns, std::size_t cellRows,
                       const RowWeights& rowWeights)
    : width_(width), height_(height) {
  if (width == 0 || height == 0 || cellColumns == 0 || cellRows == 0 || cellColumns > width || cellRows > height)
    throw std::invalid_argument("NestedGrid: a grid of at least one patch per cell");
  columnStart_ = splits(width, cellColumns);
  rowStart_ = splits(height, cellRows);
  cellOfColumn_ = owners(columnStart_);
  cellOfRow_ = owners(rowStart_);
  cellWeight_.assign(cellRows * cellColumns, 0.0);
  columnCdf_.resize(width * height);
  rowCdf_.resize(cellColumns * height);

  std::vector<double> weights(width), rowInCell(cellColumns * height);  // [cc·H + row]
  for (std::size_t row = 0; row < height; ++row) {
    rowWeights(row, weights);
    for (std::size_t cc = 0; cc < cellColumns; ++cc) {
      const std::size_t begin = columnStart_[cc], n = columnStart_[cc + 1] - begin;
      for (std::size_t i = begin; i < begin + n; ++i)
        if (!(weights[i] >= 0.0) || !std::isfinite(weights[i]))
          throw std::invalid_argument("NestedGrid: weights must be finite and ≥ 0");
      const double sum = compact_cdf::build(&weights[begin], n, &columnCdf_[row * width + begin]);
      rowInCell[cc * height + row] = sum;
      cellWeight_[cellOfRow_[row] * cellColumns + cc] += sum;
    }
  }
  for (std::size_t cc = 0; cc < cellColumns; ++cc)
    for (std::size_t cr = 0; cr < cellRows; ++cr) {
      const std::size_t begin = cc * height + rowStart_[cr], n = rowStart_[cr + 1] - rowStart_[cr];
      compact_cdf::build(&rowInCell[begin], n, &rowCdf_[begin]);
    }
}

std::size_t NestedGrid::sampleRow(std::size_t cc, std::size_t cr, double& ux) const {
  const std::size_t begin = rowStart_[cr];
  return begin + compact_cdf::sample(&rowCdf_[cc * height_ + begin], rowStart_[cr + 1] - begin, ux);
}

std::size_t NestedGrid::sampleColumn(std::size_t cc, std::size_t row, double& uy) const {
  const std::size_t begin = columnStart_[cc];
  return begin + compact_cdf::sample(&columnCdf_[row * width_ + begin], columnStart_[cc + 1] - begin, uy);
}

double NestedGrid::probabilityInCell(std::size_t column, std::size_t row) const {
  const std::size_t cc = cellOfColumn_[column], cr = cellOfRow_[row];
  return compact_cdf::share(&rowCdf_[cc * height_ + rowStart_[cr]], row - rowStart_[cr]) *
         compact_cdf::share(&columnCdf_[row * width_ + columnStart_[cc]], column - columnStart_[cc]);
}

}  // namespace glossy
