#include "materials/core/input_file.h"

#include "materials/core/input_error.h"

#include <fstream>

namespace glossy {

std::string readInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes, std::string_view kind) {
  const std::string where = path.string() + ": ";
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw InputError(where + "cannot open " + std::string(kind) + " (no such file)");
  if (std::filesystem::is_directory(status)) throw InputError(where + "is a folder, not a " + std::string(kind));
  if (!std::filesystem::is_regular_file(status)) throw InputError(where + "is not a regular file (a device, FIFO or socket)");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(where + "cannot read its size: " + ec.message());
  if (size > maxBytes)
    throw InputError(where + std::to_string(size) + " bytes, too large for a " + std::string(kind) + " (at most " +
                     std::to_string(maxBytes) + ")");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(where + "cannot open " + std::string(kind));
  // One byte more than its size asks for: a file that changes while it is read is refused, not cut.
  std::string bytes(size_t(size) + 1, '\0');
  in.read(bytes.data(), std::streamsize(bytes.size()));
  if (in.bad()) throw InputError(where + "read failed");
  if (std::uintmax_t(in.gcount()) != size) throw InputError(where + "changed size while it was read");
  bytes.resize(size_t(size));
  return bytes;
}

}  // namespace glossy
