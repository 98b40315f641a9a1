// Numbers on stdout in full double precision: the shortest text that reads back to the same double.
#pragma once

#include <charconv>
#include <string>

namespace glossy::cli {

inline void appendNumber(std::string& out, double v) {
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, end);
}

}  // namespace glossy::cli
