#include "renderer/util/notes.h"

#include "materials/core/text.h"

#include <cstdio>
#include <mutex>
#include <set>
#include <utility>
#include <vector>

namespace glossy {

namespace {

std::mutex& lock() {
  static std::mutex m;
  return m;
}

bool& keptForTaking() {
  static bool kept = false;
  return kept;
}

std::vector<std::string>& pending() {
  static std::vector<std::string> lines;
  return lines;
}

std::set<std::string>& told() {
  static std::set<std::string> lines;
  return lines;
}

}  // namespace

void note(std::string line) {
  std::lock_guard guard(lock());
  pending().push_back(safeLine(line));  // one safe line, as an error's message is (input_error.h)
}

void noteOnce(std::string line) {
  std::lock_guard guard(lock());
  if (told().insert(line).second) pending().push_back(std::move(line));
}

void flushNotes() {
  std::lock_guard guard(lock());
  if (keptForTaking()) return;
  for (const std::string& line : pending()) std::fprintf(stderr, "glossy: %s\n", line.c_str());
  std::fflush(stderr);
  pending().clear();
}

void discardNotes() {
  std::lock_guard guard(lock());
  // A line dropped untold is told when it comes again.
  for (const std::string& line : pending()) told().erase(line);
  pending().clear();
}

std::vector<std::string> takeNotes() {
  std::lock_guard guard(lock());
  return std::exchange(pending(), {});
}

void tell(const std::string& line) {
  std::lock_guard guard(lock());
  std::fprintf(stderr, "%s\n", line.c_str());
  std::fflush(stderr);
}

void keepNotesForTaking() {
  std::lock_guard guard(lock());
  keptForTaking() = true;
}

}  // namespace glossy
