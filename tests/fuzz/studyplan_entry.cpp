// A study output folder's study.json (renderer/study/study_plan.h) as a resumed run, `glossy study
// --analyse` and `glossy report` read it: the folder taken for a study's (isStudyFolder), checked as this
// study's or another's (checkStudyFolder, a resumed run, with another study file's plan), its plan read
// (readPlan) and, once accepted: checked as its own study's (it must be), written back and read again
// (the same plan must give the same text), and its rows read as the analysis and the report read them
// (readStudyRows: the perceptual folder it names, then its first sheet, which the folder does not hold).
#include "materials/core/input_error.h"
#include "renderer/study/study_folder.h"
#include "renderer/study/study_plan.h"
#include "renderer/study/study_rows.h"
#include "tests/fuzz/fuzz_entries.h"
#include "tests/fuzz/fuzz_temp_dir.h"

#include <stdexcept>
#include <string>

namespace glossy::fuzz {

namespace {

namespace fs = std::filesystem;

Bytes bytesOf(const std::string& text) { return {reinterpret_cast<const uint8_t*>(text.data()), text.size()}; }

// OUT and a second folder for the plan written back, made once for the process.
const fs::path& folders() {
  static const fs::path out = [] {
    const TempFile probe(".probe", {});
    const fs::path dir = probe.path().parent_path();
    fs::create_directories(dir / "plan" / "out");
    fs::create_directories(dir / "plan" / "again");
    return dir / "plan";
  }();
  return out;
}

}  // namespace

void studyplanEntry(Bytes data) {
  const fs::path out = folders() / "out";
  const TempFile file("plan/out/study.json", data);
  if (!study::isStudyFolder(out)) throw std::logic_error("a folder holding study.json not taken for a study's");
  study::StudyPlan other;
  other.study = "/nowhere/another-study.toml";
  try {
    study::checkStudyFolder(out, other);
  } catch (const InputError&) {
  }
  const study::StudyPlan plan = study::readPlan(out);
  try {
    study::checkStudyFolder(out, plan);
  } catch (const InputError& e) {
    throw std::logic_error(std::string("a plan refused as its own study's: ") + e.what());
  }
  const std::string json = study::planJson(plan);
  {
    const TempFile again("plan/again/study.json", bytesOf(json));
    try {
      if (study::planJson(study::readPlan(again.path().parent_path())) != json)
        throw std::logic_error("a plan written back reads as another plan");
    } catch (const InputError& e) {
      throw std::logic_error(std::string("a plan written back does not read: ") + e.what());
    }
  }
  (void)study::readStudyRows(out);
}

}  // namespace glossy::fuzz
