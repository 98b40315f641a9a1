#include "renderer/study/study_provenance.h"

#include "renderer/util/build_info.h"

#include <map>
#include <set>
#include <tuple>

namespace glossy::study {

using Json = nlohmann::ordered_json;

Json glossyJson() {
  Json j;
  j["version"] = std::string(glossyVersion());
  j["commit"] = std::string(glossyCommit());
  return j;
}

Json provenanceJson(const StudyProvenance& p) {
  Json out;
  out["studyFile"] = p.studyFile;
  out["studyFileCopy"] = p.studyText.empty() ? Json(nullptr) : Json(kStudyFileCopy);
  const SettingsProvenance& s = p.settings;
  Json js;
  js["width"] = s.width;
  js["height"] = s.height;
  js["spp"] = s.spp;
  js["sppGiven"] = s.sppGiven;
  js["time"] = s.seconds;
  js["targetError"] = s.targetError;
  js["seed"] = s.seed;
  js["maxDepth"] = s.maxDepth;
  js["lightSamples"] = s.lightSamples;
  js["bsdfSamples"] = s.bsdfSamples;
  js["exposure"] = s.exposure;
  js["panels"] = s.panels;
  js["half"] = s.half;
  js["resamples"] = s.resamples;
  js["reference"] = s.reference;
  out["settings"] = js;
  Json lightings = Json::array();
  for (const LightingProvenance& l : p.lightings) {
    Json j;
    j["name"] = l.name;
    j["kind"] = l.kind;
    j["description"] = l.description;
    j["map"] = l.map.empty() ? Json(nullptr) : Json(l.map);
    j["digest"] = l.digest.empty() ? Json(nullptr) : Json(l.digest);
    j["rotate"] = l.rotate;
    lightings.push_back(j);
  }
  out["lightings"] = lightings;
  Json scenes = Json::array();
  for (const SceneProvenance& sc : p.scenes) {
    Json j;
    j["name"] = sc.name;
    j["builtin"] = sc.builtin.empty() ? Json(nullptr) : Json(sc.builtin);
    j["file"] = sc.file;
    j["camera"] = sc.camera.empty() ? Json("first") : Json(sc.camera);
    j["digest"] = sc.digest;
    scenes.push_back(j);
  }
  out["scenes"] = scenes;
  // Per database: its materials by kind of measured panel, in the order of the names.
  std::map<std::string, std::map<std::string, int>> byDatabase;
  for (const MaterialProvenance& m : p.materials) ++byDatabase[m.database][m.measured];
  Json databases = Json::array();
  for (const auto& [db, kinds] : byDatabase) {
    Json j;
    j["database"] = db;
    int n = 0;
    Json measured;
    for (const auto& [kind, count] : kinds) {
      measured[kind] = count;
      n += count;
    }
    j["materials"] = n;
    j["measured"] = measured;
    databases.push_back(j);
  }
  out["databases"] = databases;
  Json materials = Json::array();
  for (const MaterialProvenance& m : p.materials) {
    Json j;
    j["name"] = m.name;
    j["database"] = m.database;
    j["measured"] = m.measured;
    j["measuredSource"] = m.measuredSource;
    j["measuredDigest"] = m.measuredDigest.empty() ? Json(nullptr) : Json(m.measuredDigest);
    materials.push_back(j);
  }
  out["materials"] = materials;
  return out;
}

Json fitsJson(std::span<const StudyRow> rows) {
  // label → (fit, source) → (databases, materials)
  std::map<std::string, std::map<std::tuple<std::string, std::string, std::string>, std::pair<std::set<std::string>, std::set<std::string>>>> fits;
  for (const StudyRow& r : rows) {
    auto& f = fits[r.label][{r.fit, r.fitSource, r.fitMetric}];
    f.first.insert(r.database);
    f.second.insert(r.material);
  }
  Json out = Json::array();
  for (const auto& [label, byFit] : fits) {
    Json jm;
    jm["model"] = label;
    Json list = Json::array();
    for (const auto& [key, where] : byFit) {
      const auto& [fit, source, metric] = key;
      Json j;
      j["fit"] = fit;
      j["source"] = source;
      j["metric"] = metric;
      j["databases"] = Json(std::vector<std::string>(where.first.begin(), where.first.end()));
      j["materials"] = int(where.second.size());
      list.push_back(j);
    }
    jm["fits"] = list;
    out.push_back(jm);
  }
  return out;
}

}  // namespace glossy::study
