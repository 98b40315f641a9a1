// Sets of lanes: the paths a step takes at once, each lane indexing the per-path arrays the step reads and
// writes. The wave's paths are up to kWaveSize lanes.
#pragma once

namespace glossy {

// Paths traced together by the wave, and the most lanes a batch takes.
constexpr int kWaveSize = 128;

struct Lanes {
  int lane[kWaveSize];
  int n = 0;
  void add(int i) { lane[n++] = i; }
  static Lanes first(int n) { Lanes l; while (l.n < n) l.add(l.n); return l; }  // 0, 1, …, n − 1
  const int* begin() const { return lane; }
  const int* end() const { return lane + n; }
};

// f(key, group) for each distinct key(i) among the lanes, the group's lanes in increasing order: a batch
// call per BRDF or per light. A wave mostly has one BRDF and one or two lights, so this is one or two passes.
template <class Key, class F>
void forEachGroup(const Lanes& lanes, Key key, F&& f) {
  for (Lanes rest = lanes; rest.n > 0;) {
    const auto k0 = key(rest.lane[0]);
    Lanes group, others;
    for (const int i : rest) (key(i) == k0 ? group : others).add(i);
    f(k0, group);
    rest = others;
  }
}

}  // namespace glossy
