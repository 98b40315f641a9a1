// Next-event estimation, the direct-light step of a vertex, as pbrt-v4's PathIntegrator::SampleLd: its
// light samples (a light chosen by power, a point on it, the shadow ray), then each weighed by the
// vertex's BRDF and by multiple importance sampling against the BRDF's own sampling (the power heuristic
// with sample counts; weight 1 for a delta light, which no BSDF sample finds). Written for a wave's
// vertices (lanes.h, path_vertex.h), each stage one batch over them (the lights' samples, the shadow rays,
// the BRDF's values), the k-th light samples of all of them at a time. The samples and their shadow
// rays do not depend on the BRDF, so a sheet's panels share them (panel_split.h); the weighing is each
// panel's.
#pragma once

#include "renderer/integrator/shading_point.h"

#include <algorithm>

namespace glossy {

inline double powerHeuristic(double a, double b) {
  const double a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0 ? a2 / (a2 + b2) : 0.0;
}

inline double maxComponent(const Rgb& c) { return std::max({c.r, c.g, c.b}); }

// A light sample as the shading point sees it: the shadow ray to trace and what the light brings along it,
// before the BRDF's value there.
struct SeenLightSample {
  Vec3 wiLocal{0.0};
  Rgb radiance{0.0};
  double pdf = 0.0;  // solid angle, the light's choice included
  bool delta = false;  // LightSample::delta: no BSDF sample competes with it
  Ray shadow;        // tfar < 0: nothing can lie between (the light touches the point)
};

// False when the sample brings nothing.
inline bool toLight(const ShadingPoint& sp, const ChosenLight& chosen, const LightSample& s, SeenLightSample& out) {
  if (!(s.pdf > 0.0) || glm::dot(s.wi, sp.ng) <= 0.0) return false;
  out.wiLocal = sp.frame.toLocal(s.wi);
  if (out.wiLocal.z <= 0.0) return false;
  out.radiance = s.radiance;
  out.pdf = chosen.probability * s.pdf;
  out.delta = s.delta;
  out.shadow = spawnRay(sp.position, sp.ng, sp.margin, s.wi);
  if (!s.atInfinity) {
    // To the light's point, itself moved off the light by its margin. Where the two margins overlap
    // there is no room for an occluder: the light is seen.
    const Vec3 d = s.target - out.shadow.origin;
    const double length = glm::length(d);
    const bool room = glm::dot(d, s.wi) > 0.0 && length > 0.0;
    out.shadow.dir = room ? d / length : s.wi;
    out.shadow.tfar = room ? length : -1.0;
  }
  return true;
}

// The light samples a vertex drew (VertexDraws::lightCount) with their shadow rays' verdicts.
struct VertexLight {
  int count = 0;
  SeenLightSample sample[kMaxLightSamples];
  bool visible[kMaxLightSamples] = {};  // the sample arrived from above the surface and nothing blocks it
};

// The samples of one light for a group of lanes, from their points and draws: Light::sample, unless a
// store of samples already made stands in front of it (SharedDraws::sampleLight).
inline void drawLightSamples(const Light* light, const Receiver* at, const Vec2* u, const Lanes& group, LightSample* out) {
  light->sample(at, u, group.lane, group.n, out);
}

// The step for the vertices of a wave's lanes, with its scratch (Paths keeps one).
class DirectLight {
 public:
  // light[i] for the lanes: the light samples of draws[i] at sp[i] and their shadow rays' verdicts. A
  // group's samples of one light are drawn by draw (drawLightSamples' signature).
  template <class Draw>
  void sample(const PathContext& context, const Lanes& lanes, const ShadingPoint* sp, const VertexDraws* draws,
              VertexLight* light, Draw&& draw) {
    int most = 0;
    for (const int i : lanes) {
      light[i].count = int(draws[i].lightCount);
      most = std::max(most, light[i].count);
      from_[i] = receiver(sp[i]);
    }
    for (int k = 0; k < most; ++k) {
      Lanes chosen;
      for (const int i : lanes) {
        if (k >= light[i].count) continue;
        light[i].visible[k] = false;
        chosen_[i] = context.lights.choose(draws[i].lightChoice[k]);
        u_[i] = draws[i].light[k];
        if (chosen_[i]) chosen.add(i);
      }
      forEachGroup(chosen, [&](int i) { return chosen_[i].light; },
                   [&](const Light* l, const Lanes& group) { draw(l, from_, u_, group, sample_); });
      std::fill(traced_, traced_ + kWaveSize, false);
      for (const int i : chosen) {
        traced_[i] = toLight(sp[i], chosen_[i], sample_[i], light[i].sample[k]);
        shadow_[i] = light[i].sample[k].shadow;
      }
      context.scene.bvh->occluded(traced_, shadow_, occluded_, kWaveSize);
      for (const int i : chosen) light[i].visible[k] = traced_[i] && !occluded_[i];
    }
  }

  // Each lane's light samples (sp[i].lightSamples of them, light_count.h) weighed by its BRDF, a batch per
  // BRDF, and added to radiance[i] with the path's throughput.
  void add(const RenderSettings& settings, const Lanes& lanes, const ShadingPoint* sp, const VertexLight* light,
           const Rgb* throughput, Rgb* radiance) {
    int most = 0;
    for (const int i : lanes) most = std::max(most, sp[i].lightSamples);
    for (int k = 0; k < most; ++k) {
      Lanes lit;
      for (const int i : lanes)
        if (k < sp[i].lightSamples && light[i].visible[k]) lit.add(i);
      forEachGroup(lit, [&](int i) { return sp[i].brdf; }, [&](const Brdf* brdf, const Lanes& group) {
        for (int g = 0; g < group.n; ++g) {
          wi_[g] = light[group.lane[g]].sample[k].wiLocal;
          wo_[g] = sp[group.lane[g]].woLocal;
        }
        if (settings.cosineBrdfSampling)
          for (int g = 0; g < group.n; ++g) value_[g] = valueToward(settings, sp[group.lane[g]], wi_[g]);
        else
          evalPdfBatch(*brdf, wi_, wo_, value_, group.n);
        for (int g = 0; g < group.n; ++g) {
          const int i = group.lane[g];
          const SeenLightSample& l = light[i].sample[k];
          if (maxComponent(value_[g].f) <= 0.0) continue;
          const double pdf = sp[i].lightSamples * l.pdf;
          const double w = l.delta ? 1.0 : powerHeuristic(pdf, sp[i].bsdfSamples * value_[g].pdf);
          radiance[i] += throughput[i] * (value_[g].f * l.radiance * (l.wiLocal.z * w / pdf));
        }
      });
    }
  }

 private:
  Receiver from_[kWaveSize];
  ChosenLight chosen_[kWaveSize];
  Vec2 u_[kWaveSize];
  LightSample sample_[kWaveSize];
  Ray shadow_[kWaveSize];
  bool traced_[kWaveSize], occluded_[kWaveSize];
  Vec3 wi_[kWaveSize], wo_[kWaveSize];  // the BRDF's batch, packed
  BrdfValue value_[kWaveSize];
};

}  // namespace glossy
