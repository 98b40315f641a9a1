// What glossy is: its version (the project's, CMakeLists.txt) and the commit of the source tree it was built
// from (`git describe --always --dirty`, "unknown" outside git; cmake/build_commit.cmake), for the
// provenance outputs record (a study's results.json and methods, `glossy --version`).
#pragma once

#include <string_view>

namespace glossy {

std::string_view glossyVersion();
std::string_view glossyCommit();

}  // namespace glossy
