#include "materials/params/material_file.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/core/input_file.h"
#include "materials/core/toml_input.h"
#include "materials/models/registry.h"
#include "materials/params/material_name.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace glossy {

// Checks one value against its declaration; `here` names file, fit and key.
void checkParam(const ParamSpec& spec, const ParamSet::Value& v, const std::string& here);

namespace {

void checkMetric(const std::string& metric, const std::string& what) {
  if (metric != "E1" && metric != "E2" && metric != FitId::kNgan05 && metric != FitId::kBagher12)
    throw InputError(what + " must be E1, E2, " + std::string(FitId::kNgan05) + " or " + std::string(FitId::kBagher12) +
                     ", got '" + metric + "'");
}

size_t modelRank(const std::string& model) {
  const auto& models = analyticModels();
  for (size_t i = 0; i < models.size(); ++i)
    if (models[i].name == model) return i;
  return models.size();
}

bool gridBefore(const Fit& a, const Fit& b) {
  const size_t ra = modelRank(a.id.model), rb = modelRank(b.id.model);
  if (ra != rb) return ra < rb;
  return a.id.metric != b.id.metric ? a.id.metric < b.id.metric : a.id.by < b.id.by;
}

std::string formatNumber(double v) {
  char buf[64];
  // Shortest digits that read back exactly; positional for everyday magnitudes ("0.0001", not "1e-04").
  const double mag = std::abs(v);
  const auto format = (mag == 0.0 || (mag >= 1e-6 && mag < 1e15)) ? std::chars_format::fixed : std::chars_format::general;
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, format);
  std::string s(buf, end);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // keep floats floats in TOML
  return s;
}

std::string quoteToml(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

// "fit 2 (cook-torrance:E1)", with as much of the id as is known.
std::string fitLabel(size_t index, const FitId& id) {
  std::string s = "fit " + std::to_string(index + 1);
  if (!id.model.empty()) s += " (" + id.model + ":" + (id.metric.empty() ? "?" : id.metric) + ")";
  return s;
}

std::string stringOr(const toml::table& t, std::string_view key) {
  const toml::node* n = t.get(key);
  return n && n->is_string() ? n->as_string()->get() : std::string();
}

void requireString(const toml::table& t, std::string_view key, const std::string& where) {
  const toml::node* n = t.get(key);
  if (!n) throw InputError(where + ": missing key '" + std::string(key) + "'");
  if (!n->is_string()) throw InputError(where + ": key '" + std::string(key) + "' must be a string");
}

Fit readFit(const toml::table& t, size_t index, const std::string& source) {
  Fit fit;
  fit.id = {stringOr(t, "model"), stringOr(t, "metric")};
  const std::string where = tomlAt(source, t) + fitLabel(index, fit.id);
  requireString(t, "model", where);
  requireString(t, "metric", where);
  const ModelInfo* model = &requireModel(fit.id.model, where + ": key 'model'");
  checkMetric(fit.id.metric, where + ": key 'metric':");

  for (auto&& [k, node] : t) {
    const std::string key(k.str());
    const std::string here = tomlAt(source, node) + fitLabel(index, fit.id) + ": key '" + key + "'";
    if (key == "model" || key == "metric") continue;
    if (key == "by") {
      if (!node.is_string() || node.as_string()->get() != FitId::kGlossy)
        throw InputError(here + ": must be \"glossy\" (it marks glossy's own fits; a published fit has no 'by')");
      fit.id.by = FitId::kGlossy;
      continue;
    }
    if (key == "source" || key == "settings" || key == "data" || key == "database" || key == "date") {
      if (!node.is_string()) throw InputError(here + ": must be a string");
      (key == "source" ? fit.source : key == "settings" ? fit.settings : key == "data" ? fit.data : key == "database" ? fit.database : fit.date) =
          node.as_string()->get();
      continue;
    }
    if (key == "error") {
      auto v = tomlNumber(node);
      if (!v || !std::isfinite(*v) || *v < 0.0) throw InputError(here + ": must be a finite number ≥ 0");
      fit.error = *v;
      continue;
    }
    auto spec = std::find_if(model->params.begin(), model->params.end(), [&](const ParamSpec& s) { return s.key == key; });
    if (spec == model->params.end()) {
      std::vector<std::string_view> keys{"model", "metric"};
      for (const ParamSpec& s : model->params) keys.push_back(s.key);
      for (std::string_view k : {"by", "source", "error", "data", "database", "date", "settings"}) keys.push_back(k);
      throw InputError(here + ": unknown key for the " + fit.id.model + " model (its keys: " + joined(keys, ", ") + ")");
    }
    switch (spec->kind) {
      case ParamKind::Scalar: {
        auto v = tomlNumber(node);
        if (!v) throw InputError(here + ": must be a number");
        fit.params.set(key, *v);
        break;
      }
      case ParamKind::Rgb: {
        const toml::array* arr = node.as_array();
        if (!arr || arr->size() != 3) throw InputError(here + ": must be an array of 3 numbers [R, G, B]");
        Rgb rgb;
        for (int c = 0; c < 3; ++c) {
          auto v = tomlNumber(*arr->get(size_t(c)));
          if (!v) throw InputError(here + ": must be an array of 3 numbers [R, G, B]");
          rgb[c] = *v;
        }
        fit.params.set(key, rgb);
        break;
      }
      case ParamKind::Choice: {
        if (!node.is_string()) throw InputError(here + ": must be one of " + joined(spec->choices, ", "));
        fit.params.set(key, node.as_string()->get());
        break;
      }
    }
    checkParam(*spec, *fit.params.find(key), here);
  }
  // Only `glossy fit` writes settings: a fit written before 'by' existed that has them is glossy's, not the
  // paper's (it may stand where the README once had glossy fit replace a published fit).
  if (!fit.settings.empty()) fit.id.by = FitId::kGlossy;
  validateFit(fit, where);
  return fit;
}

}  // namespace

FitId FitId::parse(std::string_view text, std::string_view context) {
  const auto colon = text.find(':');
  FitId id;
  if (colon == std::string_view::npos)
    throw InputError(std::string(context) + ": '" + std::string(text) + "' is not MODEL:METRIC (e.g. microfacet:E2)");
  id.model = std::string(text.substr(0, colon));
  std::string_view rest = text.substr(colon + 1);
  if (const auto second = rest.find(':'); second != std::string_view::npos) {
    id.by = std::string(rest.substr(second + 1));
    rest = rest.substr(0, second);
    if (id.by != FitId::kGlossy)
      throw InputError(std::string(context) + ": '" + std::string(text) + "' is not MODEL:METRIC or MODEL:METRIC:glossy (glossy's own fit)");
  }
  id.metric = std::string(rest);
  requireModel(id.model, std::string(context));
  checkMetric(id.metric, std::string(context) + ": metric");
  return id;
}

const Fit* MaterialFile::findExact(const FitId& id) const {
  for (const Fit& f : fits)
    if (f.id == id) return &f;
  return nullptr;
}

const Fit* MaterialFile::find(const FitId& id) const {
  if (const Fit* exact = findExact(id); exact || !id.by.empty()) return exact;
  return findExact({id.model, id.metric, std::string(FitId::kGlossy)});
}

void MaterialFile::put(Fit fit) {
  auto same = std::find_if(fits.begin(), fits.end(), [&](const Fit& f) { return f.id == fit.id; });
  if (same != fits.end()) fits.erase(same);
  fits.insert(std::upper_bound(fits.begin(), fits.end(), fit, gridBefore), std::move(fit));
}

void checkParam(const ParamSpec& spec, const ParamSet::Value& v, const std::string& here) {
  auto check = [&](double x, const char* channel) {
    const std::string what = here + (channel ? std::string(" (") + channel + ")" : std::string());
    if (!std::isfinite(x)) throw InputError(what + ": must be finite, got " + formatNumber(x));
    if (!inRange(x, spec.range)) throw InputError(what + ": must be " + describeRange(spec.range) + ", got " + formatNumber(x));
  };
  switch (spec.kind) {
    case ParamKind::Scalar:
      if (!std::holds_alternative<double>(v)) throw InputError(here + ": must be a number");
      check(std::get<double>(v), nullptr);
      break;
    case ParamKind::Rgb: {
      if (!std::holds_alternative<Rgb>(v)) throw InputError(here + ": must be an array of 3 numbers [R, G, B]");
      const Rgb rgb = std::get<Rgb>(v);
      check(rgb.r, "R");
      check(rgb.g, "G");
      check(rgb.b, "B");
      break;
    }
    case ParamKind::Choice: {
      if (!std::holds_alternative<std::string>(v)) throw InputError(here + ": must be a string");
      const std::string& s = std::get<std::string>(v);
      if (std::find(spec.choices.begin(), spec.choices.end(), s) == spec.choices.end())
        throw InputError(here + ": must be one of " + joined(spec.choices, ", ") + ", got '" + s + "'");
      break;
    }
  }
}

void validateFit(const Fit& fit, const std::string& context) {
  const ModelInfo* model = &requireModel(fit.id.model, context);
  checkMetric(fit.id.metric, context + ": metric");
  for (const auto& [key, value] : fit.params.values()) {
    // An init-capture: clang before 16 cannot capture a structured binding.
    auto spec = std::find_if(model->params.begin(), model->params.end(), [&k = key](const ParamSpec& s) { return s.key == k; });
    if (spec == model->params.end()) throw InputError(context + ": key '" + key + "': unknown for the " + fit.id.model + " model");
    checkParam(*spec, value, context + ": key '" + key + "'");
  }
  for (const ParamSpec& spec : model->params)
    if (!spec.optional && !fit.params.has(spec.key))
      throw InputError(context + ": missing key '" + std::string(spec.key) + "' (" + std::string(spec.meaning) + ")");
}

MaterialFile parseMaterialToml(std::string_view text, const std::string& source) {
  const toml::table root = parseToml(text, source);
  MaterialFile m;
  m.path = source;
  for (auto&& [k, node] : root) {
    const std::string key(k.str());
    const std::string here = tomlAt(source, node) + "key '" + key + "'";
    if (key == "name" || key == "measured" || key == "source") {
      if (!node.is_string()) throw InputError(here + ": must be a string");
      const std::string value = node.as_string()->get();
      if (key == "name") checkMaterialName(value, here);
      (key == "name" ? m.name : key == "measured" ? m.measured : m.source) = value;
    } else if (key == "fit") {
      const toml::array* fits = node.as_array();
      if (!fits || !fits->is_array_of_tables())
        throw InputError(here + ": must be an array of tables ([[fit]] sections)");
      for (size_t i = 0; i < fits->size(); ++i) {
        Fit fit = readFit(*fits->get(i)->as_table(), i, source);
        if (m.findExact(fit.id))
          throw InputError(tomlAt(source, *fits->get(i)) + fitLabel(i, fit.id) + ": a second " + fit.id.str() +
                           " fit (a material has at most one fit per model and metric)");
        m.put(std::move(fit));
      }
    } else {
      throw InputError(here + ": unknown key (a material file has name, measured, source and [[fit]] sections)");
    }
  }
  if (m.name.empty()) throw InputError(source + ": missing key 'name'");
  return m;
}

MaterialFile loadMaterialFile(const std::filesystem::path& path) {
  // A material file is a few kilobytes; a megabyte leaves room for long comments and notes.
  return parseMaterialToml(readInputFile(path, kMaxMaterialFileBytes, "material file"), path.string());
}

std::string toToml(const MaterialFile& m) {
  std::ostringstream out;
  out << "# glossy material parameter file: see docs/materials.md\n";
  out << "name = " << quoteToml(m.name) << "\n";
  if (!m.measured.empty()) out << "measured = " << quoteToml(m.measured) << "\n";
  if (!m.source.empty()) out << "source = " << quoteToml(m.source) << "\n";
  for (const Fit& fit : m.fits) {
    const ModelInfo* model = findModel(fit.id.model);
    out << "\n[[fit]]\nmodel = " << quoteToml(fit.id.model) << "\nmetric = " << quoteToml(fit.id.metric) << "\n";
    if (!fit.id.by.empty()) out << "by = " << quoteToml(fit.id.by) << "\n";
    for (const ParamSpec& spec : model->params) {
      const ParamSet::Value* v = fit.params.find(spec.key);
      if (!v) continue;
      out << spec.key << " = ";
      if (auto d = std::get_if<double>(v)) out << formatNumber(*d);
      if (auto c = std::get_if<Rgb>(v))
        out << "[" << formatNumber(c->r) << ", " << formatNumber(c->g) << ", " << formatNumber(c->b) << "]";
      if (auto s = std::get_if<std::string>(v)) out << quoteToml(*s);
      out << "\n";
    }
    if (!fit.source.empty()) out << "source = " << quoteToml(fit.source) << "\n";
    if (fit.error) out << "error = " << formatNumber(*fit.error) << "\n";
    for (const auto& [key, value] : {std::pair{"data", &fit.data}, {"database", &fit.database}, {"date", &fit.date}})
      if (!value->empty()) out << key << " = " << quoteToml(*value) << "\n";
    if (!fit.settings.empty()) out << "settings = " << quoteToml(fit.settings) << "\n";
  }
  return out.str();
}

Brdf makeBrdf(const Fit& fit) {
  return requireModel(fit.id.model, "fit " + fit.id.str()).make(fit.params);
}

std::optional<std::filesystem::path> resolveMeasured(const std::string& measured, const std::filesystem::path& merlDir,
                                                     const std::filesystem::path& materialDir) {
  if (measured.empty()) return std::nullopt;
  const std::filesystem::path name = measured;
  std::vector<std::filesystem::path> candidates;
  if (name.is_absolute()) candidates.push_back(name);
  if (!merlDir.empty()) candidates.push_back(merlDir / name);
  if (const char* env = std::getenv("GLOSSY_MERL_DIR"); env && *env) candidates.push_back(std::filesystem::path(env) / name);
  if (!name.is_absolute()) candidates.push_back(name);
  std::error_code ec;
  for (const auto& c : candidates) {
    if (std::filesystem::is_regular_file(c, ec)) return c;
    const std::filesystem::path xz = c.string() + ".xz";
    if (std::filesystem::is_regular_file(xz, ec)) return xz;
  }
  if (materialDir.empty()) return std::nullopt;
  // Only the name's last component, so that a name from a file cannot lead out of the folder.
  std::filesystem::path stem = name.filename();
  for (const char* extension : {".xz", ".binary", ".nbrdf"})
    if (stem.extension() == extension) stem = stem.stem();
  if (stem.empty() || stem == "." || stem == "..") return std::nullopt;
  // Beside a material file named bare (its folder "."), the network is "NAME.nbrdf", not "./NAME.nbrdf".
  const std::filesystem::path network = materialDir == "." ? std::filesystem::path(stem.string() + ".nbrdf")
                                                           : materialDir / (stem.string() + ".nbrdf");
  if (std::filesystem::is_regular_file(network, ec)) return network;
  return std::nullopt;
}

std::filesystem::path materialFolder(const std::filesystem::path& materialFile) {
  return materialFile.has_parent_path() ? materialFile.parent_path() : std::filesystem::path(".");
}

std::optional<std::filesystem::path> resolveMeasured(const MaterialFile& material, const std::filesystem::path& merlDir) {
  // A material made in memory (measuredMaterial) has no file, so nothing beside one.
  return resolveMeasured(material.measured, merlDir, material.path.empty() ? std::filesystem::path() : materialFolder(material.path));
}

namespace {

void checkMerlFolder(const std::filesystem::path& dir, const std::string& where) {
  std::error_code ec;
  const std::filesystem::file_status s = std::filesystem::status(dir, ec);
  if (!std::filesystem::exists(s)) throw InputError(where + ": no such folder");
  if (std::filesystem::is_regular_file(s)) throw InputError(where + ": is a file, not a folder of MERL tables");
  if (!std::filesystem::is_directory(s)) throw InputError(where + ": is not a folder (a FIFO, device or socket)");
}

}  // namespace

void checkMerlDirs(const std::filesystem::path& merlDir, std::string_view option) {
  if (!merlDir.empty()) checkMerlFolder(merlDir, std::string(option) + " " + printableLine(merlDir.string(), 200));
  if (const char* env = std::getenv("GLOSSY_MERL_DIR"); env && *env)
    checkMerlFolder(env, "$GLOSSY_MERL_DIR " + printableLine(env, 200));
}

}  // namespace glossy
