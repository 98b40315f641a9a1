#include "renderer/study/perceptual.h"

#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "materials/core/text.h"

#include <cmath>
#include <set>
#include <sstream>

namespace glossy::study {

namespace {

// The two tables are small (≈ 2000 and 130 lines); a larger file is not the dataset.
constexpr std::uintmax_t kMaxBytes = 4u << 20;

std::vector<std::string> readLines(const std::filesystem::path& file) {
  const std::string text = readInputFile(file, kMaxBytes, "perceptual table");
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(line);
  while (std::getline(in, cur, ';')) out.push_back(cur);
  if (!line.empty() && line.back() == ';') out.emplace_back();
  return out;
}

// A field, its surrounding double quotes removed; nullopt for a stray quote.
std::optional<std::string> unquoted(std::string s) {
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  if (s.find('"') != std::string::npos || s.empty()) return std::nullopt;
  return s;
}

[[noreturn]] void bad(const std::filesystem::path& file, std::size_t line, const std::string& what) {
  throw InputError(file.string() + ":" + std::to_string(line) + ": " + what);
}

}  // namespace

const std::vector<PerceptualFit>& perceptualFits() {
  static const std::vector<PerceptualFit> fits = {{"ABC", "microfacet:E2", "published"},
                                                  {"ABC", "smooth:E2", "published"}};
  return fits;
}

const std::vector<PerceptualFit>& judgedApproximations() {
  static const std::vector<PerceptualFit> fits = {{"WARD", "ward:Ngan05", "published"},
                                                  {"BLINN-PHONG", "blinn-phong:Ngan05", "published"},
                                                  {"LAFORTUNE", "lafortune:Ngan05", "published"},
                                                  {"SGD", "sgd:Bagher12", "published"}};
  return fits;
}

std::string perceptualName(const std::string& material) {
  std::string s = material;
  for (char& c : s)
    if (c == '_') c = '-';
  return s;
}

PerceptualData PerceptualData::read(const std::filesystem::path& dir) {
  PerceptualData data;
  {
    const auto file = dir / "PerceptualDistances.csv";
    const auto lines = readLines(file);
    if (lines.empty() || lines[0] != "\"METHOD\";\"BRDF\";\"DISTANCE\"")
      bad(file, 1, "expected the header \"METHOD\";\"BRDF\";\"DISTANCE\"");
    for (std::size_t i = 1; i < lines.size(); ++i) {
      if (lines[i].empty()) continue;
      const auto f = fields(lines[i]);
      if (f.size() != 3) bad(file, i + 1, "expected 3 fields separated by ';', got " + std::to_string(f.size()));
      const auto method = unquoted(f[0]), material = unquoted(f[1]);
      if (!method || !material) bad(file, i + 1, "malformed method or material name");
      const auto d = parseNumber(f[2]);
      if (!d || !std::isfinite(*d) || *d < 0.0 || *d > 1.0)
        bad(file, i + 1, "distance '" + shortened(f[2]) + "' is not a number in [0, 1]");
      if (!data.distances_[*method].emplace(*material, *d).second)
        bad(file, i + 1, "method " + printableLine(*method, 60) + " gives " + printableLine(*material, 60) + " twice");
    }
    if (data.distances_.empty()) bad(file, lines.size(), "no distances");
  }
  {
    const auto file = dir / "MaterialType.csv";
    const auto lines = readLines(file);
    if (lines.empty() || lines[0] != "BRDF;Type") bad(file, 1, "expected the header BRDF;Type");
    static const std::set<std::string> kClasses = {"Metal", "CMetal", "Dielectric"};
    for (std::size_t i = 1; i < lines.size(); ++i) {
      if (lines[i].empty()) continue;
      const auto f = fields(lines[i]);
      if (f.size() != 2) bad(file, i + 1, "expected 2 fields separated by ';', got " + std::to_string(f.size()));
      const auto material = unquoted(f[0]);
      if (!material) bad(file, i + 1, "malformed material name");
      if (!kClasses.count(f[1])) bad(file, i + 1, "class '" + shortened(f[1]) + "' is not Metal, CMetal or Dielectric");
      if (!data.classes_.emplace(*material, f[1]).second) bad(file, i + 1, printableLine(*material, 60) + " is given twice");
    }
    if (data.classes_.empty()) bad(file, lines.size(), "no classes");
  }
  return data;
}

std::string PerceptualData::materialClass(const std::string& material) const {
  for (const std::string& name : {material, perceptualName(material)})
    if (const auto it = classes_.find(name); it != classes_.end()) return it->second;
  return "";
}

std::optional<double> PerceptualData::distance(const std::string& method, const std::string& material) const {
  const auto m = distances_.find(method);
  if (m == distances_.end()) return std::nullopt;
  for (const std::string& name : {material, perceptualName(material)})
    if (const auto it = m->second.find(name); it != m->second.end()) return it->second;
  return std::nullopt;
}

std::size_t PerceptualData::materialCount(const std::string& method) const {
  const auto m = distances_.find(method);
  return m == distances_.end() ? 0 : m->second.size();
}

}  // namespace glossy::study
