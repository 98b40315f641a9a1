#include "renderer/plot/svg_to_png.h"

#include "renderer/util/atomic_file.h"
#include "materials/core/text.h"

#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace glossy::plot {

std::optional<std::filesystem::path> findRsvgConvert() {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::string dirs = path;
  for (size_t start = 0; start <= dirs.size();) {
    size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    const std::filesystem::path candidate = std::filesystem::path(dirs.substr(start, end - start)) / "rsvg-convert";
    std::error_code ec;
    if (end > start && std::filesystem::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return std::nullopt;
}

void svgToPng(const std::filesystem::path& rsvgConvert, const std::filesystem::path& svg, const std::filesystem::path& png,
              double zoom) {
  PendingTemporary tmp(png);
  // The PNG readable like the figures' other files (the temporary is created 0600).
  if (::fchmod(tmp.fd(), 0644) != 0) throw std::runtime_error(png.string() + ": cannot set permissions");
  // No shell: names reach rsvg-convert as they are, whatever they hold. Its stdout is the temporary.
  std::vector<std::string> args = {rsvgConvert.string(), "--zoom", formatted("%g", zoom), "--background-color", "white",
                                   "--format", "png", svg.string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, tmp.fd(), STDOUT_FILENO);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, rsvgConvert.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error(png.string() + ": cannot run " + rsvgConvert.string());
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error(png.string() + ": lost rsvg-convert");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(png.string() + ": rsvg-convert failed on " + svg.string());
  if (tmp.close() != 0 || tmp.renameTo(png) != 0) throw std::runtime_error(png.string() + ": cannot write");
}

}  // namespace glossy::plot
