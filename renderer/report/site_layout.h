// Where things live in a report site, the one place the pages and the writer agree on it:
//   SITE/index.html                       the index
//   SITE/assets/style.css, report.js      the static files
//   SITE/materials/NAME/index.html        a material's page, beside its images:
//       panel-LAYER.png, sheet-lower.png (sheet_images.h), plots/FILE
//   SITE/.glossy-manifest                 what glossy wrote (renderer/output/owned_folder.h)
// Material pages sit in a folder of their own so that no material name ("index.html", "assets") can
// collide with the site's own files. NAME and LAYER are checked plain names
// (renderer/sheet/sheet_record.h).
#pragma once

#include <string>

namespace glossy::report::layout {

inline constexpr const char* kIndex = "index.html";
inline constexpr const char* kStyle = "assets/style.css";
inline constexpr const char* kScript = "assets/report.js";
inline constexpr const char* kGenerator = "glossy report";

inline std::string materialFolder(const std::string& name) { return "materials/" + name; }
inline std::string materialPage(const std::string& name) { return materialFolder(name) + "/index.html"; }
// Relative to the material's folder.
inline std::string sheetLowerImage() { return "sheet-lower.png"; }
inline std::string panelImage(const std::string& layer) { return "panel-" + layer + ".png"; }
inline std::string plotFile(const std::string& file) { return "plots/" + file; }

}  // namespace glossy::report::layout
