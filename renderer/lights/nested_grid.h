// A piecewise-constant distribution over a W × H grid of patches, grouped into a coarser grid of cells,
// that samples a patch within a given cell: the second stage of the environment's sampling, whose first
// chooses the cell (cosine_bins.h), so that the choice of cell can change with the receiving surface
// while the distribution inside each cell is stored once.
//
// Cells split the columns and the rows as evenly as integers allow: cell column c covers patch columns
// [⌊c·W/CW⌋, ⌊(c+1)·W/CW⌋), likewise rows. Inside a cell a patch is drawn by its row (in proportion to
// the row's weight in the cell) and then its column, both by inverting CDFs (compact_cdf.h: the rows' in
// float, the columns', a table the size of the grid, in 16 bits), so the map from u to the patch is
// monotone in each coordinate and a stratified u stays stratified.
#pragma once

#include "materials/core/types.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace glossy {

class NestedGrid {
 public:
  NestedGrid() = default;
  // The weights of the patches, non-negative and finite, written a row at a time by rowWeights(row, out)
  // (out: W long), called once per row in order. 1 ≤ cellColumns ≤ W, 1 ≤ cellRows ≤ H.
  using RowWeights = std::function<void(std::size_t row, std::span<double> out)>;
  NestedGrid(std::size_t width, std::size_t height, std::size_t cellColumns, std::size_t cellRows,
             const RowWeights& rowWeights);

  std::size_t width() const { return width_; }
  std::size_t height() const { return height_; }
  std::size_t cellColumns() const { return columnStart_.size() - 1; }
  std::size_t cellRows() const { return rowStart_.size() - 1; }
  // Cell (cc, cr)'s patches: columns [columnStart(cc), columnStart(cc + 1)), rows likewise.
  std::size_t columnStart(std::size_t cc) const { return columnStart_[cc]; }
  std::size_t rowStart(std::size_t cr) const { return rowStart_[cr]; }
  std::size_t cellOfColumn(std::size_t column) const { return cellOfColumn_[column]; }
  std::size_t cellOfRow(std::size_t row) const { return cellOfRow_[row]; }
  // The sum of the weights of cell (cc, cr)'s patches.
  double cellWeight(std::size_t cc, std::size_t cr) const { return cellWeight_[cr * cellColumns() + cc]; }

  // A patch of cell (cc, cr), drawn with u in [0,1)²: u.x picks its row, u.y its column, and each
  // becomes its position within what it picked (in [0,1)), for a further warp inside the patch.
  struct Patch {
    std::size_t column, row;
  };
  Patch sample(std::size_t cc, std::size_t cr, Vec2& u) const {
    const std::size_t row = sampleRow(cc, cr, u.x);
    return {sampleColumn(cc, row, u.y), row};
  }
  // Its two steps, for callers that take many lanes a step at a time and fetch each step's table lines for
  // all lanes before any is read, so that the lanes' cache misses overlap: the row of cell (cc, cr) that
  // ux picks, then the column of that row in cell column cc that uy picks (each left at its position in
  // what it picked).
  std::size_t sampleRow(std::size_t cc, std::size_t cr, double& ux) const;
  std::size_t sampleColumn(std::size_t cc, std::size_t row, double& uy) const;
  [[gnu::always_inline]] void prefetchRows(std::size_t cc, std::size_t cr) const {
    __builtin_prefetch(&rowCdf_[cc * height_ + rowStart_[cr]]);
  }
  [[gnu::always_inline]] void prefetchColumns(std::size_t cc, std::size_t row) const {
    __builtin_prefetch(&columnCdf_[row * width_ + columnStart_[cc]]);
  }
  // The probability that sample() draws patch (column, row) from its cell.
  double probabilityInCell(std::size_t column, std::size_t row) const;

 private:
  std::size_t width_ = 0, height_ = 0;
  std::vector<std::size_t> columnStart_, rowStart_;     // CW + 1 and CH + 1 boundaries
  std::vector<std::size_t> cellOfColumn_, cellOfRow_;   // W and H
  std::vector<double> cellWeight_;                      // CH × CW
  // rowCdf_[cc·H + row]: the CDF over the rows of the cell (cc, cellOfRow(row)), by their weight in it.
  std::vector<float> rowCdf_;
  // columnCdf_[row·W + column]: the CDF over the columns of the cell's part of the row, in 16 bits (2 bytes
  // a patch: the 16k map's table is 256 MB).
  std::vector<uint16_t> columnCdf_;
};

}  // namespace glossy
