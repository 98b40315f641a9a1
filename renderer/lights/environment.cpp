// The environment light: loading lat-long maps, the constant and default skies, and importance sampling
// of the bilinearly interpolated map toward a receiving surface: a cell of the map by its light and the
// surface's horizon (cosine_bins.h), a patch in it by its share of the cell's light (nested_grid.h), then a
// point in the patch by the bilinear function of its corners (bilinear_patch.h), so that a sample's L/pdf
// barely varies.
#include "renderer/lights/environment.h"

#include "materials/core/frame.h"
#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "materials/core/text.h"
#include "materials/models/warp.h"
#include "materials/sampling/unit_interval.h"
#include "renderer/image/exr_preflight.h"
#include "renderer/lights/bilinear_patch.h"
#include "renderer/lights/cosine_bins.h"
#include "renderer/lights/default_sky.h"
#include "renderer/lights/latlong.h"
#include "renderer/lights/nested_grid.h"
#include "renderer/util/memory.h"

#include <OpenImageIO/imageio.h>

#include <glm/geometric.hpp>

#include <limits>

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

std::string withRotation(std::string description, double rotateDegrees) {
  if (rotateDegrees != 0.0) description += " rotated " + formatted("%g", rotateDegrees) + "°";
  return description;
}

void checkRotation(double rotateDegrees) {
  if (!std::isfinite(rotateDegrees))
    throw InputError("environment rotation " + formatted("%g", rotateDegrees) + " is not a finite angle");
}

// Peak bytes per texel while a map is loaded and its sampling tables built (bench/environment_memory
// measures 18.1 for a 16k map), with room to spare.
constexpr double kEnvironmentBytesPerTexel = 20.0;

void flipRows(LatLongImage& image) {
  for (int top = 0, bottom = image.height - 1; top < bottom; ++top, --bottom)
    std::swap_ranges(image.at(0, top), image.at(0, top) + std::size_t(image.width) * LatLongImage::kStride, image.at(0, bottom));
}

void flipColumns(LatLongImage& image) {
  for (int row = 0; row < image.height; ++row)
    for (int left = 0, right = image.width - 1; left < right; ++left, --right)
      std::swap_ranges(image.at(left, row), image.at(left, row) + LatLongImage::kStride, image.at(right, row));
}

LatLongImage readLatLong(const std::filesystem::path& path) {
  const std::string name = path.string();
  auto fail = [&](const std::string& problem) { return InputError(name + ": " + oneLine(problem)); };

  // OpenImageIO would read a device such as /dev/zero for ever, and wait on a FIFO for a writer.
  requireInputFile(path, "environment map");
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

  // Orientations 5–8 transpose the image (Exif's convention, which OpenImageIO follows): a lat-long map
  // stored on its side is no map glossy can read as one.
  const int orientation = spec.get_int_attribute("Orientation", 1);
  if (orientation < 1 || orientation > 4)
    throw fail("environment map's orientation " + std::to_string(orientation) +
               " transposes it (only orientations 1–4, the image flipped or not, are lat-long maps)");

  // Rows are interpolated pole to pole, so a single row stands for both poles (copied below).
  LatLongImage image(spec.width, std::max(spec.height, 2));
  // Channels 0–2 only, converted to float by OpenImageIO straight into the texels' RGB (the stride skips
  // the spare float): alpha and any extra layers are not radiance.
  if (!input->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, image.texels.data(), LatLongImage::kStride * sizeof(float)))
    throw fail("cannot read environment map pixels (" + input->geterror() + ")");
  input->close();
  // A file may store its rows or columns in another order and say so (a Radiance .hdr whose resolution line
  // reads "+Y H +X W" lists its rows bottom to top; OpenImageIO reports that as Orientation 4 and hands the
  // rows over as stored). The map's row 0 must be its top (+Y), as the file shows it.
  // (A single row is its own flip; the second row is its copy, made below.)
  if (orientation == 2 || orientation == 3) flipColumns(image);
  if ((orientation == 3 || orientation == 4) && spec.height > 1) flipRows(image);
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
  // The sampling density over (s, v), s = u_map − ½/W, is proportional, within each cell of the map, to
  // the bilinear interpolation of the texels' luminance × sin θ of their row: nearly the light the lookup
  // finds there (whose luminance is the bilinear one, times the lat-long Jacobian's sin θ), and a function
  // the patch warp can invert. rowSin[j] is row j's sin θ, except that the poles' rows, where it is 0, take
  // that of a quarter row in: light at a pole keeps a positive density.
  std::vector<double> rowSin;
  // The patches: the bilinear patches between adjacent texel centres, W × (H − 1) of them, each weighted
  // by the mean of its corners' weights (the integral of the patch's function); patch (i, j) is the map's
  // cell (i, j). Grouped into up to 64 × 32 cells, of which the bins choose one for the receiving normal.
  static constexpr std::size_t kCellColumns = 64, kCellRows = 32;
  NestedGrid patches;
  CosineBins bins;

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

  // The density on the (s, v) square at the lookup position `at`, for normal bin `bin`: the patch's
  // within its cell, as the map keeps it (in float, beside the patch's texel), times the bin's probability
  // of the cell and the patch warp's density at the position's weights.
  double densityAt(int bin, const LatLongPosition& at, const BilinearPatch& patch) const {
    const double cell = bins.probability(bin, patches.cellOfColumn(std::size_t(at.c0)), patches.cellOfRow(std::size_t(at.r0)));
    return map.cellValue(at) * cell * patch.density({at.fx, at.fy});
  }

  // The solid-angle density of sample(normal, ·) at dir, whose lookup position is at.
  double pdfAt(int bin, const Vec3& dir, const LatLongPosition& at) const {
    const double sinTheta = std::sqrt(dir.x * dir.x + dir.z * dir.z);
    if (!(sinTheta > 0.0)) return 0.0;
    return solidAngleDensity(densityAt(bin, at, patchAt(at)), sinTheta);
  }

  // The sample of the map in direction dir (with its sin θ), at the lookup position `at` the warp chose,
  // where the density on the square is `density`.
  Sample sampleAt(const LatLongPosition& at, double density, const Vec3& dir, double sinTheta) const {
    // At a pole the lat-long Jacobian vanishes and the solid-angle density is unbounded: no usable sample.
    if (density <= 0.0 || sinTheta <= 0.0) return {};
    return {dir, map.interpolate(at), solidAngleDensity(density, sinTheta)};
  }

  // The map takes the image's texels; the patches' distribution is built a row at a time from them, and
  // its densities go into the map's cell values: nothing the size of the map is made besides the texels
  // (16 bytes each) and the patches' CDFs (2).
  void buildDistribution(LatLongImage image) {
    const int width = image.width, rows = image.height - 1;
    map = LatLongMap(std::move(image));

    rowSin.resize(std::size_t(rows) + 1);
    for (int row = 0; row <= rows; ++row)
      rowSin[std::size_t(row)] = std::sin(kPi * std::clamp(double(row), 0.25, rows - 0.25) / rows);

    // A row of texels' luminance; a row of patches reads two.
    std::vector<double> top(static_cast<std::size_t>(width)), bottom(static_cast<std::size_t>(width));
    const auto luminances = [&](int row, std::vector<double>& out) {
      for (int column = 0; column < width; ++column) out[std::size_t(column)] = luminance(map.texel(column, row));
    };
    double radiance = 0.0;  // Σ over the patches of mean luminance × mean sin θ
    const std::size_t cellColumns = std::min<std::size_t>(kCellColumns, std::size_t(width));
    const std::size_t cellRows = std::min<std::size_t>(kCellRows, std::size_t(rows));
    patches = NestedGrid(std::size_t(width), std::size_t(rows), cellColumns, cellRows, [&](std::size_t y, std::span<double> weights) {
      const int row = int(y);
      luminances(row, top);
      luminances(row + 1, bottom);
      // Mean of sin θ over the row's latitude band: the Jacobian of (u, v) ↦ direction, up to 2π².
      const double v0 = double(row) / rows, v1 = double(row + 1) / rows;
      const double meanSinTheta = (std::cos(kPi * v0) - std::cos(kPi * v1)) / (kPi * (v1 - v0));
      const double sinTop = rowSin[std::size_t(row)], sinBottom = rowSin[std::size_t(row) + 1];
      for (int column = 0; column < width; ++column) {
        const std::size_t c = std::size_t(column), next = column + 1 == width ? 0 : c + 1;
        // The patch's integral is its corners' mean; it is zero only where the whole patch is black, so
        // every direction with radiance keeps a non-zero pdf (needed by MIS).
        const BilinearPatch patch{top[c] * sinTop, top[next] * sinTop, bottom[c] * sinBottom, bottom[next] * sinBottom};
        weights[c] = patch.mean();
        radiance += 0.25 * (top[c] + top[next] + bottom[c] + bottom[next]) * meanSinTheta;
      }
    });
    // Σ mean luminance × mean sin θ × (the patches' area, 2π²/(W·rows)), over 4π.
    meanLuminance = radiance * kPi / (2.0 * width * rows);
    const double patchesPerSquare = double(width) * double(rows);
    for (int row = 0; row < rows; ++row)
      for (int column = 0; column < width; ++column) {
        const double d = patches.probabilityInCell(std::size_t(column), std::size_t(row)) * patchesPerSquare;
        float f = float(d);
        // A patch that can be drawn keeps a positive pdf, however faint (MIS divides by it).
        if (d > 0.0 && f == 0.0f) f = std::numeric_limits<float>::denorm_min();
        map.setCellValue(column, row, f);
      }
  }

  // The bins over the cells, once the grid (and so the cells' directions) is known.
  void buildBins() {
    const std::size_t columns = patches.cellColumns(), rows = patches.cellRows();
    std::vector<double> light(columns * rows);
    std::vector<CosineBins::Cone> cones(columns * rows);
    for (std::size_t cr = 0; cr < rows; ++cr)
      for (std::size_t cc = 0; cc < columns; ++cc) {
        light[cr * columns + cc] = patches.cellWeight(cc, cr);
        cones[cr * columns + cc] = cellCone(cc, cr);
      }
    bins = CosineBins(columns, rows, light, cones);
  }

  // The directions of cell (cc, cr): its patches span x from columnStart(cc) to columnStart(cc + 1) and
  // y likewise, in the lookup's coordinates. Its sides are meridians and parallels, so the farthest of its
  // points from its centre is a corner.
  CosineBins::Cone cellCone(std::size_t cc, std::size_t cr) const {
    const auto direction = [&](double x, double y) {
      // A point at x = W lies at the last column's far edge, one at y = rows at the last row's.
      const int column = std::min(int(x), int(patches.width()) - 1), row = std::min(int(y), int(patches.height()) - 1);
      double sinTheta;
      return grid.direction(column, row, x - column, y - row, sinTheta);
    };
    const double x0 = double(patches.columnStart(cc)), x1 = double(patches.columnStart(cc + 1));
    const double y0 = double(patches.rowStart(cr)), y1 = double(patches.rowStart(cr + 1));
    const Vec3 axis = glm::normalize(direction(0.5 * (x0 + x1), 0.5 * (y0 + y1)));
    double radius = 0.0;
    for (const double x : {x0, x1})
      for (const double y : {y0, y1})
        radius = std::max(radius, std::acos(std::clamp(glm::dot(axis, direction(x, y)), -1.0, 1.0)));
    return {axis, radius};
  }

  static std::unique_ptr<Impl> fromMap(LatLongImage image, double rotateDegrees, std::string description) {
    auto impl = std::make_unique<Impl>();
    impl->description = withRotation(std::move(description), rotateDegrees);
    impl->uOffset = wrapUnit(rotateDegrees / 360.0);
    const int width = image.width, height = image.height;
    impl->buildDistribution(std::move(image));
    impl->grid = LatLongGrid(width, height, impl->uOffset);
    impl->buildBins();
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
  const std::string values = formatted("%g,%g,%g", radiance.r, radiance.g, radiance.b);
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(radiance[c]) || radiance[c] < 0.0)
      throw InputError("constant environment radiance " + values + " must be finite and ≥ 0");
  auto impl = std::make_unique<Impl>();
  impl->isConstant = true;
  impl->constantRadiance = radiance;
  impl->meanLuminance = luminance(radiance);
  impl->description = "constant " + values;
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

Environment::Sample Environment::sample(const Vec3& normal, Vec2 u) const {
  const bool want = true;
  Sample out;
  sample(&want, &normal, &u, &out, 1);
  return out;
}

namespace {

// The constant environment toward a normal: cosine-weighted about it, the light's own L cos θ; with no
// normal (zero), uniform over the sphere, as no direction is more important than another.
Environment::Sample constantSample(const Rgb& radiance, const Vec3& normal, Vec2 u) {
  const double r = std::sqrt(clampUnit(u.x)), phi = 2.0 * kPi * u.y;
  if (CosineBins::bin(normal) != CosineBins::kUnweighted) {
    const Frame frame(glm::normalize(normal));
    const Vec3 local = diskToCosineHemisphere({r * std::cos(phi), r * std::sin(phi)});
    if (!(local.z > 0.0)) return {frame.n, radiance, 0.0};
    const Vec3 dir = frame.toWorld(local);
    // The density as pdf() computes it from the direction, so that the two agree to the bit.
    return {dir, radiance, std::max(0.0, glm::dot(frame.n, dir)) * kInvPi};
  }
  const double cosTheta = 1.0 - 2.0 * std::clamp(u.x, 0.0, 1.0);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return {Vec3(sinTheta * std::cos(phi), cosTheta, sinTheta * std::sin(phi)), radiance, kInv4Pi};
}

double constantPdf(const Vec3& normal, const Vec3& dir) {
  if (CosineBins::bin(normal) == CosineBins::kUnweighted) return kInv4Pi;
  return std::max(0.0, glm::dot(glm::normalize(normal), dir)) * kInvPi;
}

}  // namespace

void Environment::sample(const bool* want, const Vec3* normals, const Vec2* u, Sample* out, int n) const {
  const Impl& env = *impl_;
  if (env.isConstant) {
    for (int i = 0; i < n; ++i)
      if (want[i]) out[i] = constantSample(env.constantRadiance, normals[i], u[i]);
    return;
  }
  // The wanted lanes, packed: each lane's cell for its normal, then its patch in the cell, a row and a
  // column, each step's table lines fetched for all lanes before any lane reads them.
  int lane[kMaxBatch] = {}, bin[kMaxBatch] = {}, count = 0;
  CosineBins::Cell cell[kMaxBatch];
  std::size_t row[kMaxBatch];
  Vec2 v[kMaxBatch];
  for (int i = 0; i < n; ++i) {
    if (!want[i]) continue;
    bin[count] = CosineBins::bin(normals[i]);
    v[count] = u[i];
    cell[count] = env.bins.sample(bin[count], v[count]);
    env.patches.prefetchRows(cell[count].column, cell[count].row);
    lane[count++] = i;
  }
  for (int k = 0; k < count; ++k) {
    row[k] = env.patches.sampleRow(cell[k].column, cell[k].row, v[k].x);
    env.patches.prefetchColumns(cell[k].column, row[k]);
  }
  LatLongPosition at[kMaxBatch];
  const int width = env.map.width();
  for (int k = 0; k < count; ++k) {
    const int column = int(env.patches.sampleColumn(cell[k].column, row[k], v[k].y));
    // What is left of u.x, which chose the row, places the point down the patch; of u.y, across it.
    at[k] = {column, column + 1 == width ? 0 : column + 1, int(row[k]), v[k].y, v[k].x};
  }
  env.map.prefetch(at, count);
  // The point's place in its patch, uniform so far, drawn again by the patch's bilinear function: step by
  // step for all lanes, so that the lanes' square roots and divisions overlap, where a lane at a time
  // would wait on each in turn.
  BilinearPatch patch[kMaxBatch];
  double density[kMaxBatch];
  for (int k = 0; k < count; ++k) patch[k] = env.patchAt(at[k]);
  for (int k = 0; k < count; ++k) at[k].fy = patch[k].sampleY(at[k].fy);
  for (int k = 0; k < count; ++k) at[k].fx = patch[k].sampleX(at[k].fx, at[k].fy);
  for (int k = 0; k < count; ++k) density[k] = env.densityAt(bin[k], at[k], patch[k]);
  Vec3 dirs[kMaxBatch];
  double sinTheta[kMaxBatch];
  env.grid.directions(at, dirs, sinTheta, count);
  for (int k = 0; k < count; ++k) out[lane[k]] = env.sampleAt(at[k], density[k], dirs[k], sinTheta[k]);
}

void Environment::radianceAndPdf(const bool* want, const Vec3* normals, const Vec3* dirs, Rgb* radiance, double* pdf,
                                 int n) const {
  const Impl& env = *impl_;
  if (env.isConstant) {
    for (int i = 0; i < n; ++i)
      if (want[i]) radiance[i] = radianceAndPdf(normals[i], dirs[i], pdf[i]);
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
    pdf[i] = env.pdfAt(CosineBins::bin(normals[i]), dirs[i], at[k]);
    radiance[i] = env.map.interpolate(at[k]);
  }
}

double Environment::pdf(const Vec3& normal, const Vec3& dir) const {
  double p = 0.0;
  radianceAndPdf(normal, dir, p);
  return p;
}

Rgb Environment::radianceAndPdf(const Vec3& normal, const Vec3& dir, double& pdf) const {
  const Impl& env = *impl_;
  if (env.isConstant) {
    pdf = constantPdf(normal, dir);
    return env.constantRadiance;
  }
  const LatLongPosition at = env.grid.position(dir);
  pdf = env.pdfAt(CosineBins::bin(normal), dir, at);
  return env.map.interpolate(at);
}

double Environment::meanLuminance() const { return impl_->meanLuminance; }

const std::string& Environment::description() const { return impl_->description; }

}  // namespace glossy
