#include "renderer/study/study_plan.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/params/material_name.h"
#include "renderer/output/input_folder.h"

#include <nlohmann/json.hpp>

#include <set>

namespace glossy::study {

namespace {

constexpr const char* kFormat = "glossy-study 1";
// A plan lists at most the whole library under a few lightings; a megabyte of names is not one.
constexpr std::uintmax_t kMaxPlanBytes = std::uintmax_t(16) << 20;

std::vector<std::string> names(const nlohmann::json& list, const std::string& where, const char* what) {
  if (!list.is_array()) throw InputError(where + ": '" + what + "' is not a list");
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (const auto& n : list) {
    if (!n.is_string()) throw InputError(where + ": '" + what + "' holds something that is not a name");
    const std::string name = n.get<std::string>();
    checkMaterialName(name, where + ": " + what);
    if (!seen.insert(name).second) throw InputError(where + ": " + what + " names '" + name + "' twice");
    out.push_back(name);
  }
  return out;
}

}  // namespace

std::filesystem::path sheetPath(const std::string& scene, const std::string& lighting, const std::string& material) {
  return std::filesystem::path(kSheetsFolder) / scene / lighting / (material + ".exr");
}

std::string planJson(const StudyPlan& plan) {
  nlohmann::ordered_json doc;
  doc["format"] = kFormat;
  doc["study"] = plan.study.string();
  doc["materials"] = nlohmann::ordered_json::array();
  for (const PlannedMaterial& m : plan.materials)
    doc["materials"].push_back({{"name", m.name}, {"database", m.database}, {"file", m.file.string()}});
  doc["lightings"] = plan.lightings;
  doc["scenes"] = plan.scenes;
  doc["perceptual"] = plan.perceptualDir.string();
  return doc.dump(1) + "\n";
}

bool isStudyFolder(const std::filesystem::path& out) {
  std::error_code ec;
  return std::filesystem::is_regular_file(out / kPlanFile, ec);
}

StudyPlan readPlan(const std::filesystem::path& out) {
  const std::filesystem::path file = out / kPlanFile;
  const std::string where = file.string();
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(readInputFile(out, file, kMaxPlanBytes, "study plan"));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where + ": not JSON (" + shortened(e.what()) + ")");
  }
  // Not doc.value("format", ...): it throws json's type_error for a "format" that is not a string.
  const auto format = doc.is_object() ? doc.find("format") : doc.end();
  if (format == doc.end() || !format->is_string() || format->get<std::string>() != kFormat)
    throw InputError(where + ": not a glossy study plan (no \"format\": \"" + kFormat + "\")");
  StudyPlan plan;
  try {
    std::set<std::string> seen;
    for (const auto& m : doc.at("materials")) {
      PlannedMaterial p{m.at("name").get<std::string>(), m.at("database").get<std::string>(), m.at("file").get<std::string>()};
      checkMaterialName(p.name, where + ": materials");
      if (!seen.insert(p.name).second) throw InputError(where + ": materials name '" + p.name + "' twice");
      plan.materials.push_back(std::move(p));
    }
    plan.lightings = names(doc.at("lightings"), where, "lightings");
    plan.scenes = names(doc.at("scenes"), where, "scenes");
    plan.perceptualDir = doc.at("perceptual").get<std::string>();
    if (doc.contains("study")) plan.study = doc.at("study").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where + ": not a glossy study plan (" + shortened(e.what()) + ")");
  }
  return plan;
}

}  // namespace glossy::study
