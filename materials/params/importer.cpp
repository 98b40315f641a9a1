#include "materials/params/importer.h"

#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "materials/core/text.h"
#include "materials/merl/merl_table.h"
#include "materials/models/registry.h"
#include "materials/params/material_name.h"

#include <array>
#include <regex>
#include <sstream>

namespace glossy {

namespace {

constexpr int kPrecisionFitLines = 1, kPrecisionSupplement = 2;

std::vector<std::string> splitLines(std::string_view text) {
  std::vector<std::string> lines;
  std::string line;
  std::istringstream in{std::string(text)};
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

double requireNumber(const std::string& s, const std::string& where) {
  if (const auto v = parseNumber(s)) return *v;
  throw InputError(where + ": '" + s + "' is not a number");
}

// The supplement's row label → a registry model name.
std::string supplementModel(const std::string& label) {
  if (label.rfind("Ashikhmin-Shirley", 0) == 0) return "ashikhmin-shirley";
  if (label.rfind("Cook-Torrance", 0) == 0) return "cook-torrance";
  if (label.rfind("Microfacet", 0) == 0) return "microfacet";
  if (label.rfind("Smooth Surface", 0) == 0) return "smooth";
  return {};
}

// The supplement's parameter symbols → parameter-file keys.
std::string supplementKey(const std::string& symbol) {
  static const std::map<std::string, std::string> keys = {{"K_d", "kd"}, {"K_s", "ks"}, {"A", "a"}, {"B", "b"},
                                                          {"C", "c"},   {"m", "m"},    {"n", "n"}, {"eta", "eta"}};
  const auto key = keys.find(symbol);
  return key == keys.end() ? std::string() : key->second;
}

}  // namespace

std::vector<MaterialFile> importSupplement(std::string_view text, const std::string& source) {
  static const std::regex section(R"(Material Name:\s*(\S+))");
  static const std::regex row(R"(^\s*(Ashikhmin-Shirley|Cook-Torrance|Microfacet(?: Model)?|Smooth Surface(?: Model)?)\s+E_?\{?([0-9])\}?\s+(.*)$)");
  static const std::regex channel(R"((?:^|\s)(R|G|B|Common):)");
  static const std::regex assignment(R"(([A-Za-z_]+)\s*=\s*([-+0-9.eE]+))");

  std::vector<MaterialFile> out;
  const auto lines = splitLines(text);
  for (size_t ln = 0; ln < lines.size(); ++ln) {
    const std::string where = source + ":" + std::to_string(ln + 1);
    std::smatch m;
    if (std::regex_search(lines[ln], m, section)) {
      const std::string name = m[1];
      checkMaterialName(name, where);
      out.push_back(measuredMaterial(name, kSupplementSource));
      continue;
    }
    // Strip the LaTeX of the PDF's text: $…$, backslashes, braces.
    std::string clean;
    for (char c : lines[ln])
      if (c != '$' && c != '\\' && c != '{' && c != '}') clean += c;
    if (!std::regex_match(clean, m, row)) continue;
    if (out.empty()) throw InputError(where + ": parameter row before any 'Material Name:' section");

    Fit fit;
    fit.id.model = supplementModel(m[1]);
    fit.id.metric = "E" + std::string(m[2]);
    const std::string context = where + ": " + out.back().name + " " + fit.id.str();
    const std::string rest = m[3];

    // Split "R: … G: … B: … Common: …" into its groups: each body runs from its label to the next.
    struct Group {
      std::string label;
      size_t labelStart, bodyStart;
    };
    std::vector<Group> groups;
    for (auto it = std::sregex_iterator(rest.begin(), rest.end(), channel); it != std::sregex_iterator(); ++it)
      groups.push_back({(*it)[1], size_t(it->position(1)), size_t(it->position() + it->length())});
    if (groups.size() != 4 || groups[0].label != "R" || groups[1].label != "G" || groups[2].label != "B" ||
        groups[3].label != "Common")
      throw InputError(context + ": expected the groups R:, G:, B: and Common:");
    Rgb rgbValues[2]{};
    std::string rgbKeys[2];
    for (size_t g = 0; g < groups.size(); ++g) {
      const size_t to = g + 1 < groups.size() ? groups[g + 1].labelStart : rest.size();
      const std::string body = rest.substr(groups[g].bodyStart, to - groups[g].bodyStart);
      const int c = int(g) < 3 ? int(g) : -1;
      int k = 0;
      for (auto a = std::sregex_iterator(body.begin(), body.end(), assignment); a != std::sregex_iterator(); ++a) {
        const std::string symbol = (*a)[1];
        const std::string key = supplementKey(symbol);
        if (key.empty()) throw InputError(context + ": unknown parameter '" + symbol + "'");
        const double v = requireNumber((*a)[2], context + ": " + symbol);
        if (c < 0) {
          if (fit.params.has(key)) throw InputError(context + ": parameter '" + symbol + "' given twice");
          fit.params.set(key, v);
          continue;
        }
        if (k >= 2) throw InputError(context + ": group " + groups[g].label + ": more than K_d and one specular scale");
        if (c > 0 && rgbKeys[k] != key)
          throw InputError(context + ": group " + groups[g].label + ": expected '" + rgbKeys[k] + "', got '" + key + "'");
        rgbKeys[k] = key;
        rgbValues[k][c] = v;
        ++k;
      }
      if (c >= 0 && k != 2)
        throw InputError(context + ": group " + groups[g].label + ": expected K_d and the specular scale");
    }
    for (int k = 0; k < 2; ++k) fit.params.set(rgbKeys[k], rgbValues[k]);
    validateFit(fit, context);
    if (out.back().find(fit.id)) throw InputError(context + ": a second " + fit.id.str() + " row for this material");
    out.back().put(std::move(fit));
  }
  for (const MaterialFile& m : out)
    if (m.fits.empty()) throw InputError(source + ": material '" + m.name + "' has no parameter rows");
  if (out.empty()) throw InputError(source + ": no 'Material Name:' sections found");
  return out;
}

namespace {

// Ngan et al.'s fits describe MERL tables read with 1/1500 for every channel, without the tables' own
// factors for green and blue (MerlTable::kScale: 1.15/1500 and 1.66/1500, as MERL's reader scales them): teflon's
// Ward kd is [0.296, 0.255, 0.174] for a white material, and every one of their fits' head-on albedos sits
// at (0.95–1.0, 0.81–0.87, 0.57–0.60) of the measured one where Löw's and Bagher's sit within a few per
// cent on every channel. Their albedos, kd and ks, times these factors describe the data glossy compares
// them with; the fit's `source` says so, and materials/published-fits keeps bbm's values as published.
constexpr std::array<double, 3> kMerlChannelFactors = {1.0, MerlTable::kScale[1] / MerlTable::kScale[0],
                                                        MerlTable::kScale[2] / MerlTable::kScale[0]};
constexpr std::array<double, 3> kAsPublished = {1.0, 1.0, 1.0};

// The models of other papers' published fits as bbm names them → glossy's model, metric and argument names,
// and the factors that bring the fits' albedos (kd, ks) into the units of the data glossy reads.
// He et al.'s (NganHe) is not a glossy model (docs/models.md).
struct PaperModel {
  const char* bbm;
  const char* model;
  std::string_view metric;
  std::map<std::string, std::string> keys;
  std::array<double, 3> albedoFactors;
};
const PaperModel* paperModel(const std::string& bbmModel) {
  static const PaperModel models[] = {
      {"NganWard", "ward", FitId::kNgan05, {{"albedo", "ks"}, {"roughness", "alpha"}}, kMerlChannelFactors},
      {"NganWardDuer", "ward-duer", FitId::kNgan05, {{"albedo", "ks"}, {"roughness", "alpha"}}, kMerlChannelFactors},
      // bbm evaluates the mirror-vector Phong for these; glossy reads them on the half vector (blinn_phong.h).
      {"NganBlinnPhong", "blinn-phong", FitId::kNgan05, {{"albedo", "ks"}, {"sharpness", "n"}}, kMerlChannelFactors},
      {"NganLafortune", "lafortune", FitId::kNgan05, {{"albedo", "ks"}, {"Cxy", "cxy"}, {"Cz", "cz"}, {"sharpness", "n"}}, kMerlChannelFactors},
      {"NganAshikhminShirley", "ngan-ashikhmin-shirley", FitId::kNgan05,
       {{"albedo", "ks"}, {"fresnelReflectance", "f0"}, {"sharpness", "n"}}, kMerlChannelFactors},
      // bbm's `eta` here is Schlick's F0, a reflectance (ngan_cook_torrance.h).
      {"NganCookTorrance", "ngan-cook-torrance", FitId::kNgan05, {{"albedo", "ks"}, {"eta", "f0"}, {"roughness", "m"}}, kMerlChannelFactors},
      // bbm's `eta` here is the pair [F0, F1] of Bagher's Fresnel term, each RGB (sgd.h).
      {"Bagher", "sgd", FitId::kBagher12,
       {{"albedo", "ks"}, {"alpha", "alpha"}, {"p", "p"}, {"eta", "f0,f1"}, {"K", "norm"}, {"Lambda", "lambda"},
        {"c", "c"}, {"k", "k"}, {"theta0", "theta0"}},
       kAsPublished},
  };
  for (const PaperModel& m : models)
    if (bbmModel == m.bbm) return &m;
  return nullptr;
}

}  // namespace

std::string nganFitSource(const std::string& fileName) {
  return "Ngan, Durand & Matusik 2005, published fits as transcribed by bbm (fits/" + fileName +
         ", commit 9807fb38d7ab51802f3a0fe0f65cf763cb01a0f4)";
}

std::string bagherFitSource(const std::string& fileName) {
  return "Bagher, Soler & Holzschuch 2012, published fits as transcribed by bbm (fits/" + fileName +
         ", commit 9807fb38d7ab51802f3a0fe0f65cf763cb01a0f4)";
}

namespace {

// The metric of a file of Löw et al.'s fits: from its name (*_E1.fit, *_E2.fit), else from a comment line
// ("# … E2 fits …"); empty if neither says.
std::string fitLinesMetric(const std::string& fileName, const std::vector<std::string>& lines) {
  static const std::regex fileMetric(R"(_(E[12])\.fit$)");
  static const std::regex commentMetric(R"(\b(E[12]) fits\b)");
  std::smatch m;
  if (std::regex_search(fileName, m, fileMetric)) return m[1];
  for (const auto& l : lines)
    if (!l.empty() && l[0] == '#' && std::regex_search(l, m, commentMetric)) return m[1];
  return {};
}

Rgb parseRgb(const std::string& list, const std::string& where) {
  const auto v = parseNumberList(list);
  if (!v || v->size() != 3) throw InputError(where + ": expected 3 values, got '" + list + "'");
  return Rgb((*v)[0], (*v)[1], (*v)[2]);
}

// bbm's model `bbmModel` as ours: fit's model, metric and source, and the map from bbm's argument names to
// our parameter keys.
std::map<std::string, std::string> bbmModelKeys(const std::string& bbmModel, const std::string& fileName, const std::string& where,
                                                Fit& fit) {
  if (const PaperModel* paper = paperModel(bbmModel)) {
    fit.id = {paper->model, std::string(paper->metric)};
    fit.source = paper->metric == FitId::kNgan05 ? nganFitSource(fileName) : bagherFitSource(fileName);
    return paper->keys;
  }
  if (bbmModel == "LowMicrofacetFit" || bbmModel == "LowSmooth") {
    fit.id.model = bbmModel == "LowSmooth" ? "smooth" : "microfacet";
    return {{"A", "a"}, {"B", "b"}, {"C", "c"}, {"eta", "eta"}};
  }
  if (bbmModel == "LowCookTorrance") {
    fit.id.model = "cook-torrance";
    return {{"albedo", "ks"}, {"roughness", "m"}, {"eta", "eta"}};
  }
  if (bbmModel == "LowAshikhminShirley") {
    fit.id.model = "ashikhmin-shirley";
    return {{"albedo", "ks"}, {"sharpness", "n"}, {"fresnelReflectance", "eta"}};  // it holds η, despite its name
  }
  throw InputError(where + ": unknown model '" + bbmModel + "'");
}

// The model's arguments `args` ("name = value, …") into fit's parameters, through keys.
void setArguments(const std::string& args, const std::map<std::string, std::string>& keys, const std::string& bbmModel,
                  const std::string& context, Fit& fit) {
  // A value: a number, [R, G, B], or a pair of them, [[R, G, B], [R, G, B]] (Bagher's `eta`).
  static const std::regex argument(R"((\w+)\s*=\s*(\[\s*\[[^\]]*\]\s*,\s*\[[^\]]*\]\s*\]|\[[^\]]*\]|[^,\s)]+))");
  for (auto a = std::sregex_iterator(args.begin(), args.end(), argument); a != std::sregex_iterator(); ++a) {
    const std::string arg = (*a)[1], value = (*a)[2];
    auto key = keys.find(arg);
    if (key == keys.end()) throw InputError(context + ": unknown argument '" + arg + "' of " + bbmModel);
    if (fit.params.has(key->second.substr(0, key->second.find(','))))
      throw InputError(context + ": argument '" + arg + "' given twice");
    if (const size_t comma = key->second.find(','); comma != std::string::npos) {
      // A pair of RGB values for two keys ("f0,f1"): [[...], [...]].
      static const std::regex pair(R"(^\[\s*\[([^\]]*)\]\s*,\s*\[([^\]]*)\]\s*\]$)");
      std::smatch two;
      if (!std::regex_match(value, two, pair)) throw InputError(context + ": " + arg + " must be [[R, G, B], [R, G, B]]");
      fit.params.set(key->second.substr(0, comma), parseRgb(two[1], context + ": " + arg));
      fit.params.set(key->second.substr(comma + 1), parseRgb(two[2], context + ": " + arg));
    } else if (value.front() == '[')
      fit.params.set(key->second, parseRgb(value.substr(1, value.size() - 2), context + ": " + arg));
    else
      fit.params.set(key->second, requireNumber(value, context + ": " + arg));
  }
}

// A published fit whose albedos were fitted without MERL's channel factors gets them (docs/materials.md).
void applyAlbedoFactors(const PaperModel& paper, Fit& fit) {
  const auto& k = paper.albedoFactors;
  // The decimal product (the values have a few digits, the factors two): 0.255 × 1.15 is 0.29325, not
  // the double product's 0.29324999999999996.
  const auto times = [](double v, double factor) { return std::stod(formatted("%.12g", v * factor)); };
  for (const char* albedo : {"kd", "ks"}) {
    const Rgb v = fit.params.rgb(albedo);
    fit.params.set(albedo, Rgb(times(v.r, k[0]), times(v.g, k[1]), times(v.b, k[2])));
  }
  fit.source += formatted("; kd and ks times (%g, %g, %g), MERL's channel factors, which the fits were made without "
                          "(docs/materials.md)", k[0], k[1], k[2]);
}

}  // namespace

std::vector<MaterialFile> importFitLines(std::string_view text, const std::string& source) {
  static const std::regex line(
      R"(^\s*([^=\s]+)\s*=\s*Aggregate\(\s*Lambertian\(\s*albedo\s*=\s*\[([^\]]*)\]\s*\)\s*,\s*(\w+)\((.*)\)\s*\)\s*$)");
  const auto lines = splitLines(text);
  const std::string fileName = std::filesystem::path(source).filename().string();
  const std::string metric = fitLinesMetric(fileName, lines);
  std::vector<MaterialFile> out;
  for (size_t ln = 0; ln < lines.size(); ++ln) {
    const std::string& l = lines[ln];
    if (l.find_first_not_of(" \t") == std::string::npos || l[l.find_first_not_of(" \t")] == '#') continue;
    const std::string where = source + ":" + std::to_string(ln + 1);
    std::smatch m;
    if (!std::regex_match(l, m, line))
      throw InputError(where + ": not a fit line (NAME = Aggregate(Lambertian(albedo = [...]), Model(...)))");
    const std::string name = m[1], bbmModel = m[3], args = m[4];
    checkMaterialName(name, where);
    const PaperModel* paper = paperModel(bbmModel);
    if (!paper && metric.empty())
      throw InputError(source + ": cannot tell the metric (name the file *_E1.fit or *_E2.fit)");
    Fit fit;
    fit.id.metric = metric;
    const std::map<std::string, std::string> keys = bbmModelKeys(bbmModel, fileName, where, fit);
    const std::string context = where + ": " + name + " " + fit.id.str();
    fit.params.set("kd", parseRgb(m[2], context + ": Lambertian albedo"));
    setArguments(args, keys, bbmModel, context, fit);
    validateFit(fit, context);  // kd and ks are RGB values in range before they are converted
    if (paper && paper->albedoFactors != kAsPublished) applyAlbedoFactors(*paper, fit);
    validateFit(fit, context);
    MaterialFile mat = measuredMaterial(name, paper ? fit.source : std::string(kFitLinesSource));
    mat.put(std::move(fit));
    for (const MaterialFile& prev : out)
      if (prev.name == name) throw InputError(where + ": material '" + name + "' appears twice in this file");
    out.push_back(std::move(mat));
  }
  if (out.empty()) throw InputError(source + ": no fit lines found");
  return out;
}

void Importer::addFile(const std::filesystem::path& path) {
  // The supplement's text for all 100 materials is well under a megabyte.
  const std::string s = readInputFile(path, 64 << 20, "supplement or .fit file");
  if (s.find("Aggregate(") != std::string::npos)
    add(importFitLines(s, path.string()), kPrecisionFitLines, path.string());
  else if (s.find("Material Name:") != std::string::npos)
    add(importSupplement(s, path.string()), kPrecisionSupplement, path.string());
  else
    throw InputError(path.string() + ": neither the supplement's text (no 'Material Name:') nor .fit lines (no 'Aggregate(')");
}

namespace {

// The same fit, to the precision of the sources (bbm's .fit lines round to 5 decimals): the same
// parameters, each value within 1e-5 (absolute, or relative for large values) of the other's.
bool sameFitValues(const Fit& a, const Fit& b) {
  const auto close = [](double x, double y) { return std::abs(x - y) <= 1e-5 * std::max(1.0, std::max(std::abs(x), std::abs(y))); };
  const auto& va = a.params.values();
  const auto& vb = b.params.values();
  if (va.size() != vb.size()) return false;
  for (const auto& [key, value] : va) {
    const auto other = vb.find(key);
    if (other == vb.end() || value.index() != other->second.index()) return false;
    if (const double* x = std::get_if<double>(&value)) {
      if (!close(*x, std::get<double>(other->second))) return false;
    } else if (const Rgb* c = std::get_if<Rgb>(&value)) {
      const Rgb& d = std::get<Rgb>(other->second);
      if (!close(c->r, d.r) || !close(c->g, d.g) || !close(c->b, d.b)) return false;
    } else if (value != other->second) {
      return false;
    }
  }
  return true;
}

}  // namespace

void Importer::add(std::vector<MaterialFile> materials, int precision, const std::string& from) {
  for (MaterialFile& m : materials) {
    auto [it, fresh] = entries_.try_emplace(m.name);
    Entry& e = it->second;
    if (fresh) e.material = measuredMaterial(m.name, m.source);
    for (Fit& fit : m.fits) {
      if (const Fit* earlier = e.material.findExact(fit.id); earlier && !sameFitValues(*earlier, fit))
        throw InputError((from.empty() ? std::string("import") : from) + ": gives " + m.name + "'s " + fit.id.str() +
                         " fit other values than an earlier source; which is the paper's cannot be told");
      auto p = e.precision.find(fit.id.str());
      if (p != e.precision.end() && p->second > precision) continue;
      e.precision[fit.id.str()] = precision;
      if (fit.source.empty()) fit.source = m.source;
      e.material.put(std::move(fit));
    }
  }
}

MaterialFile Importer::mergeInto(MaterialFile existing, const std::string& name) const {
  const Entry& e = entries_.at(name);
  if (existing.name.empty()) existing = measuredMaterial(name, "");
  // Make every fit's provenance explicit, merge, then let the material's source be the one most fits
  // share; a fit whose provenance differs keeps its own `source` key.
  checkKeepsPublished(existing, name);
  for (Fit& f : existing.fits)
    if (f.source.empty()) f.source = existing.source;
  // A published fit the sources give again (checked the same) is taken only at the supplement's precision.
  for (const Fit& f : e.material.fits)
    if (!existing.findExact(f.id) || e.precision.at(f.id.str()) >= kPrecisionSupplement) existing.put(f);
  std::map<std::string, int> votes;
  for (const Fit& f : existing.fits) ++votes[f.source];
  if (!votes.empty())
    existing.source =
        std::max_element(votes.begin(), votes.end(), [](auto& a, auto& b) { return a.second < b.second; })->first;
  for (Fit& f : existing.fits)
    if (f.source == existing.source) f.source.clear();
  return existing;
}

void Importer::checkKeepsPublished(const MaterialFile& existing, const std::string& name) const {
  const Entry& e = entries_.at(name);
  for (const Fit& f : e.material.fits)
    if (const Fit* old = existing.findExact(f.id); old && !sameFitValues(*old, f))
      throw InputError((existing.path.empty() ? existing.name : existing.path.string()) + ": its published " + f.id.str() +
                       " fit differs from the one imported; a published fit is never replaced (remove it from the file first)");
}

std::vector<std::string> Importer::names() const {
  std::vector<std::string> n;
  for (const auto& [name, e] : entries_) n.push_back(name);
  return n;
}

size_t Importer::fitCount() const {
  size_t n = 0;
  for (const auto& [name, e] : entries_) n += e.material.fits.size();
  return n;
}

}  // namespace glossy
