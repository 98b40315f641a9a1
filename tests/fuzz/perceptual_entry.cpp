// The perceptual dataset's two tables as a study reads them (renderer/study/perceptual.h): `perceptual =
// FOLDER` names a folder holding PerceptualDistances.csv and MaterialType.csv, read together. The first byte
// picks the table the rest of the bytes are: odd: PerceptualDistances.csv, even: MaterialType.csv; the other
// table is a valid slice of the dataset's, so that a fuzzed table is always read (the distances are read
// first, and a refused one would hide the classes). What is accepted is looked up as the study does: each
// method it compares with people at a few materials (in the dataset's spelling and in glossy's), and their classes.
#include "renderer/study/perceptual.h"
#include "tests/fuzz/fuzz_entries.h"
#include "tests/fuzz/fuzz_temp_dir.h"

#include <stdexcept>
#include <string_view>

namespace glossy::fuzz {

namespace {

constexpr std::string_view kDistances =
    "\"METHOD\";\"BRDF\";\"DISTANCE\"\n"
    "\"ABC\";\"alum-bronze\";0.216666666666667\n"
    "\"BLINN-PHONG\";\"alum-bronze\";0.533333333333333\n"
    "\"ABC\";\"blue-metallic-paint\";0.1\n";
constexpr std::string_view kClasses =
    "BRDF;Type\n"
    "alum-bronze;Metal\n"
    "blue-metallic-paint;CMetal\n"
    "white-fabric;Dielectric\n";

Bytes bytesOf(std::string_view text) { return {reinterpret_cast<const uint8_t*>(text.data()), text.size()}; }

}  // namespace

void perceptualEntry(Bytes data) {
  if (data.empty()) return;
  const bool distances = (data[0] & 1) != 0;
  const Bytes table = data.subspan(1);
  const TempFile d("PerceptualDistances.csv", distances ? table : bytesOf(kDistances));
  const TempFile c("MaterialType.csv", distances ? bytesOf(kClasses) : table);
  const study::PerceptualData read = study::PerceptualData::read(d.path().parent_path());
  for (const char* material : {"alum-bronze", "blue-metallic-paint", "white_fabric", "", "-"}) {
    const std::string cls = read.materialClass(material);
    if (!cls.empty() && cls != "Metal" && cls != "CMetal" && cls != "Dielectric")
      throw std::logic_error("an accepted class that is none of the three");
    for (const study::PerceptualFit& fit : study::perceptualFits())
      if (const auto v = read.distance(fit.method, material); v && !(*v >= 0.0 && *v <= 1.0))
        throw std::logic_error("an accepted distance outside [0, 1]");
  }
}

}  // namespace glossy::fuzz
