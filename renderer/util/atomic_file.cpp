#include "renderer/util/atomic_file.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <pthread.h>
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
//
// The handler may run on any thread, a library's worker included, while the writer's thread goes on. So a
// writer marks its slot Creating before it checks `stopping` and creates the file, and keeps it so until the
// slot names the file; the handler sets `stopping`, waits until no slot is Creating or Filling, then removes
// the named files. Either the writer sees `stopping` and creates nothing, or the handler waits for its file's
// name. The writer's thread holds the signals back while it creates, so the handler never waits for itself.
enum SlotState : int { Free = 0, Filling = 1, Named = 2, Creating = 3 };
struct Slot {
  std::atomic<int> state{Free};
  std::array<char, 4096> path{};
};
std::array<Slot, 64> slots;
std::atomic<bool> stopping{false};

// A slot holding `path` and marked Creating, or -1.
int claim(const std::string& path) {
  if (path.size() >= Slot{}.path.size()) return -1;
  for (int i = 0; i < int(slots.size()); ++i) {
    int expected = Free;
    if (slots[size_t(i)].state.compare_exchange_strong(expected, Filling)) {
      std::memcpy(slots[size_t(i)].path.data(), path.c_str(), path.size() + 1);
      slots[size_t(i)].state.store(Creating);
      return i;
    }
  }
  return -1;
}

void name(int slot, const std::string& path) {
  if (slot < 0) return;
  slots[size_t(slot)].state.store(Filling);
  std::memcpy(slots[size_t(slot)].path.data(), path.c_str(), path.size() + 1);
  slots[size_t(slot)].state.store(Named);
}

void release(int slot) {
  if (slot >= 0) slots[size_t(slot)].state.store(Free);
}

extern "C" void removeTemporariesAndStop(int sig) {
  stopping.store(true);
  // A writer creating a file on another thread takes microseconds; a second at most, then go on regardless.
  const struct timespec millisecond = {0, 1000000};
  for (int waited = 0; waited < 1000; ++waited) {
    bool busy = false;
    for (const Slot& s : slots) busy = busy || s.state.load() == Creating || s.state.load() == Filling;
    if (!busy) break;
    ::nanosleep(&millisecond, nullptr);  // async-signal-safe
  }
  for (Slot& s : slots)
    if (s.state.load() == Named) ::unlink(s.path.data());  // async-signal-safe
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
  sigset_t stops, before;
  sigemptyset(&stops);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&stops, sig);
  pthread_sigmask(SIG_BLOCK, &stops, &before);
  slot_ = claim(tmpl);
  if (stopping.load()) {  // being stopped: create nothing, and wait for the end
    release(slot_);
    for (;;) ::pause();
  }
  fd_ = mkstemp(tmpl.data());
  if (fd_ < 0) {
    const int saved = errno;
    release(slot_);
    pthread_sigmask(SIG_SETMASK, &before, nullptr);
    errno = saved;
    throw ioError(path, "cannot create a temporary file beside it");
  }
  name(slot_, tmpl);
  pthread_sigmask(SIG_SETMASK, &before, nullptr);
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
