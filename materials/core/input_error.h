// Bad input (a file that is missing, malformed or holds out-of-range values). The command line turns it
// into exit status 2 and prints what() as its single line, so the message must name the file and the problem.
#pragma once

#include <stdexcept>
#include <string>

namespace glossy {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace glossy
