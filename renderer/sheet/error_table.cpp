// A sheet's figures as text: the verdict line and the table `glossy sheet` prints.
#include "renderer/sheet/sheet.h"

#include "materials/core/text.h"

#include <algorithm>
#include <sstream>

namespace glossy {

std::string verdictText(const Sheet& sheet) {
  const std::vector<size_t>& models = sheet.verdict.models;
  if (models.empty()) return sheet.verdict.why.empty() ? std::string("no verdict") : sheet.verdict.why;
  std::string names;
  for (size_t k : models) names.append(names.empty() ? "" : ", ").append(sheet.panels[k].panel.label);
  return (models.size() == 1 ? "closest: " : "tie: ") + names;
}

std::string errorTable(const Sheet& sheet) {
  std::ostringstream s;
  s << sheet.material << ": ";
  const std::string note = sheet.measured() ? sheet.measured()->note : "none in the grid";
  if (sheet.hasMeasured())
    s << "error of each model against the measured panel (" << note << "), over the object's pixels, "
      << formatted("%d spp in %d replicates", sheet.spp, sheet.replicates) << "\n";
  else
    s << "no measured panel (" << note << "), so no errors against it\n";
  // The label column fits the longest label (a glossy fit's says so: "GGX E2 (glossy fit)").
  int w = 14;
  for (const PanelRender& p : sheet.panels) w = std::max(w, int(p.panel.label.size()));
  s << formatted("  %-*s   rel. RMSE, noise-free [95 %%]   luminance ratio [95 %%]    HDR-FLIP [95 %%]            "
                 "dE_ITP [95 %%]          SSIM [95 %%]                noisy rRMSE   BRDF E1   BRDF E2\n",
                 w, "panel");
  bool clamped = false;
  const auto row = [&](const PanelRender& p) {
    const PanelFigures& f = p.figures;
    const std::string r = !f.available ? "-"
                          : f.hasCi    ? formatted("%.4f [%.4f, %.4f]%s", f.relativeRmse, f.relativeRmseCi.lo, f.relativeRmseCi.hi,
                                                   f.clamped ? "*" : "")
                                       : formatted("%.4f%s", f.relativeRmse, f.clamped ? "*" : "");
    const std::string l = f.hasCi ? formatted("%.4f [%.4f, %.4f]", f.luminanceRatio, f.luminanceRatioCi.lo, f.luminanceRatioCi.hi)
                                  : formatted("%.4f", f.luminanceRatio);
    const auto withCi = [&](const char* format, double v, const Interval& ci) {
      if (!p.maps.available) return std::string("-");
      const std::string value = formatted(format, v);
      return p.maps.hasCi ? value + " [" + formatted(format, ci.lo) + ", " + formatted(format, ci.hi) + "]" : value;
    };
    const std::string flip = withCi("%.4f", p.maps.flip, p.maps.flipCi), deltaE = withCi("%.2f", p.maps.deltaEItp, p.maps.deltaEItpCi),
                      ssim = withCi("%.4f", p.maps.ssim, p.maps.ssimCi);
    clamped = clamped || f.clamped;
    s << formatted("  %-*s   %-29s  %-24s  %-25s  %-21s  %-25s  %11.4f   %7.4f   %7.4f\n", w, p.panel.label.c_str(), r.c_str(),
                   l.c_str(), flip.c_str(), deltaE.c_str(), ssim.c_str(), f.noisyRelativeRmse, p.brdfE1, p.brdfE2);
  };
  for (const PanelRender& p : sheet.panels) {
    if (p.empty) {
      s << formatted("  %-*s   %s\n", w, p.panel.label.c_str(), p.note.c_str());
      continue;
    }
    if (!p.figures.compared) {
      s << formatted("  %-*s   %s\n", w, p.panel.label.c_str(), p.panel.fit.empty() ? "(the reference)" : "-");
      continue;
    }
    row(p);
  }
  // What an exact model would score: the floor under every column's figure.
  if (!sheet.noiseFloor.empty && sheet.noiseFloor.figures.compared) row(sheet.noiseFloor);
  if (clamped) s << "  * the estimate of the squared error came out negative (the model is within the noise): shown as 0\n";
  // Say so rather than let a narrow interval pass for a precise one.
  for (const std::string& warning : sheet.warnings) s << "  warning: " << warning << "\n";
  if (sheet.skippedPixels > 0) s << "  " << sheet.skippedPixels << " object pixels left out: not finite in some panel\n";
  if (sheet.flipNoiseFloor >= 0.0)
    s << formatted("  HDR-FLIP includes render noise, which raises it; the [95 %%] is the noise's spread. Noise alone gives "
                   "%.4f (the measured panel against itself, half its samples each)\n",
                   sheet.flipNoiseFloor);
  if (sheet.hasMeasured()) {
    s << "  dE_ITP (ITU-R BT.2124) and SSIM compare the panels as the PNG shows them at exposure 0; noise raises dE_ITP "
         "and lowers SSIM (the noise-floor row)\n";
    s << "  " << verdictText(sheet);
    if (sheet.verdict.models.size() > 1) s << " (not separated at 95 %: more samples, e.g. --target-error, may decide)";
    s << "\n";
  }
  return s.str();
}

}  // namespace glossy
