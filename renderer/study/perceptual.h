// The released results of Lavoué, Bonneel, Farrugia, Soler, "Perceptual quality of BRDF approximations:
// dataset and metrics" (CGF 40(2), 2021), read in place from ../shared/perceptual (its SOURCES.md): the
// perceived distance of each approximation method from each measured MERL material, and each material's
// class (Metal, CMetal, Dielectric). Never copied into the repository; results that use it cite the paper.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace glossy::study {

// Which glossy fit the dataset's method rows judge. The `ABC` rows are Löw et al. 2012's model with the
// fit published in their supplement (fitted under E2, the only metric the supplement gives for the ABC
// models). Whether that is the Smooth Surface or the Microfacet variant is not stated in the released data,
// and the paper's text was not available to check, so the study compares both of glossy's published ABC
// fits with the `ABC` distances and says so in its outputs.
struct PerceptualFit {
  std::string method;     // the dataset's METHOD, e.g. "ABC"
  std::string fit;        // StudyRow::fit, e.g. "microfacet:E2"
  std::string fitSource;  // StudyRow::fitSource: "published"
};
const std::vector<PerceptualFit>& perceptualFits();
// The other approximations the dataset judged whose parameters are published and in glossy's library, each
// with the fit its rows judge: Ngan et al. 2005's Ward, Blinn-Phong and Lafortune (the dataset's 86
// materials are the 86 Ngan fitted) and Bagher et al. 2012's SGD ("SGD"; the dataset's "BAGHER" rows are
// Bagher et al.'s 2016 non-parametric model, which glossy does not have).
const std::vector<PerceptualFit>& judgedApproximations();

class PerceptualData {
 public:
  // Reads PerceptualDistances.csv (`"METHOD";"BRDF";"DISTANCE"`) and MaterialType.csv (`BRDF;Type`) from
  // `dir`. InputError naming the file (and line) for a missing or unreadable file, a wrong header, a
  // malformed line, a distance that is not a finite number in [0, 1], an unknown class or a pair given twice.
  static PerceptualData read(const std::filesystem::path& dir);

  // The class of a material as glossy names it ("alum-bronze"): "Metal", "CMetal", "Dielectric", or ""
  // where the table does not know it. The dataset spells MERL's materials as glossy's library does
  // (materials/library/merl/*.toml names); names are compared as given, then with '_' read as '-'.
  std::string materialClass(const std::string& material) const;
  // The perceived distance of `method` from `material` (0 = indistinguishable, 1 = most different), if given.
  std::optional<double> distance(const std::string& method, const std::string& material) const;
  // How many materials the dataset gives `method` for.
  std::size_t materialCount(const std::string& method) const;

 private:
  std::map<std::string, std::map<std::string, double>> distances_;  // method → material → distance
  std::map<std::string, std::string> classes_;                      // material → class
};

// The dataset's name for a glossy material name (identity for MERL names; '_' read as '-').
std::string perceptualName(const std::string& material);

}  // namespace glossy::study
