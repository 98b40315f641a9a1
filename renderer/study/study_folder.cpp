// A study's output folder, known by the plan glossy wrote there (study_folder.h).
#include "renderer/study/study_folder.h"

#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "materials/core/text.h"
#include "renderer/output/inside_folder.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/output_lock.h"

namespace glossy::study {

namespace fs = std::filesystem;

namespace {

// The lock file OutputLock makes for OUT/study.json.
const std::string kLockFile = std::string(".") + kPlanFile + ".lock";

std::string where(const fs::path& out) { return "-o " + printableLine(out.string(), 200); }

// Empty but for the lock of another run claiming it now.
bool emptyButTheLock(const fs::path& out) {
  std::error_code ec;
  for (fs::directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename() != kLockFile) return false;
  if (ec) throw InputError(where(out) + ": cannot list: " + ec.message());
  return true;
}

}  // namespace

void checkStudyFolder(const fs::path& out, const StudyPlan& plan) {
  std::error_code ec;
  const fs::file_status folder = fs::status(out, ec);
  if (!fs::exists(folder)) return;
  if (!fs::is_directory(folder)) throw InputError(where(out) + ": is not a folder");
  if (!fs::exists(fs::symlink_status(out / kPlanFile, ec))) {
    if (emptyButTheLock(out)) return;
    throw InputError(where(out) + ": a folder that is not a study's output (no " + kPlanFile +
                     "); give a new or empty folder, or the -o of an earlier run of this study");
  }
  StudyPlan there;
  try {
    there = readPlan(out);
  } catch (const InputError& e) {
    throw InputError(where(out) + ": its " + kPlanFile + " is not a plan glossy wrote (" + printableLine(e.what(), 200) +
                     "); not writing into it");
  }
  if (there.study.empty()) {
    // A plan of an older glossy, which did not name its study: this study's if it plans the same sheets.
    there.study = plan.study;
    if (planJson(there) == planJson(plan)) return;
    throw InputError(where(out) + ": holds the output of another study (its " + kPlanFile +
                     " plans other sheets); give a new or empty folder");
  }
  if (there.study != plan.study)
    throw InputError(where(out) + ": holds the output of another study, " + printableLine(there.study.string(), 200) +
                     "; give a new or empty folder");
}

void claimStudyFolder(const fs::path& out, const StudyPlan& plan) {
  // Waits for a run claiming the folder now: a few milliseconds, after which the folder says whose it is.
  const OutputLock lock(out / kPlanFile, "-o", OutputLock::Busy::Wait);
  checkStudyFolder(out, plan);
  checkWriteInside(out, out / kPlanFile, "-o");
  const std::string text = planJson(plan);
  std::string there;
  if (std::error_code ec; fs::is_regular_file(fs::symlink_status(out / kPlanFile, ec))) {
    try {
      there = readInputFile(out / kPlanFile, 16 << 20, "study plan");
    } catch (const InputError&) {
    }
  }
  // Written only when it changed: the shards of an array find the same plan and leave it be.
  if (there != text) writeFileAtomically(out / kPlanFile, text);
}

}  // namespace glossy::study
