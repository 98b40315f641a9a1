// The four kinds of figure glossy plot draws from a PlotSet (after Disney's BRDF Explorer: its θ_h plot,
// image slice, albedo plot and polar plot), each with the CSV of the numbers it draws:
//   theta_h_figure.cpp      ρ against θ_h at θ_d ∈ {1°, 30°, 60°, 80°}, φ_d = 90°, log ρ
//   image_slice_figure.cpp  ρ over (θ_h, θ_d) at φ_d = 90° per BRDF, and its log-ratio to the measured one
//   albedo_figure.cpp       directional albedo against θ_V
//   polar_figure.cpp        in-plane lobes ρ cos θ_i at θ_V ∈ {0°, 30°, 60°, 75°}
// CSV rows start with the direction pair Lx,Ly,Lz,Vx,Vy,Vz (local frame, N = +z), so that the first six
// columns of the rows are `glossy eval`'s input as they stand; then the angles, then one column per BRDF
// drawn, named by its panel label. Pairs below the horizon are left out.
#pragma once

#include "renderer/plot/figure.h"
#include "renderer/plot/plot_set.h"

#include <vector>

namespace glossy::plot {

constexpr double kDeg = kPi / 180.0;  // the figures' angles are in degrees

PlotFigure thetaHFigure(const PlotSet& set);
// One figure per BRDF present: measured first.
std::vector<PlotFigure> imageSliceFigures(const PlotSet& set);
PlotFigure albedoFigure(const PlotSet& set);
enum class RadialScale { Log, Linear };
PlotFigure polarFigure(const PlotSet& set, RadialScale scale);

}  // namespace glossy::plot
