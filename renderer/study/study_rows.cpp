#include "renderer/study/study_rows.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/params/material_file.h"
#include "renderer/sheet/comparison_grid.h"
#include "renderer/study/perceptual.h"

#include <algorithm>
#include <charconv>
#include <optional>
#include <tuple>

namespace glossy::study {

namespace {

std::string setting(const SheetRecord& sheet, const std::string& key) {
  for (const SheetSetting& s : sheet.settings)
    if (s.key == key) return s.value;
  return "";
}

template <class T>
T whole(const std::string& text) {
  T v{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  return ec == std::errc() && end == text.data() + text.size() ? v : T{};
}

// Whether a panel's fit is the paper's or glossy's own: MODEL:METRIC stands for glossy's fit in a file without
// a published one (materials/params/material_file.h), so the material file decides.
std::string fitSource(const FitId& id, const std::optional<MaterialFile>& file) {
  if (id.isGlossys()) return "glossy";
  if (file)
    if (const Fit* fit = file->find(id)) return fit->id.isGlossys() ? "glossy" : "published";
  return "published";
}

}  // namespace

std::string sheetWarning(const SheetRecord& sheet) {
  // The sheet's warnings (glossy:warnings), then, for a sheet without a verdict, why it has none ("no
  // verdict: the measured panel is below its noise").
  std::string out = joined(sheet.warnings, "; ");
  if (!sheet.verdict.starts_with("closest: ") && !sheet.verdict.starts_with("tie: ") && out.find(sheet.verdict) == std::string::npos)
    out += (out.empty() ? "" : "; ") + sheet.verdict;
  return out;
}

std::vector<StudyRow> sheetRows(const SheetRecord& sheet, const PlannedMaterial& material, const std::string& lighting,
                                const std::string& scene, const std::string& materialClass, const std::filesystem::path& relativeExr) {
  std::optional<MaterialFile> file;
  try {
    file = loadMaterialFile(material.file);
  } catch (const InputError&) {
    // Gone or changed past reading since the sheet was made: the fit's own name says what it can.
  }
  const std::vector<std::string> closest = sheet.closestLayers();
  const bool tie = sheet.isTie();
  const std::string warning = sheetWarning(sheet);
  const std::string size = setting(sheet, "size");
  const size_t x = size.find('x');
  std::vector<StudyRow> rows;
  for (const PanelRecord& p : sheet.panels) {
    if (p.isMeasured() || p.empty) continue;
    const FitId id = FitId::parse(p.fit, sheet.exr.string());
    StudyRow r;
    r.material = material.name;
    r.database = material.database;
    r.materialClass = materialClass;
    r.lighting = lighting;
    r.scene = scene;
    r.layer = p.layer;
    // The model's label whoever made the fit ("CT E2", not the sheet's "CT E2 (glossy fit)"): one model
    // compares across databases; fitSource says whose fit it is.
    r.label = SheetPanel::ofFit({id.model, id.metric}).label;
    r.fit = p.fit;
    r.fitMetric = id.metric;
    r.fitSource = fitSource(id, file);
    r.e1 = p.e1;
    r.e2 = p.e2;
    r.rrmse = p.relativeRmse.value;
    r.rrmseLo = p.relativeRmse.lo;
    r.rrmseHi = p.relativeRmse.hi;
    r.rrmseClamped = p.relativeRmse.value && p.noiseFree.starts_with("clamped");
    r.flip = p.flip.value;
    r.flipLo = p.flip.lo;
    r.flipHi = p.flip.hi;
    r.deltaEItp = p.deltaEItp.value;
    r.deltaEItpLo = p.deltaEItp.lo;
    r.deltaEItpHi = p.deltaEItp.hi;
    r.ssim = p.ssim.value;
    r.ssimLo = p.ssim.lo;
    r.ssimHi = p.ssim.hi;
    r.luminanceRatio = p.luminanceRatio.value;
    const bool named = std::find(closest.begin(), closest.end(), p.layer) != closest.end();
    r.closest = named && !tie;
    r.tied = named && tie;
    r.warning = warning;
    r.sheet = relativeExr.generic_string();
    if (x != std::string::npos) {
      r.width = whole<int>(size.substr(0, x));
      r.height = whole<int>(size.substr(x + 1));
    }
    r.spp = whole<int>(sheet.spp);
    r.seed = whole<unsigned long long>(setting(sheet, "seed"));
    rows.push_back(std::move(r));
  }
  return rows;
}

std::vector<StudyRow> readStudyRows(const std::filesystem::path& out) { return readStudyRows(out, readPlan(out)); }

std::vector<StudyRow> readStudyRows(const std::filesystem::path& out, const StudyPlan& plan) {
  std::optional<PerceptualData> perceptual;
  if (!plan.perceptualDir.empty()) perceptual = PerceptualData::read(plan.perceptualDir);
  std::vector<StudyRow> rows;
  for (const PlannedMaterial& m : plan.materials) {
    const std::string materialClass = perceptual ? perceptual->materialClass(m.name) : "";
    for (const std::string& lighting : plan.lightings)
      for (const std::string& scene : plan.scenes) {
        const std::filesystem::path relative = sheetPath(scene, lighting, m.name);
        const SheetRecord sheet = readSheetRecord(out / kSheetsFolder, out / relative);
        if (sheet.name != m.name)
          throw InputError((out / relative).string() + ": is the sheet of '" + sheet.name + "', not of '" + m.name + "'");
        for (StudyRow& r : sheetRows(sheet, m, lighting, scene, materialClass, relative)) rows.push_back(std::move(r));
      }
  }
  // Materials, lightings and scenes are sorted in the plan, and a sheet's rows are in grid order.
  return rows;
}

}  // namespace glossy::study
