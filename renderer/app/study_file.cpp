#include "renderer/app/study_file.h"

#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "materials/core/text.h"
#include "materials/core/toml_input.h"
#include "materials/params/material_file.h"
#include "materials/params/material_name.h"
#include "renderer/app/option_specs.h"
#include "renderer/sheet/comparison_grid.h"
#include "renderer/study/perceptual.h"
#include "renderer/util/data_dir.h"

#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace glossy::app {

namespace fs = std::filesystem;

namespace {

// A study file is a page of settings; anything this large is not one.
constexpr std::uintmax_t kMaxStudyFileBytes = 1 << 20;
// As --env-constant: brighter than any sky by far, finite in float times the brightest BRDF peak.
constexpr double kMaxRadiance = 1e12;
// The scenes glossy ships (scenes/), by the name a study file gives them.
constexpr const char* kBuiltinScenes[] = {"preview", "sphere"};
// Sheets a study may hold: its bookkeeping (a few hundred bytes a sheet, in every array task) and its one
// folder per lighting stay small, and a run of them ends within a cluster's budget.
constexpr std::uintmax_t kMaxStudySheets = 1000000;

struct Reader {
  std::string source;  // the study file, for messages
  fs::path folder;     // relative paths resolve against it

  [[noreturn]] void fail(const toml::node& node, const std::string& key, const std::string& why) const {
    throw InputError(tomlAt(source, node) + key + ": " + why);
  }

  // Each key of `t` must be one of `known`.
  void keys(const toml::table& t, const std::string& prefix, const std::vector<std::string_view>& known) const {
    for (const auto& [key, node] : t)
      if (std::find(known.begin(), known.end(), key.str()) == known.end())
        fail(node, prefix + std::string(key.str()), "unknown key (known here: " + joined(known, ", ") + ")");
  }

  std::string text(const toml::node& node, const std::string& key) const {
    if (!node.is_string()) fail(node, key, "must be a string");
    return node.as_string()->get();
  }

  // A path from the file, relative to the study file's folder: an existing regular file, or folder.
  fs::path path(const toml::node& node, const std::string& key, bool folderWanted) const {
    const std::string given = text(node, key);
    if (given.empty()) fail(node, key, "empty path");
    const fs::path p = fs::path(given).is_absolute() ? fs::path(given) : folder / given;
    std::error_code ec;
    if (!fs::exists(p, ec)) fail(node, key, "no such " + std::string(folderWanted ? "folder " : "file ") + p.string());
    if (folderWanted ? !fs::is_directory(p, ec) : !fs::is_regular_file(p, ec))
      fail(node, key, p.string() + " is not a " + (folderWanted ? "folder" : "regular file"));
    return fs::weakly_canonical(p, ec);
  }

  std::string name(const toml::node& node, const std::string& key, const std::string& given) const {
    if (!isMaterialName(given))
      fail(node, key, "'" + shortened(given) + "' is not a plain name (letters, digits, '_', '.', '+', '-'; it names a folder)");
    return given;
  }
};

// A library material: its database folder and file.
struct LibraryEntry {
  std::string database, stem;
  fs::path file;
};

std::vector<LibraryEntry> libraryEntries(const fs::path& library) {
  std::vector<LibraryEntry> out;
  std::error_code ec;
  for (const auto& db : fs::directory_iterator(library, ec)) {
    if (!db.is_directory(ec)) continue;
    for (const auto& f : fs::directory_iterator(db.path(), ec))
      if (f.path().extension() == ".toml" && f.is_regular_file(ec))
        out.push_back({db.path().filename().string(), f.path().stem().string(), f.path()});
  }
  std::sort(out.begin(), out.end(), [](const LibraryEntry& a, const LibraryEntry& b) { return a.file < b.file; });
  if (out.empty()) throw InputError(library.string() + ": no material library here (a folder per database of NAME.toml files)");
  return out;
}

// The library's materials a pattern names: "DATABASE/GLOB" (e.g. "merl/*", "rgl-epfl/acrylic*") or "GLOB" over
// the names of every database ("gold-paint").
std::vector<size_t> matches(const Reader& r, const toml::node& node, const std::string& key, const std::string& pattern,
                            const std::vector<LibraryEntry>& library) {
  static const std::string kAllowed = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.+-*?[]!/";
  if (pattern.empty() || pattern.find_first_not_of(kAllowed) != std::string::npos || pattern.front() == '/' ||
      pattern.find("..") != std::string::npos || std::count(pattern.begin(), pattern.end(), '/') > 1 ||
      std::count(pattern.begin(), pattern.end(), '[') != std::count(pattern.begin(), pattern.end(), ']'))
    r.fail(node, key, "'" + shortened(pattern) + "' is not a glob over the library (DATABASE/NAME or NAME, with * ? [...])");
  const bool withDatabase = pattern.find('/') != std::string::npos;
  std::vector<size_t> out;
  for (size_t k = 0; k < library.size(); ++k) {
    const std::string candidate = withDatabase ? library[k].database + "/" + library[k].stem : library[k].stem;
    const int m = ::fnmatch(pattern.c_str(), candidate.c_str(), FNM_PATHNAME);
    if (m == 0) out.push_back(k);
    else if (m != FNM_NOMATCH) r.fail(node, key, "'" + shortened(pattern) + "' is not a glob");
  }
  if (out.empty()) r.fail(node, key, "'" + shortened(pattern) + "' matches no material of the library");
  return out;
}

std::string rgbText(const Reader& r, const toml::node& node, const std::string& key) {
  std::vector<double> rgb;
  if (const auto* list = node.as_array()) {
    for (const toml::node& c : *list)
      if (const auto v = tomlNumber(c)) rgb.push_back(*v);
      else r.fail(node, key, "must be a number or [R, G, B]");
  } else if (const auto v = tomlNumber(node)) {
    rgb.assign(3, *v);
  }
  if (rgb.size() != 3) r.fail(node, key, "must be a number or [R, G, B]");
  for (double v : rgb)
    if (!std::isfinite(v) || v < 0.0 || v > kMaxRadiance)
      r.fail(node, key, formatted("radiance must be a finite number in [0, %g]", kMaxRadiance));
  return formatted("%.17g,%.17g,%.17g", rgb[0], rgb[1], rgb[2]);
}

StudyLighting readLighting(const Reader& r, const std::string& name, const toml::node& node) {
  const std::string key = "lightings." + name;
  const toml::table* t = node.as_table();
  if (!t) r.fail(node, key, "must be a table: { sky = true }, { env = \"MAP.hdr\" } or { constant = V or [R, G, B] }");
  r.keys(*t, key + ".", {"sky", "env", "constant", "rotate"});
  StudyLighting l{r.name(node, key, name), "", "", 0.0};
  const int kinds = int(t->contains("sky")) + int(t->contains("env")) + int(t->contains("constant"));
  if (kinds != 1) r.fail(node, key, "give exactly one of sky = true, env = \"MAP\", constant = V or [R, G, B]");
  if (const toml::node* sky = t->get("sky"); sky && !(sky->is_boolean() && sky->as_boolean()->get()))
    r.fail(*sky, key + ".sky", "must be true (the built-in sky)");
  if (const toml::node* env = t->get("env")) l.env = r.path(*env, key + ".env", false).string();
  if (const toml::node* c = t->get("constant")) l.envConstant = rgbText(r, *c, key + ".constant");
  if (const toml::node* rotate = t->get("rotate")) {
    const auto v = tomlNumber(*rotate);
    if (!v) r.fail(*rotate, key + ".rotate", "must be a number of degrees");
    if (!options::kEnvRotate.accepts(*v)) r.fail(*rotate, key + ".rotate", options::kEnvRotate.refusal(formatted("%g", *v)));
    if (!l.envConstant.empty()) r.fail(*rotate, key + ".rotate", "a constant environment has nothing to rotate");
    l.rotate = *v;
  }
  return l;
}

StudyScene readScene(const Reader& r, const std::string& name, const toml::node& node) {
  const std::string key = "scenes." + name;
  const toml::table* t = node.as_table();
  if (!t) r.fail(node, key, "must be a table: { builtin = \"preview\" } or { gltf = \"SCENE.gltf\" }");
  r.keys(*t, key + ".", {"builtin", "gltf", "camera"});
  StudyScene s{r.name(node, key, name), "", "", ""};
  if (int(t->contains("builtin")) + int(t->contains("gltf")) != 1) r.fail(node, key, "give exactly one of builtin = \"preview\" or \"sphere\", gltf = \"FILE\"");
  if (const toml::node* b = t->get("builtin")) {
    const std::string which = r.text(*b, key + ".builtin");
    if (std::find(std::begin(kBuiltinScenes), std::end(kBuiltinScenes), which) == std::end(kBuiltinScenes))
      r.fail(*b, key + ".builtin", "'" + shortened(which) + "' is not a built-in scene (preview, sphere)");
    s.gltf = (dataDir() / "scenes" / (which + ".gltf")).string();
    s.builtin = which;
  }
  if (const toml::node* g = t->get("gltf")) {
    s.gltf = r.path(*g, key + ".gltf", false).string();
    if (const std::string ext = fs::path(s.gltf).extension().string(); ext != ".gltf" && ext != ".glb")
      r.fail(*g, key + ".gltf", "a glTF scene ends in .gltf or .glb");
  }
  if (const toml::node* c = t->get("camera")) s.camera = r.text(*c, key + ".camera");
  return s;
}

// A number of the settings block, checked by its option's spec (the command line's range and words).
void setting(const Reader& r, const toml::table& settings, const OptionField& f) {
  const toml::node* node = settings.get(f.spec->name);
  if (!node) return;
  const std::string key = "settings." + std::string(f.spec->name);
  const auto v = tomlNumber(*node);
  if (!v) r.fail(*node, key, "must be a number");
  if (!f.spec->accepts(*v))
    r.fail(*node, key, f.spec->refusal(node->is_integer() ? std::to_string(node->as_integer()->get()) : formatted("%g", *v)));
  f.set(*v);
}

// The analysis ranks models against the measured panel, one fit per model on a sheet (a row's model is
// its label whoever made the fit, renderer/study/study_rows.cpp): panels without the measured one or
// without a model, or naming two fits of one model, could only fail once every sheet has rendered.
void checkStudyPanels(const Reader& r, const toml::node& node, const std::vector<SheetPanel>& panels) {
  const std::string key = "settings.panels";
  if (std::none_of(panels.begin(), panels.end(), [](const SheetPanel& p) { return p.fit.empty(); }))
    r.fail(node, key, "'" + shortened(panelList(panels)) + "' has no measured panel: a study measures the models against it");
  std::map<std::string, std::string> fitOfModel;
  for (const SheetPanel& p : panels) {
    if (p.fit.empty()) continue;
    const FitId id = FitId::parse(p.fit, key);
    if (const auto [it, fresh] = fitOfModel.emplace(SheetPanel::ofFit({id.model, id.metric}).label, p.fit); !fresh)
      r.fail(node, key, "'" + it->second + "' and '" + p.fit + "' are two fits of one model (" + it->first +
                            "): a study ranks one fit per model on a sheet");
  }
  if (fitOfModel.empty()) r.fail(node, key, "'" + shortened(panelList(panels)) + "' has no model panel: a study compares models");
}

void readSettings(const Reader& r, const toml::node& node, StudyFile& study) {
  const toml::table* t = node.as_table();
  if (!t) r.fail(node, "settings", "must be a table");
  const std::vector<OptionField> fields = sheetOptionFields(study.job);
  std::vector<std::string_view> known;
  for (const OptionField& f : fields) known.push_back(f.spec->name);
  known.insert(known.end(), {"panels", "half"});
  r.keys(*t, "settings.", known);
  for (const OptionField& f : fields) setting(r, *t, f);
  study.sppGiven = t->contains(options::kSheetSpp.name);
  if ((study.sppGiven || t->contains(options::kTime.name)) && !t->contains(options::kTargetError.name))
    study.job.settings.targetError = 0.0;  // a fixed cost, as given
  if (const toml::node* p = t->get("panels")) {
    const std::string key = "settings.panels";
    try {
      study.job.settings.panels = parsePanels(r.text(*p, key), key);
    } catch (const InputError& e) {
      throw InputError(tomlAt(r.source, *p) + e.what());
    }
  }
  checkStudyPanels(r, t->get("panels") ? *t->get("panels") : node, study.job.settings.panels);
  if (const toml::node* h = t->get("half")) {
    if (!h->is_boolean()) r.fail(*h, "settings.half", "must be true or false");
    study.job.half = h->as_boolean()->get();
  }
}

void readAnalysis(const Reader& r, const toml::node& node, StudyFile& study) {
  const toml::table* t = node.as_table();
  if (!t) r.fail(node, "analysis", "must be a table");
  r.keys(*t, "analysis.", {"resamples", "reference"});
  if (const toml::node* n = t->get("resamples")) {
    const auto v = tomlNumber(*n);
    if (!n->is_integer() || !v || *v < 100 || *v > 1e6) r.fail(*n, "analysis.resamples", "must be a whole number in [100, 1000000]");
    study.resamples = int(*v);
  }
  if (const toml::node* n = t->get("reference")) {
    study.referenceModel = r.text(*n, "analysis.reference");
    if (std::none_of(study.job.settings.panels.begin(), study.job.settings.panels.end(),
                     [&](const SheetPanel& p) { return !p.fit.empty() && p.label == study.referenceModel; }))
      r.fail(*n, "analysis.reference", "'" + shortened(study.referenceModel) + "' is not the label of a model panel of the sheets");
  }
}

}  // namespace

std::string databaseOfFolder(const std::string& folder) {
  static const std::map<std::string, std::string> kLabels = {{"merl", "MERL"}, {"rgl-epfl", "RGL-EPFL"}, {"nielsen2015", "Nielsen 2015"}};
  const auto it = kLabels.find(folder);
  return it == kLabels.end() ? folder : it->second;
}

SceneOptions StudyFile::sceneOptions(size_t scene, size_t lighting) const {
  SceneOptions o;
  o.scene = scenes[scene].gltf;
  o.camera = scenes[scene].camera;
  o.env = lightings[lighting].env;
  o.envConstant = lightings[lighting].envConstant;
  o.envRotate = lightings[lighting].rotate;
  return o;
}

StudyFile loadStudyFile(const fs::path& path, const fs::path& library) {
  StudyFile study;
  study.path = path;
  std::error_code ec;
  const Reader r{path.string(), fs::weakly_canonical(path, ec).parent_path()};
  study.plan.study = fs::weakly_canonical(fs::absolute(path, ec), ec);
  study.text = readInputFile(path, kMaxStudyFileBytes, "study file");
  const toml::table root = parseToml(study.text, r.source);
  r.keys(root, "", {"materials", "perceptual", "lightings", "scenes", "settings", "analysis"});

  // Settings first: the analysis's reference names one of their panels.
  study.job.settings.targetError = kStudyTargetError;
  if (const toml::node* s = root.get("settings")) readSettings(r, *s, study);
  applyPassLimits(study.job.settings, study.sppGiven);
  if (const toml::node* a = root.get("analysis")) readAnalysis(r, *a, study);

  const toml::node* materials = root.get("materials");
  if (!materials) throw InputError(r.source + ": missing key 'materials' (globs over the library, e.g. [\"merl/*\"])");
  std::vector<std::pair<const toml::node*, std::string>> patterns;
  if (materials->is_string()) patterns.emplace_back(materials, materials->as_string()->get());
  else if (const auto* list = materials->as_array(); list && !list->empty())
    for (const toml::node& p : *list) patterns.emplace_back(&p, r.text(p, "materials"));
  else r.fail(*materials, "materials", "must be a glob or a non-empty list of them");
  const std::vector<LibraryEntry> entries = libraryEntries(library);
  std::set<size_t> chosen;
  for (const auto& [node, pattern] : patterns)
    for (size_t k : matches(r, *node, "materials", pattern, entries)) chosen.insert(k);
  std::map<std::string, fs::path> byName;
  bool anyModelRow = false;
  for (size_t k : chosen) {
    const MaterialFile m = loadMaterialFile(entries[k].file);
    for (const SheetPanel& p : study.job.settings.panels)
      anyModelRow = anyModelRow || (!p.fit.empty() && m.find(FitId::parse(p.fit, "settings.panels")) != nullptr);
    if (auto [it, fresh] = byName.emplace(m.name, entries[k].file); !fresh)
      throw InputError(r.source + ": materials: " + it->second.string() + " and " + entries[k].file.string() + " both name the material '" +
                       m.name + "'");
    study.plan.materials.push_back({m.name, databaseOfFolder(entries[k].database), fs::weakly_canonical(entries[k].file, ec)});
  }
  // Without a fit of any model panel on any material, every sheet would hold the measured panel alone.
  if (!anyModelRow)
    r.fail(*materials, "materials", "no material chosen has a fit of a model panel (" + panelList(study.job.settings.panels) +
                                        "): the study would have no model to analyse");
  std::sort(study.plan.materials.begin(), study.plan.materials.end(),
            [](const study::PlannedMaterial& a, const study::PlannedMaterial& b) { return a.name < b.name; });

  if (const toml::node* p = root.get("perceptual")) {
    study.plan.perceptualDir = r.path(*p, "perceptual", true);
    // Its tables are read by the analysis, after every sheet: they are checked now.
    try {
      (void)study::PerceptualData::read(study.plan.perceptualDir);
    } catch (const InputError& e) {
      r.fail(*p, "perceptual", e.what());
    }
  }

  const toml::node* lightings = root.get("lightings");
  if (!lightings || !lightings->is_table() || lightings->as_table()->empty())
    throw InputError((lightings ? tomlAt(r.source, *lightings) : r.source + ": ") +
                     "lightings: give at least one, e.g. [lightings] sky = { sky = true }");
  for (const auto& [name, node] : *lightings->as_table()) study.lightings.push_back(readLighting(r, std::string(name.str()), node));

  if (const toml::node* scenes = root.get("scenes")) {
    if (!scenes->is_table() || scenes->as_table()->empty())
      r.fail(*scenes, "scenes", "give at least one, e.g. [scenes] preview = { builtin = \"preview\" }");
    for (const auto& [name, node] : *scenes->as_table()) study.scenes.push_back(readScene(r, std::string(name.str()), node));
  } else {
    study.scenes.push_back({"preview", (dataDir() / "scenes/preview.gltf").string(), "", "preview"});
  }
  if (const std::uintmax_t sheets = std::uintmax_t(study.plan.materials.size()) * study.lightings.size() * study.scenes.size();
      sheets > kMaxStudySheets)
    throw InputError(r.source + ": " + std::to_string(study.plan.materials.size()) + " materials × " + std::to_string(study.lightings.size()) +
                     " lightings × " + std::to_string(study.scenes.size()) + " scenes = " + std::to_string(sheets) +
                     " sheets, more than a study holds (" + std::to_string(kMaxStudySheets) + "): split it into several studies");
  // toml++ keeps a table's keys sorted: the plan's order.
  for (const StudyLighting& l : study.lightings) study.plan.lightings.push_back(l.name);
  for (const StudyScene& s : study.scenes) study.plan.scenes.push_back(s.name);
  return study;
}

}  // namespace glossy::app
