#include "materials/core/atomic_file.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace glossy {

namespace {

// The temporaries' names: TARGET + kTemporaryInfix + six characters mkstemp chooses.
constexpr std::string_view kTemporaryInfix = ".tmp.glossy-";
constexpr size_t kTemporaryRandom = 6;

std::runtime_error ioError(const std::filesystem::path& path, const char* what) {
  return std::runtime_error(path.string() + ": " + what + ": " + std::strerror(errno));
}

// The temporaries in flight, where a signal handler can read them: fixed storage (no allocation), each slot
// claimed and released through an atomic flag, its path written before the flag says it is there.
// A path too long for a slot, or more writers than slots, is simply not cleaned on signal.
struct Slot {
  std::atomic<int> state{0};  // 0 free, 1 being filled or emptied, 2 holds a path
  std::array<char, 4096> path{};
};
std::array<Slot, 64> slots;

int claim(const std::string& path) {
  if (path.size() >= Slot{}.path.size()) return -1;
  for (int i = 0; i < int(slots.size()); ++i) {
    int expected = 0;
    if (slots[size_t(i)].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(slots[size_t(i)].path.data(), path.c_str(), path.size() + 1);
      slots[size_t(i)].state.store(2);
      return i;
    }
  }
  return -1;
}

void release(int slot) {
  if (slot >= 0) slots[size_t(slot)].state.store(0);
}

extern "C" void removeTemporariesAndStop(int sig) {
  for (Slot& s : slots)
    if (s.state.load() == 2) ::unlink(s.path.data());  // async-signal-safe
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

bool isTemporaryOf(const std::filesystem::path& file, const std::filesystem::path& target) {
  const std::string name = file.filename().string(), prefix = target.filename().string() + std::string(kTemporaryInfix);
  return file.parent_path() == target.parent_path() && name.size() == prefix.size() + kTemporaryRandom && name.starts_with(prefix);
}

void removeTemporariesOnSignal() {
  struct sigaction action {};
  action.sa_handler = removeTemporariesAndStop;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &action, nullptr);
}

PendingTemporary::PendingTemporary(const std::filesystem::path& path) {
  std::string tmpl = path.string() + std::string(kTemporaryInfix) + std::string(kTemporaryRandom, 'X');
  // Claimed under the template's name first, so the file is never on disk unknown to the handler; the
  // name mkstemp fills in is then written into the same slot.
  slot_ = claim(tmpl);
  fd_ = mkstemp(tmpl.data());
  if (fd_ < 0) {
    const int saved = errno;
    release(slot_);
    errno = saved;
    throw ioError(path, "cannot create a temporary file beside it");
  }
  if (slot_ >= 0) {
    slots[size_t(slot_)].state.store(1);  // the handler skips a path while it is being rewritten
    std::memcpy(slots[size_t(slot_)].path.data(), tmpl.c_str(), tmpl.size() + 1);
    slots[size_t(slot_)].state.store(2);
  }
  tmp_ = tmpl;
}

PendingTemporary::~PendingTemporary() {
  if (fd_ >= 0) ::close(fd_);
  if (!tmp_.empty()) ::unlink(tmp_.c_str());
  release(slot_);
}

int PendingTemporary::close() {
  const int closed = ::close(fd_);
  fd_ = -1;  // closed either way
  return closed;
}

int PendingTemporary::renameTo(const std::filesystem::path& target) {
  const int renamed = std::rename(tmp_.c_str(), target.c_str());
  if (renamed == 0) {
    release(slot_);
    slot_ = -1;
    tmp_.clear();
  }
  return renamed;
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
  PendingTemporary tmp(path);
  const char* p = contents.data();
  size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(tmp.fd(), p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw ioError(path, "cannot write");
    }
    p += n;
    left -= static_cast<size_t>(n);
  }
  // mkstemp creates 0600; outputs are ordinary files.
  if (::fchmod(tmp.fd(), 0644) != 0) throw ioError(path, "cannot set permissions");
  if (::fsync(tmp.fd()) != 0) throw ioError(path, "cannot flush");
  if (tmp.close() != 0) throw ioError(path, "cannot close");
  if (tmp.renameTo(path) != 0) throw ioError(path, "cannot rename the temporary file into place");
}

}  // namespace glossy
