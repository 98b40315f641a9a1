// A study's output folder is its own only when glossy says so. Its marker is the plan glossy writes there,
// OUT/study.json (study_plan.h), which names the study file; a folder is this study's when that plan names
// this study file. So a user's folder that merely holds a file named study.json, or the folder of another
// study, is refused before any work — never filled with sheets, its files never replaced.
//
// The folder is claimed under a lock that runs take in turn (OUT/.study.json.lock, renderer/util/
// output_lock.h): of two runs of different studies starting on one new folder, the first writes its plan
// and the second finds it and is refused. Runs of one study (the shards of a job array) share the folder.
// The plan a run renders and analyses is the one it holds in memory, never one read back from the folder,
// which a later run of an edited study file may have replaced.
#pragma once

#include "renderer/study/study_plan.h"

#include <filesystem>

namespace glossy::study {

// Throws InputError "-o OUT: ..." unless OUT is missing, empty, or holds a plan glossy wrote naming
// `plan`'s study file. Writes nothing: the check made before the study's work.
void checkStudyFolder(const std::filesystem::path& out, const StudyPlan& plan);

// Makes OUT this study's folder: under its lock, checks it again and writes `plan` as OUT/study.json when it
// is not there already (a new folder, or the study file edited since the last run).
void claimStudyFolder(const std::filesystem::path& out, const StudyPlan& plan);

}  // namespace glossy::study
