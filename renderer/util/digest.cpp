#include "renderer/util/digest.h"

#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "materials/core/text.h"

#include <fstream>
#include <map>
#include <mutex>
#include <vector>

namespace glossy {

void Digest::mix(std::string_view bytes) {
  for (const char c : bytes) h_ = (h_ ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
}

Digest& Digest::add(std::string_view bytes) {
  const std::string length = std::to_string(bytes.size()) + ":";
  mix(length);
  mix(bytes);
  return *this;
}

std::string Digest::hex() const { return formatted("%016llx", static_cast<unsigned long long>(h_)); }

std::string fileDigest(const std::filesystem::path& path, std::string_view kind) {
  const std::uintmax_t size = requireInputFile(path, kind);
  std::error_code ec;
  const auto modified = std::filesystem::last_write_time(path, ec).time_since_epoch().count();
  const std::string key = path.string() + "\n" + std::to_string(size) + "\n" + std::to_string(modified);
  static std::mutex lock;
  static std::map<std::string, std::string> known;
  {
    std::lock_guard guard(lock);
    if (const auto it = known.find(key); !ec && it != known.end()) return it->second;
  }
  std::ifstream in(path, std::ios::binary);
  Digest d;
  d.add(std::to_string(size));
  std::vector<char> buffer(1 << 20);
  std::uintmax_t read = 0;
  while (in) {
    in.read(buffer.data(), std::streamsize(buffer.size()));
    const std::streamsize got = in.gcount();
    if (got <= 0) break;
    d.add(std::string_view(buffer.data(), size_t(got)));
    read += std::uintmax_t(got);
  }
  if (in.bad() || read != size) throw InputError(path.string() + ": cannot read the " + std::string(kind) + " whole");
  std::lock_guard guard(lock);
  if (!ec) known[key] = d.hex();
  return d.hex();
}

}  // namespace glossy
