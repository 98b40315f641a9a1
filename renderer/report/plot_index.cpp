// Reading plots.json (plot_index.h) with nlohmann-json.
#include "renderer/report/plot_index.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/output/input_folder.h"

#include <nlohmann/json.hpp>


namespace glossy::report {

namespace {

constexpr std::uintmax_t kMaxPlotsJsonBytes = std::uintmax_t(16) << 20;

// A file name the site may copy: one path component of letters, digits, '_', '.', '+', '-', starting with
// a letter or digit (never hidden, never "..").
bool isPlainFileName(const std::string& name) {
  if (name.empty() || name.size() > 200 || !std::isalnum((unsigned char)name[0])) return false;
  for (char c : name)
    if (!(std::isalnum((unsigned char)c) || c == '_' || c == '.' || c == '+' || c == '-')) return false;
  return true;
}

}  // namespace

PlotIndex readPlotIndex(const std::filesystem::path& plotsDir, const std::filesystem::path& folder) {
  const std::filesystem::path file = folder / "plots.json";
  const std::string where = file.string();
  const std::string bytes = readInputFile(plotsDir, file, kMaxPlotsJsonBytes, "plots.json");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(bytes);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where + ": not JSON: " + printableLine(e.what(), 200));
  }
  if (!j.is_object()) throw InputError(where + ": not a JSON object");
  auto text = [&](const nlohmann::json& o, const char* key, const std::string& what) -> std::string {
    if (!o.contains(key) || o[key].is_null()) return "";
    if (!o[key].is_string()) throw InputError(where + ": " + what + key + " is not a string");
    return printableLine(o[key].get<std::string>(), 2000);
  };
  PlotIndex index;
  index.folder = folder;
  index.material = text(j, "material", "");
  index.measured = text(j, "measured", "");
  index.channel = text(j, "channel", "");
  if (!j.contains("figures") || !j["figures"].is_array()) throw InputError(where + ": has no \"figures\" list");
  for (size_t k = 0; k < j["figures"].size(); ++k) {
    const nlohmann::json& f = j["figures"][k];
    const std::string what = "figures[" + std::to_string(k) + "].";
    if (!f.is_object()) throw InputError(where + ": " + what.substr(0, what.size() - 1) + " is not an object");
    PlotFigure fig{text(f, "kind", what), text(f, "title", what), text(f, "caption", what),
                   text(f, "png", what), text(f, "svg", what), text(f, "csv", what), ""};
    for (const std::string* name : {&fig.png, &fig.svg, &fig.csv}) {
      if (name->empty()) continue;
      if (!isPlainFileName(*name)) throw InputError(where + ": " + what + " names '" + shortened(*name) + "', not a plain file name");
      std::error_code ec;
      if (!std::filesystem::exists(std::filesystem::symlink_status(folder / *name, ec)))
        throw InputError(where + ": " + what + " names " + *name + ", which is missing");
      checkInputFile(plotsDir, folder / *name, "plot file");
    }
    if (fig.png.empty() && fig.svg.empty()) throw InputError(where + ": " + what + " has neither a png nor an svg");
    if (fig.title.empty()) fig.title = fig.kind.empty() ? "figure " + std::to_string(k + 1) : fig.kind;
    index.figures.push_back(std::move(fig));
  }
  return index;
}

}  // namespace glossy::report
