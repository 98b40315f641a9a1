// The environment light: loading lat-long maps, the constant and default skies, and importance sampling
// of the bilinearly interpolated map: a cell (bilinear patch) by its share of the light, then a point in it
// by the bilinear function of its corners (bilinear_patch.h), so that a sample's L/pdf barely varies.
#include "renderer/lights/environment.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/sampling/bilinear_patch.h"
#include "materials/sampling/blocked_distribution.h"
#include "renderer/lights/default_sky.h"
#include "renderer/lights/exr_preflight.h"
#include "renderer/lights/latlong.h"
#include "renderer/util/memory.h"

#include <OpenImageIO/imageio.h>

#include <limits>
#include <sstream>

namespace glossy {

namespace {

constexpr double kInv4Pi = 0.25 * kInvPi;

// OpenImageIO's messages may span lines; InputError's must not.
std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text.empty() ? "unknown error" : text;
}

std::string formatNumber(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

std::string withRotation(std::string description, double rotateDegrees) {
  if (rotateDegrees != 0.0) description += " rotated " + formatNumber(rotateDegrees) + "°";
  return description;
}

void checkRotation(double rotateDegrees) {
  if (!std::isfinite(rotateDegrees))
    throw InputError("environment rotation " + formatNumber(rotateDegrees) + " is not a finite angle");
}

// Peak bytes per texel while a map is loaded and its sampling tables built (bench/environment_memory
// measures 18.1 for a 16k map), with room to spare.
constexpr double kEnvironmentBytesPerTexel = 20.0;

LatLongImage readLatLong(const std::filesystem::path& path) {
  const std::string name = path.string();
  auto fail = [&](const std::string& problem) { return InputError(name + ": " + oneLine(problem)); };

  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw fail("environment map not found");
  // OpenImageIO would read a device such as /dev/zero for ever.
  if (!std::filesystem::is_regular_file(path, ec)) throw fail("is not a regular file (a folder, device or FIFO)");
  preflightExr(path);
  // The reader of the file's extension alone, made by its format's name: ImageInput::open, and create with
  // the file's name, hand a file that reader refuses to every other format OpenImageIO has (video and
  // camera-raw decoders among them), each a parser of hostile bytes and some slow to give up.
  const std::string extension = path.extension().string();
  if (extension.size() < 2) throw fail("environment map has no extension (.hdr, .exr, ...) to choose its reader by");
  auto input = OIIO::ImageInput::create(extension.substr(1));
  if (!input) throw fail("cannot read environment map (" + OIIO::geterror() + ")");
  if (OIIO::ImageSpec opened; !input->open(name, opened))
    throw fail("cannot read environment map (" + input->geterror() + ")");
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width <= 0 || spec.height <= 0) throw fail("environment map has no pixels");
  if (spec.depth > 1) throw fail("environment map is a volume, not a lat-long image");
  if (spec.nchannels < 3)
    throw fail("environment map has " + std::to_string(spec.nchannels) + " channel(s), needs RGB or RGBA");
  // A header may claim any size; what it asks for is checked before the texels are allocated: against the
  // memory here, then against glossy's limits, which hold on any machine.
  const double bytes = double(spec.width) * double(std::max(spec.height, 2)) * kEnvironmentBytesPerTexel;
  if (const double have = physicalMemoryBytes(); have > 0.0 && bytes > have)
    throw fail(formatted("environment map is %dx%d: about %.3g GB to sample, more than the %.3g GB of memory here",
                         spec.width, spec.height, bytes / 1e9, have / 1e9));
  if (spec.width > Environment::kMaxSide || spec.height > Environment::kMaxSide ||
      std::int64_t(spec.width) * std::max(spec.height, 2) > Environment::kMaxTexels)
    throw fail(formatted("environment map is %dx%d texels; glossy loads at most %d on a side and %lld in all",
                         spec.width, spec.height, Environment::kMaxSide, (long long)Environment::kMaxTexels));

  // Rows are interpolated pole to pole, so a single row stands for both poles (copied below).
  LatLongImage image(spec.width, std::max(spec.height, 2));
  // Channels 0–2 only, converted to float by OpenImageIO straight into the texels' RGB (the stride skips
  // the spare float): alpha and any extra layers are not radiance.
  if (!input->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, image.texels.data(), LatLongImage::kStride * sizeof(float)))
    throw fail("cannot read environment map pixels (" + input->geterror() + ")");
  input->close();
  if (spec.height == 1) std::copy_n(image.at(0, 0), std::size_t(spec.width) * LatLongImage::kStride, image.at(0, 1));

  for (int row = 0; row < image.height; ++row)
    for (int column = 0; column < image.width; ++column)
      for (int c = 0; c < 3; ++c) {
        const float value = image.at(column, row)[c];
        if (!std::isfinite(value) || value < 0.0f)
          throw fail("texel (" + std::to_string(column) + ", " + std::to_string(row) + ") is " +
                     (std::isfinite(value) ? "negative" : "not finite") + "; radiance must be finite and ≥ 0");
      }
  return image;
}

// The sample's lookup position: the sampled point's cell is the patch of the lookup, where
// x = u_map·W − ½ = s·W and y = v·(H − 1).
LatLongPosition cellPosition(const BlockedDistribution2D::Sample& cell, int width, int height) {
  const int column = int(cell.column), row = int(cell.row);
  return {column, column + 1 == width ? 0 : column + 1, row, cell.point.x * width - double(column),
          cell.point.y * (height - 1) - double(row)};
}

}  // namespace

struct Environment::Impl {
  std::string description;
  bool isConstant = false;
  Rgb constantRadiance{0.0};
  double meanLuminance = 0.0;

  LatLongMap map;
  // Rotation about +Y by α shifts every feature's u by −α/(2π) (φ ↦ φ − α for a right-handed turn):
  // the map is looked up at u_world + uOffset.
  double uOffset = 0.0;
  // The sampling density over (s, v), s = u_map − ½/W, is proportional to the bilinear interpolation of
  // the texels' luminance × sin θ of their row: nearly the light the lookup finds there (whose luminance
  // is the bilinear one, times the lat-long Jacobian's sin θ), and a function the patch warp can invert.
  // rowSin[j] is row j's sin θ, except that the poles' rows, where it is 0, take that of a quarter row
  // in: light at a pole keeps a positive density.
  std::vector<double> rowSin;
  // The cells: the bilinear patches between adjacent texel centres, W × (H − 1) of them, each weighted by
  // the mean of its corners' weights (the integral of the patch's function). Cell (i, j) is patch (i, j)
  // of the map. Blocked (blocked_distribution.h): a tenth of the memory of full CDFs, and a sample reads
  // one cache line of it per level, the top ones cached.
  BlockedDistribution2D distribution;

  // Directions to cells and back (the rotation included).
  LatLongGrid grid;

  // A cell's density on the (s, v) square as a density over solid angle at sin θ: the lat-long map's
  // Jacobian is dω = 2π² sin θ ds dv.
  static double solidAngleDensity(double cellValue, double sinTheta) { return cellValue / (2.0 * kPi * kPi * sinTheta); }

  // The weights of the corners of the cell a lookup falls in.
  BilinearPatch patchAt(const LatLongPosition& at) const {
    double l[4];
    map.cornerLuminances(at, l);
    const double top = rowSin[std::size_t(at.r0)], bottom = rowSin[std::size_t(at.r0) + 1];
    return {l[0] * top, l[1] * top, l[2] * bottom, l[3] * bottom};
  }

  // The density on the (s, v) square at the lookup position `at`: its cell's, as the map keeps it (in
  // float, beside the cell's texel), times the patch warp's density at the position's weights.
  double densityAt(const LatLongPosition& at, const BilinearPatch& patch) const {
    return map.cellValue(at) * patch.density({at.fx, at.fy});
  }

  // The solid-angle density of sample() at dir, whose lookup position is at.
  double pdfAt(const Vec3& dir, const LatLongPosition& at) const {
    const double sinTheta = std::sqrt(dir.x * dir.x + dir.z * dir.z);
    if (!(sinTheta > 0.0)) return 0.0;
    return solidAngleDensity(densityAt(at, patchAt(at)), sinTheta);
  }

  // The sample of the map in direction dir (with its sin θ), at the lookup position `at` the warp chose,
  // where the density on the square is `density`.
  Sample sampleAt(const LatLongPosition& at, double density, const Vec3& dir, double sinTheta) const {
    // At a pole the lat-long Jacobian vanishes and the solid-angle density is unbounded: no usable sample.
    if (density <= 0.0 || sinTheta <= 0.0) return {};
    return {dir, map.interpolate(at), solidAngleDensity(density, sinTheta)};
  }

  // The map takes the image's texels; the distribution is built a row of cells at a time from them, and
  // its densities go into the map's cell values: nothing the size of the map is made besides the texels
  // (16 bytes each) and the distribution's blocks (about 2).
  void buildDistribution(LatLongImage image) {
    const int width = image.width, cells = image.height - 1;
    map = LatLongMap(std::move(image));

    rowSin.resize(std::size_t(cells) + 1);
    for (int row = 0; row <= cells; ++row)
      rowSin[std::size_t(row)] = std::sin(kPi * std::clamp(double(row), 0.25, cells - 0.25) / cells);

    // A row of texels' luminance; a cell row reads two.
    std::vector<double> top(static_cast<std::size_t>(width)), bottom(static_cast<std::size_t>(width));
    const auto luminances = [&](int row, std::vector<double>& out) {
      for (int column = 0; column < width; ++column) out[std::size_t(column)] = luminance(map.texel(column, row));
    };
    double radiance = 0.0;  // Σ over the cells of mean luminance × mean sin θ
    distribution = BlockedDistribution2D(std::size_t(width), std::size_t(cells), [&](std::size_t y, std::span<double> weights) {
      const int cell = int(y);
      luminances(cell, top);
      luminances(cell + 1, bottom);
      // Mean of sin θ over the cell's latitude band: the Jacobian of (u, v) ↦ direction, up to 2π².
      const double v0 = double(cell) / cells, v1 = double(cell + 1) / cells;
      const double meanSinTheta = (std::cos(kPi * v0) - std::cos(kPi * v1)) / (kPi * (v1 - v0));
      const double sinTop = rowSin[std::size_t(cell)], sinBottom = rowSin[std::size_t(cell) + 1];
      for (int column = 0; column < width; ++column) {
        const std::size_t c = std::size_t(column), next = column + 1 == width ? 0 : c + 1;
        // The patch's integral is its corners' mean; it is zero only where the whole patch is black, so
        // every direction with radiance keeps a non-zero pdf (needed by MIS).
        const BilinearPatch patch{top[c] * sinTop, top[next] * sinTop, bottom[c] * sinBottom, bottom[next] * sinBottom};
        weights[c] = patch.mean();
        radiance += 0.25 * (top[c] + top[next] + bottom[c] + bottom[next]) * meanSinTheta;
      }
    });
    // Σ mean luminance × mean sin θ × (the cells' area, 2π²/(W·cells)), over 4π.
    meanLuminance = radiance * kPi / (2.0 * width * cells);
    for (int cell = 0; cell < cells; ++cell)
      for (int column = 0; column < width; ++column) {
        const double d = distribution.cellDensity(std::size_t(column), std::size_t(cell));
        float f = float(d);
        // A cell that can be drawn keeps a positive pdf, however faint (MIS divides by it).
        if (d > 0.0 && f == 0.0f) f = std::numeric_limits<float>::denorm_min();
        map.setCellValue(column, cell, f);
      }
  }

  static std::unique_ptr<Impl> fromMap(LatLongImage image, double rotateDegrees, std::string description) {
    auto impl = std::make_unique<Impl>();
    impl->description = withRotation(std::move(description), rotateDegrees);
    impl->uOffset = wrapUnit(rotateDegrees / 360.0);
    const int width = image.width, height = image.height;
    impl->buildDistribution(std::move(image));
    impl->grid = LatLongGrid(width, height, impl->uOffset);
    return impl;
  }
};

Environment::Environment(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Environment::Environment(Environment&&) noexcept = default;
Environment& Environment::operator=(Environment&&) noexcept = default;
Environment::~Environment() = default;

Environment Environment::load(const std::filesystem::path& path, double rotateDegrees) {
  checkRotation(rotateDegrees);
  return Environment(Impl::fromMap(readLatLong(path), rotateDegrees, path.filename().string()));
}

Environment Environment::constant(const Rgb& radiance) {
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(radiance[c]) || radiance[c] < 0.0)
      throw InputError("constant environment radiance " + formatNumber(radiance.r) + "," +
                       formatNumber(radiance.g) + "," + formatNumber(radiance.b) + " must be finite and ≥ 0");
  auto impl = std::make_unique<Impl>();
  impl->isConstant = true;
  impl->constantRadiance = radiance;
  impl->meanLuminance = luminance(radiance);
  impl->description = "constant " + formatNumber(radiance.r) + "," + formatNumber(radiance.g) + "," +
                      formatNumber(radiance.b);
  return Environment(std::move(impl));
}

Environment Environment::makeDefault(double rotateDegrees) {
  checkRotation(rotateDegrees);
  return Environment(Impl::fromMap(makeDefaultSky(), rotateDegrees, "default sky"));
}

Rgb Environment::radiance(const Vec3& dir) const {
  if (impl_->isConstant) return impl_->constantRadiance;
  return impl_->map.interpolate(impl_->grid.position(dir));
}

Environment::Sample Environment::sample(Vec2 u) const {
  const Impl& env = *impl_;
  if (env.isConstant) {
    // Uniform over the sphere: no direction is more important than another.
    const double cosTheta = 1.0 - 2.0 * std::clamp(u.x, 0.0, 1.0);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * kPi * u.y;
    return {Vec3(sinTheta * std::cos(phi), cosTheta, sinTheta * std::sin(phi)), env.constantRadiance, kInv4Pi};
  }

  const bool want = true;
  Sample out;
  sample(&want, &u, &out, 1);
  return out;
}

static_assert(Environment::kMaxBatch <= BlockedDistribution2D::kMaxBatch, "a batch of samples is one distribution batch");

void Environment::sample(const bool* want, const Vec2* u, Sample* out, int n) const {
  const Impl& env = *impl_;
  if (env.isConstant) {
    for (int i = 0; i < n; ++i)
      if (want[i]) out[i] = sample(u[i]);
    return;
  }
  BlockedDistribution2D::Sample cells[kMaxBatch];
  env.distribution.sample(want, u, cells, n);  // the map holds the densities
  // The wanted lanes, packed.
  int lane[kMaxBatch] = {}, count = 0;
  LatLongPosition at[kMaxBatch];
  for (int i = 0; i < n; ++i) {
    if (!want[i]) continue;
    at[count] = cellPosition(cells[i], env.map.width(), env.map.height());
    lane[count++] = i;
  }
  env.map.prefetch(at, count);
  // The point's place in its cell, uniform so far, drawn again by the cell's bilinear function: step by
  // step for all lanes, so that the lanes' square roots and divisions overlap, where a lane at a time
  // would wait on each in turn.
  BilinearPatch patch[kMaxBatch];
  double density[kMaxBatch];
  for (int k = 0; k < count; ++k) patch[k] = env.patchAt(at[k]);
  for (int k = 0; k < count; ++k) at[k].fy = patch[k].sampleY(at[k].fy);
  for (int k = 0; k < count; ++k) at[k].fx = patch[k].sampleX(at[k].fx, at[k].fy);
  for (int k = 0; k < count; ++k) density[k] = env.densityAt(at[k], patch[k]);
  Vec3 dirs[kMaxBatch];
  double sinTheta[kMaxBatch];
  env.grid.directions(at, dirs, sinTheta, count);
  for (int k = 0; k < count; ++k) out[lane[k]] = env.sampleAt(at[k], density[k], dirs[k], sinTheta[k]);
}

void Environment::radianceAndPdf(const bool* want, const Vec3* dirs, Rgb* radiance, double* pdf, int n) const {
  const Impl& env = *impl_;
  if (env.isConstant) {
    for (int i = 0; i < n; ++i)
      if (want[i]) radiance[i] = radianceAndPdf(dirs[i], pdf[i]);
    return;
  }
  int lane[kMaxBatch] = {}, count = 0;
  for (int i = 0; i < n; ++i)
    if (want[i]) lane[count++] = i;
  LatLongPosition at[kMaxBatch];
  env.grid.positions(dirs, lane, count, at);
  env.map.prefetch(at, count);
  for (int k = 0; k < count; ++k) {
    const int i = lane[k];
    pdf[i] = env.pdfAt(dirs[i], at[k]);
    radiance[i] = env.map.interpolate(at[k]);
  }
}

double Environment::pdf(const Vec3& dir) const {
  const Impl& env = *impl_;
  if (env.isConstant) return kInv4Pi;
  return env.pdfAt(dir, env.grid.position(dir));
}

Rgb Environment::radianceAndPdf(const Vec3& dir, double& pdf) const {
  const Impl& env = *impl_;
  if (env.isConstant) {
    pdf = kInv4Pi;
    return env.constantRadiance;
  }
  const LatLongPosition at = env.grid.position(dir);
  pdf = env.pdfAt(dir, at);
  return env.map.interpolate(at);
}

double Environment::meanLuminance() const { return impl_->meanLuminance; }

const std::string& Environment::description() const { return impl_->description; }

}  // namespace glossy
