// Bad input (a file that is missing, malformed or holds out-of-range values). The command line turns it
// into exit status 2 and prints what() as its single line, Python raises it as glossy.InputError, so the
// message must name the file and the problem. Every message passes safeLine here, the one place messages
// are formed: whatever a file name, a glob or a file's content puts into it, what() is one safe line.
#pragma once

#include "materials/core/text.h"

#include <stdexcept>
#include <string>

namespace glossy {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(safeLine(message)) {}
  explicit InputError(const char* message) : std::runtime_error(safeLine(message)) {}
};

}  // namespace glossy
