// What the subcommands write on stdout: lines of numbers in full double precision (the shortest text that
// reads back to the same double), and the text as a whole.
#pragma once

#include <charconv>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <string_view>

namespace glossy::cli {

// Appends "v0,v1,...\n".
inline void appendLine(std::string& out, std::initializer_list<double> values) {
  for (double v : values) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, end);
    out += ',';
  }
  out.back() = '\n';
}

// Writes `text` to stdout; the exit status: 0, or 1 when stdout did not take it (a full disk, a closed pipe).
inline int writeStdout(std::string_view text) {
  std::fwrite(text.data(), 1, text.size(), stdout);
  return std::fflush(stdout) == 0 ? 0 : 1;
}

}  // namespace glossy::cli
