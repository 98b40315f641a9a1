// glossy merge's two jobs without the command line: what the shards of a job array made, brought together
// (docs/cluster.md) — each shard's fits into the material library, every sheet's figures into one table.
// Both read and check everything before writing anything, and write atomically. `glossy merge` and the
// Python module's glossy.merge_fits and glossy.merge_sheets run them, so the two write the same bytes.
#pragma once

#include <cstddef>
#include <string>

namespace glossy::app {

struct MergeFitsRequest {
  std::string fitsDir;             // the shards' parameter files, DIR/NAME.toml (glossy fit --out-dir)
  std::string library;             // the parameter files to update, LIBRARY/NAME.toml (created when missing)
  std::string libraryName = "-o";  // what messages call it: the option that gave it
  bool replace = false;            // a file's published fit may replace a different published one
};

struct MergeFitsResult {
  size_t fits = 0, materials = 0, replaced = 0, unchanged = 0, filesWritten = 0;
};

// Each file's fits put into the library's file of its material, other fits kept: glossy's fit replaces
// glossy's earlier one of the same model and metric (saying so); a published fit is added where the library
// has none and never replaces a different published one unless `replace`. Two files naming one material are
// refused. InputError naming the file for bad input, before anything is written.
MergeFitsResult mergeFits(const MergeFitsRequest& request);

struct MergeSheetsRequest {
  std::string sheetsDir;  // a folder of sheets (glossy sheets -o DIR)
  std::string csv, json;  // the tables to write, either or both
  std::string csvName = "--csv", jsonName = "--json";  // what messages call them
};

struct MergeSheetsResult {
  size_t sheets = 0;
};

// Every sheet's figures: a CSV row per panel (and the noise-floor row), a JSON object per sheet.
MergeSheetsResult mergeSheets(const MergeSheetsRequest& request);

}  // namespace glossy::app
