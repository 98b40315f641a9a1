// Importers for published parameters: Löw et al. 2012's supplement text (sections "Material Name: X" with
// rows "Model<TAB>Metric<TAB>R: K_d = … G: … B: … Common: …") and bbm's `.fit` lines
// (`name = Aggregate(Lambertian(albedo = [...]), Model(...))`) of Löw et al.'s fits (low_*.fit) and of Ngan et
// al. 2005's (ngan_*.fit, materials/published-fits/). Both produce validated MaterialFiles.
#pragma once

#include "materials/params/material_file.h"

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace glossy {

inline constexpr std::string_view kSupplementSource = "Löw et al. 2012, supplementary material";
inline constexpr std::string_view kFitLinesSource =
    "Löw et al. 2012, published fits as transcribed by bbm (A and Ks rounded to 5 decimals)";

// `source` names the input in errors ("FILE:LINE: ...").
std::vector<MaterialFile> importSupplement(std::string_view text, const std::string& source);
// The metric is not on the lines. Löw et al.'s: from the file name (low_cooktorrance_E1.fit) or, failing that,
// from a header comment naming "E1 fits"/"E2 fits". Ngan et al.'s (models NganWard, …): FitId::kNgan05, and
// each fit's `source` names the paper, the file and bbm's commit (the file's second line names the paper);
// Bagher et al.'s (model Bagher): FitId::kBagher12, likewise.
std::vector<MaterialFile> importFitLines(std::string_view text, const std::string& source);
// The provenance of an Ngan et al. fit read from bbm's file `fileName` ("ngan_ward.fit").
std::string nganFitSource(const std::string& fileName);
// The provenance of a Bagher et al. fit read from bbm's file `fileName` ("bagher_sgd.fit").
std::string bagherFitSource(const std::string& fileName);

// Gathers fits from many sources into one MaterialFile per material. Where two sources give the same
// MODEL:METRIC for a material, the supplement's text (6 significant decimals) beats the .fit lines (5),
// and among sources of the same kind the later one wins.
class Importer {
 public:
  // Detects the kind of file from its content; throws InputError for a file of neither kind.
  void addFile(const std::filesystem::path& path);
  // Two sources that give one fit different values (beyond the less precise one's rounding) are refused,
  // naming `from`: which of them is the paper's cannot be told.
  void add(std::vector<MaterialFile> materials, int precision, const std::string& from = "");
  // Merges the gathered fits into `existing`: fits it does not have are added, others kept. A published fit
  // is never replaced: one the sources give again (to their precision) stays as it is, one they contradict
  // is refused (InputError naming the file and the fit) — a crafted .fit cannot pass for the paper's.
  MaterialFile mergeInto(MaterialFile existing, const std::string& name) const;
  // mergeInto's refusal alone: throws when the sources contradict a published fit of `existing`.
  void checkKeepsPublished(const MaterialFile& existing, const std::string& name) const;
  std::vector<std::string> names() const;
  size_t fitCount() const;

 private:
  struct Entry {
    MaterialFile material;
    std::map<std::string, int> precision;  // per fit id
  };
  std::map<std::string, Entry> entries_;
};

}  // namespace glossy
