// Only this file includes the generated header: a new commit recompiles it alone.
#include "renderer/util/build_info.h"

#include "renderer/util/glossy_commit.h"

namespace glossy {

std::string_view glossyVersion() { return GLOSSY_VERSION; }
std::string_view glossyCommit() { return GLOSSY_COMMIT; }

}  // namespace glossy
