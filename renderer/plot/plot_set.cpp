#include "renderer/plot/plot_set.h"

#include "materials/core/unit_direction.h"

#include <algorithm>
#include <cmath>

namespace glossy::plot {

std::string channelName(Channel c) {
  switch (c) {
    case Channel::R: return "R";
    case Channel::G: return "G";
    case Channel::B: return "B";
    default: return "luminance";
  }
}

CurveStyle PlotBrdf::style() const {
  CurveStyle s;
  s.colour = panel.colour.empty() ? "#999999" : panel.colour;
  s.width = isMeasured ? 2.2 : 1.6;
  if (isMeasured) return s;
  // E1 fits dashed: the pairs of one model stay apart in print and for readers who confuse the colours.
  // glossy's own fits dotted (dash-dotted under E1), apart from the published fit they share a colour with.
  const FitId id = FitId::parse(panel.fit, "plot");
  if (id.isGlossys()) s.dash = id.metric == "E1" ? "7 3 2 3" : "2 3";
  else if (id.metric == "E1") s.dash = "7 4";
  return s;
}

Vec3 asEvalReads(const Vec3& d) {
  Vec3 unit = d;
  makeUnitDirection(unit);  // the plots' directions are finite and non-zero
  return unit;
}

const PlotBrdf* PlotSet::measured() const {
  for (const PlotBrdf& b : brdfs)
    if (b.isMeasured && b.present) return &b;
  return nullptr;
}

std::vector<const PlotBrdf*> PlotSet::present() const {
  std::vector<const PlotBrdf*> out;
  for (const PlotBrdf& b : brdfs)
    if (b.present) out.push_back(&b);
  return out;
}

double PlotSet::value(const PlotBrdf& b, const Vec3& printedL, const Vec3& printedV) const {
  const Vec3 L = asEvalReads(printedL), V = asEvalReads(printedV);
  Rgb rho(0.0);
  if (b.table) {
    if (L.z > 0.0 && V.z > 0.0 && !b.table->valid(MerlTable::binOf(L, V).index())) return std::nan("");
    rho = b.table->eval(L, V);
  } else if (b.fit) {
    rho = eval(*b.fit, L, V);
  } else {
    return std::nan("");
  }
  switch (channel) {
    case Channel::R: return rho.r;
    case Channel::G: return rho.g;
    case Channel::B: return rho.b;
    default: return luminance(rho);
  }
}

std::string PlotSet::sourceLine() const {
  return "Material " + material + "; channel " + channelName(channel) + "; measured data: " + measuredLabel + ".";
}

std::string PlotSet::decadesText(int lo, int hi, const std::string& floorWord) const {
  const std::string range = "10^" + std::to_string(lo) + " to 10^" + std::to_string(hi);
  if (decades > 0) return range + ", the " + std::to_string(decades) + " decades below the peak (--decades)";
  return range + ", " + floorWord;
}

std::string PlotSet::fitsLine() const {
  std::string drawn, absent;
  for (const PlotBrdf& b : brdfs) {
    if (b.isMeasured) continue;
    std::string& list = b.present ? drawn : absent;
    list.append(list.empty() ? "" : ", ").append(b.panel.label);
  }
  std::string s = "Fits (Löw et al. 2012; E1/E2 the metric each was fitted under): " + (drawn.empty() ? std::string("none") : drawn);
  if (!absent.empty()) s += "; not in the file: " + absent;
  return s + ".";
}

std::vector<LegendEntry> PlotSet::legend() const {
  std::vector<LegendEntry> out;
  for (const PlotBrdf& b : brdfs) out.push_back({b.panel.label, b.style(), b.present, b.note});
  return out;
}

PlotSet makePlotSet(const MaterialFile& material, std::shared_ptr<const MerlTable> measured, const std::string& measuredNote,
                    Channel channel, std::span<const SheetPanel> panels) {
  PlotSet set;
  set.material = material.name;
  set.channel = channel;
  set.measuredLabel = measuredNote;
  for (const SheetPanel& panel : panels) {
    if (panel.fit.empty()) {
      set.brdfs.push_back({panel, true, measured != nullptr, measured ? "" : "no data", std::nullopt, measured});
      continue;
    }
    const Fit* fit = material.find(FitId::parse(panel.fit, material.path.string()));
    // A grid slot that only glossy's fit fills shows it under glossy's label.
    PlotBrdf b{fit && fit->id.str() != panel.fit ? SheetPanel::ofFit(fit->id) : panel, false, fit != nullptr,
               fit ? "" : "not in the file", std::nullopt, nullptr};
    if (fit) b.fit = makeBrdf(*fit);
    set.brdfs.push_back(std::move(b));
  }
  return set;
}

}  // namespace glossy::plot
