// A sheet's EXR as `glossy report` and `glossy merge sheets` read it: its header made into a SheetRecord
// (the panels' boxes, labels, figures, the verdict), and, for a sheet that is accepted, the site's images cut
// from the PNG beside it in those boxes, as the report does. OpenImageIO reads only from a path: the bytes
// become NAME.exr, with a valid PNG beside it (the record requires one).
#include "renderer/report/sheet_images.h"
#include "renderer/sheet/sheet_record.h"
#include "tests/fuzz/fuzz_entries.h"
#include "tests/fuzz/fuzz_temp_dir.h"

#include <array>

namespace glossy::fuzz {

namespace {

// A 1 × 1 RGB PNG.
constexpr std::array<uint8_t, 69> kPng = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
    0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x02, 0x00, 0x00, 0x00, 0x90, 0x77, 0x53, 0xde, 0x00, 0x00, 0x00,
    0x0c, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x60, 0x60, 0x60, 0x00, 0x00, 0x00, 0x04, 0x00, 0x01, 0xf6,
    0x17, 0x38, 0x55, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

}  // namespace

void sheetEntry(Bytes data) {
  const TempFile png("alum-bronze.png", kPng), exr("alum-bronze.exr", data);
  const SheetRecord record = readSheetRecord(exr.path());
  (void)record.closestLayers();
  (void)record.isTie();
  // The images to a folder of their own, emptied each time: the cut, not the files, is what is fuzzed.
  const std::filesystem::path out = exr.path().parent_path() / "site";
  std::filesystem::create_directory(out);
  report::writeSheetImages(record, report::readSheetPixels(record), out);
  std::error_code ec;
  std::filesystem::remove_all(out, ec);
}

}  // namespace glossy::fuzz
