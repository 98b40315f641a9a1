#include "materials/nbrdf/neural_brdf.h"

#include "materials/core/input_error.h"
#include "materials/core/lane_math.h"
#include "materials/core/input_file.h"
#include "materials/core/toml_input.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace glossy {

namespace {

constexpr std::string_view kFormat = "glossy-nbrdf 1";

// Where a key sits: the file, and the table holding it ("layer 2"; empty for the top). Messages read
// "FILE:LINE: layer 2: key 'weights' …".
struct Place {
  const std::string& source;
  std::string table;
  std::string key(const toml::node& node, std::string_view name) const {
    return tomlAt(source, node) + (table.empty() ? "" : table + ": ") + "key '" + std::string(name) + "'";
  }
  const toml::node& require(const toml::table& t, std::string_view name) const {
    const toml::node* n = t.get(name);
    if (!n) throw InputError(key(t, name) + " is missing");
    return *n;
  }
};

std::string requireString(const toml::table& t, std::string_view name, const Place& place) {
  const toml::node& n = place.require(t, name);
  if (!n.is_string()) throw InputError(place.key(n, name) + " must be a string");
  return n.as_string()->get();
}

int requireSize(const toml::table& t, std::string_view name, int most, const Place& place) {
  const toml::node& n = place.require(t, name);
  const auto* i = n.as_integer();
  if (!i || i->get() < 1 || i->get() > most)
    throw InputError(place.key(n, name) + " must be an integer from 1 to " + std::to_string(most));
  return int(i->get());
}

std::vector<double> requireNumbers(const toml::table& t, std::string_view name, size_t count, const Place& place) {
  const toml::node& n = place.require(t, name);
  const toml::array* a = n.as_array();
  if (!a) throw InputError(place.key(n, name) + " must be an array of numbers");
  if (a->size() != count)
    throw InputError(place.key(n, name) + " has " + std::to_string(a->size()) + " numbers, expected " + std::to_string(count));
  std::vector<double> out;
  out.reserve(count);
  for (const toml::node& v : *a) {
    const std::optional<double> x = tomlNumber(v);
    if (!x) throw InputError(place.key(v, name) + " must hold numbers only");
    if (!std::isfinite(*x)) throw InputError(place.key(v, name) + " holds a non-finite number");
    // The networks are float32; a weight that is not one was not converted from one.
    out.push_back(double(float(*x)));
  }
  return out;
}

}  // namespace

NeuralBrdf NeuralBrdf::load(const std::filesystem::path& path) {
  return parse(readInputFile(path, kMaxBytes, "Neural BRDF (.nbrdf)"), path.string());
}

NeuralBrdf NeuralBrdf::parse(std::string_view text, const std::string& source) {
  const toml::table root = parseToml(text, source);
  const Place top{source, ""};
  const std::string format = requireString(root, "format", top);
  if (format != kFormat)
    throw InputError(source + ": format '" + format + "' is not '" + std::string(kFormat) + "' (not a glossy Neural BRDF file)");
  if (const std::string input = requireString(root, "input", top); input != "half-difference")
    throw InputError(source + ": input '" + input + "': only 'half-difference' is known");
  if (const std::string output = requireString(root, "output", top); output != "expm1")
    throw InputError(source + ": output '" + output + "': only 'expm1' is known");

  NeuralBrdf n;
  n.source_ = source;
  n.material_ = requireString(root, "material", top);
  n.label_ = requireString(root, "label", top);
  const toml::node* layersNode = root.get("layer");
  const toml::array* layers = layersNode ? layersNode->as_array() : nullptr;
  if (!layers || !layers->is_array_of_tables() || layers->empty())
    throw InputError(source + ": needs its layers as [[layer]] tables");
  // The architecture first, from the layers' sizes alone: the chain and its cost are checked before any
  // weight is read.
  std::vector<const toml::table*> tables;
  size_t parameters = 0;
  int inputs = kInputs;
  for (size_t k = 0; k < layers->size(); ++k) {
    const toml::table& t = *(*layers)[k].as_table();
    const Place place{source, "layer " + std::to_string(k + 1)};
    const std::string where = tomlAt(source, t) + place.table;
    Layer layer;
    layer.inputs = requireSize(t, "inputs", kMaxWidth, place);
    layer.outputs = requireSize(t, "outputs", kMaxWidth, place);
    if (layer.inputs != inputs)
      throw InputError(where + ": takes " + std::to_string(layer.inputs) + " inputs, but " + std::to_string(inputs) +
                       " come to it");
    const std::string activation = requireString(t, "activation", place);
    if (activation != "relu" && activation != "linear")
      throw InputError(where + ": activation '" + activation + "': only 'relu' and 'linear' are known");
    layer.relu = activation == "relu";
    parameters += size_t(layer.inputs + 1) * size_t(layer.outputs);
    if (parameters > size_t(kMaxParameters))
      throw InputError(source + ": more than " + std::to_string(kMaxParameters) + " weights and biases by layer " +
                       std::to_string(k + 1) + " (a Neural BRDF is 6 -> 21 -> 21 -> 3, 675; a larger network would take " +
                       "hours to tabulate)");
    inputs = layer.outputs;
    tables.push_back(&t);
    n.layers_.push_back(std::move(layer));
  }
  if (inputs != kOutputs) throw InputError(source + ": the last layer has " + std::to_string(inputs) + " outputs, expected 3 (RGB)");
  if (n.layers_.back().relu) throw InputError(source + ": the last layer must be linear (its outputs go through exp(x) − 1)");

  for (size_t k = 0; k < tables.size(); ++k) {
    const toml::table& t = *tables[k];
    const Place place{source, "layer " + std::to_string(k + 1)};
    Layer& layer = n.layers_[k];
    // The file's rows are outputs; kept input-major, as evalAngles reads them.
    const std::vector<double> rows = requireNumbers(t, "weights", size_t(layer.inputs) * size_t(layer.outputs), place);
    layer.weights.resize(rows.size());
    for (int o = 0; o < layer.outputs; ++o)
      for (int i = 0; i < layer.inputs; ++i)
        layer.weights[size_t(i) * size_t(layer.outputs) + size_t(o)] = rows[size_t(o) * size_t(layer.inputs) + size_t(i)];
    layer.biases = requireNumbers(t, "biases", size_t(layer.outputs), place);
  }
  return n;
}

Rgb NeuralBrdf::evalAngles(double thetaH, double thetaD, double phiD) const {
  std::array<double, kMaxWidth> a, b;
  const double sd = std::sin(thetaD);
  a[0] = std::sin(thetaH);
  a[1] = 0.0;
  a[2] = std::cos(thetaH);
  a[3] = sd * std::cos(phiD);
  a[4] = sd * std::sin(phiD);
  a[5] = std::cos(thetaD);
  for (const Layer& layer : layers_) {
    // Each output sums its inputs in order, then the bias: the order tabulate()'s lanes keep too, so that
    // a tabulated value is the one evaluated here.
    const size_t outputs = size_t(layer.outputs);
    std::fill_n(b.begin(), outputs, 0.0);
    for (int i = 0; i < layer.inputs; ++i) {
      const double* w = &layer.weights[size_t(i) * outputs];
      const double x = a[size_t(i)];
      for (size_t o = 0; o < outputs; ++o) b[o] += w[o] * x;
    }
    for (size_t o = 0; o < outputs; ++o) {
      const double sum = b[o] + layer.biases[o];
      b[o] = layer.relu ? std::max(sum, 0.0) : sum;
    }
    std::swap(a, b);
  }
  return {std::expm1(a[0]), std::expm1(a[1]), std::expm1(a[2])};
}

namespace {

// tabulate() evaluates the network kLanes times side by side: every array below holds one value per lane,
// and each lane goes through evalAngles's arithmetic in its order (products summed input by input from 0,
// then the bias; no fused multiply-add anywhere in this file: materials/CMakeLists.txt), so a lane's result
// is the one evalAngles gives, whatever the lanes beside it and whichever kernel ran. 32 lanes keep 8 AVX2
// sums in flight, as the adds' latency needs; with fewer, each add waits for the one before.
constexpr int kLanes = 32;
using Lanes = std::array<double, kLanes>;

// A layer as the kernels read it: weights input-major, as NeuralBrdf keeps them.
struct LayerView {
  int inputs, outputs;
  bool relu;
  const double* weights;
  const double* biases;
};

// The forward pass of kLanes inputs x (6 rows) into y (3 rows, before exp(y) − 1); a and b are scratch
// of kMaxWidth rows. Inlined into each kernel below, so that each compiles it for its own ISA.
[[gnu::always_inline]] inline void forwardLanes(const LayerView* layers, int count, const Lanes* x, Lanes* a, Lanes* b,
                                                Lanes* y) {
  const Lanes* in = x;
  for (int k = 0; k < count; ++k) {
    const LayerView& layer = layers[k];
    Lanes* out = k + 1 == count ? y : (k % 2 ? b : a);
    for (int o = 0; o < layer.outputs; ++o) {
      Lanes sum{};
      for (int i = 0; i < layer.inputs; ++i) {
        const double w = layer.weights[size_t(i) * size_t(layer.outputs) + size_t(o)];
        for (int l = 0; l < kLanes; ++l) sum[l] += w * in[i][l];
      }
      for (int l = 0; l < kLanes; ++l) {
        const double s = sum[l] + layer.biases[o];
        out[o][l] = layer.relu ? std::max(s, 0.0) : s;
      }
    }
    in = out;
  }
}

using Forward = void (*)(const LayerView*, int, const Lanes*, Lanes*, Lanes*, Lanes*);
void forwardBaseline(const LayerView* layers, int count, const Lanes* x, Lanes* a, Lanes* b, Lanes* y) {
  forwardLanes(layers, count, x, a, b, y);
}
#if defined(__x86_64__)
// The same pass in AVX2's 4-lane registers, chosen at run time as lane_math's blocks are (the build is
// baseline x86-64).
__attribute__((target("avx2"))) void forwardAvx2(const LayerView* layers, int count, const Lanes* x, Lanes* a, Lanes* b,
                                                  Lanes* y) {
  forwardLanes(layers, count, x, a, b, y);
}
#endif

}  // namespace

MerlTable NeuralBrdf::tabulate() const {
  constexpr int nH = MerlTable::kThetaH, nD = MerlTable::kThetaD, nP = MerlTable::kPhiD;
  constexpr double degree = kPi / 180.0;
  // The inputs' sines and cosines, from the same arguments as evalAngles's calls: θ_h at the bins' lower
  // edges, θ_d = j°, φ_d = k° for k < 360 (k° + 180° for the second half of bin k); and at the bins' centres
  // for the horizon test.
  std::array<double, nH> sinH, cosH, sinCentreH, cosCentreH;
  for (int i = 0; i < nH; ++i) {
    const double edgeH = double(i) * i / (nH * nH) * (kPi / 2.0);
    const double centreH = (i + 0.5) * (i + 0.5) / (nH * nH) * (kPi / 2.0);
    sinH[i] = std::sin(edgeH), cosH[i] = std::cos(edgeH);
    sinCentreH[i] = std::sin(centreH), cosCentreH[i] = std::cos(centreH);
  }
  std::array<double, nD> sinD, cosD, sinCentreD, cosCentreD;
  for (int j = 0; j < nD; ++j) {
    sinD[j] = std::sin(j * degree), cosD[j] = std::cos(j * degree);
    sinCentreD[j] = std::sin((j + 0.5) * degree), cosCentreD[j] = std::cos((j + 0.5) * degree);
  }
  std::array<double, 2 * nP> sinP, cosP;
  std::array<double, nP> cosCentreP;
  for (int k = 0; k < 2 * nP; ++k) sinP[k] = std::sin(k * degree), cosP[k] = std::cos(k * degree);
  for (int k = 0; k < nP; ++k) cosCentreP[k] = std::cos((k + 0.5) * degree);

  std::vector<LayerView> layers;
  for (const Layer& l : layers_) layers.push_back({l.inputs, l.outputs, l.relu, l.weights.data(), l.biases.data()});
  Forward forward = forwardBaseline;
#if defined(__x86_64__)
  if (lanes::isa() == lanes::Isa::Avx2) forward = forwardAvx2;
#endif

  std::vector<double> values(3 * MerlTable::kBins);
  tbb::parallel_for(tbb::blocked_range<int>(0, nH), [&](const tbb::blocked_range<int>& rows) {
    std::vector<Lanes> scratch(2 * kMaxWidth);
    Lanes x[kInputs] = {}, y[kOutputs];
    // A batch holds kLanes / 2 measured bins of a row, bin m in lanes 2m (φ_d = k°) and 2m + 1 (k° + 180°).
    size_t bins[kLanes / 2];
    int inBatch = 0;
    const auto finish = [&] {
      forward(layers.data(), int(layers.size()), x, scratch.data(), scratch.data() + kMaxWidth, y);
      for (int m = 0; m < inBatch; ++m)
        for (int c = 0; c < 3; ++c) {
          const double rho = std::max(0.5 * (std::expm1(y[c][2 * m]) + std::expm1(y[c][2 * m + 1])), 0.0);
          values[size_t(c) * MerlTable::kBins + bins[m]] = double(float(rho / MerlTable::kScale[c]));
        }
      inBatch = 0;
    };
    for (int i = rows.begin(); i < rows.end(); ++i) {
      for (int j = 0; j < nD; ++j)
        for (int k = 0; k < nP; ++k) {
          const size_t bin = MerlBin{i, j, k}.index();
          // Unmeasured where the bin's centre sees a direction below the horizon: L is D turned by θ_h about
          // y, and V its mirror about H, so cos θ_{L,V} = cos θ_h cos θ_d ∓ sin θ_h sin θ_d cos φ_d.
          const double along = cosCentreH[i] * cosCentreD[j], across = sinCentreH[i] * sinCentreD[j] * cosCentreP[k];
          if (std::min(along - across, along + across) < -0.01) {
            for (int c = 0; c < 3; ++c) values[size_t(c) * MerlTable::kBins + bin] = -1.0;
            continue;
          }
          for (int side = 0; side < 2; ++side) {
            const int l = 2 * inBatch + side, p = k + side * nP;
            x[0][l] = sinH[i], x[1][l] = 0.0, x[2][l] = cosH[i];
            x[3][l] = sinD[j] * cosP[p], x[4][l] = sinD[j] * sinP[p], x[5][l] = cosD[j];
          }
          bins[inBatch++] = bin;
          if (inBatch == kLanes / 2) finish();
        }
    }
    if (inBatch > 0) finish();  // the lanes past inBatch hold earlier bins' inputs: computed, not stored
  });
  return MerlTable::fromValues(values, source_);
}

}  // namespace glossy
