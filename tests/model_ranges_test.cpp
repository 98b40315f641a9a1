// Every model's declared parameter ranges keep it finite: at every corner of the box the ranges span
// (each parameter at its lowest or highest accepted value), eval, sample and pdf are finite for a spread of
// directions, and a value just outside a range is refused by the file loader naming file, line and key.
// The loop runs over the registry, so a new model is checked without a new test. docs/materials.md's
// tables of keys and of ranges are held to the models' declarations, both ways.
#include "materials/models/brdf.h"
#include "materials/models/builtin_models.h"
#include "materials/models/registry.h"
#include "materials/params/material_file.h"
#include "materials/core/text.h"
#include "tests/support/test_support.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

namespace glossy::test {

namespace {

bool finite(const Rgb& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

Vec3 dir(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// Directions from the pole to grazing, the mirror pair included (θ of V and L equal, φ opposite).
std::vector<Vec3> directions() {
  std::vector<Vec3> out;
  for (double theta : {0.0, 1e-6, 0.3, 0.8, 1.2, 1.5, M_PI / 2 - 1e-6})
    for (double phi : {0.0, 0.7, M_PI, 4.0}) out.push_back(dir(theta, phi));
  return out;
}

// Each range's ends, per parameter (choices take their first).
std::vector<ParamSet> corners(const ModelInfo& model) {
  std::vector<ParamSet> sets(1);
  for (const ParamSpec& spec : model.params) {
    if (spec.kind == ParamKind::Choice) {
      for (ParamSet& s : sets) s.set(std::string(spec.key), std::string(spec.choices.front()));
      continue;
    }
    std::vector<ParamSet> next;
    for (const ParamSet& s : sets)
      for (double v : {spec.range.lo, spec.range.hi}) {
        ParamSet t = s;
        if (spec.kind == ParamKind::Rgb) t.set(std::string(spec.key), Rgb(v));
        else t.set(std::string(spec.key), v);
        next.push_back(std::move(t));
      }
    sets = std::move(next);
  }
  return sets;
}

std::string describe(const ModelInfo& model, const ParamSet& p) {
  std::string s(model.name);
  for (const ParamSpec& spec : model.params) {
    const ParamSet::Value* v = p.find(spec.key);
    s.append(" ").append(spec.key).append("=");
    if (std::holds_alternative<double>(*v)) s += formatted("%g", std::get<double>(*v));
    else if (std::holds_alternative<Rgb>(*v)) s += formatted("%g", std::get<Rgb>(*v).r);
    else s += std::get<std::string>(*v);
  }
  return s;
}

}  // namespace

TEST(ModelRanges, EveryRangeIsFiniteAndBounded) {
  for (const ModelInfo& model : analyticModels())
    for (const ParamSpec& spec : model.params) {
      if (spec.kind == ParamKind::Choice) continue;
      EXPECT_TRUE(std::isfinite(spec.range.lo) && std::isfinite(spec.range.hi) && spec.range.lo <= spec.range.hi)
          << model.name << " " << spec.key;
      // A parameter of a BRDF has no business beyond ±1e9; the loose default range means one was forgotten.
      // Save SGD's shadowing rate c, which Bagher et al.'s published fits take up to 1.6e109 (chrome-steel).
      const bool publishedBeyond = model.name == "sgd" && spec.key == "c";
      EXPECT_LE(spec.range.hi, publishedBeyond ? 1e300 : 1e9) << model.name << " " << spec.key;
      EXPECT_GE(spec.range.lo, -1e9) << model.name << " " << spec.key;
    }
}

TEST(ModelRanges, ModelsAreFiniteAtTheEndsOfTheirRanges) {
  const std::vector<Vec3> dirs = directions();
  const double us[] = {0.0, 1e-9, 0.25, 0.5, 0.75, 1.0 - 1e-9};
  for (const ModelInfo& model : analyticModels()) {
    for (const ParamSet& params : corners(model)) {
      const Brdf brdf = model.make(params);
      int bad = 0;
      for (const Vec3& V : dirs) {
        if (V.z <= 0.0) continue;
        for (const Vec3& L : dirs) {
          const Rgb f = eval(brdf, L, V);
          const double p = pdf(brdf, L, V);
          if (!finite(f) || !std::isfinite(p)) ++bad;
          const Vec3 mirror{-V.x, -V.y, V.z};
          if (!finite(eval(brdf, mirror, V)) || !std::isfinite(pdf(brdf, mirror, V))) ++bad;
        }
        for (double uLobe : us)
          for (double u0 : us)
            for (double u1 : us) {
              const BrdfSample s = sample(brdf, V, uLobe, {u0, u1});
              if (!std::isfinite(s.pdf) || !finite(s.weight) || !std::isfinite(s.L.x) || !std::isfinite(s.L.y) ||
                  !std::isfinite(s.L.z))
                ++bad;
            }
      }
      EXPECT_EQ(bad, 0) << describe(model, params);
    }
  }
}

TEST(ModelRanges, FileValuesOutsideARangeAreRefusedNamingFileLineAndKey) {
  TempDir dir;
  const std::filesystem::path file = dir / "tiny-m.toml";
  // Values a "positive" check lets through and that evaluate to NaN.
  for (const std::string bad : {"m = 1e-308", "m = 5e-324", "eta = 1e308", "m = 11.0"}) {
    std::string text = "name = \"tiny-m\"\n\n[[fit]]\nmodel = \"cook-torrance\"\nmetric = \"E2\"\n"
                       "kd = [0.1, 0.1, 0.1]\nks = [0.5, 0.5, 0.5]\n";
    text += bad.starts_with("m ") ? bad + "\neta = 1.5\n" : "m = 0.1\n" + bad + "\n";
    writeText(file, text);
    const std::string message = expectInputError([&] { loadMaterialFile(file); });
    const std::string key = bad.substr(0, bad.find(' '));
    const std::string line = bad.starts_with("m ") ? ":8" : ":9";
    EXPECT_NE(message.find(file.string() + line), std::string::npos) << message;
    EXPECT_NE(message.find("'" + key + "'"), std::string::npos) << message;
    EXPECT_NE(message.find("must be in ["), std::string::npos) << message;
    expectOneLineError(runGlossy({"eval", "--material", file.string(), "--fit", "cook-torrance:E2"}, "0,0,1,0,0,1\n"),
                       file.string());
  }
}

namespace {

template <class... M>
std::vector<std::string> names(ModelList<M...>) {
  return {std::string(M::kName)...};
}

// The rows of the docs table whose header line starts with `header`, each a list of its cells.
std::vector<std::vector<std::string>> docsTable(const std::string& header) {
  std::istringstream in(readText(sourceDir() / "docs/materials.md"));
  std::vector<std::vector<std::string>> rows;
  bool inTable = false;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with(header)) {
      inTable = true;
      std::getline(in, line);  // |---|---|
      continue;
    }
    if (!inTable) continue;
    if (!line.starts_with("|")) break;
    std::vector<std::string> cells;
    for (size_t at = 1, bar; (bar = line.find('|', at)) != std::string::npos; at = bar + 1) {
      std::string cell = line.substr(at, bar - at);
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      cells.push_back(cell);
    }
    rows.push_back(cells);
  }
  return rows;
}

// The `quoted` words of a cell, leaving out what parentheses hold (a choice's values).
std::vector<std::string> quoted(std::string cell) {
  cell = std::regex_replace(cell, std::regex("\\([^)]*\\)"), "");
  std::vector<std::string> out;
  const std::regex word("`([^`]+)`");
  for (auto it = std::sregex_iterator(cell.begin(), cell.end(), word); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1]);
  return out;
}

// "[0, 1e6]", "[−π/2, π/2]", "[0, 100], [−100, 100]": each range's ends, in order.
std::vector<ParamRange> ranges(std::string cell) {
  cell = std::regex_replace(cell, std::regex("\u2212"), "-");
  std::vector<ParamRange> out;
  const auto number = [](const std::string& text) {
    if (text == "π/2") return M_PI / 2;
    if (text == "-π/2") return -M_PI / 2;
    size_t used = 0;
    const double v = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument("docs/materials.md: '" + text + "' is not a number");
    return v;
  };
  const std::regex range("\\[([^,\\]]+), ([^\\]]+)\\]");
  for (auto it = std::sregex_iterator(cell.begin(), cell.end(), range); it != std::sregex_iterator(); ++it)
    out.push_back({number((*it)[1]), number((*it)[2])});
  return out;
}

bool sameEnd(double docs, double declared) { return std::abs(docs - declared) <= 1e-12 * std::max(1.0, std::abs(declared)); }

}  // namespace

// docs/materials.md's table of each model's keys and its table of accepted ranges say what the models
// declare: every built-in model in the first with exactly its keys, and in the second every (model, key)
// pair once, with its range's ends. A range or key changed in a header, or a model added, fails here
// until the docs say it.
TEST(ModelRanges, TheDocsTablesAreTheModelsDeclarations) {
  const std::vector<std::string> builtin = names(BuiltinModels{});
  std::set<std::string> keyed;
  for (const std::vector<std::string>& row : docsTable("| model | keys |")) {
    ASSERT_EQ(row.size(), 2u);
    const std::vector<std::string> keys = quoted(row[1]);
    for (const std::string& name : quoted(row[0])) {
      const ModelInfo* model = findModel(name);
      ASSERT_NE(model, nullptr) << "docs/materials.md names a model glossy does not have: " << name;
      std::vector<std::string> declared;
      for (const ParamSpec& spec : model->params) declared.emplace_back(spec.key);
      EXPECT_EQ(std::multiset<std::string>(keys.begin(), keys.end()), std::multiset<std::string>(declared.begin(), declared.end()))
          << name;
      EXPECT_TRUE(keyed.insert(name).second) << name << " has two rows";
    }
  }
  for (const std::string& name : builtin) EXPECT_TRUE(keyed.count(name)) << name << " is missing from the table of keys";

  std::map<std::pair<std::string, std::string>, int> documented;
  const auto rows = docsTable("| key | models | accepted range |");
  ASSERT_GT(rows.size(), 10u);
  for (const std::vector<std::string>& row : rows) {
    ASSERT_EQ(row.size(), 4u);
    const std::vector<std::string> keys = quoted(row[0]);
    const std::vector<ParamRange> ends = ranges(row[2]);
    ASSERT_EQ(keys.size(), ends.size()) << row[0] << " | " << row[2];
    // "all" or "all but a, b": every built-in model with the key (but those); else the models named.
    std::vector<std::string> models;
    if (row[1].starts_with("all")) {
      std::string except = row[1].substr(3);
      std::set<std::string> excluded;
      if (except.starts_with(" but ")) {
        std::istringstream list(except.substr(5));
        for (std::string n; std::getline(list, n, ',');) excluded.insert(n.substr(n.find_first_not_of(' ')));
      }
      for (const std::string& name : builtin)
        if (!excluded.count(name)) models.push_back(name);
    } else {
      std::istringstream list(row[1]);
      for (std::string n; std::getline(list, n, ',');) models.push_back(n.substr(n.find_first_not_of(' ')));
    }
    for (size_t k = 0; k < keys.size(); ++k)
      for (const std::string& name : models) {
        const ModelInfo* model = findModel(name);
        ASSERT_NE(model, nullptr) << "the table of ranges names a model glossy does not have: '" << name << "'";
        const auto spec = std::find_if(model->params.begin(), model->params.end(), [&](const ParamSpec& p) { return p.key == keys[k]; });
        if (spec == model->params.end()) {
          EXPECT_TRUE(row[1].starts_with("all")) << name << " has no key " << keys[k];
          continue;
        }
        ++documented[{name, keys[k]}];
        EXPECT_TRUE(sameEnd(ends[k].lo, spec->range.lo) && sameEnd(ends[k].hi, spec->range.hi))
            << name << " " << keys[k] << ": the docs say [" << ends[k].lo << ", " << ends[k].hi << "], the model ["
            << spec->range.lo << ", " << spec->range.hi << "]";
      }
  }
  for (const std::string& name : builtin)
    for (const ParamSpec& spec : findModel(name)->params)
      if (spec.kind != ParamKind::Choice)
        EXPECT_EQ((documented[{name, std::string(spec.key)}]), 1) << name << " " << spec.key << ": rows of the table of ranges";
}

}  // namespace glossy::test
