// The mean of a per-pixel map over the object's pixels: how every error map of a sheet becomes its figure.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace glossy {

// The mean of `map` over the pixels where mask is nonzero (one entry per pixel each); 0 if none.
// Throws std::invalid_argument if the sizes differ.
inline double maskedMean(const std::vector<float>& map, const std::vector<char>& mask) {
  if (mask.size() != map.size())
    throw std::invalid_argument("maskedMean: the mask has " + std::to_string(mask.size()) + " entries, the map " +
                                std::to_string(map.size()));
  double sum = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) sum += map[i], ++count;
  return count ? sum / double(count) : 0.0;
}

}  // namespace glossy
